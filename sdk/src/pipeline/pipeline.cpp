#include "pipeline/pipeline.hpp"

#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "core/error.hpp"
#include "core/option_table.hpp"
#include "pipeline/capture_loop.hpp"
#include "pipeline/options_io.hpp"

namespace onetip::pipeline {

// The options' ranges and relations come from the table
// (onetip/sensor_option_table.hpp), the processor's own settings from its modules.
void PipelineOptions::validate() const {
  option_table::validate(toSensorOptions(*this));
  processor.validate();
}

struct Pipeline::Processing {
  Processing(const StereoCalibration& calib, const MarkerPattern& pattern, const PipelineOptions& o)
      : processor(calib, pattern, o.processor),
        events(static_cast<std::size_t>(o.event_queue_capacity)),
        poll_events(o.event_queue_capacity > 0),
        results(static_cast<std::size_t>(o.frame_queue_capacity)),
        poll_frames(o.frame_queue_capacity > 0),
        stop_timeout(std::chrono::milliseconds(o.stop_timeout_ms)) {}

  FrameProcessor processor;
  BoundedQueue<PipelineEvent> events;
  const bool poll_events;  // event_queue_capacity > 0
  BoundedQueue<PipelineFrame> results;
  const bool poll_frames;  // frame_queue_capacity > 0
  const std::chrono::milliseconds stop_timeout;

  std::mutex callback_mutex;  // held while a callback runs
  std::shared_ptr<const EventCallback> event_callback;
  std::shared_ptr<const FrameCallback> frame_callback;
  std::atomic<std::thread::id> thread_id{};

  std::atomic<bool> rezero_requested{false}, rereference_requested{false};
  std::atomic<std::int64_t> processed{0}, skipped{0}, lost{0}, emitted{0}, callback_errors{0};

  std::mutex state_mutex;  // start/stop and the end of the processing thread
  mutable std::mutex end_mutex;
  mutable std::condition_variable end_cv;
  std::atomic<bool> started{false}, stopped{false};
  bool ended = false;  // guarded by end_mutex
  std::atomic<bool> finished{false}, source_abandoned{false};
  std::thread capture_thread, processing_thread;

  bool onProcessingThread() const { return thread_id.load() == std::this_thread::get_id(); }

  void queueEvent(PipelineEvent e) {
    ++emitted;
    if (poll_events) events.push(std::move(e));
  }

  PipelineEvent errorEvent(std::int64_t frame, SteadyClock::time_point arrival, double t, std::string message) {
    PipelineEvent e;
    e.frame = frame;
    e.arrival = arrival;
    e.event.type = input::EventType::error;
    e.event.t = t;
    e.event.message = std::move(message);
    return e;
  }

  template <typename Callback, typename Arg>
  void invoke(const std::shared_ptr<const Callback>& cb, const Arg& arg, std::int64_t frame,
              SteadyClock::time_point arrival, double t) {
    if (!cb || !*cb) return;
    std::string what;
    try {
      (*cb)(arg);
      return;
    } catch (const std::exception& ex) {
      what = ex.what();
    } catch (...) {
      what = "an exception that is not a std::exception";
    }
    ++callback_errors;
    queueEvent(errorEvent(frame, arrival, t, "a callback threw: " + what));
  }

  // Runs the callbacks, then queues the events and the result for polling.
  void deliver(std::vector<PipelineEvent>& out_events, PipelineFrame* frame, Shared& shared) {
    {
      std::lock_guard lock(callback_mutex);
      const auto ecb = event_callback;
      const auto fcb = frame_callback;
      for (const PipelineEvent& e : out_events) invoke(ecb, e, e.frame, e.arrival, e.event.t);
      if (frame) invoke(fcb, *frame, frame->frame, frame->arrival, frame->result.t);
    }
    for (PipelineEvent& e : out_events) queueEvent(std::move(e));
    if (frame) {
      shared.timing.add(kDelivery, msBetween(frame->arrival, SteadyClock::now()));
      if (poll_frames) results.push(std::move(*frame));
    }
  }

  // The processor reports bad frames by status; anything it throws (a bug or
  // an OpenCV failure) becomes a skipped frame here, never the end of the thread.
  FrameResult runProcessor(const Captured& c) {
    try {
      return runProcessorUnguarded(c);
    } catch (const std::exception& e) {
      FrameResult r;
      r.t = c.timestamp_s;
      r.status = FrameStatus::skipped;
      r.message = std::string("processing failed: ") + e.what();
      return r;
    }
  }

