// capture/open_frame_source.hpp — a FrameSource from a specification string.
//
// Specifications (docs/reference.md, `--input SRC`):
//   "v4l2:/dev/videoN"  a V4L2 camera (capture/v4l2_source.hpp)
//   "SCHEME:REST"       a source registered for SCHEME, e.g. "sim:press.yaml"
//                       once the simulator has called
//                       registerFrameSourceScheme("sim", ...)
//   a session folder    a recorded session (holds session.csv; session_source.hpp)
//   a folder            its image files, sorted by name (folder_source.hpp)
//   a file              a video file (video_source.hpp)
// A scheme is two or more letters or digits before the first ':'.
// Throws InputError naming the spec when it cannot be opened.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "capture/frame_source.hpp"

namespace onetip::capture {

// Makes a source from the part of the spec after "SCHEME:".
using FrameSourceFactory = std::function<std::unique_ptr<FrameSource>(const std::string& rest)>;

// Registers (or replaces) the factory for "SCHEME:..." specs.
void registerFrameSourceScheme(const std::string& scheme, FrameSourceFactory factory);

std::unique_ptr<FrameSource> openFrameSource(const std::string& spec);

}  // namespace onetip::capture
