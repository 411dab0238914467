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
# -gline-tables-only: the sanitizers' reports need file and line, not variables; it compiles 15 %
# faster than -g and its objects are a sixth of the size (measured on a Ceres translation unit).
flags="-O2 -gline-tables-only -DNDEBUG"
CC=clang CXX=clang++ cmake -S . -B build-san -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS_RELWITHDEBINFO="$flags" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" -DONETIP_SANITIZE=ON -DONETIP_FUZZ=ON -DONETIP_BUILD_TESTS=ON -DONETIP_BUILD_BENCHMARKS=OFF \
  -DONETIP_WITH_DDS=ON >/dev/null
cmake --build build-san -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
(cd build-san && ctest --output-on-failure -j"$(nproc)" -LE "package|docs" "$@") || status=1
bash tests/fuzz/run_fuzzers.sh build-san "${FUZZ_SECONDS:-10}" | tee "${FUZZ_RESULTS:-build-san/fuzz-results.txt}" ||
  status=1
exit $status
