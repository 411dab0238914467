// Sensor: the fingertip sensor over the C ABI — a frame source, its
// calibration and pattern, and the library's threaded pipeline (capture and
// processing threads, a bounded latest-frame-wins queue).
//
// Threads: every method may be called from any thread. Callbacks (OnEvent,
// OnFrame) run on the library's processing thread, one at a time, in frame
// order; Unity code should instead drain PollEvent() on the main thread
// (Unity/OnetipSensorBehaviour.cs). Start, Stop and Dispose from inside a
// callback throw OnetipException (kind State). Positions in mm in the sensor
// frame S, angles in degrees, times in seconds (Values.cs).
using System;
using System.Runtime.InteropServices;
using Onetip.Interop;

namespace Onetip
{
    public sealed class Sensor : IDisposable
    {
        readonly SensorHandle handle;
        readonly CallbackRouter router = new CallbackRouter();
        Marker[] markerBuffer = new Marker[1024];

        /// <summary>Opens the source ("v4l2:/dev/videoN", a folder, a video file or
        /// "sim:SCENARIO.yaml"); calibration and pattern files may be null for "sim:"
        /// sources; reference: a rest-state image or null (the first frame). Does not
        /// start. Throws OnetipException (kind Input) naming the bad file, source or option.</summary>
        public Sensor(string source, string calibration = null, string pattern = null, string reference = null,
                      SensorOptions options = null)
        {
            if (source == null) throw new ArgumentNullException("source");
            Errors.RequireMinorVersion("Sensor (events and frames with their uncertainty)");
            NativeError e;
            int code = NativeMethods.onetip_sensor_create(NativeMethods.AbiVersion, source, calibration, pattern,
                                                          reference, options ?? SensorOptions.Default(),
                                                          out handle, out e);
            Errors.Check(code, ref e);
            handle.Router = GCHandle.Alloc(router);
        }

        /// <summary>"MAJOR.MINOR.PATCH" of the loaded library.</summary>
        public static string LibraryVersion
        {
            get { return Marshal.PtrToStringAnsi(NativeMethods.onetip_version_string()); }
        }
        /// <summary>The loaded library's C ABI version, and the one this wrapper expects.</summary>
        public static uint LibraryAbiVersion { get { return NativeMethods.onetip_abi_version(); } }
        public static uint WrapperAbiVersion { get { return NativeMethods.AbiVersion; } }
        /// <summary>Seconds on the clock of SensorEvent.ArrivalS.</summary>
        public static double ClockSeconds() { return NativeMethods.onetip_clock_seconds(); }

        public void Start() { NativeError e; Errors.Check(NativeMethods.onetip_sensor_start(handle, out e), ref e); }

        /// <summary>Stops both threads and returns once callbacks have finished; queued events stay pollable.
        /// Before Start it ends a sensor that never ran: waiters return and Start then throws (kind State).</summary>
        public void Stop() { NativeError e; Errors.Check(NativeMethods.onetip_sensor_stop(handle, out e), ref e); }

        public bool IsRunning
        {
            get { int v; NativeError e; Errors.Check(NativeMethods.onetip_sensor_is_running(handle, out v, out e), ref e); return v != 0; }
        }

        public bool IsFinished
        {
            get { int v; NativeError e; Errors.Check(NativeMethods.onetip_sensor_is_finished(handle, out v, out e), ref e); return v != 0; }
        }

        /// <summary>Waits up to timeoutS seconds (negative: no limit) for the source to end; returns IsFinished.</summary>
        public bool WaitFinished(double timeoutS)
        {
            int finished;
            NativeError e;
            Errors.Check(NativeMethods.onetip_sensor_wait_finished(handle, timeoutS, out finished, out e), ref e);
            return finished != 0;
        }

        /// <summary>callback(event) on the processing thread; null removes it. Once this
        /// returns, the previous callback is never called again.</summary>
        public void OnEvent(Action<SensorEvent> callback)
        {
            router.OnEvent = callback;
            NativeError e;
            Errors.Check(NativeMethods.onetip_sensor_set_event_sd_callback(
                handle, callback == null ? null : CallbackRouter.EventTrampoline, RouterPointer(), out e), ref e);
        }

