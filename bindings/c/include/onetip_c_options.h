/**
 * @file onetip_c_options.h
 * @brief The options of a sensor through the C ABI (included by onetip_c.h):
 * the struct onetip_options and its filter kinds, and the functions that fill,
 * read, write and check it, with the option table (minor version 1) that
 * describes each option and reaches it by key.
 */
#ifndef ONETIP_C_OPTIONS_H
#define ONETIP_C_OPTIONS_H

#include "onetip_c_base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The smoothing of the 6-D input (onetip_options::filter; as onetip::FilterKind). */
typedef enum onetip_filter_kind {
  ONETIP_FILTER_NONE = 0,            /**< No smoothing. */
  ONETIP_FILTER_MOVING_AVERAGE = 1,  /**< Mean of the last onetip_options::filter_window frames. */
  ONETIP_FILTER_ONE_EURO = 2         /**< The 1-euro filter (Casiez et al. 2012). */
} onetip_filter_kind;

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

#ifdef __cplusplus
}
#endif

#endif /* ONETIP_C_OPTIONS_H */
