// haptics/render_worker.hpp — the kNN queries of the haptic loop, off the
// 1 kHz thread (journal paper Sec. 2.3; da Vinci paper Algorithm 1).
//
// The sensor side submit()s each new sensed vector (100 Hz for a BioTac); a
// worker thread, asleep until one arrives, renders it with n neighbours
// (knn_renderer.hpp), looks up the vibration filter of the rendered
// configuration (vibration_table.hpp, optional) and publishes the result in a
// LatestValue slot (latest_value.hpp). The 1 kHz display loop only ever
// fetch()es the newest result: it never waits for a query, however long an
// off-manifold query takes (up to ~1 ms on the 166,375-row set); it holds or
// ramps towards the newest command meanwhile (command_ramp.hpp). Submissions
// that arrive while a query runs replace each other: the worker always renders
// the newest vector, never a backlog.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "haptics/knn_renderer.hpp"
#include "haptics/latest_value.hpp"
#include "haptics/vibration_table.hpp"

namespace onetip::haptics {

struct RenderedCommand {
  std::uint64_t sequence = 0;                 // of the sensed vector it answers (0: none yet)
  bool found = false;                         // a dataset row qualified (knn_renderer.hpp); false: do not command
  std::array<double, 3> command{};            // servo angles, degrees (NaN when !found)
  const TransferFunction* vibration = nullptr;  // table entry of the command (nullptr without a table or found)
  double query_us = 0.0;                      // time the render took
};

class RenderWorker {
 public:
  static constexpr int kMaxChannels = 64;
  struct Sensed {
    std::uint64_t sequence = 0;
    std::array<double, kMaxChannels> values{};
  };

  // renderer and table (optional) must outlive the worker; neighbors >= 1.
  RenderWorker(const KnnRenderer& renderer, int neighbors, const VibrationTable* table = nullptr);
  ~RenderWorker();  // stops and joins the thread
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  // Sensor side (one thread): hands over a sensed vector (channels() values).
  // Never blocks.
  void submit(const double* sensed);
  // Display side (one thread): the newest result; true when new since the last call.
  bool latest(RenderedCommand& out) { return output_.fetch(out); }
  std::uint64_t rendered() const noexcept { return rendered_.load(std::memory_order_relaxed); }

 private:
  void run();

  const KnnRenderer& renderer_;
  int neighbors_;
  const VibrationTable* table_;
  LatestValue<Sensed> input_;
  LatestValue<RenderedCommand> output_;
  std::uint64_t submitted_ = 0;          // sensor side
  std::atomic<std::uint64_t> signal_{0};  // bumped per submission (and on stop); the worker waits on it
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> rendered_{0};
  std::thread thread_;
};

}  // namespace onetip::haptics
