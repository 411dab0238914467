// CliReference: the C++ pipeline's answer for a scenario, read from the
// pose.csv (frame,contact,state,dx,dy,dz,yaw,pitch,roll,sd_dx,...,sd_roll) and
// markers.csv (frame,id,x,y,z) that `onetip process` wrote (docs/reference.md).
using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace Onetip.Tests
{
    sealed class CliReference
    {
        public readonly SortedDictionary<long, double[]> Pose = new SortedDictionary<long, double[]>();  // dx..roll
        public readonly Dictionary<long, double[]> Sd = new Dictionary<long, double[]>();  // sd_dx..sd_roll
        public readonly HashSet<long> Contact = new HashSet<long>();
        public readonly Dictionary<long, List<double[]>> Markers = new Dictionary<long, List<double[]>>();  // id,x,y,z

        public CliReference(string posePath, string markersPath)
        {
            foreach (var f in Rows(posePath, "frame,contact,state,dx,dy,dz,yaw,pitch,roll," +
                                             "sd_dx,sd_dy,sd_dz,sd_yaw,sd_pitch,sd_roll")) {
                long frame = long.Parse(f[0], CultureInfo.InvariantCulture);
                Pose[frame] = f.Skip(3).Take(6).Select(Number).ToArray();
                Sd[frame] = f.Skip(9).Take(6).Select(Number).ToArray();
                if (f[1] == "1") Contact.Add(frame);
            }
            foreach (var f in Rows(markersPath, "frame,id,x,y,z")) {
                long frame = long.Parse(f[0], CultureInfo.InvariantCulture);
                List<double[]> list;
                if (!Markers.TryGetValue(frame, out list)) Markers[frame] = list = new List<double[]>();
                list.Add(f.Skip(1).Select(Number).ToArray());
            }
        }

        public long[] ContactFrames() { return Contact.OrderBy(f => f).ToArray(); }

        static double Number(string s) { return double.Parse(s, CultureInfo.InvariantCulture); }

        static IEnumerable<string[]> Rows(string path, string header)
        {
            var lines = File.ReadAllLines(path);
            if (lines.Length == 0 || lines[0].Trim() != header)
                throw new InvalidDataException(path + ": expected the header " + header);
            return lines.Skip(1).Where(l => l.Length > 0).Select(l => l.Split(','));
        }
    }
}
