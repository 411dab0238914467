// bindings/c/src/c_options.hpp — onetip_options (onetip_c.h) from and to the
// public SensorOptions: one field map serves both directions (c_options.cpp),
// so the struct carries exactly the table's options with the C++ values.
#pragma once

#include "onetip/sensor_options.hpp"
#include "onetip_c.h"

namespace onetip::c_api {

onetip_options toC(const SensorOptions& o) noexcept;
// Throws Error(input) when lossless is not 0/1 or filter not a onetip_filter_kind
// (values the C++ types cannot hold); validates the rest only when `validate`.
SensorOptions fromC(const onetip_options& c, bool validate = true);

}  // namespace onetip::c_api
