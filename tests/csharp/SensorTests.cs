// The C# wrapper against the real libonetip (label csharp): the simulated
// press end to end, compared frame by frame with `onetip process` (the C++
// pipeline) on the same scenario, bad input at the boundary, and the option
// table (OptionsTests.cs).
// Usage: mono OnetipTests.exe SCENARIO.yaml POSE.csv MARKERS.csv WORK_DIR BEYOND_RANGE.yaml, or OnetipTests.exe options,
// or OnetipTests.exe uncertainty-in-contact SCENARIO.yaml (UncertaintyTests.cs)
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading;
using Onetip.Interop;

namespace Onetip.Tests
{
    static class SensorTests
    {
        const double Tolerance = 2e-6;  // the CSV files carry 6 decimals

        static int Main(string[] args)
        {
            if (args.Length == 1 && args[0] == "options") {  // the option table alone (label options)
                OptionsTests.Run();
                Console.WriteLine(Check.Failures == 0 ? "all option checks passed" : Check.Failures + " checks failed");
                return Check.Failures == 0 ? 0 : 1;
            }
            if (args.Length == 2 && args[0] == "uncertainty-in-contact") {
                UncertaintyTests.InContact(args[1]);
                Console.WriteLine(Check.Failures == 0 ? "all uncertainty checks passed" : Check.Failures + " checks failed");
                return Check.Failures == 0 ? 0 : 1;
            }
            if (args.Length != 5) {
                Console.Error.WriteLine("usage: OnetipTests.exe SCENARIO.yaml POSE.csv MARKERS.csv WORK_DIR BEYOND_RANGE.yaml | " +
                                        "options | uncertainty-in-contact SCENARIO.yaml");
                return 2;
            }
            Console.WriteLine("onetip " + Sensor.LibraryVersion + ", C ABI " + Sensor.LibraryAbiVersion);
            Check.That(Sensor.LibraryAbiVersion == Sensor.WrapperAbiVersion, "the library's ABI version is the wrapper's");
            var reference = new CliReference(args[1], args[2]);
            EndToEnd(args[0], reference);
            BeyondTheWorkingRange(args[4]);
            BadInput(args[3]);
            CallbacksThatThrow(args[3]);
            UnityAxesTests.Run();
            OptionsTests.Run();
            Console.WriteLine(Check.Failures == 0 ? "all checks passed" : Check.Failures + " checks failed");
            return Check.Failures == 0 ? 0 : 1;
        }

        static void EndToEnd(string scenario, CliReference reference)
        {
            var options = SensorOptions.Default();
            options.Lossless = true;
            options.EventQueueCapacity = 100000;
            options.FrameQueueCapacity = 1000;
            var fromCallback = new List<SensorEvent>();
            var callbackThreads = new HashSet<int>();
            var polled = new List<SensorEvent>();
            var frames = new List<FrameResult>();
            SensorStats stats;
            using (var sensor = new Sensor("sim:" + scenario, null, null, null, options)) {
                sensor.OnEvent(e => {
                    lock (fromCallback) {
                        fromCallback.Add(e);
                        callbackThreads.Add(Thread.CurrentThread.ManagedThreadId);
                    }
                });
                sensor.Start();
                SensorEvent ev;
                while (sensor.WaitEvent(5.0, out ev)) polled.Add(ev);
                Check.That(sensor.WaitFinished(60.0), "the simulated sensor finishes");
                FrameResult frame;
                while (sensor.PollFrame(out frame)) frames.Add(frame);
                stats = sensor.GetStats();
                Check.That(sensor.CallbackErrorCount == 0, "no callback threw");
            }

            long[] contact = reference.ContactFrames();
            Check.That(contact.Length > 0, "the C++ reference saw a contact");
            if (contact.Length == 0) return;
            var begins = polled.Where(e => e.Type == EventType.ContactBegin).ToList();
            var ends = polled.Where(e => e.Type == EventType.ContactEnd).ToList();
            var inputs = polled.Where(e => e.Type == EventType.Input).ToList();
            Check.That(begins.Count == 1 && begins[0].Frame == contact[0], "one contact begin, at the reference's first contact frame");
            Check.That(ends.Count == 1 && ends[0].Frame == contact[contact.Length - 1] + 1,
                       "one contact end, at the frame after the reference's last contact frame");
            // The shipped press stays inside the working range (dz in [0, 3] mm): no error event.
            var errors = polled.Where(e => e.Type == EventType.Error).ToList();
            Check.That(errors.Count == 0, "the shipped press gives no error event: " + string.Join("; ", errors));
            Check.That(inputs.Select(e => e.Frame).SequenceEqual(contact), "an input event for every contact frame of the reference");
            foreach (var e in inputs)
                CompareInput(e.Input, reference.Pose[e.Frame], "input event of frame " + e.Frame);
            Check.That(inputs.Max(e => e.Input.Dz) > 2.0, "the press goes deeper than 2 mm");
            Console.WriteLine("end to end: {0} events, {1} input events matched the C++ pipeline, contact frames {2}..{3}",
                              polled.Count, inputs.Count, contact[0], contact[contact.Length - 1]);

            Check.That(fromCallback.Select(e => (int)e.Type * 100000L + e.Frame)
                           .SequenceEqual(polled.Select(e => (int)e.Type * 100000L + e.Frame)),
                       "the callback saw the polled events, in order");
            Check.That(callbackThreads.Count == 1 && !callbackThreads.Contains(Thread.CurrentThread.ManagedThreadId),
                       "callbacks ran on one thread, not this one");

            var processed = frames.Where(f => f.Status == FrameStatus.Ok || f.Status == FrameStatus.Reference).ToList();
            Check.That(processed.Select(f => f.Frame).SequenceEqual(reference.Pose.Keys), "a frame result for every processed frame");
            foreach (var f in processed) {
                CompareInput(f.Raw, reference.Pose[f.Frame], "raw of frame " + f.Frame);
                CompareMarkers(f, reference.Markers[f.Frame]);
            }
            Check.That(stats.FramesProcessed == reference.Pose.Count && stats.FramesDropped == 0, "every frame processed, none dropped");
            UncertaintyTests.AgainstTheReference(reference, polled, fromCallback, processed);
        }

