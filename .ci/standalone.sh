#!/usr/bin/env bash
# CI: a clone of the committed tree, alone in a scratch folder (no sibling
# folders at all), configures, builds the test programs that read test data
# (tests/data) and passes the tests that read it (the real photos). Measured
# 10.5 min on the 2-core development machine while three other builds ran
# (SDK and four test programs built, 11 tests; no benchmarks, Python or C#).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
git clone -q --no-local . "$scratch/onetip"
cd "$scratch/onetip"
if git grep -n '\.\./share[d]' -- ':!README.md'; then
  echo "standalone: the tree refers to a sibling folder (above)" >&2
  exit 1
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DONETIP_BUILD_BENCHMARKS=OFF -DONETIP_BUILD_PYTHON=OFF \
  -DONETIP_BUILD_CSHARP=OFF >/dev/null
cmake --build build -j"$(nproc)" --target test_core test_vision test_vision3d test_vision_end_to_end >/dev/null
(cd build && ctest --output-on-failure -j"$(nproc)" \
  -R '^(Files\.ReadsTheReferenceCalibration|RealPhotos\.|CalibrateCommand\.|Triangulator\.RealBoards|VisionEndToEnd\.RealPhotos)')
echo "standalone: clone, build and data tests took $(( $(date +%s) - start )) s"
