// NativeMethods: the C ABI of libonetip (onetip_c.h) as P/Invoke entry
// points. The library is found by the name "onetip": libonetip.so through
// the dynamic loader's path (LD_LIBRARY_PATH, Unity's Plugins folder) or a
// Mono dllmap; onetip.dll on Windows.
using System;
using System.Runtime.InteropServices;

namespace Onetip.Interop
{
    internal static class NativeMethods
    {
        const string Library = "onetip";

        /// <summary>ONETIP_C_ABI_VERSION of the header this wrapper was written against.</summary>
        internal const uint AbiVersion = 1;
        /// <summary>ONETIP_C_ABI_MINOR_VERSION it needs (1: the option table and keyed access;
        /// 2: the uncertainty forms of poll, wait and the callbacks, onetip_c_uncertainty.h).</summary>
        internal const uint AbiMinorVersion = 2;

        /// <summary>onetip_event_sd_callback: evt points to an onetip_event_sd.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        internal delegate void EventCallback(IntPtr evt, IntPtr user);
        /// <summary>onetip_frame_sd_callback: an onetip_frame_sd and markerCount onetip_marker_sd.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        internal delegate void FrameCallback(IntPtr frame, IntPtr markers, int markerCount, IntPtr user);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint onetip_abi_version();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint onetip_abi_minor_version();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr onetip_version_string();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern double onetip_clock_seconds();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_options_default(uint abi, [Out] SensorOptions options, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_options_load(uint abi, [MarshalAs(UnmanagedType.LPStr)] string path,
                                                       [Out] SensorOptions options, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_options_save(uint abi, [In] SensorOptions options,
                                                       [MarshalAs(UnmanagedType.LPStr)] string path, out NativeError error);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_options_validate(uint abi, [In] SensorOptions options, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_option_count();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_option_describe(uint abi, int row, out NativeOptionInfo info, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_options_get(uint abi, [In] SensorOptions options,
                                                      [MarshalAs(UnmanagedType.LPStr)] string name, int index,
                                                      out double value, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_options_set(uint abi, [In, Out] SensorOptions options,
                                                      [MarshalAs(UnmanagedType.LPStr)] string name, int index,
                                                      double value, out NativeError error);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_create(uint abi, [MarshalAs(UnmanagedType.LPStr)] string source,
                                                        [MarshalAs(UnmanagedType.LPStr)] string calibration,
                                                        [MarshalAs(UnmanagedType.LPStr)] string pattern,
                                                        [MarshalAs(UnmanagedType.LPStr)] string reference,
                                                        [In] SensorOptions options, out SensorHandle sensor,
                                                        out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_destroy(IntPtr sensor, out NativeError error);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_start(SensorHandle sensor, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_stop(SensorHandle sensor, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_is_running(SensorHandle sensor, out int running, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_is_finished(SensorHandle sensor, out int finished, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_wait_finished(SensorHandle sensor, double timeoutS, out int finished,
                                                               out NativeError error);

        // Events, frames and markers through their uncertainty forms (minor version 2).
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_set_event_sd_callback(SensorHandle sensor, EventCallback callback,
                                                                       IntPtr user, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_set_frame_sd_callback(SensorHandle sensor, FrameCallback callback,
                                                                       IntPtr user, out NativeError error);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_poll_event_sd(SensorHandle sensor, out NativeEventSd evt, out int got,
                                                               out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_wait_event_sd(SensorHandle sensor, double timeoutS,
                                                               out NativeEventSd evt, out int got, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_poll_frame_sd(SensorHandle sensor, out NativeFrameSd frame,
                                                               [In, Out] Marker[] markers, int capacity,
                                                               out int markerCount, out int got, out NativeError error);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_rezero(SensorHandle sensor, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_rereference(SensorHandle sensor, out NativeError error);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern int onetip_sensor_get_stats(SensorHandle sensor, out NativeStats stats,
                                                           out NativeError error);
    }
}
