// `onetip joystick`: the pipeline feeding a Linux uinput virtual joystick
// (os_outputs/uinput_joystick.hpp, docs/os_outputs.md: six axes ABS_X..ABS_RZ,
// BTN_TRIGGER for the press) until SIGINT/SIGTERM or the end of the source.
#include "command.hpp"
#include "os_outputs/uinput_joystick.hpp"
#include "pipeline_command.hpp"

namespace onetip::tools {
namespace {

int runJoystick(const Args& args) {
  auto pipeline = openPipelineFromArgs(args);
  os_outputs::UinputJoystickOptions o;
  o.node = args.optional("uinput").value_or(o.node);
  if (auto name = args.optional("name")) o.device.name = *name;
  os_outputs::UinputJoystick joystick(o);
  joystick.open();  // InputError naming the node: missing, permissions, not uinput
  pipeline->onEvent([&joystick](const pipeline::PipelineEvent& e) { joystick.publish(e.event); });
  std::fprintf(stderr, "onetip joystick: device at %s\n", joystick.sysfsPath().c_str());
  const int code = runPipelineUntilInterrupted(*pipeline);
  joystick.close();
  return code;
}

std::vector<OptionSpec> joystickOptions() {
  std::vector<OptionSpec> o = pipelineInputOptions();
  o.push_back({"uinput", "uinput device node (default /dev/uinput)", false, false});
  o.push_back({"name", "device name games see (default \"onetip tactile joystick\")", false, false});
  return o;
}

const CommandRegistrar reg{{"joystick",
                            "Expose the 6-D input as a Linux uinput virtual joystick (six axes and a trigger "
                            "button) until interrupted or the source ends.",
                            joystickOptions(), runJoystick}};

}  // namespace
}  // namespace onetip::tools
