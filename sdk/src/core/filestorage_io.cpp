#include "core/filestorage_io.hpp"

#include "core/atomic_file.hpp"

namespace onetip {

YamlWriter::YamlWriter()
    : fs_(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML) {}

void YamlWriter::save(const std::string& path) {
  const std::string text = fs_.releaseAndGetString();
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace onetip
