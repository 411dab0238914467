// `onetip spnav`: the pipeline feeding a spacenavd-compatible server
// (os_outputs/spnav_server.hpp, docs/os_outputs.md) until SIGINT/SIGTERM or
// the end of the source. 3-D programs using libspnav reach it with
// SPNAV_SOCKET=PATH.
#include <chrono>
#include <thread>

#include "command.hpp"
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
  os_outputs::SpnavServer server(o);
  server.start();
  pipeline->onEvent([&server](const pipeline::PipelineEvent& e) { server.publish(e.event); });
  const double wait_s = args.getDouble("wait-client", 0);
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
  o.push_back({"wait-client", "wait up to this many seconds for a first client before starting (default 0)", false,
               false});
  return o;
}

const CommandRegistrar reg{{"spnav",
                            "Serve the 6-D input as a spacenavd-compatible 3-D mouse on an AF_UNIX socket "
                            "(libspnav clients: SPNAV_SOCKET=PATH) until interrupted or the source ends.",
                            spnavOptions(), runSpnav}};

}  // namespace
}  // namespace onetip::tools
