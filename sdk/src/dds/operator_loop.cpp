#include "dds/operator_loop.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "haptics/command_ramp.hpp"
#include "haptics/render_worker.hpp"

namespace onetip::dds {
namespace {

haptics::PeriodicLoopOptions loopOptions(const OperatorLoopOptions& o) {
  o.validate();
  haptics::PeriodicLoopOptions l;
  l.period_ms = 1000.0 / o.rate_hz;
  l.priority = o.priority;
  return l;
}

}  // namespace

void OperatorLoopOptions::validate() const {
  if (neighbors < 1) throw InputError("operator loop neighbors: must be >= 1 (got " + std::to_string(neighbors) + ")");
  if (!(stale_s > 0 && stale_s <= 10)) throw InputError("operator loop stale_s: must be in (0, 10] s");
  if (!(rate_hz >= 1 && rate_hz <= 10000)) throw InputError("operator loop rate_hz: must be 1 .. 10000");
  if (ramp_ticks < 1) throw InputError("operator loop ramp_ticks: must be >= 1");
}

OperatorLoop::OperatorLoop(SensedVectorSubscriber& input, const haptics::KnnRenderer& renderer,
                           devices::CutaneousDevice& device, const OperatorLoopOptions& options)
    : input_(input), renderer_(renderer), device_(device), options_(options), loop_(loopOptions(options)) {
  if (device_.goalSize() != 3)
    throw InputError("operator loop: the device takes " + std::to_string(device_.goalSize()) +
                     " goal values, the renderer gives 3 servo angles");
  if (renderer_.channels() > haptics::RenderWorker::kMaxChannels)
    throw InputError("operator loop: the dataset has " + std::to_string(renderer_.channels()) +
                     " channels, the render worker takes at most " +
                     std::to_string(haptics::RenderWorker::kMaxChannels));
}

OperatorLoopStats OperatorLoop::run(double duration_s) {
  using Clock = std::chrono::steady_clock;
  OperatorLoopStats stats;
  haptics::RenderWorker worker(renderer_, options_.neighbors);
  const auto stale_after = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options_.stale_s));
  std::uint64_t submitted = 0, resume_from = 1;
  Clock::time_point last_arrival{};
  bool stale = true;  // no sample yet
  std::optional<haptics::CommandRamp> ramp;
  SensedSample sample;
  std::array<Clock::time_point, 64> arrived{};  // arrival of submission k at [k % 64]
  pipeline::TimingStats response({"sample_to_command"}, 10000);

  // A refused sample (or a render that found no dataset row) retracts at
  // once, in its own tick: nothing is commanded until a command rendered from
  // a later sample, as after a stall. It does not count as an arrival, so a
  // stream of refused samples also goes stale.
  auto refuse = [&](const std::string& why, std::uint64_t resume) {
    ++stats.refused;
    device_.reportInputError(why);
    stale = true;
    resume_from = resume;
    ramp.reset();
  };

  const long ticks = duration_s > 0 ? std::lround(duration_s * options_.rate_hz) : -1;
  stats.loop = loop_.run(ticks, [&](long) {
    const std::uint64_t before = input_.received();
    const bool taken = input_.takeNewest(sample);
    stats.received += input_.received() - before;
    if (taken) {
      const std::string why =
          sample.undecodable.empty() ? renderer_.bounds().refusal(sample.values) : sample.undecodable;
      if (!why.empty()) {
        refuse(why, submitted + 1);
        return;
      }
      worker.submit(sample.values.data());
      ++submitted;
      last_arrival = sample.received;
      arrived[submitted % arrived.size()] = sample.received;
    }
    const bool timed_out = Clock::now() - last_arrival > stale_after;
    const bool writer_gone = !stale && input_.aliveWriters() == 0;
    if (submitted == 0 || timed_out || writer_gone) {
      if (!stale) {
        device_.reportInputError(timed_out ? "the remote sensed stream is stale (no sample for " +
                                                 std::to_string(options_.stale_s) + " s)"
                                           : std::string("the remote sensed stream's publisher is gone (DDS liveliness lost)"));
        ++stats.stalls;
        if (!timed_out) ++stats.writers_lost;
        stale = true;
        resume_from = submitted + 1;
        ramp.reset();
      }
      return;
    }
    haptics::RenderedCommand c;
    if (worker.latest(c) && c.sequence >= resume_from) {
      if (!c.found) {
        refuse("no dataset row is a finite distance from the sensed vector", c.sequence + 1);
        return;
      }
      if (!ramp) ramp.emplace(c.command, options_.ramp_ticks);
      else ramp->target(c.command);
      stale = false;
      if (submitted - c.sequence < arrived.size())  // its arrival time is still in the ring
        response.add(0, std::chrono::duration<double, std::milli>(Clock::now() - arrived[c.sequence % arrived.size()]).count());
    }
    if (!ramp) return;  // waiting for a command rendered after the stall
    const std::array<double, 3>& m = ramp->step();
    device_.command(m);
    ++stats.commands;
  });
  stats.rendered = worker.rendered();
  stats.ignored = input_.follower().ignored();
  stats.sample_to_command = response.summary().front();
  return stats;
}

}  // namespace onetip::dds
