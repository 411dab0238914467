#!/usr/bin/env bash
# CI's sanitizer leg: one clang tree (build-san) for AddressSanitizer + UndefinedBehaviorSanitizer
# and for the libFuzzer harnesses. Everything is compiled with -fsanitize=address,undefined, the
# code the harnesses parse also with -fsanitize=fuzzer-no-link (sdk/cmake/OnetipFuzzCoverage.cmake);
# the harnesses alone link libFuzzer (-fsanitize=fuzzer, tests/fuzz/CMakeLists.txt). The suite runs
# under the sanitizers, DDS included, but for the tests that run a document's lines as written
# (labels package and docs: they check the document, and the code under them runs under the
# sanitizers in the other tests) and the Release-only tests of tests/support/sanitizer_leg.hpp,
# which report themselves skipped. Then every harness runs from its committed seeds for
# FUZZ_SECONDS (default 10) each.
# Extra arguments go to ctest (.ci/run passes --output-junit); the harnesses' table is also written
# to FUZZ_RESULTS (default build-san/fuzz-results.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh --tests
source .ci/build-env.sh
# The tree is CMakePresets.json's `sanitize` preset, so a developer gets the same one with
# `cmake --preset sanitize`: clang, -O2 -gline-tables-only (the sanitizers' reports need file and line,
# not variables; it compiles 15 % faster than -g and its objects are a sixth of the size, measured on a
# Ceres translation unit), ONETIP_SANITIZE, ONETIP_FUZZ, DDS on, benchmarks off.
cmake --preset sanitize >/dev/null
cmake --build build-san -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
# The preset's test filter leaves out the labels package and docs and sets the same sanitizer options.
ctest --preset sanitize -j"$(nproc)" "$@" || status=1
bash tests/fuzz/run_fuzzers.sh build-san "${FUZZ_SECONDS:-10}" | tee "${FUZZ_RESULTS:-build-san/fuzz-results.txt}" ||
  status=1
exit $status
