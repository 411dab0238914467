#!/usr/bin/env bash
# The main job on the embedded default sensor (the simulator): installs what the SDK
# needs and is missing (.ci/install-deps.sh, without --tests), builds Release (the
# `onetip` program and everything `cmake --install` installs: the shared library, the
# Python module, the C# assembly), plays a scripted touch (press, slide, twist,
# release), prints the 6-D stream as it goes and writes what the camera saw to
# out/demo/contact_sheet.png. The tests are configured too when GoogleTest is installed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh
source .ci/build-env.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target onetip_cli onetip onetip_python onetip_csharp
mkdir -p out
rm -rf out/demo  # this script's own output of an earlier run: `onetip demo` never replaces a folder
./build/bin/onetip demo --scenario samples/scenarios/demo_touch.yaml --out out/demo
