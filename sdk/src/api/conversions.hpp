// api/conversions.hpp — between the public value types (onetip/*.hpp) and
// the pipeline's internal ones. Pure copies: units and frames are the same on
// both sides (mm in S, degrees, seconds); times on the steady clock become
// seconds of onetip::clockSeconds().
#pragma once

#include "onetip/events.hpp"
#include "onetip/sensor.hpp"
#include "onetip/sensor_options.hpp"
#include "pipeline/pipeline.hpp"

namespace onetip::api {

double toClockSeconds(pipeline::SteadyClock::time_point t) noexcept;

// The public options over the default processor settings (or `base`'s).
pipeline::PipelineOptions toPipelineOptions(const SensorOptions& o, const pipeline::PipelineOptions& base = {});
SensorOptions toSensorOptions(const pipeline::PipelineOptions& o);

Event toEvent(const pipeline::PipelineEvent& e);
FrameResult toFrameResult(const pipeline::PipelineFrame& f);
SensorStats toSensorStats(const pipeline::PipelineStats& s);

}  // namespace onetip::api
