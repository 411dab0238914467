// os_outputs/spnav_server.hpp — a spacenavd-compatible server: 3-D programs
// that use libspnav (Blender, FreeCAD, ...) read the fingertip as a 3-D mouse
// by connecting to `socket_path` (SPNAV_SOCKET=PATH for libspnav clients).
//
// Wire protocol: spnav_protocol.hpp (v0 events, the v1 handshake and the v1
// requests). What is sent (output_intent.hpp):
//   - a motion event for every `input` event while the finger is deflected,
//     the six values scaled by spnavAxes(value, range, full_scale * s)
//     (axis_scaling.hpp: x=dx, y=dy, z=dz, rx=pitch, ry=roll, rz=yaw; ±4 mm,
//     3 mm, ±40/±40/±15 deg -> ±350 by default), s being the client's own
//     sensitivity (1 unless the client sets it); motions that scale to all
//     zero are sent once, not repeated;
//   - an explicit all-zero motion at contact end (always);
//   - button 0 press / release for the press button.
// Period: ms since the previous motion (event timestamps).
//
// Robustness: all sockets are non-blocking and one I/O thread serves them
// with poll(). publish() only formats the events into each client's bounded
// queue (max_queued_events; when full the OLDEST queued event is dropped and
// counted, so the latest state and the final zero get through) and wakes the
// I/O thread: it never waits for a client. A client that never reads only
// loses its own events; one that sends garbage (see spnav_protocol.hpp) is
// disconnected. A client is idle while it neither sends anything nor takes
// any byte the server writes (its socket buffer full); one idle for
// idle_timeout_ms with events waiting for it is disconnected (a stalled
// reader). When all max_clients slots are taken, a new connection evicts the
// client idle the longest if it has been idle for idle_timeout_ms, so idle
// clients never lock out a new one; otherwise the new connection is closed at
// once (every slot is held by an active client). Events are
// held for a new client until it sends its first word (the libspnav
// handshake) or hello_timeout_ms passes, so the handshake reply is never
// preceded by an event.
//
// Thread-safety: publish() and stats() may be called from any thread, also
// concurrently with each other; start() and stop() from one controlling
// thread, and stop() only once the producers have stopped publishing (stop
// the pipeline first). publish() before start() or after stop() does nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "input/input_event.hpp"
#include "os_outputs/axis_scaling.hpp"

namespace onetip::os_outputs {

struct SpnavServerOptions {
  std::string socket_path;        // required; created 0600 (unix_listener.hpp)
  WorkingRange range;             // the 6-D values that map to ±full_scale
  double full_scale = 350;        // spnav units at the end of the range, (0, 1e6]
  int max_clients = 16;           // 1..1024, and within the open-file limit (descriptor_budget.hpp)
  int max_queued_events = 256;    // per client, 1..65536
  int hello_timeout_ms = 500;     // 0..10000
  int idle_timeout_ms = 10000;    // 100..3600000: idle clients are evicted after this
  std::string device_name = "onetip tactile fingertip";  // v1 DEV_NAME reply
  std::string device_path;        // v1 DEV_PATH reply, e.g. the input source
  void validate() const;          // InputError naming the bad field
};

struct SpnavServerStats {
  int clients = 0;                      // connected now
  std::uint64_t accepted = 0;           // connections accepted in total
  std::uint64_t refused = 0;            // closed at once: over max_clients, none idle
  std::uint64_t shed = 0;               // closed at once: the process was out of open files (EMFILE)
  std::uint64_t idle_evictions = 0;     // disconnected after idle_timeout_ms (stalled, or for a new client)
  std::uint64_t garbage_disconnects = 0;
  std::uint64_t hangups = 0;            // clients that closed or failed
  std::uint64_t events_published = 0;   // publish() calls
  std::uint64_t messages_queued = 0;    // 32-byte events queued to clients
  std::uint64_t bytes_sent = 0;         // written to client sockets (events and replies)
  std::uint64_t messages_dropped = 0;   // dropped from full client queues
};

class SpnavServer {
 public:
  explicit SpnavServer(SpnavServerOptions options);
  ~SpnavServer();  // stop()
  SpnavServer(const SpnavServer&) = delete;
  SpnavServer& operator=(const SpnavServer&) = delete;

  // Validates the options, listens at socket_path and starts the I/O thread.
  // InputError naming the field or the path when it cannot.
  void start();
  // Disconnects every client, removes the socket, joins the thread. Idempotent.
  void stop() noexcept;
  bool running() const noexcept;

  // Formats the event for every connected client; never blocks on a client.
  void publish(const input::InputEvent& event);
  SpnavServerStats stats() const;
  const SpnavServerOptions& options() const noexcept { return options_; }

 private:
  struct State;
  SpnavServerOptions options_;
  std::unique_ptr<State> state_;
};

}  // namespace onetip::os_outputs
