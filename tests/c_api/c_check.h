/* tests/c_api/c_check.h — the assertion of the C tests (C11, no framework):
 * CHECK(cond, printf-format, ...) prints the failed condition with its file,
 * line and message and counts it in `failures`, which main() turns into the
 * exit code. Include once per test program. */
#ifndef ONETIP_TESTS_C_CHECK_H
#define ONETIP_TESTS_C_CHECK_H

#include <stdio.h>

static int failures = 0;
#define CHECK(cond, ...)                                                \
  do {                                                                  \
    if (!(cond)) {                                                      \
      fprintf(stderr, "FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stderr, __VA_ARGS__);                                     \
      fprintf(stderr, "\n");                                            \
      ++failures;                                                       \
    }                                                                   \
  } while (0)

#endif
