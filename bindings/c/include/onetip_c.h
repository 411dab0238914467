/**
 * @file onetip_c.h
 * @brief The C ABI of the onetip SDK (in libonetip.so), for C, C#/Unity
 * (P/Invoke) and any language with a C FFI.
 *
 * Frames and units (docs/reference.md): positions in millimetres in the sensor
 * frame S (origin at the rest-state marker centroid, z out of the pad towards
 * the finger, x along increasing marker column, y = z x x); angles in degrees;
 * the 6-D input is [dx, dy, dz, yaw, pitch, roll], the finger's motion since
 * contact onset (dz: press depth, positive into the pad). Times in seconds.
 *
 * Rules of the boundary:
 *  - Every function that can fail returns an onetip_error_kind (ONETIP_OK = 0)
 *    and, when `error` is not NULL, fills it with the same kind and a one-line
 *    message ("" on success). No C++ exception ever leaves the library.
 *    Out-parameters are written only on success, unless a function says otherwise.
 *  - Version handshake: the entry points (onetip_sensor_create, the
 *    onetip_options_* functions and onetip_option_describe) take the ABI
 *    version the caller was compiled against; pass ONETIP_C_ABI_VERSION. A
 *    different version fails with ONETIP_ERROR_VERSION and a message giving
 *    both versions. Additions that keep the ABI compatible raise
 *    ONETIP_C_ABI_MINOR_VERSION instead: a caller that uses functions of minor
 *    version m needs onetip_abi_minor_version() >= m.
 *  - Handles are opaque; each onetip_sensor_create has its onetip_sensor_destroy.
 *    A handle is a number looked up in a registry of live sensors, never
 *    dereferenced and never reused: a NULL handle gives
 *    ONETIP_ERROR_NULL_ARGUMENT, a destroyed (or made-up) one
 *    ONETIP_ERROR_INVALID_HANDLE. A call racing with onetip_sensor_destroy on
 *    another thread keeps the sensor alive until it returns.
 *    onetip_sensor_destroy(NULL) is a no-op returning ONETIP_OK.
 *  - Ownership: the library keeps no pointer the caller passes (strings,
 *    structs) beyond the call, except a callback's `user` pointer, which it
 *    passes back untouched and never frees. Strings it returns are static.
 *  - Structs are flat and fixed-size (no pointers, no unions); strings are
 *    NUL-terminated and truncated to fit; enums travel as int32_t.
 *
 * Threads: every function may be called from any thread. Callbacks run on the
 * sensor's processing thread, one at a time, in frame order; inside one you may
 * poll, read stats, rezero, rereference and set callbacks, but
 * onetip_sensor_start/stop/destroy and onetip_sensor_wait_finished/wait_event
 * of the same sensor fail with ONETIP_ERROR_STATE there (they would wait for
 * themselves), and so do stop/destroy of another sensor while that sensor's own
 * callback is running (two callbacks stopping each other would wait forever).
 * The event and frame pointers given to a callback are valid only during the
 * call. Replacing a callback (or setting NULL) from another thread waits for a
 * call in progress to finish, so once onetip_sensor_set_*_callback returns the
 * old callback is never called again.
 *
 * This is the one header to include; it includes the others, one concept each:
 *  - onetip_c_base.h: the export macro, the ABI version, the error kinds and
 *    onetip_error, the library's version and clock;
 *  - onetip_c_data.h: what a sensor reports: onetip_event, onetip_frame,
 *    onetip_marker, onetip_stats and their enums;
 *  - onetip_c_options.h: onetip_options, its functions and the option table;
 *  - onetip_c_sensor.h: the handle, its lifetime, run, callbacks, poll and wait;
 *  - onetip_c_uncertainty.h: the uncertainty forms (minor version 2).
 */
#ifndef ONETIP_C_H
#define ONETIP_C_H

#include "onetip_c_base.h"
#include "onetip_c_data.h"
#include "onetip_c_options.h"
#include "onetip_c_sensor.h"

/* Minor version 2: the uncertainty forms of the poll, wait and callback functions. */
#include "onetip_c_uncertainty.h"

#endif /* ONETIP_C_H */
