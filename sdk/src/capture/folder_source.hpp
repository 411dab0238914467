// capture/folder_source.hpp — frames from a folder of image files.
//
// The folder's .png files (also .jpg/.jpeg/.bmp/.tif/.tiff, any case), sorted
// by file name, are read as 8-bit grey frames (colour is converted, 16-bit is
// scaled down by OpenCV). A folder with a single frame is a valid stream of
// one frame. Each file's header is checked before decoding (capture/image_file.hpp:
// the stream's size once known, a pixel bound before), so a small file that
// claims a huge image costs nothing. Files that fail that check or to decode,
// or whose size or content fails the FrameChecker (capture/frame_check.hpp),
// are returned as skipped frames and the stream goes on. Timestamps are index / nominal_rate_hz seconds.
#pragma once

#include <string>
#include <vector>

#include "capture/frame_check.hpp"
#include "capture/frame_source.hpp"

namespace onetip::capture {

struct FolderSourceOptions {
  double nominal_rate_hz = 30.0;
  FrameCheckOptions check;
  void validate() const;  // throws InputError naming the bad field
};

class FolderSource : public FrameSource {
 public:
  // Throws InputError when the folder is missing or holds no image files.
  explicit FolderSource(const std::string& folder, FolderSourceOptions options = {});
  Frame next() override;
  std::string describe() const override { return folder_; }
  const std::vector<std::string>& files() const noexcept { return files_; }

 private:
  std::string folder_;
  FolderSourceOptions options_;
  std::vector<std::string> files_;
  size_t position_ = 0;
  FrameChecker checker_;
};

}  // namespace onetip::capture
