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
 */
#ifndef ONETIP_C_H
#define ONETIP_C_H

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

/** The ABI this header describes; bumped on any incompatible change. */
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

/** The kind of an onetip_event (as onetip::EventType). */
typedef enum onetip_event_type {
  ONETIP_EVENT_CONTACT_BEGIN = 0,  /**< A contact starts; the 6-D input restarts from zero. */
  ONETIP_EVENT_CONTACT_END = 1,    /**< The contact ended; the 6-D input is zero again. */
  ONETIP_EVENT_INPUT = 2,          /**< The 6-D input of a frame in contact (one per such frame). */
  ONETIP_EVENT_PRESS = 3,          /**< The press button went down (dz rose above onetip_options::press_mm). */
  ONETIP_EVENT_RELEASE = 4,        /**< The press button went up (dz fell below onetip_options::release_mm). */
  ONETIP_EVENT_STATE_CHANGED = 5,  /**< The contact state changed (see onetip_event::state). */
  ONETIP_EVENT_ERROR = 6           /**< Something the caller should know (source error, unusable frame, too few markers, a callback that threw): see onetip_event::message. */
} onetip_event_type;

/** The contact state of a frame (as onetip::ContactState). */
typedef enum onetip_contact_state {
  ONETIP_STATE_NONE = 0,          /**< No contact. */
  ONETIP_STATE_STICK = 1,         /**< In contact; no contact marker slips. */
  ONETIP_STATE_PARTIAL_SLIP = 2,  /**< In contact; some contact markers slip while others stick. */
  ONETIP_STATE_SLIP = 3           /**< In contact; the whole contact slips. */
} onetip_contact_state;

/** What became of one frame (as onetip::FrameStatus). */
typedef enum onetip_frame_status {
  ONETIP_FRAME_OK = 0,         /**< Processed. */
  ONETIP_FRAME_REFERENCE = 1,  /**< This frame became the rest state. */
  ONETIP_FRAME_SKIPPED = 2,    /**< Unusable frame: see message. */
  ONETIP_FRAME_LOST = 3        /**< Too few markers: see message; no pose update. */
} onetip_frame_status;

/** The smoothing of the 6-D input (onetip_options::filter; as onetip::FilterKind). */
typedef enum onetip_filter_kind {
  ONETIP_FILTER_NONE = 0,            /**< No smoothing. */
  ONETIP_FILTER_MOVING_AVERAGE = 1,  /**< Mean of the last onetip_options::filter_window frames. */
  ONETIP_FILTER_ONE_EURO = 2         /**< The 1-euro filter (Casiez et al. 2012). */
} onetip_filter_kind;

/** Size of the message of onetip_event and onetip_frame, including the terminating NUL. */
#define ONETIP_EVENT_MESSAGE_SIZE 160
/** One event of a running sensor (as onetip::Event). */
typedef struct onetip_event {       /* 240 bytes */
  int32_t type;                     /**< An onetip_event_type. */
  int32_t state;                    /**< An onetip_contact_state: the contact state at this event. */
  int64_t frame;                    /**< Source frame index, -1 when not tied to a frame (a device-level source error). */
  double t;                         /**< That frame's timestamp from its source, s. */
  double arrival_s;                 /**< When the frame arrived from the source, s, on onetip_clock_seconds(). */
  double input[6];                  /**< dx, dy, dz (mm), yaw, pitch, roll (deg), filtered and shaped; zero out of contact. */
  char message[ONETIP_EVENT_MESSAGE_SIZE];  /**< Error events: one line saying what happened; "" otherwise. */
} onetip_event;

/** Stage order of onetip_frame::times_ms (as onetip::StageTimes). */
enum { ONETIP_STAGE_CAPTURE = 0, ONETIP_STAGE_QUEUE, ONETIP_STAGE_DETECT, ONETIP_STAGE_TRACK,
       ONETIP_STAGE_TRIANGULATE, ONETIP_STAGE_CONTACT, ONETIP_STAGE_POSE, ONETIP_STAGE_PROCESS,
       ONETIP_FRAME_STAGES };
