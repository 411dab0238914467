// The values a Sensor reports (onetip_c.h, onetip/events.hpp): the 6-D
// input, events, markers and per-frame results. Positions in mm in the
// sensor frame S (origin at the rest-state marker centroid, z out of the pad,
// x along marker columns, y = z x x); angles in degrees; times in seconds.
using System;
using System.Runtime.InteropServices;
using Onetip.Interop;

namespace Onetip
{
    public enum EventType { ContactBegin = 0, ContactEnd = 1, Input = 2, Press = 3, Release = 4, StateChanged = 5, Error = 6 }
    public enum ContactState { None = 0, Stick = 1, PartialSlip = 2, Slip = 3 }
    public enum FrameStatus { Ok = 0, Reference = 1, Skipped = 2, Lost = 3 }
    public enum FilterKind { None = 0, MovingAverage = 1, OneEuro = 2 }

    /// <summary>[dx, dy, dz, yaw, pitch, roll]: the finger's motion since contact
    /// onset; dx, dy, dz in mm (dz = press depth, positive into the pad), yaw
    /// about S.z, pitch about S.x, roll about S.y in degrees (docs/reference.md).</summary>
    public struct Input6
    {
        public double Dx, Dy, Dz, Yaw, Pitch, Roll;

        public Input6(double dx, double dy, double dz, double yaw, double pitch, double roll)
        {
            Dx = dx; Dy = dy; Dz = dz; Yaw = yaw; Pitch = pitch; Roll = roll;
        }

        internal static Input6 From(double[] v) { return new Input6(v[0], v[1], v[2], v[3], v[4], v[5]); }
        public double[] ToArray() { return new[] { Dx, Dy, Dz, Yaw, Pitch, Roll }; }
        public override string ToString()
        {
            return string.Format("[{0:F3}, {1:F3}, {2:F3}, {3:F2}, {4:F2}, {5:F2}]", Dx, Dy, Dz, Yaw, Pitch, Roll);
        }
    }

    public struct SensorEvent
    {
        public EventType Type;
        public ContactState State;
        public long Frame;        // source frame index, -1 when not tied to a frame
        public double T;          // that frame's timestamp, s
        public double ArrivalS;   // when it arrived, s on Sensor.ClockSeconds()
        public Input6 Input;      // filtered and shaped; zero out of contact
        /// <summary>One standard deviation of each component of the measured 6-D input (FrameResult.Sd;
        /// mm, degrees); zero out of contact, wide for a component the pad cannot see.</summary>
        public Input6 Sd;
        public string Message;    // error events

        internal static SensorEvent From(ref NativeEventSd native)
        {
            NativeEvent e = native.Event;
            return new SensorEvent {
                Type = (EventType)e.Type, State = (ContactState)e.State, Frame = e.Frame, T = e.T,
                ArrivalS = e.ArrivalS, Input = Input6.From(e.Input), Sd = Input6.From(native.Sd),
                Message = e.Message ?? ""
            };
        }

        public override string ToString()
        {
            return Type == EventType.Error ? string.Format("{0} frame {1}: {2}", Type, Frame, Message)
                                           : string.Format("{0} frame {1} {2}", Type, Frame, Input);
        }
    }

    /// <summary>One marker (id = row * cols + col), laid out as onetip_marker_sd: the fields of
    /// onetip_marker, then the stick probability.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Marker
    {
        public int Id;
        int valid, displaced;
        public int Region;                    // contact region (0 = largest), -1 outside
        public double X, Y, Z;                // position in S, mm (when Valid)
        public double Ux, Uy, Uz;             // displacement from rest, S, mm (when Displaced)
        /// <summary>In [0, 1]: the marker moves with the finger (sticks) in this frame; 0 outside the tracked contact.</summary>
        public double StickProbability;
        public bool Valid { get { return valid != 0; } }
        public bool Displaced { get { return displaced != 0; } }
    }

    public sealed class FrameResult
    {
        public long Frame;
        public double T, ArrivalS;
        public FrameStatus Status;
        public bool Contact, Pressed, OutOfRange;
        public ContactState State;
        public int Rows, Cols, ContactRegions;
        public double MaxNormalMm;
        public Input6 Raw;            // measured (what `onetip process` writes to pose.csv)
        public Input6 Input;          // filtered and shaped, as in events
        /// <summary>One standard deviation of each component of Raw (pose.csv's sd_dx .. sd_roll; mm,
        /// degrees); zero out of contact, wide for a component the pad cannot see.</summary>
        public Input6 Sd;
        public double[] TimesMs;      // capture, queue, detect, track, triangulate, contact, pose, process
        public string Message;        // why, when skipped or lost
        public Marker[] Markers;      // Rows * Cols entries, index = id

        internal static FrameResult From(ref NativeFrameSd native, Marker[] markers)
        {
            NativeFrame f = native.Frame;
            return new FrameResult {
                Sd = Input6.From(native.Sd),
                Frame = f.Frame, T = f.T, ArrivalS = f.ArrivalS, Status = (FrameStatus)f.Status,
                Contact = f.Contact != 0, Pressed = f.Pressed != 0, OutOfRange = f.OutOfRange != 0,
                State = (ContactState)f.State, Rows = f.Rows, Cols = f.Cols, ContactRegions = f.ContactRegions,
                MaxNormalMm = f.MaxNormalMm, Raw = Input6.From(f.Raw), Input = Input6.From(f.Input),
                TimesMs = f.TimesMs, Message = f.Message ?? "", Markers = markers
            };
        }
    }

    public struct StageTiming
    {
        public string Stage;  // "capture", "queue", "detect", ..., "process", "delivery"
        public long Count;
        public double MedianMs, P99Ms, MaxMs;
    }

    public sealed class SensorStats
    {
        public long FramesCaptured, FramesProcessed, FramesDropped, FramesSkipped, FramesLost, SourceErrors;
        public long EventsEmitted, EventsDropped, FrameResultsDropped, CallbackErrors;
        public bool SourceAbandoned;
        public StageTiming[] Stages;

        internal static SensorStats From(ref NativeStats s)
        {
            var stages = new StageTiming[Math.Max(0, Math.Min(s.StageCount, s.Stages.Length))];
            for (int i = 0; i < stages.Length; ++i)
                stages[i] = new StageTiming { Stage = s.Stages[i].Stage, Count = s.Stages[i].Count,
                                              MedianMs = s.Stages[i].MedianMs, P99Ms = s.Stages[i].P99Ms,
                                              MaxMs = s.Stages[i].MaxMs };
            return new SensorStats {
                FramesCaptured = s.FramesCaptured, FramesProcessed = s.FramesProcessed, FramesDropped = s.FramesDropped,
                FramesSkipped = s.FramesSkipped, FramesLost = s.FramesLost, SourceErrors = s.SourceErrors,
                EventsEmitted = s.EventsEmitted, EventsDropped = s.EventsDropped,
                FrameResultsDropped = s.FrameResultsDropped, CallbackErrors = s.CallbackErrors,
                SourceAbandoned = s.SourceAbandoned != 0, Stages = stages
            };
        }
    }
}
