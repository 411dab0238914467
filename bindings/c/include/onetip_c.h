/* onetip_c.h — the C ABI of the onetip SDK (in libonetip.so), for C, C#/Unity
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
 *  - Version handshake: the entry points (onetip_sensor_create, the
 *    onetip_options_* functions and onetip_option_describe) take the ABI
 *    version the caller was compiled against; pass ONETIP_C_ABI_VERSION. A
 *    different version fails with ONETIP_ERROR_VERSION and a message giving
 *    both versions. Additions that keep the ABI compatible raise
 *    ONETIP_C_ABI_MINOR_VERSION instead: a caller that uses functions of minor
 *    version m needs onetip_abi_minor_version() >= m.
 *  - Handles are opaque; each create has its destroy. A NULL handle gives
 *    ONETIP_ERROR_NULL_ARGUMENT, a destroyed (or foreign) one
 *    ONETIP_ERROR_INVALID_HANDLE — detected from a registry of live handles,
 *    the pointer is never dereferenced. (If the allocator reuses the address
 *    for a new sensor, a stale handle names that one: don't keep them.)
 *    onetip_sensor_destroy(NULL) is a no-op returning ONETIP_OK.
 *  - Structs are flat and fixed-size (no pointers, no unions); strings are
 *    NUL-terminated and truncated to fit; enums travel as int32_t.
 *
 * Threads: every function may be called from any thread. Callbacks run on the
 * sensor's processing thread, one at a time, in frame order; inside one you may
 * poll, read stats, rezero and rereference, but onetip_sensor_start/stop/destroy
 * and onetip_sensor_wait_finished/wait_event of the same sensor fail with
 * ONETIP_ERROR_STATE there (they would wait for themselves), and so do
 * stop/destroy of another sensor while that sensor's own callback is running
 * (two callbacks stopping each other would wait forever). The event and frame
 * pointers given to a callback are valid only during the call. Replacing a
 * callback (or setting NULL) waits for a call in progress to finish, so once
 * onetip_sensor_set_*_callback returns the old callback is never called again.
 */
#ifndef ONETIP_C_H
#define ONETIP_C_H

#include <stdint.h>

#if defined(_WIN32) && defined(ONETIP_C_BUILDING)
#define ONETIP_C_API __declspec(dllexport)
#elif defined(_WIN32)
#define ONETIP_C_API __declspec(dllimport)
#else
#define ONETIP_C_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The ABI this header describes; bumped on any incompatible change. */
#define ONETIP_C_ABI_VERSION 1u
/* Compatible additions to version 1: 1 = the option table (onetip_option_count,
 * onetip_option_describe) and keyed option access (onetip_options_get/_set/_validate). */
#define ONETIP_C_ABI_MINOR_VERSION 1u

typedef enum onetip_error_kind {
  ONETIP_OK = 0,
  ONETIP_ERROR_NULL_ARGUMENT = 1,   /* a required pointer (handle, string, out-parameter) was NULL */
  ONETIP_ERROR_INVALID_HANDLE = 2,  /* the handle was destroyed or never created by this library */
  ONETIP_ERROR_VERSION = 3,         /* the caller's ONETIP_C_ABI_VERSION differs from the library's */
  ONETIP_ERROR_INPUT = 4,           /* bad input: missing/malformed file, bad source, invalid option */
  ONETIP_ERROR_STATE = 5,           /* not valid now (start twice, stop from inside a callback, ...) */
  ONETIP_ERROR_INTERNAL = 6         /* unexpected failure inside the library (a bug) */
} onetip_error_kind;

#define ONETIP_ERROR_MESSAGE_SIZE 256
typedef struct onetip_error {
  int32_t kind;                               /* onetip_error_kind */
  char message[ONETIP_ERROR_MESSAGE_SIZE];    /* one line; "" when kind == ONETIP_OK */
} onetip_error;

typedef enum onetip_event_type {
  ONETIP_EVENT_CONTACT_BEGIN = 0,  /* a contact starts; the 6-D input restarts from zero */
  ONETIP_EVENT_CONTACT_END = 1,    /* the contact ended; the 6-D input is zero again */
  ONETIP_EVENT_INPUT = 2,          /* the 6-D input of a frame in contact (every such frame) */
  ONETIP_EVENT_PRESS = 3,          /* the press button went down */
  ONETIP_EVENT_RELEASE = 4,        /* the press button went up */
  ONETIP_EVENT_STATE_CHANGED = 5,  /* the contact state changed (see `state`) */
  ONETIP_EVENT_ERROR = 6           /* see `message` */
} onetip_event_type;