/** @var ONETIP_STAGE_CAPTURE
 *  @brief The source's read of the frame (grab and decode).
 *  @var ONETIP_STAGE_QUEUE
 *  @brief Waiting between capture and processing.
 *  @var ONETIP_STAGE_DETECT
 *  @brief Finding the markers in both views.
 *  @var ONETIP_STAGE_TRACK
 *  @brief Tracking the markers from the previous frame.
 *  @var ONETIP_STAGE_TRIANGULATE
 *  @brief Stereo triangulation of the markers.
 *  @var ONETIP_STAGE_CONTACT
 *  @brief Contact analysis.
 *  @var ONETIP_STAGE_POSE
 *  @brief The 6-D pose and its events.
 *  @var ONETIP_STAGE_PROCESS
 *  @brief All of processing, detect to pose and events.
 *  @var ONETIP_FRAME_STAGES
 *  @brief The number of stages in onetip_frame::times_ms.
 */

/** Everything the pipeline knows about one processed frame, but its markers (as onetip::FrameResult; markers: onetip_marker). */
typedef struct onetip_frame {
  int64_t frame;                    /**< Source frame index. */
  double t;                         /**< The frame's timestamp from its source, s. */
  double arrival_s;                 /**< onetip_clock_seconds() at the frame's arrival, s. */
  int32_t status;                   /**< An onetip_frame_status. */
  int32_t contact;                  /**< 1 when a finger touches the pad, else 0. */
  int32_t state;                    /**< An onetip_contact_state; ONETIP_STATE_NONE out of contact. */
  int32_t pressed;                  /**< The press button, 0/1. */
  int32_t out_of_range;             /**< 1 when raw exceeded the working range (raw is then clamped to clamp_factor times it), else 0. */
  int32_t rows, cols;
  /** @var rows
   *  @brief Rows of the marker grid (0 when skipped or lost); rows * cols markers.
   *  @var cols
   *  @brief Columns of the marker grid (0 when skipped or lost).
   */
  int32_t contact_regions;          /**< Separate contact regions (fingers). */
  double max_normal_mm;             /**< Deepest normal deformation of the pad, mm. */
  double raw[6];                    /**< Measured 6-D input (pose.csv): dx, dy, dz (mm), yaw, pitch, roll (deg). */
  double input[6];                  /**< raw filtered and shaped (gain, dead zone), as in events; mm and deg. */
  double times_ms[ONETIP_FRAME_STAGES];  /**< Time per stage, ms, indexed by ONETIP_STAGE_CAPTURE .. ONETIP_STAGE_PROCESS. */
  char message[ONETIP_EVENT_MESSAGE_SIZE];  /**< Why, when skipped or lost; "" otherwise. */
} onetip_frame;

/** One marker of the grid in one frame (as onetip::MarkerState). */
typedef struct onetip_marker {      /* one per marker id = row * cols + col */
  int32_t id;                       /**< Marker id = row * cols + col (also its index in the array). */
  int32_t valid;                    /**< 1 when triangulated this frame (position is meaningful), else 0. */
  int32_t displaced;                /**< 1 when the displacement is known (valid now and at rest), else 0. */
  int32_t region;                   /**< Contact region (0 = largest) it belongs to; -1 outside every region. */
  double position[3];               /**< Position x, y, z in S, mm (when valid). */
  double displacement[3];           /**< Displacement from rest along S.x, S.y, S.z, mm (when displaced); -displacement[2] is the press depth here. */
} onetip_marker;

/** The options of a sensor: one field per row of the option table, named as its key.
 * Each one's meaning, range, unit and default are documented at the field of
 * the same name of onetip::SensorOptions (onetip/sensor_option_table.hpp), and
 * onetip_option_describe gives them at run time. Fill it with
 * onetip_options_default() or onetip_options_load(); onetip_options_validate()
 * checks it. */
