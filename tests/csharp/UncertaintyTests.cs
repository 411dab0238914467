// The uncertainty through the C# wrapper (C ABI minor version 2): SensorEvent.Sd,
// FrameResult.Sd and Marker.StickProbability of the simulated press equal
// pose.csv's sd columns from `onetip process` (the C++ pipeline), events carry
// the sd of their frame, Marker has the layout of onetip_marker_sd; and, with
// the estimator's uncertainty, frames in contact have a positive sd on every
// axis and sticking markers (InContact).
using System;
using System.Collections.Generic;
using System.Linq;
using System.Runtime.InteropServices;

namespace Onetip.Tests
{
    static class UncertaintyTests
    {
        const double Tolerance = 2e-6;  // pose.csv carries 6 decimals

        internal static void AgainstTheReference(CliReference reference, List<SensorEvent> polled,
                                                 List<SensorEvent> fromCallback, List<FrameResult> frames)
        {
            Check.That(Marshal.SizeOf(typeof(Marker)) == 72, "Marker is laid out as onetip_marker_sd (72 bytes)");
            var sdOf = new Dictionary<long, Input6>();
            foreach (var f in frames) {
                sdOf[f.Frame] = f.Sd;
                var sd = f.Sd.ToArray();
                for (int i = 0; i < 6; ++i) {
                    Check.Near(sd[i], reference.Sd[f.Frame][i], Tolerance, "sd of frame " + f.Frame + " [" + i + "]");
                    if (!f.Contact) Check.That(sd[i] == 0, "sd is 0 out of contact: frame " + f.Frame);
                }
                foreach (var m in f.Markers) {
                    Check.That(m.StickProbability >= 0 && m.StickProbability <= 1,
                               "stick probability in [0, 1]: frame " + f.Frame + " marker " + m.Id);
                    if (!f.Contact) Check.That(m.StickProbability == 0, "0 out of contact: frame " + f.Frame);
                }
            }
            var inputs = polled.Where(e => e.Type == EventType.Input).ToList();
            foreach (var e in inputs)
                Check.That(sdOf.ContainsKey(e.Frame) && e.Sd.ToArray().SequenceEqual(sdOf[e.Frame].ToArray()),
                           "the input event of frame " + e.Frame + " carries its frame's sd");
            Check.That(fromCallback.Count == polled.Count &&
                           fromCallback.Zip(polled, (a, b) => a.Sd.ToArray().SequenceEqual(b.Sd.ToArray())).All(x => x),
                       "callback and poll queue give the same sd");
            Console.WriteLine("uncertainty: sd of {0} frames equal to pose.csv's, {1} input events carry their frame's",
                              frames.Count, inputs.Count);
        }

        // Needs the estimator's uncertainty (pose/pose_uncertainty): until then every sd is 0.
        internal static void InContact(string scenario)
        {
            var options = SensorOptions.Default();
            options.Lossless = true;
            options.FrameQueueCapacity = 1000;
            var frames = new List<FrameResult>();
            using (var sensor = new Sensor("sim:" + scenario, null, null, null, options)) {
                sensor.Start();
                Check.That(sensor.WaitFinished(120.0), "the simulated sensor finishes");
                FrameResult frame;
                while (sensor.PollFrame(out frame)) frames.Add(frame);
            }
            // After the onset: there the input is zero by definition and its sd 0.
            var contact = frames.Where((f, i) => f.Contact && i > 0 && frames[i - 1].Contact).ToList();
            Check.That(contact.Count > 20, "the press is in contact for more than 20 frames");
            foreach (var f in contact) {
                Check.That(f.Sd.ToArray().All(v => v > 0), "frame " + f.Frame + ": a positive sd on every axis " + f.Sd);
                Check.That(f.Markers.Any(m => m.StickProbability > 0), "frame " + f.Frame + ": some marker sticks");
            }
        }
    }
}
