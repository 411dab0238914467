// NativeStructs: the flat structs of onetip_c.h, laid out field for field
// (sequential, natural alignment, as the C compiler lays them out).
// Positions in mm in the sensor frame S, angles in degrees, times in seconds.
using System.Runtime.InteropServices;

namespace Onetip.Interop
{
    [StructLayout(LayoutKind.Sequential, CharSet = CharSet.Ansi)]
    internal struct NativeError
    {
        public int Kind;
        [MarshalAs(UnmanagedType.ByValTStr, SizeConst = 256)] public string Message;
    }

    [StructLayout(LayoutKind.Sequential, CharSet = CharSet.Ansi)]
    internal struct NativeEvent
    {
        public int Type;
        public int State;
        public long Frame;
        public double T;
        public double ArrivalS;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] Input;
        [MarshalAs(UnmanagedType.ByValTStr, SizeConst = 160)] public string Message;
    }

    [StructLayout(LayoutKind.Sequential, CharSet = CharSet.Ansi)]
    internal struct NativeFrame
    {
        public long Frame;
        public double T;
        public double ArrivalS;
        public int Status;
        public int Contact;
        public int State;
        public int Pressed;
        public int OutOfRange;
        public int Rows, Cols;
        public int ContactRegions;
        public double MaxNormalMm;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] Raw;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] Input;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 8)] public double[] TimesMs;
        [MarshalAs(UnmanagedType.ByValTStr, SizeConst = 160)] public string Message;
    }

    /// <summary>onetip_event_sd: the event, then one sd per component of the 6-D input.</summary>
    [StructLayout(LayoutKind.Sequential, CharSet = CharSet.Ansi)]
    internal struct NativeEventSd
    {
        public NativeEvent Event;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] Sd;
    }

    /// <summary>onetip_frame_sd: the frame, then one sd per component of its raw 6-D input.</summary>
    [StructLayout(LayoutKind.Sequential, CharSet = CharSet.Ansi)]
    internal struct NativeFrameSd
    {
        public NativeFrame Frame;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] Sd;
    }

    [StructLayout(LayoutKind.Sequential, CharSet = CharSet.Ansi)]
    internal struct NativeStageTiming
    {
        [MarshalAs(UnmanagedType.ByValTStr, SizeConst = 16)] public string Stage;
        public long Count;
        public double MedianMs, P99Ms, MaxMs;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeStats
    {
        public long FramesCaptured, FramesProcessed, FramesDropped, FramesSkipped, FramesLost, SourceErrors;
        public long EventsEmitted, EventsDropped, FrameResultsDropped, CallbackErrors;
        public int SourceAbandoned;
        public int StageCount;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 16)] public NativeStageTiming[] Stages;
    }

    [StructLayout(LayoutKind.Sequential, CharSet = CharSet.Ansi)]
    internal struct NativeOptionInfo
    {
        [MarshalAs(UnmanagedType.ByValTStr, SizeConst = 48)] public string Name;
        public int Type;
        public int Count;
        public double Min, Max;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public double[] DefaultValue;
        [MarshalAs(UnmanagedType.ByValTStr, SizeConst = 16)] public string Unit;
        [MarshalAs(UnmanagedType.ByValTStr, SizeConst = 96)] public string Choices;
        [MarshalAs(UnmanagedType.ByValTStr, SizeConst = 128)] public string Doc;
    }
}
