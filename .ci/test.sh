#!/usr/bin/env bash
# Installs what the SDK and the whole suite need and is missing, builds Release, builds the API reference (Doxygen, warnings are errors)
# and runs the whole test suite with ctest. Extra arguments go to ctest (e.g. -L sim to run one area).
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh --tests  # the SDK and everything the suite needs
source .ci/build-env.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DONETIP_BUILD_TESTS=ON -DONETIP_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build -j"$(nproc)"
cmake --build build --target docs
cd build && ctest --output-on-failure -j"$(nproc)" "$@"
