// os_outputs/descriptor_budget.hpp — a server's clients within the process's
// open-file limit (issue 39: `spnav --max-clients 1024` under `ulimit -n
// 1024` hit EMFILE, its accept loop spun, new clients hung and the frame
// source, unable to open files, ended early).
//   * reserveDescriptorsFor() checks at start that the clients fit beside
//     kDescriptorReserve descriptors for everything else (frame files, the
//     camera, DDS, the socket itself), raising the soft RLIMIT_NOFILE up to the
//     hard one if that is enough, else refusing with an InputError naming both.
//   * SpareDescriptor keeps one descriptor (/dev/null) in hand: when accept()
//     fails with EMFILE or ENFILE, it is given up for the time it takes to
//     accept the waiting connection and close it (the client sees the end at
//     once instead of hanging, and the listener stops being readable, so the
//     poll loop does not spin). Without a spare, the listener rests briefly.
#pragma once

namespace onetip::os_outputs {

inline constexpr int kDescriptorReserve = 64;

// Throws InputError "<what>: N clients need N + 64 open files; the open-file limit (ulimit -n) is L".
void reserveDescriptorsFor(int clients, const char* what);

class SpareDescriptor {
 public:
  SpareDescriptor();
  ~SpareDescriptor();
  SpareDescriptor(const SpareDescriptor&) = delete;
  SpareDescriptor& operator=(const SpareDescriptor&) = delete;

  // After accept() on `listener` failed with EMFILE/ENFILE: accepts and closes one waiting
  // connection using the spare. False when there was no spare to give up (rest the listener).
  bool shedOne(int listener);

 private:
  int fd_ = -1;
};

}  // namespace onetip::os_outputs
