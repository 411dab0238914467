// core/filestorage_io.hpp — writing OpenCV FileStorage YAML documents
// (calibration, pattern and options files), so OpenCV's cv::FileStorage reads
// what onetip writes. Reading goes through core/config_file.hpp.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace onetip {

// A FileStorage writer that keeps the document in memory; save() commits it
// atomically to `path` as YAML.
class YamlWriter {
 public:
  YamlWriter();
  cv::FileStorage& fs() { return fs_; }
  void save(const std::string& path);

 private:
  cv::FileStorage fs_;
};

}  // namespace onetip
