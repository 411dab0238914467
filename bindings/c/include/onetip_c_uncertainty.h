/**
 * @file onetip_c_uncertainty.h
 * @brief The uncertainty of the 6-D input and the stick probability of each
 * marker through the C ABI (minor version 2; included by onetip_c.h).
 *
 * The structs of minor version 1 (onetip_event, onetip_frame, onetip_marker)
 * keep their size and layout: a caller built against an older header allocates
 * them. The uncertainty comes in new structs that hold the old one as their
 * first member and add the new fields after it, filled by new functions that
 * mirror the old ones (poll, wait, callbacks) and follow the same rules
 * (onetip_c.h: errors, handles, threads, callbacks inside callbacks). A caller
 * that uses them needs onetip_abi_minor_version() >= 2; against an older
 * library these symbols are missing (the dynamic loader or P/Invoke reports it
 * at the first call), so check the minor version first.
 *
 * What the numbers mean (as onetip::Event::sd, onetip::FrameResult::sd and
 * onetip::MarkerState::stick_probability): `sd` holds one standard deviation
 * of each component of the measured 6-D input, dx, dy, dz in mm and yaw,
 * pitch, roll in degrees (pose.csv's sd_dx .. sd_roll), 0 out of contact; a
 * component the pad cannot see (a turn while every contact marker slips) has a
 * wide one. The stick probability of a marker is in [0, 1]: how likely it
 * moves with the finger in this frame, 0 outside the tracked contact.
 *
 * A sensor has one event callback and one frame callback: setting the
 * uncertainty form replaces the plain one and the other way round.
 */
#ifndef ONETIP_C_UNCERTAINTY_H
#define ONETIP_C_UNCERTAINTY_H

#include "onetip_c.h"

#ifdef __cplusplus
extern "C" {
#endif

/** An event with the uncertainty of the 6-D input (minor version 2; as onetip::Event). */
typedef struct onetip_event_sd {
  onetip_event event;  /**< The event, exactly as onetip_sensor_poll_event gives it. */
  double sd[6];        /**< One standard deviation of dx, dy, dz (mm), yaw, pitch, roll (deg) of the measured input; 0 out of contact. */
} onetip_event_sd;

/** A frame result with the uncertainty of its measured 6-D input (minor version 2; as onetip::FrameResult). */
typedef struct onetip_frame_sd {
  onetip_frame frame;  /**< The frame, exactly as onetip_sensor_poll_frame gives it. */
  double sd[6];        /**< One standard deviation of each component of onetip_frame::raw: mm, mm, mm, deg, deg, deg; 0 out of contact. */
} onetip_frame_sd;

/** A marker with its stick probability (minor version 2; as onetip::MarkerState). */
typedef struct onetip_marker_sd {
  onetip_marker marker;      /**< The marker, exactly as onetip_sensor_poll_frame gives it. */
  double stick_probability;  /**< In [0, 1]: the marker moves with the finger (sticks) in this frame; 0 outside the tracked contact. */
} onetip_marker_sd;

/**
 * @brief Called with each event of a sensor and its uncertainty, on its processing thread (minor version 2).
 * @param event the event; valid only during the call (copy what you keep).
 * @param user the pointer given to onetip_sensor_set_event_sd_callback, untouched.
 */
typedef void (*onetip_event_sd_callback)(const onetip_event_sd* event, void* user);
/**
 * @brief Called with each processed frame after its events, on the sensor's processing thread (minor version 2).
 * @param frame the frame's result; valid only during the call.
 * @param markers marker_count markers indexed by id; valid only during the call.
 * @param marker_count rows * cols of the frame (0 when skipped or lost).
 * @param user the pointer given to onetip_sensor_set_frame_sd_callback, untouched.
 */
typedef void (*onetip_frame_sd_callback)(const onetip_frame_sd* frame, const onetip_marker_sd* markers,
                                         int32_t marker_count, void* user);

/**
 * @brief Takes the oldest queued event with its uncertainty, without blocking
 * (minor version 2; the queue of onetip_sensor_poll_event, which it shares).
 * @param sensor the handle.
 * @param out filled when an event was taken.
 * @param got receives 1 when an event was taken, else 0 (set to 0 first).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT (sensor, out, got); ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_poll_event_sd(onetip_sensor* sensor, onetip_event_sd* out, int32_t* got,
                                                 onetip_error* error);
/**
 * @brief Waits up to timeout_s seconds for an event with its uncertainty
 * (minor version 2; as onetip_sensor_wait_event).
 * @param sensor the handle.
 * @param timeout_s seconds; < 0, INFINITY or >= 1e9 mean no limit.
 * @param out filled when an event was taken.
 * @param got receives 1 when an event was taken, else 0 (set to 0 first).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK (also on time-out: *got = 0); ONETIP_ERROR_NULL_ARGUMENT
 *         (sensor, out, got); ONETIP_ERROR_INVALID_HANDLE; ONETIP_ERROR_INPUT
 *         when timeout_s is NaN; ONETIP_ERROR_STATE from inside this sensor's callback.
 */
ONETIP_C_API int32_t onetip_sensor_wait_event_sd(onetip_sensor* sensor, double timeout_s, onetip_event_sd* out,
                                                 int32_t* got, onetip_error* error);
/**
 * @brief Takes the oldest queued frame result with its uncertainty and the
 * markers' stick probabilities, without blocking (minor version 2; the queue
 * of onetip_sensor_poll_frame, which it shares).
 * @param sensor the handle.
 * @param out filled when a result was taken.
 * @param markers an array of `capacity` markers to fill, or NULL with capacity 0.
 * @param capacity the length of `markers`, >= 0; min(capacity, rows * cols)
 *        markers are copied, indexed by id.
 * @param marker_count receives rows * cols of the frame (also when capacity is
 *        smaller, so a caller can size its array); set to 0 first.
 * @param got receives 1 when a result was taken, else 0 (set to 0 first).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT (sensor, out, marker_count, got,
 *         or markers when capacity > 0); ONETIP_ERROR_INVALID_HANDLE;
 *         ONETIP_ERROR_INPUT when capacity is negative.
 */
ONETIP_C_API int32_t onetip_sensor_poll_frame_sd(onetip_sensor* sensor, onetip_frame_sd* out,
                                                 onetip_marker_sd* markers, int32_t capacity, int32_t* marker_count,
                                                 int32_t* got, onetip_error* error);
/**
 * @brief Sets the event callback in its uncertainty form (minor version 2),
 * replacing the previous event callback of either form; same rules as
 * onetip_sensor_set_event_callback.
 * @param sensor the handle.
 * @param callback called once per event on the processing thread; NULL removes it.
 * @param user passed back untouched to each call; must stay valid while the
 *        callback is set (the library never frees it).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT; ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_set_event_sd_callback(onetip_sensor* sensor, onetip_event_sd_callback callback,
                                                         void* user, onetip_error* error);
/**
 * @brief Sets the frame callback in its uncertainty form (minor version 2),
 * replacing the previous frame callback of either form; same rules as
 * onetip_sensor_set_frame_callback.
 * @param sensor the handle.
 * @param callback called once per processed frame, after that frame's event
 *        callbacks, on the processing thread; NULL removes it.
 * @param user passed back untouched to each call; must stay valid while the callback is set.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT; ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_set_frame_sd_callback(onetip_sensor* sensor, onetip_frame_sd_callback callback,
                                                         void* user, onetip_error* error);

#ifdef __cplusplus
}
#endif

#endif /* ONETIP_C_UNCERTAINTY_H */
