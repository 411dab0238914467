#include "haptics/render_worker.hpp"

#include <chrono>

#include "core/error.hpp"

namespace onetip::haptics {

RenderWorker::RenderWorker(const KnnRenderer& renderer, int neighbors, const VibrationTable* table)
    : renderer_(renderer), neighbors_(neighbors), table_(table) {
  if (neighbors < 1) throw InputError("RenderWorker: neighbors must be at least 1");
  if (renderer.channels() > kMaxChannels)
    throw InputError("RenderWorker: at most " + std::to_string(kMaxChannels) + " sensed channels");
  thread_ = std::thread([this] { run(); });
}

RenderWorker::~RenderWorker() {
  stop_.store(true);
  signal_.fetch_add(1);
  signal_.notify_one();
  thread_.join();
}

void RenderWorker::submit(const double* sensed) {
  Sensed s;
  s.sequence = ++submitted_;
  std::copy_n(sensed, renderer_.channels(), s.values.begin());
  input_.publish(s);
  signal_.fetch_add(1, std::memory_order_release);
  signal_.notify_one();
}

void RenderWorker::run() {
  std::uint64_t seen = 0;
  Sensed s;
  while (true) {
    signal_.wait(seen, std::memory_order_acquire);
    seen = signal_.load(std::memory_order_acquire);
    if (stop_.load()) return;
    if (!input_.fetch(s)) continue;
    const auto t0 = std::chrono::steady_clock::now();
    const RenderResult r = renderer_.render(s.values.data(), neighbors_);
    RenderedCommand out;
    out.sequence = s.sequence;
    out.found = r.found();
    out.command = r.command;
    out.vibration = table_ && out.found ? &table_->lookup(r.command) : nullptr;
    out.query_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    output_.publish(out);
    rendered_.fetch_add(1, std::memory_order_relaxed);
  }
}

}  // namespace onetip::haptics