  FrameResult runProcessorUnguarded(const Captured& c) {
    if (rezero_requested.exchange(false)) processor.rezero();
    if (rereference_requested.exchange(false)) {
      FrameResult r = processor.setReference(c.grey, c.timestamp_s);
      if (r.status != FrameStatus::reference) rereference_requested = true;  // try the next frame
      return r;
    }
    return processor.process(c.grey, c.timestamp_s);
  }

  void handle(Captured& c, Shared& shared) {
    std::vector<PipelineEvent> out;
    if (c.kind != Captured::Kind::frame) {
      std::string msg = c.kind == Captured::Kind::skipped
                            ? "frame " + std::to_string(c.index) + " skipped by the source: " + c.message
                            : "frame source: " + c.message;
      if (c.kind == Captured::Kind::source_failed) msg += " (giving up after repeated errors)";
      const bool device_level = c.kind != Captured::Kind::skipped;
      out.push_back(errorEvent(device_level ? -1 : c.index, c.arrival, c.timestamp_s, std::move(msg)));
      deliver(out, nullptr, shared);
      return;
    }
    PipelineFrame pf;
    pf.frame = c.index;
    pf.arrival = c.arrival;
    pf.capture_ms = c.capture_ms;
    pf.queue_ms = msBetween(c.arrival, SteadyClock::now());
    const bool had_reference = processor.hasReference();
    pf.result = runProcessor(c);
    ++processed;
    FrameResult& r = pf.result;
    if (r.status == FrameStatus::skipped || r.status == FrameStatus::lost) {
      (r.status == FrameStatus::lost ? lost : skipped) += 1;
      const bool no_rest = !had_reference || (r.status == FrameStatus::skipped && rereference_requested);
      out.push_back(errorEvent(c.index, c.arrival, c.timestamp_s,
                               "frame " + std::to_string(c.index) + (no_rest ? " (rest state): " : ": ") + r.message));
    }
    for (input::InputEvent& e : r.pose.events) out.push_back({std::move(e), c.index, c.arrival});
    r.pose.events.clear();
    const StageTimes& st = r.times;
    for (const auto& [stage, ms] : {std::pair{kQueue, pf.queue_ms},
                                    {kDetect, st.detect},
                                    {kTrack, st.track},
                                    {kTriangulate, st.triangulate},
                                    {kContact, st.contact},
                                    {kPose, st.pose},
                                    {kProcess, st.process}})
      shared.timing.add(stage, ms);
    deliver(out, &pf, shared);
  }

