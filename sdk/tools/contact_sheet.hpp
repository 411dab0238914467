// tools/contact_sheet.hpp — a PNG "contact sheet": a grid of downscaled frames,
// each captioned, so a run can be looked at in one picture.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace onetip::tools {

class ContactSheet {
 public:
  // Keeps up to `tiles` frames chosen evenly from a run of `frame_count` frames.
  ContactSheet(int frame_count, int tiles = 12, int columns = 4, int tile_width = 480);
  bool wants(int frame_index) const;
  // Adds a frame (grey or BGR) with caption lines drawn on it.
  void add(const cv::Mat& frame, const std::vector<std::string>& caption);
  // Writes the grid atomically; throws InputError when it cannot.
  void save(const std::string& path) const;
  // The grid as PNG bytes; throws InputError when there is no frame or it cannot be encoded.
  std::vector<unsigned char> png(const std::string& path_for_messages) const;

 private:
  int frame_count_, tiles_, columns_, tile_width_;
  std::vector<cv::Mat> images_;
};

}  // namespace onetip::tools
