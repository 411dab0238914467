// UnityAxes: the 6-D input in Unity's frame (left-handed, y up), for a pad
// lying face up: S.x -> Unity +x (right), S.y -> Unity +z (forward, along the
// finger), S.z (out of the pad) -> Unity +y (up). This swap of y and z is a
// reflection M, so a rotation by angle a about axis u in S becomes a rotation
// by -a about M u in Unity: R_unity = M R_S M^T.
//
// Position: the finger point's motion T(c0) - c0 = (dx, dy, -dz) in S (dz is
// the press depth into the pad), i.e. (dx, -dz, dy) in Unity, times
// unitsPerMm. Rotation: R_S = Rz(yaw) Ry(roll) Rx(pitch) (docs/reference.md) as
// the quaternion q_S = qz(yaw) qy(roll) qx(pitch) = (w, x, y, z); in Unity
// (x, y, z, w) = (-x, -z, -y, w). Plain doubles, no UnityEngine types, so
// the maths is compiled and tested outside Unity.
using System;

namespace Onetip
{
    public static class UnityAxes
    {
        /// <summary>Translation in Unity units (x, y, z).</summary>
        public static void Position(Input6 v, double unitsPerMm, out double x, out double y, out double z)
        {
            x = v.Dx * unitsPerMm;
            y = -v.Dz * unitsPerMm;
            z = v.Dy * unitsPerMm;
        }

        /// <summary>Rotation as a Unity quaternion (x, y, z, w), angles scaled by rotationGain.</summary>
        public static void Rotation(Input6 v, double rotationGain, out double x, out double y, out double z, out double w)
        {
            double toHalfRad = rotationGain * Math.PI / 360.0;
            double cy = Math.Cos(v.Yaw * toHalfRad), sy = Math.Sin(v.Yaw * toHalfRad);
            double cr = Math.Cos(v.Roll * toHalfRad), sr = Math.Sin(v.Roll * toHalfRad);
            double cp = Math.Cos(v.Pitch * toHalfRad), sp = Math.Sin(v.Pitch * toHalfRad);
            // qz(yaw) * qy(roll) = (cy cr, -sy sr, cy sr, sy cr) as (w, x, y, z); then * qx(pitch)
            double w1 = cy * cr, x1 = -sy * sr, y1 = cy * sr, z1 = sy * cr;
            double qw = w1 * cp - x1 * sp;
            double qx = w1 * sp + x1 * cp;
            double qy = y1 * cp + z1 * sp;
            double qz = z1 * cp - y1 * sp;
            x = -qx;
            y = -qz;
            z = -qy;
            w = qw;
        }
    }
}
