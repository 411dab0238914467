// UnityAxes against an independent construction: the rotation matrix
// R_S = Rz(yaw) Ry(roll) Rx(pitch) of docs/reference.md, carried into Unity's
// axes by the reflection M that swaps y and z (R_unity = M R_S M), must turn
// vectors exactly as the quaternion UnityAxes.Rotation returns.
using System;

namespace Onetip.Tests
{
    static class UnityAxesTests
    {
        public static void Run()
        {
            var random = new Random(7);
            for (int trial = 0; trial < 50; ++trial) {
                var input = new Input6(0, 0, 0, Angle(random, 15), Angle(random, 40), Angle(random, 40));
                double[,] rs = Multiply(Multiply(Rz(input.Yaw), Ry(input.Roll)), Rx(input.Pitch));
                double[,] m = { { 1, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 } };
                double[,] ru = Multiply(Multiply(m, rs), m);
                double qx, qy, qz, qw;
                UnityAxes.Rotation(input, 1.0, out qx, out qy, out qz, out qw);
                Check.Near(qx * qx + qy * qy + qz * qz + qw * qw, 1.0, 1e-12, "unit quaternion");
                double[] v = { random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5 };
                double[] expected = Apply(ru, v), got = Rotate(qx, qy, qz, qw, v);
                for (int i = 0; i < 3; ++i) Check.Near(got[i], expected[i], 1e-12, "Unity rotation of trial " + trial);
            }
            double x, y, z;
            UnityAxes.Position(new Input6(1, 2, 3, 0, 0, 0), 0.5, out x, out y, out z);
            Check.That(x == 0.5 && y == -1.5 && z == 1.0, "S.x -> x, S.y -> z, press depth -> down");
        }

        static double Angle(Random r, double limit) { return (r.NextDouble() * 2 - 1) * limit; }
        static double Rad(double deg) { return deg * Math.PI / 180; }
        static double[,] Rx(double a) { double c = Math.Cos(Rad(a)), s = Math.Sin(Rad(a)); return new[,] { { 1, 0, 0 }, { 0, c, -s }, { 0, s, c } }; }
        static double[,] Ry(double a) { double c = Math.Cos(Rad(a)), s = Math.Sin(Rad(a)); return new[,] { { c, 0, s }, { 0, 1, 0 }, { -s, 0, c } }; }
        static double[,] Rz(double a) { double c = Math.Cos(Rad(a)), s = Math.Sin(Rad(a)); return new[,] { { c, -s, 0 }, { s, c, 0 }, { 0, 0, 1 } }; }

        static double[,] Multiply(double[,] a, double[,] b)
        {
            var r = new double[3, 3];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    for (int k = 0; k < 3; ++k) r[i, j] += a[i, k] * b[k, j];
            return r;
        }

        static double[] Apply(double[,] a, double[] v)
        {
            var r = new double[3];
            for (int i = 0; i < 3; ++i)
                for (int k = 0; k < 3; ++k) r[i] += a[i, k] * v[k];
            return r;
        }

        // v' = v + 2w (q x v) + 2 q x (q x v): the rotation Unity's Quaternion * Vector3 performs.
        static double[] Rotate(double x, double y, double z, double w, double[] v)
        {
            double[] q = { x, y, z };
            double[] t = Cross(q, v);
            double[] u = Cross(q, t);
            return new[] { v[0] + 2 * w * t[0] + 2 * u[0], v[1] + 2 * w * t[1] + 2 * u[1], v[2] + 2 * w * t[2] + 2 * u[2] };
        }

        static double[] Cross(double[] a, double[] b)
        {
            return new[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
        }
    }
}