        // A press to 5 mm (tests/data/scenarios/press_beyond_range.yaml): an error event "beyond the working
        // range" at each frame where the measured input leaves the range, and nowhere else.
        static void BeyondTheWorkingRange(string scenario)
        {
            var options = SensorOptions.Default();
            options.Lossless = true;
            options.EventQueueCapacity = 100000;
            options.FrameQueueCapacity = 1000;
            var events = new List<SensorEvent>();
            var frames = new SortedDictionary<long, FrameResult>();
            using (var sensor = new Sensor("sim:" + scenario, null, null, null, options)) {
                sensor.Start();
                SensorEvent ev;
                while (sensor.WaitEvent(5.0, out ev)) events.Add(ev);
                Check.That(sensor.WaitFinished(60.0), "the simulated sensor finishes");
                FrameResult frame;
                while (sensor.PollFrame(out frame)) frames[frame.Frame] = frame;
            }
            var leaves = frames.Values.Where(f => f.OutOfRange && !(frames.ContainsKey(f.Frame - 1) && frames[f.Frame - 1].OutOfRange))
                                      .Select(f => f.Frame).ToList();
            var errors = events.Where(e => e.Type == EventType.Error).ToList();
            var reported = errors.Where(e => e.Message.Contains("working range")).Select(e => e.Frame).ToList();
            Check.That(leaves.Count > 0, "the press leaves the working range");
            Check.That(reported.SequenceEqual(leaves), "an error event where the input leaves the working range, and only there: " +
                       string.Join(",", reported) + " vs " + string.Join(",", leaves));
            foreach (var f in leaves)
                Check.That(frames[f].Raw.Dz > options.WorkingRange[2], "it is the press depth that leaves, frame " + f);
            foreach (var e in errors)
                Check.That(e.ToString() == "Error frame " + e.Frame + ": " + e.Message, "ToString() shows the message: " + e);
            Console.WriteLine("beyond the working range: reported at frame(s) {0}", string.Join(",", reported));
        }

        static void CompareInput(Input6 got, double[] expected, string what)
        {
            var v = got.ToArray();
            for (int i = 0; i < 6; ++i) Check.Near(v[i], expected[i], Tolerance, what + " [" + i + "]");
        }

        static void CompareMarkers(FrameResult f, List<double[]> expected)
        {
            Check.That(f.Markers.Length == f.Rows * f.Cols, "frame " + f.Frame + ": one marker per grid id");
            var valid = f.Markers.Where(m => m.Valid).ToList();
            Check.That(valid.Count == expected.Count, "frame " + f.Frame + ": as many valid markers as markers.csv rows");
            for (int i = 0; i < Math.Min(valid.Count, expected.Count); ++i) {
                var m = valid[i];
                Check.That(m.Id == (int)expected[i][0], "frame " + f.Frame + ": marker id " + m.Id);
                Check.Near(m.X, expected[i][1], Tolerance, "marker " + m.Id + ".x");
                Check.Near(m.Y, expected[i][2], Tolerance, "marker " + m.Id + ".y");
                Check.Near(m.Z, expected[i][3], Tolerance, "marker " + m.Id + ".z");
            }
        }

