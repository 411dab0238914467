// SensorOptions: how a Sensor runs, laid out as onetip_options (onetip_c.h):
// one field (or property) per row of the library's option table, named as the
// row in PascalCase; OptionInfo.Table() gives each row's type, default, range,
// unit and meaning (onetip/sensor_option_table.hpp). Start from Default() (the
// library's defaults) or Load() a YAML/JSON file; Validate(), Set() and the
// Sensor check values against the table (OnetipException, kind Input, naming
// the field, its range and unit). Axis arrays: dx, dy, dz (mm), yaw, pitch, roll (deg).
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

        /// <summary>Every value in its range and release_mm below press_mm, else OnetipException (Input).</summary>
        public void Validate()
        {
            NativeError e;
            Errors.Check(NativeMethods.onetip_options_validate(NativeMethods.AbiVersion, this, out e), ref e);
        }

        /// <summary>Value `index` (0, or 0..5 for axes) of the option `name` (a table row's name).</summary>
        public double Get(string name, int index = 0)
        {
            double value;
            NativeError e;
            Errors.Check(NativeMethods.onetip_options_get(NativeMethods.AbiVersion, this, name, index, out value, out e), ref e);
            return value;
        }

        /// <summary>Sets value `index` of the option `name` after checking it against the table;
        /// unchanged when it throws.</summary>
        public void Set(string name, double value, int index = 0)
        {
            NativeError e;
            Errors.Check(NativeMethods.onetip_options_set(NativeMethods.AbiVersion, this, name, index, value, out e), ref e);
        }

        /// <summary>Writes every field as YAML; the file is replaced atomically.</summary>
        public void Save(string path)
        {
            NativeError e;
            Errors.Check(NativeMethods.onetip_options_save(NativeMethods.AbiVersion, this, path, out e), ref e);
        }
    }
}