typedef enum onetip_contact_state {
  ONETIP_STATE_NONE = 0,
  ONETIP_STATE_STICK = 1,
  ONETIP_STATE_PARTIAL_SLIP = 2,
  ONETIP_STATE_SLIP = 3
} onetip_contact_state;

typedef enum onetip_frame_status {
  ONETIP_FRAME_OK = 0,
  ONETIP_FRAME_REFERENCE = 1,  /* this frame became the rest state */
  ONETIP_FRAME_SKIPPED = 2,    /* unusable frame: see message */
  ONETIP_FRAME_LOST = 3        /* too few markers: see message */
} onetip_frame_status;

typedef enum onetip_filter_kind {
  ONETIP_FILTER_NONE = 0,
  ONETIP_FILTER_MOVING_AVERAGE = 1,
  ONETIP_FILTER_ONE_EURO = 2
} onetip_filter_kind;

#define ONETIP_EVENT_MESSAGE_SIZE 160
typedef struct onetip_event {       /* 240 bytes */
  int32_t type;                     /* onetip_event_type */
  int32_t state;                    /* onetip_contact_state */
  int64_t frame;                    /* source frame index, -1 when not tied to a frame */
  double t;                         /* that frame's timestamp, s */
  double arrival_s;                 /* when the frame arrived from the source, onetip_clock_seconds() */
  double input[6];                  /* dx, dy, dz (mm), yaw, pitch, roll (deg); filtered and shaped */
  char message[ONETIP_EVENT_MESSAGE_SIZE];  /* error events */
} onetip_event;

/* Stage order of onetip_frame.times_ms. */
enum { ONETIP_STAGE_CAPTURE = 0, ONETIP_STAGE_QUEUE, ONETIP_STAGE_DETECT, ONETIP_STAGE_TRACK,
       ONETIP_STAGE_TRIANGULATE, ONETIP_STAGE_CONTACT, ONETIP_STAGE_POSE, ONETIP_STAGE_PROCESS,
       ONETIP_FRAME_STAGES };

typedef struct onetip_frame {
  int64_t frame;                    /* source frame index */
  double t;                         /* timestamp, s */
  double arrival_s;                 /* onetip_clock_seconds() at arrival */
  int32_t status;                   /* onetip_frame_status */
  int32_t contact;                  /* 0/1 */
  int32_t state;                    /* onetip_contact_state */
  int32_t pressed;                  /* the press button, 0/1 */
  int32_t out_of_range;             /* raw beyond the working range, 0/1 */
  int32_t rows, cols;               /* marker grid; rows * cols markers */
  int32_t contact_regions;
  double max_normal_mm;             /* deepest normal deformation, mm */
  double raw[6];                    /* measured 6-D input (pose.csv), mm / deg */
  double input[6];                  /* filtered and shaped, as in events */
  double times_ms[ONETIP_FRAME_STAGES];
  char message[ONETIP_EVENT_MESSAGE_SIZE];  /* why, when skipped or lost */
} onetip_frame;

typedef struct onetip_marker {      /* one per marker id = row * cols + col */
  int32_t id;
  int32_t valid;                    /* triangulated this frame */
  int32_t displaced;                /* displacement known (valid now and at rest) */
  int32_t region;                   /* contact region (0 = largest), -1 outside */
  double position[3];               /* S, mm */
  double displacement[3];           /* from rest, S, mm */
} onetip_marker;

/* Options: one field per row of the option table (onetip/sensor_option_table.hpp
 * has each one's meaning, range and unit; onetip_option_describe gives the same
 * at run time), named as its key. */
typedef struct onetip_options {
  int32_t queue_capacity;
  int32_t lossless;                 /* 0: latest frame wins (drops counted); 1: capture waits */
  int32_t event_queue_capacity;
  int32_t frame_queue_capacity;
  int32_t timing_window;
  int32_t max_consecutive_source_errors;
  int32_t stop_timeout_ms;
  int32_t min_markers;
  int32_t filter;                   /* onetip_filter_kind */
  int32_t filter_window;
  double playback_rate;
  double working_range[6];          /* dx, dy, dz (mm), yaw, pitch, roll (deg) */
  double clamp_factor;
  double press_mm;
  double release_mm;
  double gain[6];
  double dead_zone[6];
  double filter_min_cutoff_hz;
  double filter_beta;
  double filter_derivative_cutoff_hz;
} onetip_options;

