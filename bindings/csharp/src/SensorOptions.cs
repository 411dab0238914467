// SensorOptions: how a Sensor runs, laid out as onetip_options (onetip_c.h);
// onetip/sensor_options.hpp gives each field's meaning, units and range.
// Start from Default() (the library's defaults) or Load() a YAML/JSON file;
// the library validates when a Sensor is created (OnetipException, kind
// Input, naming the bad field). Axis arrays: dx, dy, dz (mm), yaw, pitch, roll (deg).
using System.Runtime.InteropServices;
using Onetip.Interop;

namespace Onetip
{
    [StructLayout(LayoutKind.Sequential)]
    public sealed class SensorOptions
    {
        public int QueueCapacity;
        int lossless;
        public int EventQueueCapacity;
        public int FrameQueueCapacity;
        public int TimingWindow;
        public int MaxConsecutiveSourceErrors;
        public int StopTimeoutMs;
        public int MinMarkers;
        int filter;
        public int FilterWindow;
        public double PlaybackRate;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] WorkingRange = new double[6];
        public double ClampFactor;
        public double PressMm;
        public double ReleaseMm;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] Gain = new double[6];
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] DeadZone = new double[6];
        public double FilterMinCutoffHz;
        public double FilterBeta;
        public double FilterDerivativeCutoffHz;

        /// <summary>false: the latest frame wins (live cameras); true: capture waits, nothing dropped.</summary>
        public bool Lossless { get { return lossless != 0; } set { lossless = value ? 1 : 0; } }
        public FilterKind Filter { get { return (FilterKind)filter; } set { filter = (int)value; } }

        public static SensorOptions Default()
        {
            var o = new SensorOptions();
            NativeError e;
            Errors.Check(NativeMethods.onetip_options_default(NativeMethods.AbiVersion, o, out e), ref e);
            return o;
        }

        public static SensorOptions Load(string path)
        {
            var o = new SensorOptions();
            NativeError e;
            Errors.Check(NativeMethods.onetip_options_load(NativeMethods.AbiVersion, path, o, out e), ref e);
            return o;
        }

        /// <summary>Writes every field as YAML; the file is replaced atomically.</summary>
        public void Save(string path)
        {
            NativeError e;
            Errors.Check(NativeMethods.onetip_options_save(NativeMethods.AbiVersion, this, path, out e), ref e);
        }
    }
}
