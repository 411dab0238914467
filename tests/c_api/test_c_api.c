/* End-to-end test of the C ABI, written in C11: the simulated sensor through
 * onetip_c.h, compared with the C++ API's events for the same frames (a CSV
 * written by cpp_reference; the poll queue read through the uncertainty form of
 * minor version 2, whose sd must equal the C++ Event::sd), and bad input at every boundary.
 * Usage: test_c_api SCENARIO.yaml REFERENCE.csv WORK_DIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_check.h"
#include "onetip_c.h"

/* --- events received by the callback ----------------------------------- */
#define MAX_EVENTS 4096
typedef struct collected {
  onetip_event events[MAX_EVENTS];
  double sd[MAX_EVENTS][6]; /* the same events' sd, taken from the poll queue */
  int count;
  int frames_seen;
  int markers_valid_last; /* valid markers in the last frame callback */
  int bad_marker_ids;
} collected;

static void on_event(const onetip_event* e, void* user) {
  collected* c = (collected*)user;
  if (c->count < MAX_EVENTS) c->events[c->count++] = *e;
}

static void on_frame(const onetip_frame* f, const onetip_marker* markers, int32_t n, void* user) {
  collected* c = (collected*)user;
  int valid = 0;
  c->frames_seen++;
  if (n != f->rows * f->cols) c->bad_marker_ids++;
  for (int32_t i = 0; i < n; ++i) {
    if (markers[i].id != i) c->bad_marker_ids++;
    valid += markers[i].valid;
  }
  c->markers_valid_last = valid;
}

/* --- the C++ reference ---------------------------------------------------- */
typedef struct reference_row {
  long long frame;
  int type;
  double v[6];
  double sd[6];
} reference_row;

static int load_reference(const char* path, reference_row* rows, int max_rows) {
  FILE* f = fopen(path, "r");
  char line[512];
  int n = 0;
  if (!f) return -1;
  if (!fgets(line, sizeof line, f)) {
    fclose(f);
    return -1;
  }
  while (n < max_rows && fgets(line, sizeof line, f)) {
    reference_row* r = &rows[n];
    if (sscanf(line, "%lld,%d,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &r->frame, &r->type, &r->v[0],
               &r->v[1], &r->v[2], &r->v[3], &r->v[4], &r->v[5], &r->sd[0], &r->sd[1], &r->sd[2], &r->sd[3],
               &r->sd[4], &r->sd[5]) == 14)
      ++n;
  }
  fclose(f);
  return n;
}

