#include "interrupt.hpp"

namespace onetip::tools {
namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);
extern "C" void onInterrupt(int) { g_interrupted.store(true); }

}  // namespace

InterruptHandlers::InterruptHandlers() {
  g_interrupted.store(false);
  struct sigaction sa {};
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
}

InterruptHandlers::~InterruptHandlers() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
}

bool interruptRequested() noexcept { return g_interrupted.load(); }
const std::atomic<bool>* interruptFlag() noexcept { return &g_interrupted; }

}  // namespace onetip::tools
