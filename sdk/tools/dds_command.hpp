// tools/dds_command.hpp — the options `onetip publish` and `onetip teleop`
// share for reaching a DDS domain: --domain N, --namespace NAME, --interface
// IF, --peer A[,B...] (dds/participant.hpp).
#pragma once

#include <vector>

#include "command.hpp"
#include "dds/participant.hpp"

namespace onetip::tools {

std::vector<OptionSpec> ddsOptionSpecs();
dds::DdsOptions ddsOptionsFromArgs(const Args& args);  // InputError naming the bad option

}  // namespace onetip::tools
