/**
 * @file onetip_c_data.h
 * @brief What a running sensor reports through the C ABI (included by
 * onetip_c.h): the event types, contact states and frame statuses, the
 * structs onetip_event, onetip_frame (with its stage times), onetip_marker and
 * onetip_stats, and the names of the enums.
 *
 * Every struct is flat and fixed-size; strings are NUL-terminated and enums
 * travel as int32_t. Units and frames: onetip_c.h's description.
 */
#ifndef ONETIP_C_DATA_H
#define ONETIP_C_DATA_H

#include "onetip_c_base.h"

#ifdef __cplusplus
extern "C" {
#endif

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

#ifdef __cplusplus
}
#endif

#endif /* ONETIP_C_DATA_H */
