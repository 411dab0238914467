#include "capture/session_source.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

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
  std::string text;
  {
    std::ifstream in(csv, std::ios::binary);
    if (!in) throw InputError(csv + ": cannot open");
    std::stringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  text.erase(text.find_last_of('\n') == std::string::npos ? 0 : text.find_last_of('\n') + 1);  // complete lines only
  const CsvTable t = parseCsv(text, csv);
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

}  // namespace onetip::capture
