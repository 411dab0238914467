// `onetip spnav`: the pipeline feeding a spacenavd-compatible server
// (os_outputs/spnav_server.hpp, docs/os_outputs.md) until SIGINT/SIGTERM or
// the end of the source. 3-D programs using libspnav reach it with
// SPNAV_SOCKET=PATH.
#include <chrono>
#include <cmath>
#include <thread>

#include "command.hpp"
#include "core/error.hpp"
#include "os_outputs/spnav_server.hpp"
#include "pipeline_command.hpp"

namespace onetip::tools {
namespace {

int runSpnav(const Args& args) {
  auto pipeline = openPipelineFromArgs(args);
  os_outputs::SpnavServerOptions o;
  o.socket_path = args.get("socket");
  o.device_path = args.get("input");
  o.full_scale = args.getDouble("full-scale", o.full_scale);
  o.max_clients = args.getInt("max-clients", o.max_clients);
  const double idle_s = args.getDouble("idle-timeout", o.idle_timeout_ms / 1000.0);
  if (!(idle_s >= 0.1 && idle_s <= 3600)) throw InputError("option '--idle-timeout': must be in [0.1, 3600] s");
  o.idle_timeout_ms = static_cast<int>(std::lround(idle_s * 1000));
  const double wait_s = args.getDouble("wait-client", 0);
  if (!(wait_s >= 0 && wait_s <= 86400)) throw InputError("option '--wait-client': must be in [0, 86400] s");
  os_outputs::SpnavServer server(o);
  server.start();
  pipeline->onEvent([&server](const pipeline::PipelineEvent& e) { server.publish(e.event); });
  const int code = runPipelineUntilInterrupted(*pipeline, [&] {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
    while (wait_s > 0 && server.stats().clients == 0 && !interruptRequested()) {
      if (std::chrono::steady_clock::now() > deadline) return true;  // go on without a client
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return !interruptRequested();
  });
  pipeline->stop();  // producers first (docs/os_outputs.md), then the server
  // Let clients read what was queued last (the final zero) before the sockets close.
  for (int i = 0; i < 50 && server.stats().clients > 0 && !interruptRequested(); ++i) {
    const auto s = server.stats();
    if (s.bytes_sent >= s.messages_queued * 32) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  server.stop();
  return code;
}

std::vector<OptionSpec> spnavOptions() {
  std::vector<OptionSpec> o = pipelineInputOptions();
  o.push_back({"socket", "AF_UNIX socket path to serve (created 0600; clients: SPNAV_SOCKET=PATH)", false, true});
  o.push_back({"full-scale", "spnav units at the end of the working range (default 350)", false, false});
  o.push_back({"wait-client", "wait up to this many seconds, [0, 86400], for a first client before starting (default 0)",
               false, false});
  o.push_back({"max-clients", "client slots, 1..1024 (default 16); a full server evicts the longest-idle client for a "
                              "new one once it has been idle for --idle-timeout",
               false, false});
  o.push_back({"idle-timeout", "seconds, [0.1, 3600] (default 10): a client that neither sends nor reads for this long "
                               "is evicted when events wait for it or a new client needs its slot",
               false, false});
  return o;
}

const CommandRegistrar reg{{"spnav",
                            "Serve the 6-D input as a spacenavd-compatible 3-D mouse on an AF_UNIX socket "
                            "(libspnav clients: SPNAV_SOCKET=PATH) until interrupted or the source ends.",
                            spnavOptions(), runSpnav}};

}  // namespace
}  // namespace onetip::tools
