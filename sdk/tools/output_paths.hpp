// tools/output_paths.hpp — an output must never overwrite an input or another
// output of the same run (`--out` equal to `--calib` once overwrote the
// calibration), nor a device or folder (core/atomic_file.hpp refuses those).
//
// Two paths name the same file when both exist and are the same inode
// (std::filesystem::equivalent: hard links and symlinks included), or, when
// one does not exist yet, when their normalised absolute forms are equal.
#pragma once

#include <string>
#include <vector>

#include "command.hpp"

namespace onetip::tools {

// Throws InputError "option '--A' and '--B' name the same file (PATH)" for
// the first clash among the given options that are set.
void refuseOutputClashes(const Args& args, const std::vector<std::string>& output_options,
                         const std::vector<std::string>& input_options);

}  // namespace onetip::tools
