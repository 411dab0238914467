// haptics/remote_interactions.hpp — the six remote interactions of the
// journal paper (Fig. 4): a flat plate moved by hand against a stationary
// fingertip sensor, here as plate trajectories in the device frame D.
//
// The fingertip is the sensor's FingertipShape (tactile_sensor_model.hpp;
// by default the BioTac-like ellipsoid, centre C = (0, 0, 7), semi-axes
// A = (7, 11, 7) mm; onetip's dome is a sphere). A plate with unit normal n
// (into the finger) first touches it at support distance h(n) = |A o n|
// (component-wise product) from C; pressing it `depth` mm further puts its
// face through c = C - n (h(n) - depth). Normals by interaction:
//   back  (proximal side):  n = (0,  sin b, cos b)   tip:   n = (0, -sin b, cos b)
//   left:                   n = (sin b, 0, cos b)    right: n = (-sin b, 0, cos b)
// X-flat-X (one repetition of `repetition_s` s, phase u in [0, 1], cosine
// blends): u < 0.15 the plate approaches at b = side_tilt_deg from depth
// -0.5 mm (clear) to press_mm; it then rolls to b = 0 (the pulp) by u = 0.5
// and back to the side by u = 0.85, then leaves. flat: b = 0, depth -0.5 ->
// 1.3 press_mm -> -0.5. complex: one repetition of each of the other five in
// turn. Each interaction is repeated `repetitions` times; samples at rate_hz.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "haptics/platform_kinematics.hpp"
#include "haptics/tactile_sensor_model.hpp"

namespace onetip::haptics {

enum class RemoteInteraction { back_flat_back, tip_flat_tip, left_flat_left, right_flat_right, flat, complex };

constexpr std::array<RemoteInteraction, 6> kRemoteInteractions = {
    RemoteInteraction::back_flat_back, RemoteInteraction::tip_flat_tip, RemoteInteraction::left_flat_left,
    RemoteInteraction::right_flat_right, RemoteInteraction::flat, RemoteInteraction::complex};

// "back-flat-back", "tip-flat-tip", "left-flat-left", "right-flat-right", "flat", "complex"
std::string_view toString(RemoteInteraction interaction);

struct InteractionOptions {
  double rate_hz = 100.0;        // the BioTac's 100 Hz
  int repetitions = 3;
  double repetition_s = 4.0;
  double press_mm = 1.5;
  double side_tilt_deg = 30.0;
  void validate() const;         // throws InputError naming the bad field
};

std::vector<ContactPlane> remoteInteraction(RemoteInteraction interaction, const InteractionOptions& options = {},
                                            const FingertipShape& shape = {});

}  // namespace onetip::haptics
