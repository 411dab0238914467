// soak — does the SDK's memory stay flat over 100,000 frames and more?
//
//   soak SCENARIO.yaml FRAMES OUT.csv [field|images|pipeline|all]
//
// Three legs, each FRAMES frames long, on one scenario played round and round
// (it must start and end at rest, as samples/scenarios/demo_touch.yaml does):
//   field   the simulator at field level (a new sim::Simulator every pass, so
//           its construction and teardown are soaked too) into one
//           input::PoseTracker that lives for the whole leg: contact analysis,
//           stick/slip, pose and events on exact marker fields.
//   images  the scenario's frames rendered once (1920x1080 grey), then given
//           again and again to one pipeline::FrameProcessor: corner detection,
//           tracking, triangulation, contact, pose, every frame.
//   pipeline the same rendered frames from an in-memory source through one
//           threaded pipeline::Pipeline (what the public Sensor runs): capture
//           and processing threads, the bounded frame queue (lossless, so every
//           frame is processed), event and frame callbacks, and the poll queues,
//           which nobody polls, so they stay full and drop their oldest entries.
// The process's resident set (VmRSS of /proc/self/status, kB) is sampled
// before the first frame, every 5,000 frames and after the last. Warm-up is the first 10,000
// frames of a leg; "flat" means the samples after it span at most 2 MB
// (2,048 kB). Writes CSV rows `leg,frames,seconds,rss_kb,contact_frames`
// (contact_frames: frames so far in which the estimator reported contact,
// so a leg that silently stopped working shows) and prints per leg the span,
// the drift (last - first sample after warm-up) and the frame rate.
// Exit 0 when every leg ran and stayed flat, 1 otherwise.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "input/pose_tracker.hpp"
#include "pipeline/frame_processor.hpp"
#include "pipeline/pipeline.hpp"
#include "sim/scenario.hpp"
#include "sim/simulator.hpp"

namespace {

using namespace onetip;
using Clock = std::chrono::steady_clock;

constexpr long kSampleEvery = 5000;
constexpr long kWarmUp = 10000;
constexpr long kFlatKb = 2048;

long residentKb() {
  std::ifstream in("/proc/self/status");
  std::string key;
  long kb = -1;
  while (in >> key) {
    if (key == "VmRSS:") {
      in >> kb;
      break;
    }
    in.ignore(1 << 12, '\n');
  }
  return kb;
}

struct Sample {
  long frames;
  double seconds;
  long rss_kb;
  long contact_frames;
};

class Leg {
 public:
  explicit Leg(std::string name) : name_(std::move(name)), start_(Clock::now()) {}
  // Records a sample when `frames` is a multiple of kSampleEvery, or when `last` (the leg's end).
  void at(long frames, long contact_frames, bool last = false) {
    if (frames % kSampleEvery != 0 && !last) return;
    if (!samples_.empty() && samples_.back().frames == frames) return;
    samples_.push_back(
        {frames, std::chrono::duration<double>(Clock::now() - start_).count(), residentKb(), contact_frames});
  }
  // Writes the rows, prints the summary; returns whether the leg stayed flat.
  bool report(std::ofstream& csv) const {
    long lo = -1, hi = -1, first = -1, last = -1;
    for (const Sample& s : samples_) {
      csv << name_ << ',' << s.frames << ',' << s.seconds << ',' << s.rss_kb << ',' << s.contact_frames << '\n';
      if (s.frames < kWarmUp) continue;
      if (first < 0) first = lo = hi = s.rss_kb;
      lo = std::min(lo, s.rss_kb), hi = std::max(hi, s.rss_kb), last = s.rss_kb;
    }
    const Sample& end = samples_.back();
    const bool flat = first >= 0 && hi - lo <= kFlatKb && end.contact_frames > 0;
    std::printf(
        "%s: %ld frames in %.1f s (%.0f frames/s), %ld with contact; RSS %ld kB at start, after warm-up "
        "%ld..%ld kB (span %ld kB, drift %+ld kB): %s\n",
        name_.c_str(), end.frames, end.seconds, static_cast<double>(end.frames) / end.seconds, end.contact_frames,
        samples_.front().rss_kb, lo, hi, hi - lo, last - first,
        flat        ? "flat"
        : first < 0 ? "NOT FLAT (no sample after the warm-up)"
                    : "NOT FLAT");
    std::fflush(stdout);
    return flat;
  }

