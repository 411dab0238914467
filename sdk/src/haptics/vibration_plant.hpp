// haptics/vibration_plant.hpp — the simulated ground truth of the vibration
// channel: vibrotactile motor on the platform -> fingertip -> the sensor's AC
// pressure channel, sampled at 2200 Hz, for one platform configuration.
//
// Three second-order sections in series, each mapped to z by the bilinear
// transform pre-warped at its own frequency, so the plant is exactly a
// 6-pole/6-zero H(z):
//   AC coupling:  high-pass,  f = 8 Hz, Q = 0.707
//   contact:      resonance   s^2 + (w/Qz) s + w^2 over s^2 + (w/Qp) s + w^2
//                 (a peak of Qp/Qz, here 4x = +12 dB) at f_r
//   sensor:       low-pass,   f = 900 Hz, Q = 0.6
// times a gain g. The contact resonance stiffens with the platform's press and
// tilt (platform_kinematics.hpp: z_mm, roll, pitch):
//   press = clamp(z_mm, 0, 3) mm,  tilt = hypot(roll, pitch) deg
//   f_r   = 140 Hz + 60 Hz/mm * press + 2 Hz/deg * tilt
//   Qp    = 3 + 1.5 * press,  Qz = Qp / 4,  g = 0.5 + 0.5 * press / 3
// A stand-in for the Forcereactor motor + BioTac of the paper, not a fit.
#pragma once

#include "haptics/platform_kinematics.hpp"
#include "haptics/transfer_function.hpp"

namespace onetip::haptics {

TransferFunction vibrationPlant(const PlatformPose& pose);

}  // namespace onetip::haptics
