// MonoPInvokeCallbackAttribute: marks the static methods that native code
// calls back (Sensor's trampolines), so ahead-of-time compilers (Unity's
// IL2CPP, Xamarin/Mono full AOT) generate native entry points for them. They
// recognise the attribute by its name, so this local copy works without
// referencing Unity's assemblies.
using System;

namespace Onetip.Interop
{
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        public MonoPInvokeCallbackAttribute(Type delegateType) { DelegateType = delegateType; }
        public Type DelegateType { get; private set; }
    }
}