typedef struct onetip_options {
  int32_t queue_capacity;           /**< Frames waiting between the capture and the processing thread (onetip::SensorOptions::queue_capacity). */
  int32_t lossless;                 /**< 0: latest frame wins (drops counted); 1: capture waits (onetip::SensorOptions::lossless). */
  int32_t event_queue_capacity;     /**< Events in the poll queue, 0: off (onetip::SensorOptions::event_queue_capacity). */
  int32_t frame_queue_capacity;     /**< Frame results in the poll queue, 0: off (onetip::SensorOptions::frame_queue_capacity). */
  int32_t timing_window;            /**< Frames in the per-stage timing statistics (onetip::SensorOptions::timing_window). */
  int32_t max_consecutive_source_errors;  /**< Source errors in a row after which the source is given up (onetip::SensorOptions::max_consecutive_source_errors). */
  int32_t stop_timeout_ms;          /**< How long stop waits for a source blocked in a read, ms (onetip::SensorOptions::stop_timeout_ms). */
  int32_t min_markers;              /**< Fewer triangulated markers: the frame is lost (onetip::SensorOptions::min_markers). */
  int32_t filter;                   /**< An onetip_filter_kind (onetip::SensorOptions::filter). */
  int32_t filter_window;            /**< Moving average: frames averaged (onetip::SensorOptions::filter_window). */
  double playback_rate;             /**< File and sim: sources: 0 as fast as they decode, 1 real time (onetip::SensorOptions::playback_rate). */
  double working_range[6];          /**< dx, dy, dz (mm), yaw, pitch, roll (deg); beyond it a frame is out of range (onetip::SensorOptions::working_range). */
  double clamp_factor;              /**< raw is clamped to this many working ranges (onetip::SensorOptions::clamp_factor). */
  double press_mm;                  /**< The press button goes down when dz exceeds this, mm (onetip::SensorOptions::press_mm). */
  double release_mm;                /**< The press button goes up when dz falls below this, mm; below press_mm (onetip::SensorOptions::release_mm). */
  double gain[6];                   /**< Per axis dx..roll, input = gain * sign(x) * max(0, |x| - dead_zone) (onetip::SensorOptions::gain). */
  double dead_zone[6];              /**< Per axis: dx, dy, dz (mm), yaw, pitch, roll (deg); magnitudes below it give 0 (onetip::SensorOptions::dead_zone). */
  double filter_min_cutoff_hz;      /**< One-euro filter: cutoff at rest, Hz (onetip::SensorOptions::filter_min_cutoff_hz). */
  double filter_beta;               /**< One-euro filter: cutoff increase per unit of speed (onetip::SensorOptions::filter_beta). */
  double filter_derivative_cutoff_hz;  /**< One-euro filter: cutoff of the speed estimate, Hz (onetip::SensorOptions::filter_derivative_cutoff_hz). */
} onetip_options;

/** How an option's value is carried (onetip_option_info::type; as onetip::OptionType). */
typedef enum onetip_option_type {
  ONETIP_OPTION_INTEGER = 0,  /**< An int32_t field. */
  ONETIP_OPTION_REAL = 1,     /**< A double. */
  ONETIP_OPTION_FLAG = 2,     /**< An int32_t, 0 or 1. */
  ONETIP_OPTION_CHOICE = 3,   /**< An int32_t enum: value k is the k-th name of `choices`. */
  ONETIP_OPTION_AXES = 4      /**< double[6]: dx, dy, dz, yaw, pitch, roll. */
} onetip_option_type;

/** Size of onetip_option_info::name, including the NUL. */
#define ONETIP_OPTION_NAME_SIZE 48
/** Size of onetip_option_info::unit, including the NUL. */
#define ONETIP_OPTION_UNIT_SIZE 16
/** Size of onetip_option_info::choices, including the NUL. */
#define ONETIP_OPTION_CHOICES_SIZE 96
/** Size of onetip_option_info::doc, including the NUL. */
#define ONETIP_OPTION_DOC_SIZE 128
/** One row of the option table (onetip_option_describe). */
typedef struct onetip_option_info {
  char name[ONETIP_OPTION_NAME_SIZE];  /**< The key: onetip_options field, options file key. */
  int32_t type;                        /**< An onetip_option_type. */
  int32_t count;                       /**< Number of values: 1, or 6 for ONETIP_OPTION_AXES. */
  double min, max;
  /** @var min
   *  @brief Lower end of the closed range of every value, in the option's unit.
   *  @var max
   *  @brief Upper end of the closed range of every value, in the option's unit.
   */
  double default_value[6];             /**< The default; the first `count` are used. */
  char unit[ONETIP_OPTION_UNIT_SIZE];  /**< "" when none; "mm|deg": mm for dx, dy, dz, deg for yaw, pitch, roll. */
  char choices[ONETIP_OPTION_CHOICES_SIZE];  /**< ONETIP_OPTION_CHOICE: the names in value order, separated by spaces; else "". */
  char doc[ONETIP_OPTION_DOC_SIZE];    /**< One line. */
} onetip_option_info;

