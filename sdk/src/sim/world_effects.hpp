// sim/world_effects.hpp — the pad as it is in the world (issue 38): the
// effects a real sensor shows beside its contact mechanics, each a scenario
// section and each off by default (then every output is what it was without
// them, byte for byte):
//   viscoelastic  the gel creeps under a held press and recovers slowly
//                 (sim/viscoelastic_layer.hpp; field and image level)
//   drift         the rest state drifts over minutes (sim/rest_drift.hpp;
//                 field and image level)
//   camera_shift  the camera or a mirror moves against the pad
//                 (sim/camera_shift.hpp; image level only)
//   damage        markers hidden for good by a tear or dirt
//                 (sim/marker_damage.hpp; image: smudged, field: invalid)
//   light         per-frame flicker and exposure steps
//                 (sim/light_flicker.hpp; image level only)
#pragma once

#include "sim/camera_shift.hpp"
#include "sim/light_flicker.hpp"
#include "sim/marker_damage.hpp"
#include "sim/rest_drift.hpp"
#include "sim/viscoelastic_layer.hpp"

namespace onetip::sim {

struct WorldEffects {
  ViscoelasticOptions viscoelastic;
  RestDriftOptions drift;
  CameraShiftOptions camera_shift;
  MarkerDamageOptions damage;
  LightFlickerOptions light;
  bool any() const {
    return viscoelastic.enabled() || drift.enabled() || camera_shift.enabled() || damage.enabled() ||
           light.enabled();
  }
};

}  // namespace onetip::sim