typedef enum onetip_option_type {
  ONETIP_OPTION_INTEGER = 0,  /* an int32_t field */
  ONETIP_OPTION_REAL = 1,     /* a double */
  ONETIP_OPTION_FLAG = 2,     /* an int32_t, 0 or 1 */
  ONETIP_OPTION_CHOICE = 3,   /* an int32_t enum: value k is the k-th name of `choices` */
  ONETIP_OPTION_AXES = 4      /* double[6]: dx, dy, dz, yaw, pitch, roll */
} onetip_option_type;

#define ONETIP_OPTION_NAME_SIZE 48
#define ONETIP_OPTION_UNIT_SIZE 16
#define ONETIP_OPTION_CHOICES_SIZE 96
#define ONETIP_OPTION_DOC_SIZE 128
/* One row of the option table. */
typedef struct onetip_option_info {
  char name[ONETIP_OPTION_NAME_SIZE];  /* the key: onetip_options field, file key */
  int32_t type;                        /* onetip_option_type */
  int32_t count;                       /* values: 1, or 6 for ONETIP_OPTION_AXES */
  double min, max;                     /* closed range of every value */
  double default_value[6];             /* the first `count` are used */
  char unit[ONETIP_OPTION_UNIT_SIZE];  /* "" when none; "mm|deg": mm for dx, dy, dz, deg for yaw, pitch, roll */
  char choices[ONETIP_OPTION_CHOICES_SIZE];  /* CHOICE: the names in value order, separated by spaces */
  char doc[ONETIP_OPTION_DOC_SIZE];    /* one line */
} onetip_option_info;

#define ONETIP_STAGE_NAME_SIZE 16
#define ONETIP_MAX_STAGES 16
typedef struct onetip_stage_timing {
  char stage[ONETIP_STAGE_NAME_SIZE];  /* "capture", "queue", "detect", ..., "process", "delivery" */
  int64_t count;
  double median_ms, p99_ms, max_ms;
} onetip_stage_timing;

typedef struct onetip_stats {
  int64_t frames_captured, frames_processed, frames_dropped, frames_skipped, frames_lost, source_errors;
  int64_t events_emitted, events_dropped, frame_results_dropped, callback_errors;
  int32_t source_abandoned;
  int32_t stage_count;
  onetip_stage_timing stages[ONETIP_MAX_STAGES];
} onetip_stats;

typedef struct onetip_sensor onetip_sensor;

typedef void (*onetip_event_callback)(const onetip_event* event, void* user);
typedef void (*onetip_frame_callback)(const onetip_frame* frame, const onetip_marker* markers,
                                      int32_t marker_count, void* user);

/* The library's ABI version (compare with ONETIP_C_ABI_VERSION), its minor version
 * (>= ONETIP_C_ABI_MINOR_VERSION for every function of this header) and "MAJOR.MINOR.PATCH". */
ONETIP_C_API uint32_t onetip_abi_version(void);
ONETIP_C_API uint32_t onetip_abi_minor_version(void);
ONETIP_C_API const char* onetip_version_string(void);
/* Seconds on the steady clock of onetip_event.arrival_s. */
ONETIP_C_API double onetip_clock_seconds(void);
/* A short static name for a kind, event type or contact state ("input", "stick", ...); "unknown" if out of range. */
ONETIP_C_API const char* onetip_error_kind_name(int32_t kind);
ONETIP_C_API const char* onetip_event_type_name(int32_t type);
ONETIP_C_API const char* onetip_contact_state_name(int32_t state);

ONETIP_C_API int32_t onetip_options_default(uint32_t abi_version, onetip_options* out, onetip_error* error);
ONETIP_C_API int32_t onetip_options_load(uint32_t abi_version, const char* path, onetip_options* out,
                                         onetip_error* error);
ONETIP_C_API int32_t onetip_options_save(uint32_t abi_version, const onetip_options* options, const char* path,
                                         onetip_error* error);
/* Every value in its range and the relations between options hold (release_mm < press_mm);
 * ONETIP_ERROR_INPUT naming the first bad field otherwise ("options.queue_capacity: must be in [1, 64] frames, got 0"). */
ONETIP_C_API int32_t onetip_options_validate(uint32_t abi_version, const onetip_options* options, onetip_error* error);

/* The option table (minor version 1): rows 0..onetip_option_count() - 1, in the order of the options file. */
ONETIP_C_API int32_t onetip_option_count(void);
ONETIP_C_API int32_t onetip_option_describe(uint32_t abi_version, int32_t row, onetip_option_info* out,
                                            onetip_error* error);
