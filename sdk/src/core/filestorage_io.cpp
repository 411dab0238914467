#include "core/filestorage_io.hpp"

#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace onetip {

cv::FileStorage openForReading(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path + ": no such file");
  try {
    cv::FileStorage fs(path, cv::FileStorage::READ);
    if (!fs.isOpened()) throw InputError(path + ": not a YAML or JSON document");
    return fs;
  } catch (const cv::Exception& e) {
    throw InputError(path + ": malformed YAML/JSON (" + e.err + ")");
  }
}

namespace {
cv::FileNode required(const cv::FileNode& parent, const std::string& key, const std::string& where) {
  cv::FileNode n = parent[key];
  if (n.empty() || n.isNone()) throw InputError(where + ": missing key '" + key + "'");
  return n;
}
}  // namespace

double readRequiredReal(const cv::FileNode& parent, const std::string& key,
                        const std::string& where) {
  cv::FileNode n = required(parent, key, where);
  if (!n.isReal() && !n.isInt()) throw InputError(where + ": " + key + ": expected a number");
  return static_cast<double>(n);
}

int readRequiredInt(const cv::FileNode& parent, const std::string& key, const std::string& where) {
  cv::FileNode n = required(parent, key, where);
  if (n.isInt()) return static_cast<int>(n);
  if (n.isReal()) {
    const double v = static_cast<double>(n);
    if (v == static_cast<double>(static_cast<int>(v))) return static_cast<int>(v);
  }
  throw InputError(where + ": " + key + ": expected an integer");
}

cv::Mat readRequiredMat(const cv::FileNode& parent, const std::string& key, int rows, int cols,
                        const std::string& where) {
  cv::FileNode n = required(parent, key, where);
  cv::Mat m;
  try {
    if (n.isMap()) {
      n >> m;
    } else if (n.isSeq()) {
      std::vector<double> v;
      n >> v;
      m = cv::Mat(v, true).reshape(1, static_cast<int>(v.size()) == rows * cols ? rows : 1);
    }
  } catch (const cv::Exception&) {
    m.release();
  }
  if (m.empty() || static_cast<int>(m.total()) != rows * cols)
    throw InputError(where + ": " + key + ": expected a " + std::to_string(rows) + "x" +
                     std::to_string(cols) + " matrix");
  cv::Mat d;
  m.reshape(1, rows).convertTo(d, CV_64F);
  for (auto it = d.begin<double>(); it != d.end<double>(); ++it)
    if (!std::isfinite(*it)) throw InputError(where + ": " + key + ": contains a non-finite value");
  return d;
}

YamlWriter::YamlWriter()
    : fs_(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML) {}

void YamlWriter::save(const std::string& path) {
  const std::string text = fs_.releaseAndGetString();
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace onetip
