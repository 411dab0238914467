/**
 * @file onetip_c_sensor.h
 * @brief A sensor through the C ABI (included by onetip_c.h): the opaque
 * handle and its lifetime (create, destroy), the run (start, stop, wait for
 * the end), the callbacks, the poll and wait queues of events and frames,
 * rezero, rereference and the statistics.
 *
 * Handles, threads and what may be called inside a callback: onetip_c.h's
 * description.
 */
#ifndef ONETIP_C_SENSOR_H
#define ONETIP_C_SENSOR_H

#include "onetip_c_base.h"
#include "onetip_c_data.h"
#include "onetip_c_options.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A sensor: an opaque handle from onetip_sensor_create, released by onetip_sensor_destroy. */
typedef struct onetip_sensor onetip_sensor;

/**
 * @brief Called with each event of a sensor, on its processing thread.
 * @param event the event; valid only during the call (copy what you keep).
 * @param user the pointer given to onetip_sensor_set_event_callback, untouched.
 */
typedef void (*onetip_event_callback)(const onetip_event* event, void* user);
/**
 * @brief Called with each processed frame after its events, on the sensor's processing thread.
 * @param frame the frame's result; valid only during the call.
 * @param markers marker_count markers indexed by id; valid only during the call.
 * @param marker_count rows * cols of the frame (0 when skipped or lost).
 * @param user the pointer given to onetip_sensor_set_frame_callback, untouched.
 */
typedef void (*onetip_frame_callback)(const onetip_frame* frame, const onetip_marker* markers,
                                      int32_t marker_count, void* user);

/**
 * @brief Opens a sensor (as onetip::Sensor's constructor); does not start it.
 *
 * The strings and the options are copied; none is kept.
 * @param abi_version pass ONETIP_C_ABI_VERSION.
 * @param source "v4l2:/dev/videoN", a folder of images, a recorded session
 *        folder, a video file, or "sim:SCENARIO.yaml".
 * @param calibration the calibration file (docs/reference.md); NULL or "" for
 *        "sim:" sources uses the simulator's exact one (then pattern too).
 * @param pattern the pattern file; given together with calibration, or neither.
 * @param reference a rest-state image (no finger on the pad), or NULL/"" for
 *        the first good frame.
 * @param options NULL for the defaults; else checked as onetip_options_validate.
 * @param out receives the new handle, owned by the caller until
 *        onetip_sensor_destroy; set to NULL first (when out is not NULL), so it
 *        is NULL on failure.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_VERSION; ONETIP_ERROR_NULL_ARGUMENT (source,
 *         out); ONETIP_ERROR_INPUT naming the bad file, source or option.
 */
ONETIP_C_API int32_t onetip_sensor_create(uint32_t abi_version, const char* source, const char* calibration,
                                          const char* pattern, const char* reference,
                                          const onetip_options* options, onetip_sensor** out,
                                          onetip_error* error);
/**
 * @brief Stops the sensor (if running; as onetip_sensor_stop) and frees it; the
 * handle is invalid afterwards.
 * @param sensor the handle; NULL is a no-op returning ONETIP_OK.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_INVALID_HANDLE; ONETIP_ERROR_STATE from inside
 *         this sensor's callback, or from another sensor's callback while this
 *         sensor's callback is running (the sensor is then not destroyed).
 */
ONETIP_C_API int32_t onetip_sensor_destroy(onetip_sensor* sensor, onetip_error* error);

/**
 * @brief Starts the capture and processing threads; returns at once.
 * @param sensor the handle.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT; ONETIP_ERROR_INVALID_HANDLE;
 *         ONETIP_ERROR_STATE when started before (a sensor runs once, also
 *         after a stop) or called from inside this sensor's callback.
 */
ONETIP_C_API int32_t onetip_sensor_start(onetip_sensor* sensor, onetip_error* error);
/**
 * @brief Stops both threads and returns once the callbacks have finished.
 *
 * A source blocked in a read is abandoned after onetip_options::stop_timeout_ms.
 * Idempotent. Before start it ends a sensor that never ran: onetip_sensor_wait_finished
 * returns (finished 0) in every thread and onetip_sensor_start is then refused;
 * onetip_sensor_destroy does the same. Events and frames already queued stay pollable.
 * @param sensor the handle.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT; ONETIP_ERROR_INVALID_HANDLE;
 *         ONETIP_ERROR_STATE from inside this sensor's callback, or from another
 *         sensor's callback while this sensor's callback is running.
 */
