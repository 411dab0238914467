/**
 * @file onetip/onetip.hpp
 * @brief The whole public C++ API in one include.
 *
 * Start with onetip::Sensor (sensor.hpp) and the events it reports
 * (events.hpp); frames, units and the 6-D input are described in types.hpp.
 * Link with `onetip::onetip` (CMake `find_package(onetip)`) or `pkg-config onetip`.
 */
#pragma once

#include "onetip/error.hpp"
#include "onetip/events.hpp"
#include "onetip/joystick_axes.hpp"
#include "onetip/sensor.hpp"
#include "onetip/sensor_options.hpp"
#include "onetip/simulated_sensor.hpp"
#include "onetip/types.hpp"
#include "onetip/version.hpp"