static void test_end_to_end(const char* scenario, const char* reference_csv) {
  static collected got;
  static reference_row ref[MAX_EVENTS];
  char source[1024];
  onetip_error err;
  onetip_options options;
  onetip_sensor* sensor = NULL;
  int32_t finished = 0, begin = 0, end = 0, inputs = 0, matched = 0, compared = 0;
  double worst = 0;

  snprintf(source, sizeof source, "sim:%s", scenario);
  CHECK(onetip_options_default(ONETIP_C_ABI_VERSION, &options, &err) == ONETIP_OK, "%s", err.message);
  options.lossless = 1; /* every frame, as the C++ reference did */
  CHECK(onetip_sensor_create(ONETIP_C_ABI_VERSION, source, NULL, NULL, NULL, &options, &sensor, &err) == ONETIP_OK,
        "%s", err.message);
  if (!sensor) return;
  CHECK(onetip_sensor_set_event_callback(sensor, on_event, &got, &err) == ONETIP_OK, "%s", err.message);
  CHECK(onetip_sensor_set_frame_callback(sensor, on_frame, &got, &err) == ONETIP_OK, "%s", err.message);
  CHECK(onetip_sensor_start(sensor, &err) == ONETIP_OK, "%s", err.message);
  CHECK(onetip_sensor_wait_finished(sensor, 120.0, &finished, &err) == ONETIP_OK && finished == 1, "finished %d %s",
        finished, err.message);

  /* the poll queue saw the same events as the callback, in the same order; its uncertainty form
   * (minor version 2) holds the plain event first */
  {
    onetip_event_sd e;
    int32_t have = 0, i = 0, same = 1;
    CHECK(onetip_abi_minor_version() >= 2, "minor version %u", onetip_abi_minor_version());
    while (onetip_sensor_poll_event_sd(sensor, &e, &have, &err) == ONETIP_OK && have) {
      if (i >= got.count || memcmp(&e.event, &got.events[i], sizeof e.event) != 0) same = 0;
      if (i < MAX_EVENTS) memcpy(got.sd[i], e.sd, sizeof e.sd);
      ++i;
    }
    CHECK(same && i == got.count, "poll queue: %d events, callback: %d", i, got.count);
  }
  {
    onetip_stats st;
    CHECK(onetip_sensor_get_stats(sensor, &st, &err) == ONETIP_OK, "%s", err.message);
    CHECK(st.frames_dropped == 0 && st.frames_processed == got.frames_seen && st.stage_count >= 8,
          "dropped %lld processed %lld frames seen %d stages %d", (long long)st.frames_dropped,
          (long long)st.frames_processed, got.frames_seen, st.stage_count);
    CHECK(strcmp(st.stages[7].stage, "process") == 0 && st.stages[7].median_ms > 0, "stage 7 %s %g",
          st.stages[7].stage, st.stages[7].median_ms);
  }
  CHECK(got.bad_marker_ids == 0 && got.markers_valid_last > 12, "marker ids wrong %d, valid %d", got.bad_marker_ids,
        got.markers_valid_last);
  CHECK(onetip_sensor_destroy(sensor, &err) == ONETIP_OK, "%s", err.message);

  for (int i = 0; i < got.count; ++i) {
    const onetip_event* e = &got.events[i];
    if (e->type == ONETIP_EVENT_CONTACT_BEGIN && !begin) begin = 1;
    if (e->type == ONETIP_EVENT_INPUT && begin && !end) ++inputs;
    if (e->type == ONETIP_EVENT_CONTACT_END && begin) end = 1;
  }
  CHECK(begin && inputs > 10 && end, "contact begin %d, %d inputs, contact end %d", begin, inputs, end);

  {
    const int n = load_reference(reference_csv, ref, MAX_EVENTS);
    CHECK(n > 0, "reference %s unreadable", reference_csv);
    CHECK(n == got.count, "C++ API gave %d events, C ABI %d", n, got.count);
    for (int i = 0; i < got.count && i < n; ++i) {
      const onetip_event* e = &got.events[i];
      if (e->type != ONETIP_EVENT_INPUT) continue;
      ++compared;
      if (ref[i].frame != e->frame || ref[i].type != e->type) continue;
      double d = 0;
      for (int k = 0; k < 6; ++k) d = fmax(d, fmax(fabs(ref[i].v[k] - e->input[k]), fabs(ref[i].sd[k] - got.sd[i][k])));
      worst = fmax(worst, d);
      if (d <= 1e-12) ++matched;
    }
    CHECK(compared > 10 && matched == compared,
          "%d of %d input events (input and sd) match the C++ API (worst difference %g)", matched, compared, worst);
    printf("end to end: %d events, %d input events (input and sd) all equal to the C++ API's (worst difference %g)\n",
           got.count, compared, worst);
  }
}

/* --- bad input at the boundary -------------------------------------------- */
static void expect_error(int32_t rc, const onetip_error* err, int32_t kind, const char* needle, const char* what) {
  CHECK(rc == kind && err->kind == kind, "%s: got %s (%d), wanted %s", what, onetip_error_kind_name(rc), rc,
        onetip_error_kind_name(kind));
  CHECK(strlen(err->message) > 0 && (!needle || strstr(err->message, needle)), "%s: message '%s' lacks '%s'", what,
        err->message, needle ? needle : "");
}

static int32_t callback_calls = 0;
static void count_event(const onetip_event* e, void* user) {
  (void)e;
  (void)user;
  ++callback_calls;
}