        static void BadInput(string work)
        {
            string missing = Path.Combine(work, "missing.yaml");
            var e = Check.Throws<OnetipException>(() => new Sensor("sim:" + missing), "a missing scenario");
            Check.That(e != null && e.Kind == ErrorKind.Input && e.Message.Contains("missing.yaml"),
                       "a missing scenario is an Input error naming it: " + (e == null ? "" : e.Message));
            e = Check.Throws<OnetipException>(() => SensorOptions.Load(missing), "a missing options file");
            Check.That(e != null && e.Kind == ErrorKind.Input && e.Message.Contains("missing.yaml"), "options: Input error naming the file");
            var bad = SensorOptions.Default();
            bad.QueueCapacity = 0;
            e = Check.Throws<OnetipException>(() => new Sensor("sim:" + Scenario(work, 0.1), null, null, null, bad), "queue_capacity 0");
            Check.That(e != null && e.Kind == ErrorKind.Input && e.Message.Contains("queue_capacity"), "a bad option is named");

            NativeError error;
            int code = NativeMethods.onetip_options_default(NativeMethods.AbiVersion + 1, SensorOptions.Default(), out error);
            Check.That(code == (int)ErrorKind.Version && error.Message.Length > 0, "a wrong ABI version is refused: " + error.Message);

            var options = SensorOptions.Default();
            options.Gain = new double[] { 1, 2, 3, 4, 5, 6 };
            options.Lossless = true;
            string saved = Path.Combine(work, "options.yaml");
            options.Save(saved);
            var loaded = SensorOptions.Load(saved);
            Check.That(loaded.Lossless && loaded.Gain.SequenceEqual(options.Gain) && loaded.PressMm == options.PressMm,
                       "options survive Save and Load");

            var sensor = new Sensor("sim:" + Scenario(work, 0.1));
            sensor.Start();
            e = Check.Throws<OnetipException>(sensor.Start, "start twice");
            Check.That(e != null && e.Kind == ErrorKind.State, "start twice is a State error");
            sensor.Dispose();
            sensor.Dispose();  // twice is harmless
            Check.Throws<ObjectDisposedException>(sensor.Start, "a call after Dispose");
            SensorEvent ignored;
            Check.Throws<ObjectDisposedException>(() => sensor.PollEvent(out ignored), "a poll after Dispose");
            WaitWithoutLimitEndsWhenAnotherThreadDisposes(work);
        }

        // Issue 39: WaitFinished(infinity) on a sensor never started never returned, even once another thread
        // disposed the sensor (the wait held the handle, so its release waited for the wait).
        static void WaitWithoutLimitEndsWhenAnotherThreadDisposes(string work)
        {
            var sensor = new Sensor("sim:" + Scenario(work, 0.1));
            bool finished = true;
            var waiter = new Thread(() => finished = sensor.WaitFinished(double.PositiveInfinity));
            waiter.IsBackground = true;  // a waiter that never returns fails the check, not the process
            waiter.Start();
            Check.That(!waiter.Join(300), "nothing ends a sensor nobody started: the waiter waits");
            sensor.Dispose();
            Check.That(waiter.Join(30000), "the waiter returns once another thread disposes the sensor");
            Check.That(!finished, "and says the sensor did not finish");
        }

        static void CallbacksThatThrow(string work)
        {
            var options = SensorOptions.Default();
            options.Lossless = true;
            using (var sensor = new Sensor("sim:" + Scenario(work, 0.2), null, null, null, options)) {
                int calls = 0;
                ErrorKind disposeInside = ErrorKind.None;
                sensor.OnFrame(f => {
                    ++calls;
                    if (f.Frame == 3) {
                        try {
                            sensor.Dispose();  // not allowed from inside a callback
                        } catch (OnetipException x) {
                            disposeInside = x.Kind;
                        }
                    }
                    throw new InvalidOperationException("boom " + f.Frame);
                });
                sensor.Start();
                Check.That(sensor.WaitFinished(60.0), "a sensor whose callback throws still finishes");
                Check.That(calls == 7 && sensor.CallbackErrorCount == 7, "every frame's callback ran and its exception was caught");
                var last = sensor.LastCallbackException;
                Check.That(last is InvalidOperationException && last.Message == "boom 6", "the last exception is kept");
                Check.That(sensor.GetStats().FramesProcessed == 7, "the sensor went on after the exceptions");
                Check.That(disposeInside == ErrorKind.State, "Dispose from inside a callback is a State error");
            }
        }

        // A short scenario: a finger held off the pad for `seconds` (30 fps).
        static string Scenario(string work, double seconds)
        {
            string path = Path.Combine(work, "hold_" + seconds.ToString(System.Globalization.CultureInfo.InvariantCulture) + "s.yaml");
            File.WriteAllText(path, "%YAML:1.0\n---\nname: hold\nfps: 30\nindenters:\n  - shape: ellipsoid\n" +
                                    "    semi_axes: [7, 9, 6]\n    keyframes:\n      - {t: 0.0, x: 0, y: 0, depth: -0.3}\n" +
                                    "      - {t: " + seconds.ToString(System.Globalization.CultureInfo.InvariantCulture) +
                                    ", depth: -0.3}\n");
            return path;
        }
    }
}
