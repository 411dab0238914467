// SensorHandle: owns one onetip_sensor*. Releasing it (Dispose, or the
// finalizer when a Sensor was never disposed) destroys the native sensor,
// which stops its threads and waits for a callback in progress; only then
// is the GCHandle that routes callbacks to managed code freed, so no
// callback can reach a freed handle.
using System;
using System.Runtime.InteropServices;
using Microsoft.Win32.SafeHandles;

namespace Onetip.Interop
{
    internal sealed class SensorHandle : SafeHandleZeroOrMinusOneIsInvalid
    {
        internal SensorHandle() : base(true) { }

        /// <summary>The CallbackRouter this sensor's callbacks reach (allocated by Sensor).</summary>
        internal GCHandle Router;

        protected override bool ReleaseHandle()
        {
            NativeError error;
            bool destroyed = NativeMethods.onetip_sensor_destroy(handle, out error) == 0;
            if (destroyed && Router.IsAllocated) Router.Free();
            return destroyed;
        }
    }
}
