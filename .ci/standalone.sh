#!/usr/bin/env bash
# CI: a clone of the committed tree, alone in a scratch folder (no sibling
# folders at all), configures without the optional DDS module, builds the test
# programs that read test data (tests/data) and passes the tests that read it
# (the real photos) and the hostile-input tests. Measured 10.5 min on the
# 2-core development machine while three other builds ran (SDK and four test
# programs built, 11 tests; no benchmarks, Python or C#), before the DDS module
# was left out (saves ~0.8 min) and test_hostile added (~0.5 min, 10 tests ~12 s).
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
# Configured as on a machine without the DDS packages (issue 19): CMake is told
# Cyclone DDS is not there, so ONETIP_WITH_DDS takes its default, OFF, and the
# SDK, the CLI (built for VisionEndToEnd) and these tests must build and pass
# without it. The CLI's hostile-input tests (label hostile) run here too.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DONETIP_BUILD_BENCHMARKS=OFF -DONETIP_BUILD_PYTHON=OFF \
  -DONETIP_BUILD_CSHARP=OFF -DCMAKE_DISABLE_FIND_PACKAGE_CycloneDDS=ON >/dev/null
if ! grep -q '^ONETIP_WITH_DDS:BOOL=OFF$' build/CMakeCache.txt; then
  echo "standalone: ONETIP_WITH_DDS is not OFF without Cyclone DDS" >&2
  exit 1
fi
cmake --build build -j"$(nproc)" --target test_core test_vision test_vision3d test_vision_end_to_end test_hostile >/dev/null
if ldd build/bin/onetip | grep -q ddsc; then
  echo "standalone: the CLI links Cyclone DDS in a build without the DDS module" >&2
  exit 1
fi
(cd build && ctest --output-on-failure -j"$(nproc)" \
  -R '^(Files\.ReadsTheReferenceCalibration|RealPhotos\.|CalibrateCommand\.|Triangulator\.RealBoards|VisionEndToEnd\.RealPhotos|Hostile)')
echo "standalone: clone, build and data tests took $(( $(date +%s) - start )) s"
