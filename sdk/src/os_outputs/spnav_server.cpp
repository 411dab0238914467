#include "os_outputs/spnav_server.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>
#include <mutex>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "core/error.hpp"
#include "core/option_checks.hpp"
#include "os_outputs/descriptor_budget.hpp"
#include "os_outputs/output_intent.hpp"
#include "os_outputs/spnav_protocol.hpp"
#include "os_outputs/unix_listener.hpp"

namespace onetip::os_outputs {

namespace {
using Clock = std::chrono::steady_clock;
constexpr size_t kReadChunk = 4096;        // bytes read from one client per wake-up
constexpr size_t kStageMessages = 16;      // queued events moved to the socket per refill
constexpr size_t kMaxStagedBytes = 65536;  // stop reading a client whose replies pile up
constexpr int kBacklog = 16;

}  // namespace

void SpnavServerOptions::validate() const {
  if (socket_path.empty()) throw InputError("spnav options: socket_path: must not be empty");
  range.validate();
  if (!std::isfinite(full_scale) || full_scale <= 0 || full_scale > 1e6) {
    throw InputError("spnav options: full_scale: must be in (0, 1e6]");
  }
  requireInRange("spnav options: max_clients", max_clients, 1, 1024, "clients");
  requireInRange("spnav options: max_queued_events", max_queued_events, 1, 65536, "events");
  requireInRange("spnav options: hello_timeout_ms", hello_timeout_ms, 0, 10000, "ms");
  requireInRange("spnav options: idle_timeout_ms", idle_timeout_ms, 100, 3600000, "ms");
}

struct SpnavServer::State {
  struct Client {
    Client(int socket, spnav::DeviceInfo device, Clock::time_point deadline, Clock::time_point now)
        : fd(socket), session(std::move(device)), hello_deadline(deadline), last_activity(now) {}
    ~Client() { ::close(fd); }
    Client(const Client&) = delete;
    Client& operator=(const Client&) = delete;

    // Touched by the I/O thread only.
    int fd;
    spnav::Session session;
    Clock::time_point hello_deadline;
    Clock::time_point last_activity;  // connected, or last sent us bytes / took bytes we wrote
    bool released = false;  // events may flow (greeted, or hello timed out)
    bool dead = false;
    std::vector<std::byte> staging;
    size_t staged_sent = 0;
    // Guarded by State::mutex.
    std::deque<spnav::Message> queue;
    float sensitivity = 1.0f;
    std::uint32_t event_mask = spnav::kEvMaskMotion | spnav::kEvMaskButton;
    bool last_motion_zero = true;
  };

  explicit State(const SpnavServerOptions& o) : options(o) {}

  const SpnavServerOptions& options;
  UnixListener listener;
  int wake_fd = -1;
  std::thread thread;
  std::atomic<bool> stopping{false};
  mutable std::mutex mutex;
  std::vector<std::unique_ptr<Client>> clients;  // changed by the I/O thread, under mutex
  OutputTracker tracker;                         // under mutex
  SpnavServerStats stats;                        // under mutex
  SpareDescriptor spare;                         // I/O thread: for EMFILE (descriptor_budget.hpp)
  Clock::time_point listener_rests_until{};      // I/O thread: out of descriptors and no spare

