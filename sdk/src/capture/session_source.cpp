#include "capture/session_source.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "capture/image_file.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"

namespace onetip::capture {

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kHeader = {"frame", "timestamp_s", "file"};

// "frames/<name>" with a plain name: nothing that leaves the session folder.
bool safeFrameFile(const std::string& file) {
  if (file.rfind("frames/", 0) != 0) return false;
  const std::string name = file.substr(7);
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
         name.find('\0') == std::string::npos;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

bool isSessionFolder(const std::string& folder) {
  std::error_code ec;
  return fs::is_regular_file(fs::path(folder) / "session.csv", ec);
}

SessionSource::SessionSource(const std::string& folder) : folder_(folder) {
  const std::string csv = (fs::path(folder) / "session.csv").string();
  const CsvTable t = readCsv(csv);
  if (t.header != kHeader) throw InputError(csv + ": line 1: the header must be frame,timestamp_s,file");
  if (t.rows.empty()) throw InputError(csv + ": no recorded frames");
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string line = csv + ": line " + std::to_string(r + 2);
    const double index = parseNumber(t.rows[r][0], line + ", column frame");
    const double timestamp = parseNumber(t.rows[r][1], line + ", column timestamp_s");
    if (index != std::floor(index) || index < 0 || index > 9e15)
      throw InputError(line + ", column frame: '" + t.rows[r][0] + "' is not a frame index");
    if (!entries_.empty() && index <= static_cast<double>(entries_.back().index))
      throw InputError(line + ", column frame: frame indices must increase");
    if (!entries_.empty() && timestamp < entries_.back().timestamp_s)
      throw InputError(line + ", column timestamp_s: timestamps must not decrease");
    if (!safeFrameFile(t.rows[r][2]))
      throw InputError(line + ", column file: '" + t.rows[r][2] + "' is not a file name under frames/");
    entries_.push_back({static_cast<std::int64_t>(index), timestamp, t.rows[r][2]});
  }
}

Frame SessionSource::next() {
  Frame f;
  if (position_ >= entries_.size()) return f;  // end
  const Entry& e = entries_[position_++];
  f.index = e.index;
  f.timestamp_s = e.timestamp_s;
  ImageLimits limits;
  limits.expected = checker_.streamSize();
  cv::Mat grey;
  std::vector<std::uint8_t> bytes;
  std::optional<std::string> problem = readFileBytes((fs::path(folder_) / e.file).string(), limits.max_file_bytes, bytes);
  if (!problem && endsWith(e.file, ".jpg")) {  // a camera's MJPEG: TurboJPEG, as live (tables or not)
    cv::Size declared;
    problem = imageHeaderProblem(bytes.data(), bytes.size(), limits, declared);
    if (!problem) {
      const DecodeResult d = jpeg_.decode(bytes.data(), bytes.size(), declared, grey);
      if (!d.ok) problem = d.message;
    }
  } else if (!problem) {
    GreyImage image = decodeGreyImage(bytes.data(), bytes.size(), limits);
    problem = image.problem;
    grey = std::move(image.grey);
  }
  if (!problem) problem = checker_.problem(grey);
  return deliver(std::move(f), std::move(grey), problem, e.file);
}

SessionWriter::SessionWriter(std::string folder) : folder_(std::move(folder)) {
  std::error_code ec;
  fs::create_directory(fs::path(folder_) / "frames", ec);
  if (ec) throw InputError(folder_ + ": cannot create frames/ (" + ec.message() + ")");
}

void SessionWriter::add(const Frame& frame) {
  char name[40];
  std::snprintf(name, sizeof name, "frames/%06lld.%s", static_cast<long long>(frame.index),
                frame.encoded.empty() ? "png" : "jpg");
  std::vector<std::uint8_t> png;
  if (frame.encoded.empty() && !cv::imencode(".png", frame.grey, png, {cv::IMWRITE_PNG_COMPRESSION, 1}))
    throw InputError(folder_ + "/" + name + ": cannot encode the frame");
  const std::vector<std::uint8_t>& bytes = frame.encoded.empty() ? png : frame.encoded;
  // The session folder is itself staged (core/atomic_file.hpp AtomicDir): frames are written in place,
  // created exclusively so nothing already there is followed or overwritten.
  const std::string path = (fs::path(folder_) / name).string();
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  bool written = fd >= 0;
  for (size_t done = 0; written && done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    written = n > 0;
    done += written ? static_cast<size_t>(n) : 0;
  }
  if (fd >= 0 && ::close(fd) != 0) written = false;
  if (!written) throw InputError(path + ": cannot write the frame (" + std::strerror(errno) + ")");
  char timestamp[40];
  std::snprintf(timestamp, sizeof timestamp, "%.17g", frame.timestamp_s);  // round-trips the double exactly
  rows_.push_back({std::to_string(frame.index), timestamp, name});
}

void SessionWriter::finish() {
  CsvWriter csv((fs::path(folder_) / "session.csv").string(), kHeader);
  for (const auto& row : rows_) csv.row(row);
  csv.commit();
}

}  // namespace onetip::capture
