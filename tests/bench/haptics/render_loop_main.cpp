// haptic_render_loop: a simulated 1 kHz haptic display loop on one core.
// Each 1 ms tick: take the newest sensed vector (the BioTac-like sensor in the
// six remote interactions, 100 Hz, so a new vector every 10th tick), render it
// with n = 8 neighbours on the 166,375-row 3-deg dataset when it is new,
// select the vibration filter of the rendered configuration (the simulated
// plant's transfer function, standing in for the identified table), and
// filter the 2.2 or 2.3 AC samples (2200 Hz) that arrived in this tick. A
// deadline is missed when a tick's work ends after the next tick starts.
// usage: haptic_render_loop [seconds=60] [out.csv]
//   out.csv rows `what,value`: ticks, missed, missed_percent, work_p50_us,
//   work_p99_us, work_max_us.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/csv_table.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/remote_interactions.hpp"
#include "haptics/vibration_channel.hpp"
#include "haptics/vibration_plant.hpp"

using namespace onetip;
using namespace onetip::haptics;

namespace {
double nowUs() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) * 1e-3;
}
}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::stod(argv[1]) : 60.0;
  const PlatformKinematics device;
  const TactileDataset dataset = simulateDataset(device, BiotacLikeSensor(), 3.0);
  const KnnRenderer renderer(dataset);
  BiotacLikeOptions o;
  o.noise_counts = 2.0;
  const BiotacLikeSensor sensor(o);
  std::vector<std::vector<double>> sensed;
  for (RemoteInteraction i : kRemoteInteractions)
    for (const ContactPlane& p : remoteInteraction(i)) sensed.push_back(sensor.sense(p));

  VibrationChannel vibration(vibrationPlant(device.forward({30, 30, 30})));
  const long ticks = std::lround(seconds * 1000.0);
  std::vector<double> work_us;
  work_us.reserve(static_cast<size_t>(ticks));
  long missed = 0;
  double ac_phase = 0.0, ac_clock = 0.0, sink = 0.0;
  timespec next{};
  clock_gettime(CLOCK_MONOTONIC, &next);
  for (long tick = 0; tick < ticks; ++tick) {
    next.tv_nsec += 1000000;
    if (next.tv_nsec >= 1000000000) {
      next.tv_nsec -= 1000000000;
      ++next.tv_sec;
    }
    const double start = nowUs();
    if (tick % 10 == 0) {
      const auto& s = sensed[static_cast<size_t>(tick / 10) % sensed.size()];
      const RenderResult r = renderer.render(s.data(), 8);
      vibration.select(vibrationPlant(device.forward(r.command)));
      sink += r.command[0];
    }
    for (ac_clock += kVibrationRateHz / 1000.0; ac_clock >= 1.0; ac_clock -= 1.0) {
      ac_phase += 2.0 * M_PI * 180.0 / kVibrationRateHz;
      sink += vibration.process(std::sin(ac_phase));
    }
    const double end = nowUs();
    work_us.push_back(end - start);
    const double deadline = static_cast<double>(next.tv_sec) * 1e6 + static_cast<double>(next.tv_nsec) * 1e-3;
    if (end > deadline) ++missed;
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr);
  }
  std::sort(work_us.begin(), work_us.end());
  const double pct = 100.0 * static_cast<double>(missed) / static_cast<double>(ticks);
  std::printf("ticks %ld missed %ld (%.3f%%) work p50 %.1f us p99 %.1f us max %.1f us (checksum %g)\n", ticks, missed,
              pct, work_us[work_us.size() / 2], work_us[work_us.size() * 99 / 100], work_us.back(), sink);
  if (argc > 2) {
    CsvWriter out(argv[2], {"what", "value"});
    out.row({"ticks", std::to_string(ticks)});
    out.row({"missed", std::to_string(missed)});
    out.row({"missed_percent", formatNumber(pct, 4)});
    out.row({"work_p50_us", formatNumber(work_us[work_us.size() / 2], 2)});
    out.row({"work_p99_us", formatNumber(work_us[work_us.size() * 99 / 100], 2)});
    out.row({"work_max_us", formatNumber(work_us.back(), 2)});
    out.commit();
  }
  return 0;
}