/** Size of onetip_stage_timing::stage, including the NUL. */
#define ONETIP_STAGE_NAME_SIZE 16
/** Capacity of onetip_stats::stages. */
#define ONETIP_MAX_STAGES 16
/** Timing of one stage over the last onetip_options::timing_window frames (as onetip::TimingSummary). */
typedef struct onetip_stage_timing {
  char stage[ONETIP_STAGE_NAME_SIZE];  /**< "capture", "queue", "detect", ..., "process", "delivery" (frame arrival to the end of its callbacks). */
  int64_t count;                       /**< Samples in the window. */
  double median_ms, p99_ms, max_ms;
  /** @var median_ms
   *  @brief Median of the window, ms.
   *  @var p99_ms
   *  @brief 99th percentile of the window (nearest rank), ms.
   *  @var max_ms
   *  @brief Largest sample of the window, ms.
   */
} onetip_stage_timing;

/** Counters of a sensor since it was created (as onetip::SensorStats). */
typedef struct onetip_stats {
  int64_t frames_captured, frames_processed, frames_dropped, frames_skipped, frames_lost, source_errors;
  /** @var frames_captured
   *  @brief Good frames from the source.
   *  @var frames_processed
   *  @brief Frames through the processor (any status).
   *  @var frames_dropped
   *  @brief Stale frames dropped by the latest-frame-wins queue.
   *  @var frames_skipped
   *  @brief Unusable frames (from the source or the processor).
   *  @var frames_lost
   *  @brief Frames with too few markers.
   *  @var source_errors
   *  @brief Device-level errors of the source.
   */
  int64_t events_emitted, events_dropped, frame_results_dropped, callback_errors;
  /** @var events_emitted
   *  @brief Events produced (to callbacks and the poll queue).
   *  @var events_dropped
   *  @brief Events dropped from a full poll queue.
   *  @var frame_results_dropped
   *  @brief Frame results dropped from a full poll queue.
   *  @var callback_errors
   *  @brief Callbacks that threw.
   */
  int32_t source_abandoned;         /**< 1 when stop gave up waiting for a blocked source read, else 0. */
  int32_t stage_count;              /**< Entries used in `stages` (at most ONETIP_MAX_STAGES). */
  onetip_stage_timing stages[ONETIP_MAX_STAGES];  /**< Per-stage timing: capture, queue, detect, track, triangulate, contact, pose, process, delivery. */
} onetip_stats;

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

/** @return the library's ABI version; compare with ONETIP_C_ABI_VERSION. Never fails. */
ONETIP_C_API uint32_t onetip_abi_version(void);
/** @return the library's minor ABI version: >= ONETIP_C_ABI_MINOR_VERSION for every function of this header. Never fails. */
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
/**
 * @brief A short static name for an event type.
 * @param type an onetip_event_type.
 * @return "contact_begin", "contact_end", "input", "press", "release",
 *         "state_changed", "error", or "unknown" when out of range; static.
 */
ONETIP_C_API const char* onetip_event_type_name(int32_t type);
/**
 * @brief A short static name for a contact state.
 * @param state an onetip_contact_state.
 * @return "none", "stick", "partial_slip", "slip", or "unknown" when out of range; static.
 */
ONETIP_C_API const char* onetip_contact_state_name(int32_t state);

/**
 * @brief The default options.
 * @param abi_version pass ONETIP_C_ABI_VERSION.
 * @param out receives the defaults.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_VERSION; ONETIP_ERROR_NULL_ARGUMENT when out is NULL.
 */
ONETIP_C_API int32_t onetip_options_default(uint32_t abi_version, onetip_options* out, onetip_error* error);
/**
 * @brief Reads an options file (YAML or JSON; every key optional, a missing key
 * keeps its default, an unknown key is an error) over the defaults.
 * @param abi_version pass ONETIP_C_ABI_VERSION.
 * @param path the file; copied, not kept.
 * @param out receives the options (valid); untouched on failure.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_VERSION; ONETIP_ERROR_NULL_ARGUMENT (path, out);
 *         ONETIP_ERROR_INPUT naming the file, line and key when it cannot be
 *         read, is malformed, has an unknown key or a value out of range.
 */
ONETIP_C_API int32_t onetip_options_load(uint32_t abi_version, const char* path, onetip_options* out,
                                         onetip_error* error);
