/**
 * @file onetip_c_base.h
 * @brief The base of the C ABI, included by onetip_c.h and by each of its
 * other headers: the export macro, the ABI version of the handshake, the error
 * kinds and the onetip_error every call fills, and the library's version and
 * clock.
 *
 * The rules of the boundary (errors, the version handshake, handles, threads)
 * are in onetip_c.h's description.
 */
#ifndef ONETIP_C_BASE_H
#define ONETIP_C_BASE_H

#include <stdint.h>

#if defined(_WIN32) && defined(ONETIP_C_BUILDING)
#define ONETIP_C_API __declspec(dllexport)
#elif defined(_WIN32)
#define ONETIP_C_API __declspec(dllimport)
#else
/** Marks the functions exported by libonetip (default visibility; dllexport/dllimport on Windows). */
#define ONETIP_C_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** The ABI onetip_c.h and the headers it includes describe; bumped on any incompatible change. */
#define ONETIP_C_ABI_VERSION 1u
/** Compatible additions to version 1: 1 = the option table (onetip_option_count,
 * onetip_option_describe) and keyed option access (onetip_options_get/_set/_validate);
 * 2 = the uncertainty of the 6-D input and the markers' stick probability
 * (onetip_c_uncertainty.h: onetip_sensor_poll_event_sd and the other *_sd functions). */
#define ONETIP_C_ABI_MINOR_VERSION 2u

/** The result of every function that can fail; onetip_error::kind holds the same value. */
typedef enum onetip_error_kind {
  ONETIP_OK = 0,                    /**< Success. */
  ONETIP_ERROR_NULL_ARGUMENT = 1,   /**< A required pointer (handle, string, out-parameter) was NULL. */
  ONETIP_ERROR_INVALID_HANDLE = 2,  /**< The handle was destroyed or never created by this library. */
  ONETIP_ERROR_VERSION = 3,         /**< The caller's ONETIP_C_ABI_VERSION differs from the library's. */
  ONETIP_ERROR_INPUT = 4,           /**< Bad input: missing/malformed file, bad source, invalid option or argument. */
  ONETIP_ERROR_STATE = 5,           /**< Not valid now (start twice, stop from inside a callback, ...). */
  ONETIP_ERROR_INTERNAL = 6         /**< Unexpected failure inside the library (a bug), or out of memory. */
} onetip_error_kind;

/** Size of onetip_error::message, including the terminating NUL. */
#define ONETIP_ERROR_MESSAGE_SIZE 256
/** What went wrong, filled by every function that takes one (when the pointer is not NULL). */
typedef struct onetip_error {
  int32_t kind;                               /**< An onetip_error_kind; ONETIP_OK on success. */
  char message[ONETIP_ERROR_MESSAGE_SIZE];    /**< One line naming the bad file, key, argument or call; "" when kind == ONETIP_OK. */
} onetip_error;

/** @return the library's ABI version; compare with ONETIP_C_ABI_VERSION. Never fails. */
ONETIP_C_API uint32_t onetip_abi_version(void);
/** @return the library's minor ABI version: >= ONETIP_C_ABI_MINOR_VERSION for every function of onetip_c.h and the headers it includes. Never fails. */
ONETIP_C_API uint32_t onetip_abi_minor_version(void);
/** @return "MAJOR.MINOR.PATCH" of the loaded library; a static string (never NULL, never free it). */
ONETIP_C_API const char* onetip_version_string(void);
/** @return seconds on the steady (monotonic) clock of onetip_event::arrival_s; its origin is unspecified, use differences. Never fails. */
ONETIP_C_API double onetip_clock_seconds(void);
/**
 * @brief A short static name for an error kind.
 * @param kind an onetip_error_kind.
 * @return "ok", "null_argument", "invalid_handle", "version", "input", "state",
 *         "internal", or "unknown" when out of range; static, never free it.
 */
ONETIP_C_API const char* onetip_error_kind_name(int32_t kind);

#ifdef __cplusplus
}
#endif

#endif /* ONETIP_C_BASE_H */
