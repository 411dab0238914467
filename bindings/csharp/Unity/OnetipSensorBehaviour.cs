// OnetipSensorBehaviour: drives a GameObject with the fingertip's 6-D input.
//
// Put libonetip.so (Linux), and Onetip.dll or the bindings/csharp/src/*.cs
// files, in the project's Assets/Plugins; add this component to the object to
// move. The sensor runs on the library's own threads; Update() drains its
// event queue on the main thread (no callbacks into managed code, so nothing
// touches Unity objects off the main thread). While a contact lasts the target
// is placed at its rest pose moved by the input (UnityAxes: S.x -> x, S.y -> z,
// out of the pad -> y; mm scaled by unitsPerMm, degrees by rotationGain); at
// contact end it returns to rest. LastSd is the uncertainty of that input (one
// standard deviation per axis, mm and degrees): a game can freeze an axis
// whose sd is wide (a turn the pad cannot see).
//
// Editor domain reload: the native sensor is released in OnDisable (also
// called before a script reload and on exit from play mode), OnDestroy and,
// as a last resort, on AppDomain unload, so no native thread outlives the
// managed code it reports to.
using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Events;

namespace Onetip
{
    public sealed class OnetipSensorBehaviour : MonoBehaviour
    {
        [Tooltip("\"sim:<path>/press.yaml\", \"v4l2:/dev/video0\", a folder or a video file")]
        public string source = "sim:Assets/StreamingAssets/press.yaml";
        [Tooltip("Calibration file (empty for sim: sources)")] public string calibration = "";
        [Tooltip("Pattern file (empty for sim: sources)")] public string pattern = "";
        [Tooltip("Object to move (default: this one)")] public Transform target;
        [Tooltip("Unity units per millimetre of finger motion")] public float unitsPerMm = 0.01f;
        [Tooltip("Scene degrees per degree of finger rotation")] public float rotationGain = 1f;
        [Tooltip("At most this many events per frame (the rest wait for the next Update)")] public int maxEventsPerUpdate = 256;

        public UnityEvent onContactBegin = new UnityEvent();
        public UnityEvent onContactEnd = new UnityEvent();
        public UnityEvent onPress = new UnityEvent();
        public UnityEvent onRelease = new UnityEvent();

        public Input6 LastInput { get; private set; }
        /// <summary>One standard deviation of each axis of the last input event (SensorEvent.Sd; mm,
        /// degrees); zero out of contact.</summary>
        public Input6 LastSd { get; private set; }
        public bool InContact { get; private set; }

        Sensor sensor;
        Vector3 restPosition;
        Quaternion restRotation;

        static readonly HashSet<OnetipSensorBehaviour> live = new HashSet<OnetipSensorBehaviour>();
        static bool unloadHooked;

        void OnEnable()
        {
            if (target == null) target = transform;
            restPosition = target.localPosition;
            restRotation = target.localRotation;
            HookDomainUnload();
            try {
                sensor = new Sensor(source, calibration, pattern);
                sensor.Start();
                lock (live) live.Add(this);
            } catch (Exception e) {  // OnetipException (bad source or file), DllNotFoundException (no plugin)
                Debug.LogError("onetip: " + e.Message);
                Release();
                enabled = false;
            }
        }

        void Update()
        {
            if (sensor == null) return;
            SensorEvent e;
            for (int i = 0; i < maxEventsPerUpdate && sensor.PollEvent(out e); ++i) Handle(e);
        }

        void Handle(SensorEvent e)
        {
            switch (e.Type) {
                case EventType.ContactBegin: InContact = true; Apply(new Input6(), e.Sd); onContactBegin.Invoke(); break;
                case EventType.Input: Apply(e.Input, e.Sd); break;
                case EventType.ContactEnd: InContact = false; Apply(new Input6(), new Input6()); onContactEnd.Invoke(); break;
                case EventType.Press: onPress.Invoke(); break;
                case EventType.Release: onRelease.Invoke(); break;
                case EventType.Error: Debug.LogWarning("onetip: " + e.Message); break;
            }
        }

        void Apply(Input6 input, Input6 sd)
        {
            LastInput = input;
            LastSd = sd;
            double x, y, z, w;
            UnityAxes.Position(input, unitsPerMm, out x, out y, out z);
            target.localPosition = restPosition + new Vector3((float)x, (float)y, (float)z);
            UnityAxes.Rotation(input, rotationGain, out x, out y, out z, out w);
            target.localRotation = restRotation * new Quaternion((float)x, (float)y, (float)z, (float)w);
        }

        /// <summary>The 6-D input restarts from zero now (as if a new contact began).</summary>
        public void Rezero() { if (sensor != null) sensor.Rezero(); }

        void OnDisable() { Release(); }
        void OnDestroy() { Release(); }

        void Release()
        {
            lock (live) live.Remove(this);
            if (sensor == null) return;
            sensor.Dispose();
            sensor = null;
            if (target != null) {
                target.localPosition = restPosition;
                target.localRotation = restRotation;
            }
        }

        // Editor reloads unload the AppDomain; a sensor that somehow missed OnDisable is freed here.
        static void HookDomainUnload()
        {
            if (unloadHooked) return;
            unloadHooked = true;
            AppDomain.CurrentDomain.DomainUnload += (s, a) => {
                OnetipSensorBehaviour[] all;
                lock (live) { all = new OnetipSensorBehaviour[live.Count]; live.CopyTo(all); live.Clear(); }
                foreach (var b in all)
                    if (b.sensor != null) { b.sensor.Dispose(); b.sensor = null; }
            };
        }
    }
}
