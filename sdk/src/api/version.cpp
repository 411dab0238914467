#include "onetip/version.hpp"

#define ONETIP_STR2(x) #x
#define ONETIP_STR(x) ONETIP_STR2(x)

namespace onetip {
const char* versionString() noexcept {
  return ONETIP_STR(ONETIP_VERSION_MAJOR) "." ONETIP_STR(ONETIP_VERSION_MINOR) "." ONETIP_STR(ONETIP_VERSION_PATCH);
}
}  // namespace onetip
