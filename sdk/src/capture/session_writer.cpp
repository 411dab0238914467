#include "capture/session_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <vector>

namespace onetip::capture {

namespace fs = std::filesystem;

namespace {

// Writes all of `bytes` to `fd`; false with errno set on a failure or a short write.
bool writeAll(int fd, const char* bytes, size_t size) {
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, bytes + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

// Creates `path` exclusively (nothing already there is followed or overwritten) and writes `bytes`.
bool writeNewFile(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) return false;
  bool written = writeAll(fd, reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const int saved = errno;
  if (::close(fd) != 0 && written) return false;
  errno = saved;
  return written;
}

}  // namespace

SessionWriter::SessionWriter(std::string folder) : folder_(std::move(folder)) {
  std::error_code ec;
  fs::create_directory(fs::path(folder_) / "frames", ec);
  if (ec) throw InputError(folder_ + ": cannot create frames/ (" + ec.message() + ")");
  const std::string csv = (fs::path(folder_) / "session.csv").string();
  csv_fd_ = ::open(csv.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_APPEND | O_CLOEXEC, 0666);
  static const std::string header = "frame,timestamp_s,file\n";
  if (csv_fd_ < 0 || !writeAll(csv_fd_, header.data(), header.size()))
    throw SessionWriteError(csv + ": cannot write (" + std::strerror(errno) + ")");
  csv_size_ = static_cast<long long>(header.size());
}

SessionWriter::~SessionWriter() {
  if (csv_fd_ >= 0) ::close(csv_fd_);
}

void SessionWriter::add(const Frame& frame) {
  if (csv_fd_ < 0) throw std::logic_error("SessionWriter::add after finish");
  char name[40];
  std::snprintf(name, sizeof name, "frames/%06lld.%s", static_cast<long long>(frame.index),
                frame.encoded.empty() ? "png" : "jpg");
  std::vector<std::uint8_t> png;
  if (frame.encoded.empty() && !cv::imencode(".png", frame.grey, png, {cv::IMWRITE_PNG_COMPRESSION, 1}))
    throw InputError(folder_ + "/" + name + ": cannot encode the frame");
  const std::string path = (fs::path(folder_) / name).string();
  if (!writeNewFile(path, frame.encoded.empty() ? png : frame.encoded)) {
    const int saved = errno;
    if (saved != EEXIST) ::unlink(path.c_str());
    throw SessionWriteError(path + ": cannot write the frame (" + std::strerror(saved) + ")");
  }
  char row[128];  // %.17g round-trips the double exactly
  const int n = std::snprintf(row, sizeof row, "%lld,%.17g,%s\n", static_cast<long long>(frame.index), frame.timestamp_s,
                              name);
  if (!writeAll(csv_fd_, row, static_cast<size_t>(n))) {
    const int saved = errno;
    const bool cut_back = ::ftruncate(csv_fd_, csv_size_) == 0;
    (void)cut_back;  // if not, a cut row has no newline: the reader leaves it out anyway
    ::unlink(path.c_str());
    throw SessionWriteError(folder_ + "/session.csv: cannot write (" + std::strerror(saved) + ")");
  }
  csv_size_ += n;
  ++frames_;
}

void SessionWriter::finish() {
  if (csv_fd_ < 0) return;
  const bool synced = ::fdatasync(csv_fd_) == 0;
  const int saved = errno;
  const bool closed = ::close(csv_fd_) == 0;
  csv_fd_ = -1;
  if (!synced || !closed)
    throw SessionWriteError(folder_ + "/session.csv: cannot write (" + std::strerror(synced ? errno : saved) + ")");
}

}  // namespace onetip::capture
