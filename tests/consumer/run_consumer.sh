#!/usr/bin/env bash
# Installs the build tree into a temporary prefix, builds tests/consumer against
# it with find_package(onetip) only, and runs it. Usage: run_consumer.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/tests/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
LD_LIBRARY_PATH="$work/prefix/lib:${LD_LIBRARY_PATH:-}" "$work/build/consumer" "$src/samples/scenarios/press.yaml"
LD_LIBRARY_PATH="$work/prefix/lib:${LD_LIBRARY_PATH:-}" "$work/build/consumer_c" "$src/samples/scenarios/press.yaml"
test -f "$work/prefix/include/onetip_c.h" || { echo "onetip_c.h not installed" >&2; exit 1; }
# the library exports only the public API
if nm -D --defined-only "$work/prefix/lib/libonetip.so" | grep -q 'onetip3sim'; then
  echo "internal symbols leak from libonetip.so" >&2
  exit 1
fi
echo "consumer: ok"