        /// <summary>callback(frame) on the processing thread, with every marker; null removes it.</summary>
        public void OnFrame(Action<FrameResult> callback)
        {
            router.OnFrame = callback;
            NativeError e;
            Errors.Check(NativeMethods.onetip_sensor_set_frame_sd_callback(
                handle, callback == null ? null : CallbackRouter.FrameTrampoline, RouterPointer(), out e), ref e);
        }

        /// <summary>Callbacks that threw (caught here: they never unwind into the library), and the last exception.</summary>
        public int CallbackErrorCount { get { return router.ErrorCount; } }
        public Exception LastCallbackException { get { return router.LastError; } }

        /// <summary>Non-blocking: the oldest queued event.</summary>
        public bool PollEvent(out SensorEvent evt)
        {
            NativeEventSd native;
            int got;
            NativeError e;
            Errors.Check(NativeMethods.onetip_sensor_poll_event_sd(handle, out native, out got, out e), ref e);
            evt = got != 0 ? SensorEvent.From(ref native) : default(SensorEvent);
            return got != 0;
        }

        /// <summary>Blocks up to timeoutS seconds for an event; false on time-out, or
        /// at once when the sensor has finished or stopped and nothing is queued.</summary>
        public bool WaitEvent(double timeoutS, out SensorEvent evt)
        {
            NativeEventSd native;
            int got;
            NativeError e;
            Errors.Check(NativeMethods.onetip_sensor_wait_event_sd(handle, timeoutS, out native, out got, out e), ref e);
            evt = got != 0 ? SensorEvent.From(ref native) : default(SensorEvent);
            return got != 0;
        }

        /// <summary>Non-blocking: the oldest queued per-frame result, with every marker.</summary>
        public bool PollFrame(out FrameResult frame)
        {
            lock (router) {
                NativeFrameSd native;
                int count, got;
                NativeError e;
                Errors.Check(NativeMethods.onetip_sensor_poll_frame_sd(handle, out native, markerBuffer,
                                                                       markerBuffer.Length, out count, out got, out e),
                             ref e);
                frame = null;
                if (got == 0) return false;
                if (count > markerBuffer.Length) {  // a grid larger than the buffer: this frame's markers are cut
                    markerBuffer = new Marker[count];  // short (Markers.Length < Rows * Cols); later ones are whole
                    count = 0;
                }
                var markers = new Marker[count];
                Array.Copy(markerBuffer, markers, count);
                frame = FrameResult.From(ref native, markers);
                return true;
            }
        }

        /// <summary>The 6-D input restarts from zero at the next frame.</summary>
        public void Rezero() { NativeError e; Errors.Check(NativeMethods.onetip_sensor_rezero(handle, out e), ref e); }

        /// <summary>The next good frame becomes the new rest state (finger off the pad).</summary>
        public void Rereference() { NativeError e; Errors.Check(NativeMethods.onetip_sensor_rereference(handle, out e), ref e); }

        public SensorStats GetStats()
        {
            NativeStats native;
            NativeError e;
            Errors.Check(NativeMethods.onetip_sensor_get_stats(handle, out native, out e), ref e);
            return SensorStats.From(ref native);
        }

        /// <summary>Stops the sensor and frees it; later calls throw ObjectDisposedException. A WaitFinished
        /// in another thread (even without limit, on a sensor never started) returns false.</summary>
        public void Dispose()
        {
            if (CallbackRouter.InsideCallback)
                throw new OnetipException(ErrorKind.State, "Sensor.Dispose: not from inside one of its callbacks");
            // A thread inside WaitFinished keeps the handle in use, so its release would wait for that thread:
            // stop first, which ends every wait, then release.
            try {
                NativeError e;
                if (!handle.IsClosed) NativeMethods.onetip_sensor_stop(handle, out e);
            } catch (ObjectDisposedException) {  // disposed meanwhile by another thread
            }
            handle.Dispose();
        }

        IntPtr RouterPointer()
        {
            if (handle.IsClosed) throw new ObjectDisposedException("Sensor");
            return GCHandle.ToIntPtr(handle.Router);
        }
    }
}
