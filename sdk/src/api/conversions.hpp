// api/conversions.hpp — between the public value types (onetip/*.hpp) and
// the pipeline's internal ones (the options: pipeline/options_io.hpp). Pure
// copies: units and frames are the same on both sides (mm in S, degrees,
// seconds); times on the steady clock become seconds of onetip::clockSeconds().
#pragma once

#include "onetip/events.hpp"
#include "onetip/sensor.hpp"
#include "pipeline/pipeline.hpp"

namespace onetip::api {

double toClockSeconds(pipeline::SteadyClock::time_point t) noexcept;

Event toEvent(const pipeline::PipelineEvent& e);
FrameResult toFrameResult(const pipeline::PipelineFrame& f);
SensorStats toSensorStats(const pipeline::PipelineStats& s);

}  // namespace onetip::api
