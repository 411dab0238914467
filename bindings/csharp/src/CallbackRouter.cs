// CallbackRouter: the AOT-safe path from native callbacks to managed ones.
// Native code gets only two static trampolines (one delegate instance each,
// kept alive for the life of the process) and, as `user`, a GCHandle to the
// sensor's router, which holds the managed callbacks. A managed callback that
// throws never unwinds into native code: the exception is caught and kept
// (Sensor.CallbackErrorCount, Sensor.LastCallbackException).
using System;
using System.Runtime.InteropServices;
using System.Threading;

namespace Onetip.Interop
{
    internal sealed class CallbackRouter
    {
        internal volatile Action<SensorEvent> OnEvent;
        internal volatile Action<FrameResult> OnFrame;
        int errorCount;
        Exception lastError;

        internal int ErrorCount { get { return Volatile.Read(ref errorCount); } }
        internal Exception LastError { get { return Volatile.Read(ref lastError); } }

        [ThreadStatic] static bool insideCallback;
        /// <summary>True on a thread that is running one of our callbacks now.</summary>
        internal static bool InsideCallback { get { return insideCallback; } }

        internal static readonly NativeMethods.EventCallback EventTrampoline = OnNativeEvent;
        internal static readonly NativeMethods.FrameCallback FrameTrampoline = OnNativeFrame;

        [MonoPInvokeCallback(typeof(NativeMethods.EventCallback))]
        static void OnNativeEvent(IntPtr evt, IntPtr user)
        {
            Route(user, router => {
                var callback = router.OnEvent;
                if (callback == null) return;
                var native = (NativeEventSd)Marshal.PtrToStructure(evt, typeof(NativeEventSd));
                callback(SensorEvent.From(ref native));
            });
        }

        [MonoPInvokeCallback(typeof(NativeMethods.FrameCallback))]
        static void OnNativeFrame(IntPtr frame, IntPtr markers, int markerCount, IntPtr user)
        {
            Route(user, router => {
                var callback = router.OnFrame;
                if (callback == null) return;
                var native = (NativeFrameSd)Marshal.PtrToStructure(frame, typeof(NativeFrameSd));
                callback(FrameResult.From(ref native, CopyMarkers(markers, markerCount)));
            });
        }

        static void Route(IntPtr user, Action<CallbackRouter> call)
        {
            CallbackRouter router = null;
            insideCallback = true;
            try {
                router = (CallbackRouter)GCHandle.FromIntPtr(user).Target;
                call(router);
            } catch (Exception e) {
                if (router != null) {
                    Interlocked.Increment(ref router.errorCount);
                    Volatile.Write(ref router.lastError, e);
                }
            } finally {
                insideCallback = false;
            }
        }

        internal static Marker[] CopyMarkers(IntPtr markers, int count)
        {
            var result = new Marker[Math.Max(0, count)];
            int size = Marshal.SizeOf(typeof(Marker));
            for (int i = 0; i < result.Length; ++i)
                result[i] = (Marker)Marshal.PtrToStructure(new IntPtr(markers.ToInt64() + (long)i * size), typeof(Marker));
            return result;
        }
    }
}