/* Keyed access to value `index` (0, or 0..5 for axes) of the option `name`, as a double (exact for
 * integers, flags and choices). set checks the value against the table (range; whole numbers for
 * integers, flags and choices) and changes nothing when it fails with ONETIP_ERROR_INPUT; so does an
 * unknown name or index, or a struct whose lossless is not 0/1 or whose filter is not a filter kind. */
ONETIP_C_API int32_t onetip_options_get(uint32_t abi_version, const onetip_options* options, const char* name,
                                        int32_t index, double* out, onetip_error* error);
ONETIP_C_API int32_t onetip_options_set(uint32_t abi_version, onetip_options* options, const char* name,
                                        int32_t index, double value, onetip_error* error);

/* Opens `source` ("v4l2:/dev/videoN", a folder, a video file or "sim:SCENARIO.yaml").
 * calibration / pattern: files (docs/reference.md); NULL or "" for "sim:" sources uses
 * the simulator's exact ones. reference: rest-state image or NULL/"" (first frame).
 * options: NULL for the defaults. Does not start. */
ONETIP_C_API int32_t onetip_sensor_create(uint32_t abi_version, const char* source, const char* calibration,
                                          const char* pattern, const char* reference,
                                          const onetip_options* options, onetip_sensor** out,
                                          onetip_error* error);
/* Stops (if running) and frees; the handle is invalid afterwards. */
ONETIP_C_API int32_t onetip_sensor_destroy(onetip_sensor* sensor, onetip_error* error);

ONETIP_C_API int32_t onetip_sensor_start(onetip_sensor* sensor, onetip_error* error);
ONETIP_C_API int32_t onetip_sensor_stop(onetip_sensor* sensor, onetip_error* error);
/* *out = 1 while running / once the source ended and every frame was processed. */
ONETIP_C_API int32_t onetip_sensor_is_running(onetip_sensor* sensor, int32_t* out, onetip_error* error);
ONETIP_C_API int32_t onetip_sensor_is_finished(onetip_sensor* sensor, int32_t* out, onetip_error* error);
/* Waits up to timeout_s for the end; *finished = 1 if it ended. Time-outs here and in
 * onetip_sensor_wait_event: < 0, INFINITY or >= 1e9 s mean no limit; NaN is ONETIP_ERROR_INPUT. */
ONETIP_C_API int32_t onetip_sensor_wait_finished(onetip_sensor* sensor, double timeout_s, int32_t* finished,
                                                 onetip_error* error);

/* callback NULL removes it; `user` is passed back untouched. */
ONETIP_C_API int32_t onetip_sensor_set_event_callback(onetip_sensor* sensor, onetip_event_callback callback,
                                                      void* user, onetip_error* error);
ONETIP_C_API int32_t onetip_sensor_set_frame_callback(onetip_sensor* sensor, onetip_frame_callback callback,
                                                      void* user, onetip_error* error);

/* Non-blocking: *got = 1 and *out filled when an event was queued, else *got = 0. */
ONETIP_C_API int32_t onetip_sensor_poll_event(onetip_sensor* sensor, onetip_event* out, int32_t* got,
                                              onetip_error* error);
/* Blocks up to timeout_s seconds (see wait_finished for the limits; does not block once the sensor
 * finished or stopped and the queue is empty). */
ONETIP_C_API int32_t onetip_sensor_wait_event(onetip_sensor* sensor, double timeout_s, onetip_event* out,
                                              int32_t* got, onetip_error* error);
/* Non-blocking per-frame result. markers may be NULL (capacity 0): then only *marker_count
 * (rows * cols) is set; otherwise min(capacity, rows * cols) markers are copied. */
ONETIP_C_API int32_t onetip_sensor_poll_frame(onetip_sensor* sensor, onetip_frame* out, onetip_marker* markers,
                                              int32_t capacity, int32_t* marker_count, int32_t* got,
                                              onetip_error* error);

ONETIP_C_API int32_t onetip_sensor_rezero(onetip_sensor* sensor, onetip_error* error);
ONETIP_C_API int32_t onetip_sensor_rereference(onetip_sensor* sensor, onetip_error* error);
ONETIP_C_API int32_t onetip_sensor_get_stats(onetip_sensor* sensor, onetip_stats* out, onetip_error* error);

#ifdef __cplusplus
}
#endif

#endif /* ONETIP_C_H */
