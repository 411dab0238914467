// tools/output_paths.hpp — an output must never overwrite an input or another
// output of the same run (`--out` equal to `--calib` once overwrote the
// calibration), nor a device or folder (core/atomic_file.hpp refuses those),
// and a path that cannot be written is refused before the run does any work.
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

// Checked before any work, so that a run never renders or processes every
// frame only to find at the end that its output cannot be written:
//   * each set option of `file_options` names a file this run may create or
//     replace: its folder exists and can be written in, and the path is absent
//     or a regular file ("is a directory" when a folder is there);
//   * each set option of `folder_options` names a folder to create: absent or
//     empty, in an existing folder that can be written in (not . or ..).
// Throws InputError "--OPTION PATH: why".
void refuseUnwritableOutputs(const Args& args, const std::vector<std::string>& file_options,
                             const std::vector<std::string>& folder_options);
// The same checks for one path; `what` names it in the message (e.g. "--out").
void requireWritableFile(const std::string& what, const std::string& path);
void requireCreatableFolder(const std::string& what, const std::string& path);

}  // namespace onetip::tools
