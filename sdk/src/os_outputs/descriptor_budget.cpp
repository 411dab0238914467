#include "os_outputs/descriptor_budget.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>

#include "core/error.hpp"

namespace onetip::os_outputs {

void reserveDescriptorsFor(int clients, const char* what) {
  const rlim_t needed = static_cast<rlim_t>(clients) + kDescriptorReserve;
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur >= needed) return;
  if (limit.rlim_max == RLIM_INFINITY || limit.rlim_max >= needed) {
    rlimit raised = limit;
    raised.rlim_cur = needed;
    if (::setrlimit(RLIMIT_NOFILE, &raised) == 0) return;
  }
  throw InputError(std::string(what) + ": " + std::to_string(clients) + " clients need " + std::to_string(needed) +
                   " open files (" + std::to_string(kDescriptorReserve) +
                   " kept for the rest); the open-file limit (ulimit -n) is " + std::to_string(limit.rlim_cur) +
                   ": allow fewer clients or raise the limit");
}

SpareDescriptor::SpareDescriptor() : fd_(::open("/dev/null", O_RDONLY | O_CLOEXEC)) {}

SpareDescriptor::~SpareDescriptor() {
  if (fd_ >= 0) ::close(fd_);
}

bool SpareDescriptor::shedOne(int listener) {
  if (fd_ < 0) fd_ = ::open("/dev/null", O_RDONLY | O_CLOEXEC);  // one may have come free since
  if (fd_ < 0) return false;
  ::close(fd_);
  const int client = ::accept4(listener, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
  if (client >= 0) ::close(client);
  fd_ = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  return client >= 0;
}

}  // namespace onetip::os_outputs