static void test_bad_input(const char* scenario, const char* work_dir) {
  onetip_error err;
  onetip_options options;
  onetip_sensor* sensor = (onetip_sensor*)(void*)0x1; /* must be reset to NULL on failure */
  onetip_event event;
  int32_t got = 7, flag = 0;
  char source[1024], path[1024];
  snprintf(source, sizeof source, "sim:%s", scenario);

  CHECK(onetip_abi_version() == ONETIP_C_ABI_VERSION, "abi %u", onetip_abi_version());
  CHECK(strcmp(onetip_event_type_name(ONETIP_EVENT_INPUT), "input") == 0, "name");
  CHECK(strcmp(onetip_contact_state_name(99), "unknown") == 0, "name");

  expect_error(onetip_sensor_create(ONETIP_C_ABI_VERSION + 1, source, NULL, NULL, NULL, NULL, &sensor, &err), &err,
               ONETIP_ERROR_VERSION, "version", "wrong ABI version");
  CHECK(sensor == NULL, "out not reset");
  expect_error(onetip_options_default(0, &options, &err), &err, ONETIP_ERROR_VERSION, "version", "options version");
  expect_error(onetip_sensor_create(ONETIP_C_ABI_VERSION, NULL, NULL, NULL, NULL, NULL, &sensor, &err), &err,
               ONETIP_ERROR_NULL_ARGUMENT, "source", "NULL source");
  expect_error(onetip_sensor_create(ONETIP_C_ABI_VERSION, source, NULL, NULL, NULL, NULL, NULL, &err), &err,
               ONETIP_ERROR_NULL_ARGUMENT, "out", "NULL out");
  expect_error(onetip_sensor_create(ONETIP_C_ABI_VERSION, "sim:/no/such/scenario.yaml", NULL, NULL, NULL, NULL,
                                    &sensor, &err),
               &err, ONETIP_ERROR_INPUT, "/no/such/scenario.yaml", "missing scenario");
  expect_error(onetip_sensor_create(ONETIP_C_ABI_VERSION, "/no/such/folder", "/no/calib.yaml", "/no/pattern.yaml",
                                    NULL, NULL, &sensor, &err),
               &err, ONETIP_ERROR_INPUT, "/no/", "missing folder");
  expect_error(onetip_sensor_create(ONETIP_C_ABI_VERSION, source, "/no/calib.yaml", "/no/pattern.yaml", NULL, NULL,
                                    &sensor, &err),
               &err, ONETIP_ERROR_INPUT, "/no/calib.yaml", "missing calibration");
  expect_error(onetip_sensor_create(ONETIP_C_ABI_VERSION, source, NULL, NULL, "/no/ref.png", NULL, &sensor, &err),
               &err, ONETIP_ERROR_INPUT, "/no/ref.png", "missing reference");
  onetip_options_default(ONETIP_C_ABI_VERSION, &options, &err);
  options.queue_capacity = 0;
  expect_error(onetip_sensor_create(ONETIP_C_ABI_VERSION, source, NULL, NULL, NULL, &options, &sensor, &err), &err,
               ONETIP_ERROR_INPUT, "queue_capacity", "bad option");
  options.queue_capacity = 2;
  options.filter = 9;
  expect_error(onetip_options_save(ONETIP_C_ABI_VERSION, &options, "/tmp/never.yaml", &err), &err, ONETIP_ERROR_INPUT,
               "filter", "bad filter");
  expect_error(onetip_options_load(ONETIP_C_ABI_VERSION, "/no/options.yaml", &options, &err), &err,
               ONETIP_ERROR_INPUT, "/no/options.yaml", "missing options file");

  /* options round trip through YAML */
  {
    onetip_options a, b;
    onetip_options_default(ONETIP_C_ABI_VERSION, &a, &err);
    a.press_mm = 2.25;
    a.working_range[3] = 20;
    a.filter = ONETIP_FILTER_ONE_EURO;
    a.lossless = 1;
    snprintf(path, sizeof path, "%s/c_options.yaml", work_dir);
    CHECK(onetip_options_save(ONETIP_C_ABI_VERSION, &a, path, &err) == ONETIP_OK, "%s", err.message);
    CHECK(onetip_options_load(ONETIP_C_ABI_VERSION, path, &b, &err) == ONETIP_OK, "%s", err.message);
    CHECK(memcmp(&a, &b, sizeof a) == 0, "options differ after a YAML round trip");
  }

  /* NULL handles and out-parameters; the error pointer itself may be NULL */
  expect_error(onetip_sensor_start(NULL, &err), &err, ONETIP_ERROR_NULL_ARGUMENT, "handle", "start NULL");
  expect_error(onetip_sensor_poll_event(NULL, &event, &got, &err), &err, ONETIP_ERROR_NULL_ARGUMENT, "handle",
               "poll NULL");
  CHECK(got == 0, "got not reset");
  CHECK(onetip_sensor_rezero(NULL, NULL) == ONETIP_ERROR_NULL_ARGUMENT, "NULL error pointer");
  CHECK(onetip_sensor_destroy(NULL, &err) == ONETIP_OK, "destroy(NULL) is a no-op");
  expect_error(onetip_sensor_start((onetip_sensor*)(void*)0x12345, &err), &err, ONETIP_ERROR_INVALID_HANDLE, "live",
               "made-up handle");

  /* a live sensor: wrong call order, NULL out-params, then calls after destroy */
  CHECK(onetip_sensor_create(ONETIP_C_ABI_VERSION, source, NULL, NULL, NULL, NULL, &sensor, &err) == ONETIP_OK, "%s",
        err.message);
  expect_error(onetip_sensor_poll_event(sensor, NULL, &got, &err), &err, ONETIP_ERROR_NULL_ARGUMENT, "out",
               "poll NULL out");
  expect_error(onetip_sensor_get_stats(sensor, NULL, &err), &err, ONETIP_ERROR_NULL_ARGUMENT, "out", "stats NULL");
  expect_error(onetip_sensor_poll_frame(sensor, NULL, NULL, 0, &flag, &got, &err), &err, ONETIP_ERROR_NULL_ARGUMENT,
               "out", "frame NULL");
  CHECK(onetip_sensor_wait_event(sensor, 0.01, &event, &got, &err) == ONETIP_OK && got == 0, "wait before start");
  CHECK(onetip_sensor_set_event_callback(sensor, count_event, NULL, &err) == ONETIP_OK, "%s", err.message);
  CHECK(onetip_sensor_start(sensor, &err) == ONETIP_OK, "%s", err.message);
  expect_error(onetip_sensor_start(sensor, &err), &err, ONETIP_ERROR_STATE, "start", "second start");
  CHECK(onetip_sensor_rezero(sensor, &err) == ONETIP_OK, "%s", err.message);
  CHECK(onetip_sensor_is_running(sensor, &flag, &err) == ONETIP_OK, "%s", err.message);
  CHECK(onetip_sensor_stop(sensor, &err) == ONETIP_OK, "%s", err.message);
  CHECK(onetip_sensor_stop(sensor, &err) == ONETIP_OK, "stop is idempotent: %s", err.message);
  CHECK(onetip_sensor_destroy(sensor, &err) == ONETIP_OK, "%s", err.message);
  expect_error(onetip_sensor_start(sensor, &err), &err, ONETIP_ERROR_INVALID_HANDLE, "destroyed", "after destroy");
  expect_error(onetip_sensor_poll_event(sensor, &event, &got, &err), &err, ONETIP_ERROR_INVALID_HANDLE, "destroyed",
               "poll after destroy");
  expect_error(onetip_sensor_destroy(sensor, &err), &err, ONETIP_ERROR_INVALID_HANDLE, "destroyed",
               "double destroy");
}

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: test_c_api SCENARIO.yaml REFERENCE.csv WORK_DIR\n");
    return 2;
  }
  printf("onetip %s, C ABI %u\n", onetip_version_string(), onetip_abi_version());
  test_bad_input(argv[1], argv[3]);
  test_end_to_end(argv[1], argv[2]);
  if (failures) fprintf(stderr, "%d check(s) failed\n", failures);
  return failures ? 1 : 0;
}