/**
 * @brief Writes every option as YAML; the file is replaced atomically (never half-written).
 * @param abi_version pass ONETIP_C_ABI_VERSION.
 * @param options the options to write; must be valid (as onetip_options_validate).
 * @param path the file to write; copied, not kept.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_VERSION; ONETIP_ERROR_NULL_ARGUMENT (options, path);
 *         ONETIP_ERROR_INPUT when the options are invalid or the file cannot be
 *         written (the file is then left as it was).
 */
ONETIP_C_API int32_t onetip_options_save(uint32_t abi_version, const onetip_options* options, const char* path,
                                         onetip_error* error);
/**
 * @brief Checks every value against its range and the relations between options (release_mm < press_mm).
 * @param abi_version pass ONETIP_C_ABI_VERSION.
 * @param options the options to check; not changed.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_VERSION; ONETIP_ERROR_NULL_ARGUMENT;
 *         ONETIP_ERROR_INPUT naming the first bad field ("options.queue_capacity:
 *         must be in [1, 64] frames, got 0"), also when lossless is not 0/1 or
 *         filter is not an onetip_filter_kind.
 */
ONETIP_C_API int32_t onetip_options_validate(uint32_t abi_version, const onetip_options* options, onetip_error* error);

/** @return the number of rows of the option table (minor version 1): rows 0 .. count - 1, in the order of the options file. Never fails. */
ONETIP_C_API int32_t onetip_option_count(void);
/**
 * @brief Describes one row of the option table (minor version 1).
 * @param abi_version pass ONETIP_C_ABI_VERSION.
 * @param row in [0, onetip_option_count() - 1].
 * @param out receives the row: name, type, count, range, default, unit, choices, doc.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_VERSION; ONETIP_ERROR_NULL_ARGUMENT;
 *         ONETIP_ERROR_INPUT when row is out of range.
 */
ONETIP_C_API int32_t onetip_option_describe(uint32_t abi_version, int32_t row, onetip_option_info* out,
                                            onetip_error* error);
/**
 * @brief Keyed read (minor version 1): value `index` of the option `name`, as a
 * double in the option's unit (exact for integers, flags and choices).
 * @param abi_version pass ONETIP_C_ABI_VERSION.
 * @param options the options to read.
 * @param name an option key (onetip_option_info::name), e.g. "press_mm".
 * @param index 0, or 0..5 (dx, dy, dz, yaw, pitch, roll) for ONETIP_OPTION_AXES.
 * @param out receives the value.
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_VERSION; ONETIP_ERROR_NULL_ARGUMENT (options,
 *         name, out); ONETIP_ERROR_INPUT for an unknown name or index, or a
 *         struct whose lossless is not 0/1 or whose filter is not a filter kind.
 */
ONETIP_C_API int32_t onetip_options_get(uint32_t abi_version, const onetip_options* options, const char* name,
                                        int32_t index, double* out, onetip_error* error);
/**
 * @brief Keyed write (minor version 1): sets value `index` of the option `name`.
 *
 * Checks the value against the table (range; whole numbers for integers, flags
 * and choices), not the relations between options (onetip_options_validate does).
 * @param abi_version pass ONETIP_C_ABI_VERSION.
 * @param options the options to change; unchanged on failure.
 * @param name an option key (onetip_option_info::name), e.g. "press_mm".
 * @param index 0, or 0..5 (dx, dy, dz, yaw, pitch, roll) for ONETIP_OPTION_AXES.
 * @param value the new value in the option's unit (mm, degrees, Hz, ...).
 * @param error NULL, or filled with the outcome.
 * @return ONETIP_OK; ONETIP_ERROR_VERSION; ONETIP_ERROR_NULL_ARGUMENT (options,
 *         name); ONETIP_ERROR_INPUT for an unknown name or index, a value out of
 *         range or not whole, or a struct whose lossless is not 0/1 or whose
 *         filter is not a filter kind.
 */
ONETIP_C_API int32_t onetip_options_set(uint32_t abi_version, onetip_options* options, const char* name,
                                        int32_t index, double value, onetip_error* error);

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

/* Minor version 2: the uncertainty forms of the poll, wait and callback functions. */
#include "onetip_c_uncertainty.h"

#endif /* ONETIP_C_H */