ONETIP_C_API int32_t onetip_sensor_stop(onetip_sensor* sensor, onetip_error* error);
/**
 * @brief Whether the sensor is running: started and not yet stopped or finished.
 * @param sensor the handle.
 * @param out receives 1 or 0.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT (sensor, out); ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_is_running(onetip_sensor* sensor, int32_t* out, onetip_error* error);
/**
 * @brief Whether the source ended (or was given up after errors) and every frame was processed.
 * @param sensor the handle.
 * @param out receives 1 or 0 (0 when a stop ended the run early).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT (sensor, out); ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_is_finished(onetip_sensor* sensor, int32_t* out, onetip_error* error);
/**
 * @brief Waits up to timeout_s seconds for the end of the run (the source
 * finished, or a stop).
 * @param sensor the handle.
 * @param timeout_s seconds; < 0, INFINITY or >= 1e9 mean no limit (the same
 *        limits hold for onetip_sensor_wait_event). On a sensor not started it
 *        waits for another thread to start it and the run to end, or to stop or
 *        destroy it.
 * @param finished receives 1 when the source finished, else 0 (set to 0 first).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT (sensor, finished);
 *         ONETIP_ERROR_INVALID_HANDLE; ONETIP_ERROR_INPUT when timeout_s is NaN;
 *         ONETIP_ERROR_STATE from inside this sensor's callback.
 */
ONETIP_C_API int32_t onetip_sensor_wait_finished(onetip_sensor* sensor, double timeout_s, int32_t* finished,
                                                 onetip_error* error);

/**
 * @brief Sets the event callback, replacing the previous one.
 *
 * Called from another thread this waits for a callback call in progress, so
 * the old callback is never called after it returns; from inside a callback
 * the new one takes effect from the next frame.
 * @param sensor the handle.
 * @param callback called once per event on the processing thread; NULL removes it.
 * @param user passed back untouched to each call; must stay valid while the
 *        callback is set (the library never frees it).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT; ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_set_event_callback(onetip_sensor* sensor, onetip_event_callback callback,
                                                      void* user, onetip_error* error);
/**
 * @brief Sets the frame callback, replacing the previous one; same rules as
 * onetip_sensor_set_event_callback.
 * @param sensor the handle.
 * @param callback called once per processed frame, after that frame's event
 *        callbacks, on the processing thread; NULL removes it.
 * @param user passed back untouched to each call; must stay valid while the callback is set.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT; ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_set_frame_callback(onetip_sensor* sensor, onetip_frame_callback callback,
                                                      void* user, onetip_error* error);

/**
 * @brief Takes the oldest queued event, without blocking.
 *
 * The poll queue holds up to onetip_options::event_queue_capacity events
 * (0: no queue), every event after the callbacks ran; when full the oldest is
 * dropped (onetip_stats::events_dropped).
 * @param sensor the handle.
 * @param out filled when an event was taken.
 * @param got receives 1 when an event was taken, else 0 (set to 0 first).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT (sensor, out, got); ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_poll_event(onetip_sensor* sensor, onetip_event* out, int32_t* got,
                                              onetip_error* error);
/**
 * @brief Waits up to timeout_s seconds for an event (see onetip_sensor_poll_event).
 *
 * Does not block before start, nor once the sensor finished or stopped and the queue is empty.
 * @param sensor the handle.
 * @param timeout_s seconds; < 0, INFINITY or >= 1e9 mean no limit.
 * @param out filled when an event was taken.
 * @param got receives 1 when an event was taken, else 0 (set to 0 first).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK (also on time-out: *got = 0); ONETIP_ERROR_NULL_ARGUMENT
 *         (sensor, out, got); ONETIP_ERROR_INVALID_HANDLE; ONETIP_ERROR_INPUT
 *         when timeout_s is NaN; ONETIP_ERROR_STATE from inside this sensor's callback.
 */
ONETIP_C_API int32_t onetip_sensor_wait_event(onetip_sensor* sensor, double timeout_s, onetip_event* out,
                                              int32_t* got, onetip_error* error);
/**
 * @brief Takes the oldest queued frame result, without blocking.
 *
 * The queue holds up to onetip_options::frame_queue_capacity results (0: no
 * queue), the oldest dropped when full.
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
ONETIP_C_API int32_t onetip_sensor_poll_frame(onetip_sensor* sensor, onetip_frame* out, onetip_marker* markers,
                                              int32_t capacity, int32_t* marker_count, int32_t* got,
                                              onetip_error* error);

/**
 * @brief Re-zero: the 6-D input restarts from zero at the next processed frame
 * (as if a new contact began there). Allowed inside callbacks.
 * @param sensor the handle.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT; ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_rezero(onetip_sensor* sensor, onetip_error* error);
/**
 * @brief Re-reference: the next good frame becomes the new rest state (the
 * finger must be off the pad) and the sensor frame S is re-derived from it; a
 * frame that cannot gives an error event and the next is tried. Allowed inside callbacks.
 * @param sensor the handle.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT; ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_rereference(onetip_sensor* sensor, onetip_error* error);
/**
 * @brief A snapshot of the sensor's counters and per-stage timing.
 * @param sensor the handle.
 * @param out receives the statistics.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_NULL_ARGUMENT (sensor, out); ONETIP_ERROR_INVALID_HANDLE.
 */
ONETIP_C_API int32_t onetip_sensor_get_stats(onetip_sensor* sensor, onetip_stats* out, onetip_error* error);

#ifdef __cplusplus
}
#endif

#endif /* ONETIP_C_SENSOR_H */
