// onetip/version.hpp — the SDK's version, at compile time and at run time.
#pragma once

#include "onetip/export.hpp"

#define ONETIP_VERSION_MAJOR 0
#define ONETIP_VERSION_MINOR 1
#define ONETIP_VERSION_PATCH 0

namespace onetip {
// "MAJOR.MINOR.PATCH" of the library actually loaded (may differ from the headers).
ONETIP_EXPORT const char* versionString() noexcept;
}  // namespace onetip
