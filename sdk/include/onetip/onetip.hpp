// onetip/onetip.hpp — the whole public C++ API in one include.
// Frames, units and the 6-D input: types.hpp and events.hpp.
#pragma once

#include "onetip/error.hpp"
#include "onetip/events.hpp"
#include "onetip/joystick_axes.hpp"
#include "onetip/sensor.hpp"
#include "onetip/sensor_options.hpp"
#include "onetip/simulated_sensor.hpp"
#include "onetip/types.hpp"
#include "onetip/version.hpp"
