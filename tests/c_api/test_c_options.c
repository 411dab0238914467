/* The C surface of the option table (label options), written in C11 against
 * onetip_c.h only, as a C user would:
 *  - every row of onetip_option_describe is reachable by key, its default is
 *    what onetip_options_default gives, and its strings are not truncated;
 *  - onetip_options_set accepts each value AT min and max and refuses values
 *    just outside (nextafter; +-1 for integers), non-whole integers and
 *    unknown keys/indices, leaving the struct unchanged when it refuses;
 *  - the onetip_options struct, listed field by field below, holds exactly
 *    the table's options: same names, same types, defaults equal to the table's,
 *    each key writes its own field, and a field set out of range directly is
 *    refused by onetip_options_validate.
 * Usage: test_c_options */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "c_check.h"
#include "onetip_c.h"

#define ABI ONETIP_C_ABI_VERSION

/* --- the struct, field by field (the only hand-written list here) -------- */
typedef struct field {
  const char* name;
  int32_t type; /* the onetip_option_type the field's C type can carry */
  size_t offset;
} field;
#define INTEGER(f) \
  { #f, ONETIP_OPTION_INTEGER, offsetof(onetip_options, f) }
#define REAL(f) \
  { #f, ONETIP_OPTION_REAL, offsetof(onetip_options, f) }
#define FLAG(f) \
  { #f, ONETIP_OPTION_FLAG, offsetof(onetip_options, f) }
#define CHOICE(f) \
  { #f, ONETIP_OPTION_CHOICE, offsetof(onetip_options, f) }
#define AXES(f) \
  { #f, ONETIP_OPTION_AXES, offsetof(onetip_options, f) }
static const field kFields[] = {
    INTEGER(queue_capacity),
    FLAG(lossless),
    INTEGER(event_queue_capacity),
    INTEGER(frame_queue_capacity),
    INTEGER(timing_window),
    INTEGER(max_consecutive_source_errors),
    INTEGER(stop_timeout_ms),
    INTEGER(min_markers),
    CHOICE(filter),
    INTEGER(filter_window),
    REAL(playback_rate),
    AXES(working_range),
    REAL(clamp_factor),
    REAL(press_mm),
    REAL(release_mm),
    AXES(gain),
    AXES(dead_zone),
    REAL(filter_min_cutoff_hz),
    REAL(filter_beta),
    REAL(filter_derivative_cutoff_hz),
};
enum { kFieldCount = sizeof kFields / sizeof kFields[0] };

static int is_int_field(int32_t type) { return type != ONETIP_OPTION_REAL && type != ONETIP_OPTION_AXES; }

static double read_field(const onetip_options* o, const field* f, int k) {
  const char* base = (const char*)o + f->offset;
  if (is_int_field(f->type)) return ((const int32_t*)(const void*)base)[0];
  return ((const double*)(const void*)base)[k];
}

static void write_field(onetip_options* o, const field* f, int k, double v) {
  char* base = (char*)o + f->offset;
  if (is_int_field(f->type))
    ((int32_t*)(void*)base)[0] = (int32_t)v;
  else
    ((double*)(void*)base)[k] = v;
}

static const field* field_named(const char* name) {
  for (int i = 0; i < kFieldCount; ++i)
    if (strcmp(kFields[i].name, name) == 0) return &kFields[i];
  return NULL;
}

/* Just outside the closed range [min, max] on one side: the next double, or the next integer. */
static double below(const onetip_option_info* r) {
  return is_int_field(r->type) ? r->min - 1 : nextafter(r->min, -INFINITY);
}
static double above(const onetip_option_info* r) {
  return is_int_field(r->type) ? r->max + 1 : nextafter(r->max, INFINITY);
}

static void expect_refused(onetip_options* o, const onetip_option_info* r, int k, double v, const char* what) {
  onetip_options before = *o;
  onetip_error err;
  int32_t code = onetip_options_set(ABI, o, r->name, k, v, &err);
  CHECK(code == ONETIP_ERROR_INPUT, "%s[%d] = %.17g (%s) gave %d", r->name, k, v, what, code);
  CHECK(strstr(err.message, r->name) != NULL, "the message names the option: %s", err.message);
  CHECK(memcmp(&before, o, sizeof before) == 0, "%s: a refused set changed the struct", r->name);
}

static void expect_accepted(onetip_options* o, const onetip_option_info* r, int k, double v) {
  onetip_error err;
  double back = -12345;
  CHECK(onetip_options_set(ABI, o, r->name, k, v, &err) == ONETIP_OK, "%s[%d] = %.17g: %s", r->name, k, v, err.message);
  CHECK(onetip_options_get(ABI, o, r->name, k, &back, &err) == ONETIP_OK, "%s", err.message);
  CHECK(back == v, "%s[%d]: set %.17g, got %.17g", r->name, k, v, back);
  const field* f = field_named(r->name);
  if (f) CHECK(read_field(o, f, k) == v, "%s[%d]: the key did not write its own struct field", r->name, k);
}

static void test_row(const onetip_option_info* r, const onetip_options* defaults, int* matched) {
  onetip_error err;
  const field* f = field_named(r->name);
  CHECK(f != NULL, "the table's option '%s' has no onetip_options field", r->name);
  if (f) {
    CHECK(f->type == r->type, "%s: struct field type %d, table type %d", r->name, f->type, r->type);
    matched[f - kFields]++;
  }
  CHECK(r->count == (r->type == ONETIP_OPTION_AXES ? 6 : 1), "%s: count %d", r->name, r->count);
  CHECK(r->min <= r->max, "%s: empty range", r->name);
  for (int k = 0; k < r->count; ++k) {
    double value = -12345;
    CHECK(onetip_options_get(ABI, defaults, r->name, k, &value, &err) == ONETIP_OK, "%s: %s", r->name, err.message);
    CHECK(value == r->default_value[k], "%s[%d]: onetip_options_default gives %.17g, the table %.17g", r->name, k,
          value, r->default_value[k]);
    if (f)
      CHECK(read_field(defaults, f, k) == r->default_value[k], "%s[%d]: the struct's default %.17g, the table %.17g",
            r->name, k, read_field(defaults, f, k), r->default_value[k]);

    onetip_options o = *defaults;
    expect_accepted(&o, r, k, r->min);
    expect_accepted(&o, r, k, r->max);
    expect_refused(&o, r, k, below(r), "just below min");
    expect_refused(&o, r, k, above(r), "just above max");
    expect_refused(&o, r, k, NAN, "NaN");
    if (is_int_field(r->type) && r->max > r->min) expect_refused(&o, r, k, r->min + 0.5, "not whole");

    /* Out of range written straight into the struct: validate refuses it, naming the option. */
    if (f) {
      onetip_options direct = *defaults;
      write_field(&direct, f, k, above(r));
      CHECK(onetip_options_validate(ABI, &direct, &err) == ONETIP_ERROR_INPUT && strstr(err.message, r->name),
            "%s[%d] = %.17g in the struct: validate said '%s'", r->name, k, above(r), err.message);
    }
  }
  onetip_options o = *defaults;
  expect_refused(&o, r, r->count, r->min, "index past the values");
  expect_refused(&o, r, -1, r->min, "negative index");
}

int main(void) {
  onetip_options defaults;
  onetip_option_info info;
  onetip_error err;
  int matched[kFieldCount] = {0};
  CHECK(onetip_abi_minor_version() >= ONETIP_C_ABI_MINOR_VERSION, "library minor %u", onetip_abi_minor_version());
  CHECK(onetip_options_default(ABI, &defaults, &err) == ONETIP_OK, "%s", err.message);
  CHECK(onetip_options_validate(ABI, &defaults, &err) == ONETIP_OK, "the defaults are valid: %s", err.message);

  const int32_t n = onetip_option_count();
  CHECK(n == kFieldCount, "the table has %d options, onetip_options %d fields", n, (int)kFieldCount);
  for (int32_t i = 0; i < n; ++i) {
    CHECK(onetip_option_describe(ABI, i, &info, &err) == ONETIP_OK, "row %d: %s", i, err.message);
    CHECK(strlen(info.name) > 0 && strlen(info.name) < ONETIP_OPTION_NAME_SIZE - 1, "row %d: name '%s'", i, info.name);
    CHECK(strlen(info.doc) > 0 && strlen(info.doc) < ONETIP_OPTION_DOC_SIZE - 1, "%s: doc truncated", info.name);
    CHECK(strlen(info.unit) < ONETIP_OPTION_UNIT_SIZE - 1, "%s: unit truncated", info.name);
    CHECK(strlen(info.choices) < ONETIP_OPTION_CHOICES_SIZE - 1, "%s: choices truncated", info.name);
    if (info.type == ONETIP_OPTION_CHOICE) {
      int names = 1;
      for (const char* c = info.choices; *c; ++c) names += *c == ' ';
      CHECK(info.min == 0 && info.max == names - 1, "%s: %d choices for [%g, %g]", info.name, names, info.min,
            info.max);
    }
    test_row(&info, &defaults, matched);
  }
  for (int i = 0; i < kFieldCount; ++i)
    CHECK(matched[i] == 1, "onetip_options.%s matches %d table rows", kFields[i].name, matched[i]);

  /* The relation between two options, and the boundary's own errors. */
  {
    onetip_options o = defaults;
    CHECK(onetip_options_set(ABI, &o, "release_mm", 0, o.press_mm, &err) == ONETIP_OK, "%s", err.message);
    CHECK(onetip_options_validate(ABI, &o, &err) == ONETIP_ERROR_INPUT && strstr(err.message, "press_mm"),
          "release_mm == press_mm: '%s'", err.message);
    o = defaults;
    o.lossless = 2;
    CHECK(
        onetip_options_set(ABI, &o, "press_mm", 0, 2.0, &err) == ONETIP_ERROR_INPUT && strstr(err.message, "lossless"),
        "a struct that C++ cannot hold is refused: '%s'", err.message);
  }
  CHECK(onetip_options_set(ABI, &defaults, "no_such_option", 0, 1, &err) == ONETIP_ERROR_INPUT &&
            strstr(err.message, "no_such_option"),
        "unknown key: '%s'", err.message);
  CHECK(onetip_options_set(ABI, NULL, "gain", 0, 1, &err) == ONETIP_ERROR_NULL_ARGUMENT, "NULL options");
  CHECK(onetip_options_get(ABI, &defaults, NULL, 0, NULL, &err) == ONETIP_ERROR_NULL_ARGUMENT, "NULL name");
  CHECK(onetip_option_describe(ABI, n, &info, &err) == ONETIP_ERROR_INPUT, "row past the end");
  CHECK(onetip_option_describe(ABI + 1, 0, &info, &err) == ONETIP_ERROR_VERSION, "wrong ABI version");

  printf("%d options checked, %d failures\n", (int)n, failures);
  return failures == 0 ? 0 : 1;
}
