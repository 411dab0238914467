// core/filestorage_io.hpp — reading and writing OpenCV FileStorage documents
// (YAML or JSON) with errors that name the file and the key.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace onetip {

// Opens `path` for reading; throws InputError if it is missing or malformed.
cv::FileStorage openForReading(const std::string& path);

// Required entries: throw InputError "<path>: <key>: ..." when absent or of
// the wrong type.
double readRequiredReal(const cv::FileNode& parent, const std::string& key,
                        const std::string& where);
int readRequiredInt(const cv::FileNode& parent, const std::string& key, const std::string& where);
cv::Mat readRequiredMat(const cv::FileNode& parent, const std::string& key, int rows, int cols,
                        const std::string& where);

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