  void loop(Shared& shared) {
    thread_id = std::this_thread::get_id();
    Captured c;
    while (!shared.stop && shared.frames.waitPop(c, std::chrono::milliseconds(-1))) {
      if (shared.stop) break;
      handle(c, shared);
    }
    finished = !shared.stop;
    events.close();
    results.close();
    std::lock_guard lock(end_mutex);
    ended = true;
    end_cv.notify_all();
  }
};

Pipeline::Pipeline(std::unique_ptr<capture::FrameSource> source, const StereoCalibration& calib,
                   const MarkerPattern& pattern, PipelineOptions options) {
  if (!source) throw InputError("pipeline: no frame source");
  options.validate();
  processing_ = std::make_unique<Processing>(calib, pattern, options);
  shared_ = std::make_shared<Shared>(std::move(source), options);
}

Pipeline::~Pipeline() {
  try {
    stop();
  } catch (...) {  // stop() from a callback: nothing sensible is left to do here
  }
}

void Pipeline::setReference(const cv::Mat& grey) {
  std::lock_guard lock(processing_->state_mutex);
  if (processing_->started) throw PipelineStateError("pipeline: setReference() after start()");
  const FrameResult r = processing_->processor.setReference(grey, 0);
  if (r.status != FrameStatus::reference) throw InputError("reference image: " + r.message);
}

void Pipeline::onEvent(EventCallback callback) {
  auto p = std::make_shared<const EventCallback>(std::move(callback));
  if (processing_->onProcessingThread()) {
    processing_->event_callback = std::move(p);  // we hold callback_mutex already
    return;
  }
  std::lock_guard lock(processing_->callback_mutex);
  processing_->event_callback = std::move(p);
}

void Pipeline::onFrame(FrameCallback callback) {
  auto p = std::make_shared<const FrameCallback>(std::move(callback));
  if (processing_->onProcessingThread()) {
    processing_->frame_callback = std::move(p);
    return;
  }
  std::lock_guard lock(processing_->callback_mutex);
  processing_->frame_callback = std::move(p);
}

void Pipeline::start() {
  Processing& p = *processing_;
  if (p.onProcessingThread()) throw PipelineStateError("pipeline: start() from inside a callback");
  std::lock_guard lock(p.state_mutex);
  if (p.started || p.stopped) throw PipelineStateError("pipeline: already started or stopped (a pipeline runs once)");
  p.started = true;
  std::shared_ptr<Shared> shared = shared_;
  p.processing_thread = std::thread([&p, shared] { p.loop(*shared); });
  p.capture_thread = std::thread([shared] { shared->captureLoop(); });
}

void Pipeline::stop() {
  Processing& p = *processing_;
  if (p.onProcessingThread()) throw PipelineStateError("pipeline: stop() from inside a callback");
  std::lock_guard lock(p.state_mutex);
  if (p.stopped) return;
  p.stopped = true;
  if (!p.started) {  // it never ran and now never will: whoever waits for its end is released
    std::lock_guard end_lock(p.end_mutex);
    p.ended = true;
    p.end_cv.notify_all();
    return;
  }
  shared_->requestStop();
  {
    std::unique_lock exit_lock(shared_->mutex);
    const bool exited = shared_->wake.wait_for(exit_lock, p.stop_timeout, [&] { return shared_->capture_exited; });
    exit_lock.unlock();
    if (exited) {
      p.capture_thread.join();
    } else {
      p.source_abandoned = true;  // blocked in source.next(): the thread owns `shared` and ends by itself
      p.capture_thread.detach();
    }
  }
  p.processing_thread.join();
}

bool Pipeline::running() const noexcept {
  std::lock_guard lock(processing_->end_mutex);
  return processing_->started && !processing_->stopped && !processing_->ended;
}

bool Pipeline::finished() const noexcept { return processing_->finished; }

bool Pipeline::waitFinished(double timeout_s) const {
  Processing& p = *processing_;
  std::unique_lock lock(p.end_mutex);
  if (std::isnan(timeout_s)) throw InputError("waitFinished: timeout_s is NaN");
  const auto done = [&] { return p.ended; };
  if (timeout_s < 0 || timeout_s >= kNoTimeLimitS)  // no limit (infinities too: never converted to a clock)
    p.end_cv.wait(lock, done);
  else
    p.end_cv.wait_for(lock, std::chrono::duration<double>(timeout_s), done);
  return p.finished;
}

bool Pipeline::pollEvent(PipelineEvent& out) { return processing_->events.tryPop(out); }

bool Pipeline::waitEvent(PipelineEvent& out, double timeout_s) {
  if (!std::isfinite(timeout_s) || timeout_s < 0) timeout_s = 0;
  // Before start() nothing could arrive; after the end the queue is closed and drains.
  if (!processing_->started) return processing_->events.tryPop(out);
  return processing_->events.waitPop(out, std::chrono::duration<double>(timeout_s));
}

bool Pipeline::pollFrame(PipelineFrame& out) { return processing_->results.tryPop(out); }

void Pipeline::rezero() noexcept { processing_->rezero_requested = true; }
void Pipeline::rereference() noexcept { processing_->rereference_requested = true; }

PipelineStats Pipeline::stats() const {
  const Processing& p = *processing_;
  PipelineStats s;
  s.frames_captured = shared_->captured;
  s.frames_processed = p.processed;
  s.frames_dropped = shared_->frames.dropped();
  s.frames_skipped = shared_->skipped + p.skipped;
  s.frames_unreadable = shared_->skipped;
  s.frames_lost = p.lost;
  s.source_errors = shared_->source_errors;
  s.events_emitted = p.emitted;
  s.events_dropped = p.events.dropped();
  s.frame_results_dropped = p.results.dropped();
  s.callback_errors = p.callback_errors;
  s.source_abandoned = p.source_abandoned;
  s.stages = shared_->timing.summary();
  return s;
}

}  // namespace onetip::pipeline
