// Latency of the threaded pipeline as a C ABI user sees it: for every event,
// the time from its frame's arrival (handed over by the source) to the event
// callback (onetip_clock_seconds() - event.arrival_s), beside the processing
// time alone (the frame's times_ms[ONETIP_STAGE_PROCESS]) and the whole
// delivery. The simulated sensor plays a scenario paced at its own frame
// rate (playback_rate 1, like a live 30 fps camera: the render of the next
// frame does not count), latest-frame-wins as for a camera.
// Writes CSV rows `scenario,metric,count,median_ms,p99_ms,max_ms`.
// Usage: bench_pipeline_latency SCENARIO.yaml [OUT.csv]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "onetip_c.h"

namespace {

struct Samples {
  std::mutex mutex;
  std::vector<double> event_latency_ms, process_ms, queue_ms;
};

void onEvent(const onetip_event* e, void* user) {
  const double now = onetip_clock_seconds();
  auto* s = static_cast<Samples*>(user);
  std::lock_guard lock(s->mutex);
  s->event_latency_ms.push_back((now - e->arrival_s) * 1000);
}

void onFrame(const onetip_frame* f, const onetip_marker*, int32_t, void* user) {
  auto* s = static_cast<Samples*>(user);
  std::lock_guard lock(s->mutex);
  if (f->status == ONETIP_FRAME_OK) {
    s->process_ms.push_back(f->times_ms[ONETIP_STAGE_PROCESS]);
    s->queue_ms.push_back(f->times_ms[ONETIP_STAGE_QUEUE]);
  }
}

// Nearest-rank percentile, as the SDK's own statistics.
double percentile(std::vector<double> v, double p) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const auto rank = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))));
  return v[std::min(rank, v.size()) - 1];
}

bool check(int32_t rc, const onetip_error& err) {
  if (rc != ONETIP_OK) std::fprintf(stderr, "bench_pipeline_latency: %s\n", err.message);
  return rc == ONETIP_OK;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_pipeline_latency SCENARIO.yaml [OUT.csv]\n");
    return 2;
  }
  onetip_error err;
  onetip_options options;
  if (!check(onetip_options_default(ONETIP_C_ABI_VERSION, &options, &err), err)) return 1;
  options.playback_rate = 1;
  onetip_sensor* sensor = nullptr;
  const std::string source = std::string("sim:") + argv[1];
  if (!check(onetip_sensor_create(ONETIP_C_ABI_VERSION, source.c_str(), nullptr, nullptr, nullptr, &options, &sensor,
                                  &err),
             err))
    return 1;
  Samples samples;
  int32_t finished = 0;
  onetip_stats stats{};
  const bool ok = check(onetip_sensor_set_event_callback(sensor, onEvent, &samples, &err), err) &&
                  check(onetip_sensor_set_frame_callback(sensor, onFrame, &samples, &err), err) &&
                  check(onetip_sensor_start(sensor, &err), err) &&
                  check(onetip_sensor_wait_finished(sensor, 600, &finished, &err), err) &&
                  check(onetip_sensor_get_stats(sensor, &stats, &err), err);
  onetip_sensor_destroy(sensor, nullptr);
  if (!ok || !finished) return 1;

  std::FILE* out = argc > 2 ? std::fopen(argv[2], "w") : nullptr;
  if (out) std::fprintf(out, "scenario,metric,count,median_ms,p99_ms,max_ms\n");
  const auto row = [&](const char* metric, const std::vector<double>& v) {
    const double mx = v.empty() ? NAN : *std::max_element(v.begin(), v.end());
    std::printf("%-32s n %5zu  median %7.3f ms  p99 %7.3f ms  max %7.3f ms\n", metric, v.size(), percentile(v, 0.5),
                percentile(v, 0.99), mx);
    if (out)
      std::fprintf(out, "%s,%s,%zu,%.4f,%.4f,%.4f\n", argv[1], metric, v.size(), percentile(v, 0.5),
                   percentile(v, 0.99), mx);
  };
  row("arrival_to_c_callback", samples.event_latency_ms);
  row("processing_alone", samples.process_ms);
  row("queue_wait", samples.queue_ms);
  std::printf("frames: %lld captured, %lld processed, %lld dropped\n", static_cast<long long>(stats.frames_captured),
              static_cast<long long>(stats.frames_processed), static_cast<long long>(stats.frames_dropped));
  if (out) std::fclose(out);
  return 0;
}
