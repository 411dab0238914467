/**
 * @file onetip/version.hpp
 * @brief The SDK's version, at compile time (macros) and at run time (versionString()).
 */
#pragma once

#include "onetip/export.hpp"

/// Major version of the headers compiled against.
#define ONETIP_VERSION_MAJOR 0
/// Minor version of the headers compiled against.
#define ONETIP_VERSION_MINOR 1
/// Patch version of the headers compiled against.
#define ONETIP_VERSION_PATCH 0

namespace onetip {
/**
 * @brief The version of the library actually loaded, which may differ from the
 * ONETIP_VERSION_* macros of the headers a program was compiled with.
 * @return "MAJOR.MINOR.PATCH", a static string (never NULL, never freed). Any thread.
 */
ONETIP_EXPORT const char* versionString() noexcept;
}  // namespace onetip