 private:
  std::string name_;
  Clock::time_point start_;
  std::vector<Sample> samples_;
};

bool soakField(const sim::Scenario& scenario, long frames, std::ofstream& csv) {
  Leg leg("field");
  input::PoseTracker tracker;
  long done = 0, contact = 0;
  double t0 = 0;  // the tracker's clock keeps running across passes
  leg.at(0, 0);
  while (done < frames) {
    sim::Simulator simulator(scenario);
    const double period = 1.0 / scenario.fps;
    while (!simulator.done() && done < frames) {
      const sim::GroundTruthFrame& f = simulator.next();
      contact += tracker.update(f.markers, simulator.restMarkers(), t0 + f.t).contact ? 1 : 0;
      leg.at(++done, contact);
    }
    t0 += simulator.current().t + period;
  }
  leg.at(done, contact, true);
  return leg.report(csv);
}

std::vector<cv::Mat> renderAll(sim::Simulator& simulator) {
  std::vector<cv::Mat> images;
  while (!simulator.done()) {
    simulator.next();
    images.push_back(simulator.render());
  }
  return images;
}

bool soakImages(const sim::Scenario& scenario, long frames, std::ofstream& csv) {
  sim::Simulator simulator(scenario);
  const std::vector<cv::Mat> images = renderAll(simulator);
  const double period = 1.0 / scenario.fps;
  pipeline::FrameProcessor processor(simulator.calibration(), simulator.pattern());
  Leg leg("images");
  long contact = 0;
  leg.at(0, 0);
  for (long k = 0; k < frames; ++k) {
    const auto r =
        processor.process(images[static_cast<std::size_t>(k) % images.size()], static_cast<double>(k) * period);
    contact += r.pose.contact ? 1 : 0;
    leg.at(k + 1, contact);
  }
  leg.at(frames, contact, true);
  return leg.report(csv);
}

// The rendered frames round and round, `frames` of them, timestamped at the scenario's rate.
class LoopSource : public capture::FrameSource {
 public:
  LoopSource(const std::vector<cv::Mat>& images, long frames, double period)
      : images_(images), frames_(frames), period_(period) {}
  capture::Frame next() override {
    capture::Frame f;
    if (index_ >= frames_) return f;  // end
    f.status = capture::FrameStatus::ok;
    f.index = index_;
    f.timestamp_s = static_cast<double>(index_) * period_;
    f.grey = images_[static_cast<std::size_t>(index_++) % images_.size()];  // shared, read only
    return count(std::move(f));
  }
  std::string describe() const override { return "soak loop"; }

 private:
  const std::vector<cv::Mat>& images_;
  long frames_, index_ = 0;
  double period_;
};

bool soakPipeline(const sim::Scenario& scenario, long frames, std::ofstream& csv) {
  sim::Simulator simulator(scenario);
  const std::vector<cv::Mat> images = renderAll(simulator);
  pipeline::PipelineOptions options;
  options.lossless = true;
  pipeline::Pipeline pipe(std::make_unique<LoopSource>(images, frames, 1.0 / scenario.fps), simulator.calibration(),
                          simulator.pattern(), options);
  Leg leg("pipeline");
  long done = 0, contact = 0, events = 0;
  leg.at(0, 0);
  pipe.onEvent([&](const pipeline::PipelineEvent&) { ++events; });
  pipe.onFrame([&](const pipeline::PipelineFrame& f) {  // on the processing thread, one frame at a time
    contact += f.result.pose.contact ? 1 : 0;
    leg.at(++done, contact);
  });
  pipe.start();
  pipe.waitFinished(-1);
  leg.at(done, contact, true);  // the processing thread has ended
  const auto stats = pipe.stats();
  std::printf("pipeline: %lld processed, %lld dropped, %ld events (%lld dropped from the unpolled queue)\n",
              static_cast<long long>(stats.frames_processed), static_cast<long long>(stats.frames_dropped), events,
              static_cast<long long>(stats.events_dropped));
  return leg.report(csv) && stats.frames_processed == frames;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: soak SCENARIO.yaml FRAMES OUT.csv [field|images|pipeline|all]\n");
    return 2;
  }
  try {
    const sim::Scenario scenario = sim::loadScenario(argv[1]);
    const long frames = std::stol(argv[2]);
    const std::string legs = argc > 4 ? argv[4] : "all";
    std::ofstream csv(argv[3]);
    csv << "leg,frames,seconds,rss_kb,contact_frames\n";
    bool ok = true;
    if (legs == "field" || legs == "all") ok = soakField(scenario, frames, csv) && ok;
    if (legs == "images" || legs == "all") ok = soakImages(scenario, frames, csv) && ok;
    if (legs == "pipeline" || legs == "all") ok = soakPipeline(scenario, frames, csv) && ok;
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "soak: %s\n", e.what());
    return 1;
  }
}
