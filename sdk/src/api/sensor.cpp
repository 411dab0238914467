#include "onetip/sensor.hpp"

#include "api/conversions.hpp"
#include "api/public_error.hpp"
#include "pipeline/open_pipeline.hpp"
#include "pipeline/options_io.hpp"

namespace onetip {

struct Sensor::Impl {
  std::string source;
  std::unique_ptr<pipeline::Pipeline> pipeline;
};

Sensor::Sensor(const SensorConfig& config, const SensorOptions& options) : impl_(std::make_unique<Impl>()) {
  api::withPublicErrors([&] {
    impl_->source = config.source;
    impl_->pipeline = pipeline::openPipeline({config.source, config.calibration, config.pattern, config.reference},
                                             pipeline::toPipelineOptions(options));
  });
}

Sensor::~Sensor() = default;  // the Pipeline's destructor stops it

void Sensor::start() {
  api::withPublicErrors([&] { impl_->pipeline->start(); });
}

void Sensor::stop() {
  api::withPublicErrors([&] { impl_->pipeline->stop(); });
}

bool Sensor::running() const noexcept { return impl_->pipeline->running(); }
bool Sensor::finished() const noexcept { return impl_->pipeline->finished(); }

bool Sensor::waitFinished(double timeout_s) const {
  return api::withPublicErrors([&] { return impl_->pipeline->waitFinished(timeout_s); });
}

void Sensor::onEvent(EventCallback callback) {
  api::withPublicErrors([&] {
    if (!callback) return impl_->pipeline->onEvent({});
    impl_->pipeline->onEvent([cb = std::move(callback)](const pipeline::PipelineEvent& e) { cb(api::toEvent(e)); });
  });
}

void Sensor::onFrame(FrameCallback callback) {
  api::withPublicErrors([&] {
    if (!callback) return impl_->pipeline->onFrame({});
    impl_->pipeline->onFrame(
        [cb = std::move(callback)](const pipeline::PipelineFrame& f) { cb(api::toFrameResult(f)); });
  });
}

bool Sensor::pollEvent(Event& event) {
  return api::withPublicErrors([&] {
    pipeline::PipelineEvent e;
    if (!impl_->pipeline->pollEvent(e)) return false;
    event = api::toEvent(e);
    return true;
  });
}

bool Sensor::waitEvent(Event& event, double timeout_s) {
  return api::withPublicErrors([&] {
    pipeline::PipelineEvent e;
    if (!impl_->pipeline->waitEvent(e, timeout_s)) return false;
    event = api::toEvent(e);
    return true;
  });
}

bool Sensor::pollFrame(FrameResult& frame) {
  return api::withPublicErrors([&] {
    pipeline::PipelineFrame f;
    if (!impl_->pipeline->pollFrame(f)) return false;
    frame = api::toFrameResult(f);
    return true;
  });
}

void Sensor::reZero() { impl_->pipeline->rezero(); }
void Sensor::reReference() { impl_->pipeline->rereference(); }

SensorStats Sensor::stats() const {
  return api::withPublicErrors([&] { return api::toSensorStats(impl_->pipeline->stats()); });
}

const std::string& Sensor::source() const noexcept { return impl_->source; }

double clockSeconds() noexcept { return api::toClockSeconds(pipeline::SteadyClock::now()); }

}  // namespace onetip
