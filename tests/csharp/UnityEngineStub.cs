// UnityEngineStub: just enough of UnityEngine's surface (names and
// signatures, no behaviour) to compile bindings/csharp/Unity/*.cs with Mono
// in CI, so a typo or an API misuse there fails the build. Never shipped; in
// Unity the real UnityEngine is used. It includes UnityEngine.EventType, as
// Unity does, to catch ambiguities with Onetip.EventType.
using System;

namespace UnityEngine
{
    public enum EventType { MouseDown, MouseUp }
    public class Object { }
    public class Component : Object { public Transform transform { get { return null; } } }
    public class Behaviour : Component { public bool enabled { get; set; } }
    public class MonoBehaviour : Behaviour { }
    public class Transform : Component
    {
        public Vector3 localPosition { get; set; }
        public Quaternion localRotation { get; set; }
    }
    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 operator +(Vector3 a, Vector3 b) { return new Vector3(a.x + b.x, a.y + b.y, a.z + b.z); }
    }
    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public static Quaternion operator *(Quaternion a, Quaternion b) { return a; }
    }
    public static class Debug
    {
        public static void LogError(object message) { }
        public static void LogWarning(object message) { }
    }
    [AttributeUsage(AttributeTargets.Field)]
    public sealed class TooltipAttribute : Attribute { public TooltipAttribute(string tooltip) { } }
}

namespace UnityEngine.Events
{
    public class UnityEvent { public void Invoke() { } }
}