  void wake() const noexcept {
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto n = ::write(wake_fd, &one, sizeof(one));
  }
  void enqueue(Client& c, const spnav::Message& m);
  void run();
  void acceptClients();
  void readFrom(Client& c);
  void flush(Client& c);
  bool hasOutput(Client& c);
  int pollTimeoutMs(Clock::time_point now) const;
  bool evictIdlest(Clock::time_point now);
  void evictStalled(Clock::time_point now);
  void removeDead();
};

void SpnavServer::State::enqueue(Client& c, const spnav::Message& m) {
  if (c.queue.size() >= static_cast<size_t>(options.max_queued_events)) {
    c.queue.pop_front();
    ++stats.messages_dropped;
  }
  c.queue.push_back(m);
  ++stats.messages_queued;
}

bool SpnavServer::State::hasOutput(Client& c) {
  if (!c.released) return false;
  if (c.staged_sent < c.staging.size()) return true;
  std::lock_guard lock(mutex);
  return !c.queue.empty();
}

void SpnavServer::State::acceptClients() {
  for (;;) {
    const int fd = ::accept4(listener.fd(), nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0 && (errno == EMFILE || errno == ENFILE)) {  // out of descriptors: shed the client, never spin
      if (spare.shedOne(listener.fd())) {
        std::lock_guard lock(mutex);
        ++stats.shed;
        continue;
      }
      listener_rests_until = Clock::now() + std::chrono::milliseconds(100);
    }
    if (fd < 0) return;  // EAGAIN: none left (other errors: try again on the next wake-up)
    const auto now = Clock::now();
    std::lock_guard lock(mutex);
    const auto live = std::count_if(clients.begin(), clients.end(), [](const auto& c) { return !c->dead; });
    if (live >= options.max_clients && !evictIdlest(now)) {
      ::close(fd);
      ++stats.refused;
      continue;
    }
    spnav::DeviceInfo device{options.device_name, options.device_path, kAxisCount, 1};
    auto c = std::make_unique<Client>(fd, std::move(device), now + std::chrono::milliseconds(options.hello_timeout_ms),
                                      now);
    c->released = options.hello_timeout_ms == 0;
    clients.push_back(std::move(c));
    ++stats.accepted;
  }
}

void SpnavServer::State::readFrom(Client& c) {
  std::byte buffer[kReadChunk];
  const ssize_t n = ::recv(c.fd, buffer, sizeof(buffer), MSG_DONTWAIT);
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return;
  if (n <= 0) {
    c.dead = true;
    std::lock_guard lock(mutex);
    ++stats.hangups;
    return;
  }
  c.last_activity = Clock::now();
  const auto result = c.session.feed(std::span<const std::byte>(buffer, static_cast<size_t>(n)));
  if (result.garbage) {
    c.dead = true;
    std::lock_guard lock(mutex);
    ++stats.garbage_disconnects;
    return;
  }
  c.staging.insert(c.staging.end(), result.reply.begin(), result.reply.end());
  if (c.session.greeted()) c.released = true;
  std::lock_guard lock(mutex);
  c.sensitivity = c.session.sensitivity();
  c.event_mask = c.session.eventMask();
}

void SpnavServer::State::flush(Client& c) {
  while (!c.dead && c.released) {
    if (c.staged_sent == c.staging.size()) {
      c.staging.clear();
      c.staged_sent = 0;
      std::lock_guard lock(mutex);
      for (size_t i = 0; i < kStageMessages && !c.queue.empty(); ++i) {
        const auto* p = reinterpret_cast<const std::byte*>(c.queue.front().data());
        c.staging.insert(c.staging.end(), p, p + spnav::kMessageBytes);
        c.queue.pop_front();
      }
      if (c.staging.empty()) return;
    }
    const ssize_t n = ::send(c.fd, c.staging.data() + c.staged_sent, c.staging.size() - c.staged_sent,
                             MSG_DONTWAIT | MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return;
      c.dead = true;
      std::lock_guard lock(mutex);
      ++stats.hangups;
      return;
    }
    c.staged_sent += static_cast<size_t>(n);
    if (n > 0) c.last_activity = Clock::now();
    std::lock_guard lock(mutex);
    stats.bytes_sent += static_cast<std::uint64_t>(n);
  }
}

int SpnavServer::State::pollTimeoutMs(Clock::time_point now) const {
  int timeout = -1;
  for (const auto& c : clients) {
    if (c->released) continue;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(c->hello_deadline - now).count();
    const int ms = static_cast<int>(std::clamp<long long>(left + 1, 0, 10000));
    timeout = timeout < 0 ? ms : std::min(timeout, ms);
  }
  constexpr int kIdleCheckMs = 250;  // idle clients are looked for at least this often
  if (!clients.empty()) timeout = timeout < 0 ? kIdleCheckMs : std::min(timeout, kIdleCheckMs);
  return timeout;
}

bool SpnavServer::State::evictIdlest(Clock::time_point now) {  // under mutex
  Client* idlest = nullptr;
  for (auto& c : clients)
    if (!c->dead && (!idlest || c->last_activity < idlest->last_activity)) idlest = c.get();
  if (!idlest || now - idlest->last_activity < std::chrono::milliseconds(options.idle_timeout_ms)) return false;
  idlest->dead = true;
  ++stats.idle_evictions;
  return true;
}

void SpnavServer::State::evictStalled(Clock::time_point now) {
  for (auto& c : clients) {
    if (c->dead || now - c->last_activity < std::chrono::milliseconds(options.idle_timeout_ms) || !hasOutput(*c))
      continue;
    c->dead = true;
    std::lock_guard lock(mutex);
    ++stats.idle_evictions;
  }
}

void SpnavServer::State::removeDead() {
  std::lock_guard lock(mutex);
  std::erase_if(clients, [](const std::unique_ptr<Client>& c) { return c->dead; });
  stats.clients = static_cast<int>(clients.size());
}

void SpnavServer::State::run() {
  std::vector<pollfd> fds;
  while (!stopping.load()) {
    fds.clear();
    fds.push_back({wake_fd, POLLIN, 0});
    const auto rest_left = std::chrono::ceil<std::chrono::milliseconds>(listener_rests_until - Clock::now()).count();
    fds.push_back({rest_left > 0 ? -1 : listener.fd(), POLLIN, 0});  // a negative descriptor is not polled
    for (auto& c : clients) {
      short events = c->staging.size() - c->staged_sent < kMaxStagedBytes ? POLLIN : 0;
      if (hasOutput(*c)) events |= POLLOUT;
      fds.push_back({c->fd, events, 0});
    }
    int timeout = pollTimeoutMs(Clock::now());
    if (rest_left > 0) timeout = timeout < 0 ? static_cast<int>(rest_left) : std::min(timeout, static_cast<int>(rest_left));
    if (::poll(fds.data(), fds.size(), timeout) < 0 && errno != EINTR) break;
    if (fds[0].revents & POLLIN) {
      std::uint64_t count = 0;
      [[maybe_unused]] const auto n = ::read(wake_fd, &count, sizeof(count));
    }
    // Clients accepted below are not in `fds`; they are polled from the next round.
    const size_t polled = fds.size() - 2;
    for (size_t i = 0; i < polled; ++i) {
      if (fds[i + 2].revents & (POLLIN | POLLHUP | POLLERR)) readFrom(*clients[i]);
    }
    if (fds[1].revents & POLLIN) acceptClients();
    const auto now = Clock::now();
    for (auto& c : clients) {
      if (!c->released && now >= c->hello_deadline) c->released = true;
      flush(*c);
    }
    evictStalled(Clock::now());
    removeDead();
  }
}

SpnavServer::SpnavServer(SpnavServerOptions options) : options_(std::move(options)) {}

SpnavServer::~SpnavServer() { stop(); }

bool SpnavServer::running() const noexcept { return state_ != nullptr; }

void SpnavServer::start() {
  if (state_) return;
  options_.validate();
  reserveDescriptorsFor(options_.max_clients, "spnav options: max_clients");
  auto state = std::make_unique<State>(options_);
  state->listener = UnixListener::listenAt(options_.socket_path, kBacklog);
  state->wake_fd = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (state->wake_fd < 0) throw InputError("spnav server: eventfd: " + std::string(std::strerror(errno)));
  state->thread = std::thread([s = state.get()] { s->run(); });
  state_ = std::move(state);
}

void SpnavServer::stop() noexcept {
  if (!state_) return;
  state_->stopping.store(true);
  state_->wake();
  if (state_->thread.joinable()) state_->thread.join();
  state_->clients.clear();
  state_->listener.close();
  ::close(state_->wake_fd);
  state_.reset();
}

void SpnavServer::publish(const input::InputEvent& event) {
  if (!state_) return;
  State& s = *state_;
  bool queued = false;
  {
    std::lock_guard lock(s.mutex);
    ++s.stats.events_published;
    const auto intents = s.tracker.onEvent(event);
    for (auto& c : s.clients) {
      for (const OutputIntent& intent : intents) {
        if (intent.kind == OutputIntent::Kind::button) {
          if (!(c->event_mask & spnav::kEvMaskButton)) continue;
          s.enqueue(*c, spnav::buttonMessage(intent.press, 0));
          queued = true;
          continue;
        }
        if (!(c->event_mask & spnav::kEvMaskMotion)) continue;
        const auto axes = spnavAxes(intent.value, options_.range, options_.full_scale * c->sensitivity);
        const bool zero = std::all_of(axes.begin(), axes.end(), [](std::int32_t v) { return v == 0; });
        if (zero && !intent.rest && c->last_motion_zero) continue;
        c->last_motion_zero = zero;
        s.enqueue(*c, spnav::motionMessage(axes, intent.period_ms));
        queued = true;
      }
    }
  }
  if (queued) s.wake();
}

SpnavServerStats SpnavServer::stats() const {
  if (!state_) return {};
  std::lock_guard lock(state_->mutex);
  return state_->stats;
}

}  // namespace onetip::os_outputs
