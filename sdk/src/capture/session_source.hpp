// capture/session_source.hpp — recorded sessions (`onetip record`) as a frame
// source, and the writer that records them.
//
// A session folder holds
//   session.csv   frame,timestamp_s,file — one row per recorded frame, written
//                 as soon as the frame is (capture/session_writer.hpp): the
//                 frame's index in the live stream (gaps where the live
//                 source skipped one), its timestamp (s, as the live source
//                 stamped it) and its file under frames/;
//   frames/       the frames as delivered: a camera's MJPEG bytes unchanged
//                 (NNNNNN.jpg), decoded frames as lossless 8-bit grey PNG
//                 (NNNNNN.png);
//   calib.yaml, pattern.yaml   the calibration and pattern of the live run,
//                 when it had them.
// A folder with session.csv opens as a SessionSource wherever a source is
// taken (open_frame_source.hpp): it replays the recorded frames with their
// recorded indices and timestamps, as fast as they are asked for (the
// pipeline's playback_rate paces them at recorded speed). So processing a
// session gives the frames, numbering and times of the live run. session.csv
// is checked before any frame is read: a header other than the above, a
// non-increasing frame index, a non-finite or decreasing timestamp, or a file
// name that leaves frames/ is an InputError naming the line.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "capture/frame_check.hpp"
#include "capture/frame_source.hpp"
#include "capture/jpeg_grey_decoder.hpp"

namespace onetip::capture {

// True when `folder` holds a session.csv.
bool isSessionFolder(const std::string& folder);

class SessionSource : public FrameSource {
 public:
  explicit SessionSource(const std::string& folder);  // throws InputError
  Frame next() override;
  std::string describe() const override { return folder_; }
  std::size_t size() const noexcept { return entries_.size(); }

 private:
  struct Entry {
    std::int64_t index;
    double timestamp_s;
    std::string file;  // relative to the folder
  };
  std::string folder_;
  std::vector<Entry> entries_;
  std::size_t position_ = 0;
  FrameChecker checker_;
  JpegGreyDecoder jpeg_;
};

}  // namespace onetip::capture
