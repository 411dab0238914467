// capture/session_writer.hpp — records a session folder (session_source.hpp)
// so that it survives its recorder being killed at any moment (issue 39).
//
// session.csv is created with its header when the writer is, and each frame
// is appended as it comes: first the frame's file under frames/ (created
// exclusively, written whole), then its row, in one write(2) on the session
// descriptor. A process killed at any moment (SIGKILL included) leaves a
// session.csv whose complete lines name complete frames with their true
// indices and timestamps; a row cut short is left out by the reader. When a
// write fails (a full disk, EFBIG under a file-size limit), what that frame
// added is taken back (session.csv truncated to its last complete row, the
// frame's file removed) and a SessionWriteError names the file and the cause:
// the frames already recorded stay a whole session.
#pragma once

#include <cstddef>
#include <string>

#include "capture/frame_source.hpp"
#include "core/error.hpp"

namespace onetip::capture {

// A write that failed for lack of room or another I/O error (not bad input): the session so far is whole.
class SessionWriteError : public InputError {
 public:
  using InputError::InputError;
};

class SessionWriter {
 public:
  // `folder` must exist (normally an AtomicDir's staging folder); creates frames/ and session.csv.
  explicit SessionWriter(std::string folder);  // throws InputError
  ~SessionWriter();
  SessionWriter(const SessionWriter&) = delete;
  SessionWriter& operator=(const SessionWriter&) = delete;

  // Records an ok frame: its encoded bytes when it has them, else lossless PNG of its grey image.
  // Throws SessionWriteError when a write fails (nothing of this frame is left behind).
  void add(const Frame& frame);
  void finish();  // closes session.csv; throws SessionWriteError on I/O failure
  std::size_t frames() const noexcept { return frames_; }

 private:
  std::string folder_;
  int csv_fd_ = -1;
  long long csv_size_ = 0;  // bytes of complete rows
  std::size_t frames_ = 0;
};

}  // namespace onetip::capture
