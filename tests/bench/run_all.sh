#!/usr/bin/env bash
# Runs every benchmark executable in BUILD/bench and writes one CSV per
# benchmark to docs/data/<name>.csv (Google Benchmark's CSV format; medians of
# 5 repetitions), then redraws the charts with docs/make_charts.py.
# Usage: tests/bench/run_all.sh [BUILD_DIR] [FILTER_REGEX]
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$src/build}
filter=${2:-.}
mkdir -p "$src/docs/data"
for exe in "$build"/bench/bench_*; do
  [ -x "$exe" ] || continue
  name=$(basename "$exe")
  echo "$name" | grep -Eq "$filter" || continue
  echo "== $name"
  # pin to one core: the figures are per-core costs
  taskset -c 0 "$exe" --benchmark_out="$src/docs/data/$name.csv" --benchmark_out_format=csv \
    --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
done
/usr/bin/python3 "$src/docs/make_charts.py"
