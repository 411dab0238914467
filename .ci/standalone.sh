#!/usr/bin/env bash
# CI: a clone of the committed tree, alone in a scratch folder (no sibling folders at all),
# configured as on a machine without Cyclone DDS, builds the SDK, the CLI and the test programs
# that read test data (tests/data), and passes the tests that read it (the real photos) and the
# hostile-input tests. The compiler cache (.ci/build-env.sh, based at the clone's root) serves it
# the objects of an earlier build of the same sources, so it costs minutes when the Release leg
# ran before it. Extra arguments go to ctest (.ci/run passes --output-junit).
set -euo pipefail
cd "$(dirname "$0")/.."
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
git clone -q --no-local . "$scratch/onetip"
cd "$scratch/onetip"
if git grep -n '\.\./share[d]' -- ':!README.md'; then
  echo "standalone: the tree refers to a sibling folder (above)" >&2
  exit 1
fi
source .ci/build-env.sh
# ONETIP_WITH_DDS takes its default, OFF, when CMake is told Cyclone DDS is not there: the SDK,
# the CLI (built for VisionEndToEnd) and these tests must build and pass without it.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DONETIP_BUILD_TESTS=ON -DONETIP_BUILD_BENCHMARKS=OFF -DONETIP_BUILD_PYTHON=OFF \
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
  -R '^(Files\.ReadsTheReferenceCalibration|RealPhotos\.|CalibrateCommand\.|Triangulator\.RealBoards|VisionEndToEnd\.RealPhotos|Hostile)' "$@")
