#!/usr/bin/env bash
# Builds the pose benchmark and campaign programs of another commit (a
# baseline estimator: the SDK keeps only its current estimator) in a scratch
# worktree, then times contact + pose against this checkout's build in
# alternating rounds on one core and plays the same campaign seeds through both.
#   docs/pose/baseline_from_commit.sh COMMIT [OUT_DIR] [RUNS]
# Writes OUT_DIR/bench_pose_COMMIT.csv (round, who, benchmark, median ns) and
# OUT_DIR/campaign_COMMIT.csv, OUT_DIR/campaign_this.csv (pose_campaign rows;
# the baseline's table has the columns its commit knew). This checkout's
# build/ must be configured; the baseline worktree is removed at the end.
set -euo pipefail
cd "$(dirname "$0")/../.."
commit=${1:?usage: docs/pose/baseline_from_commit.sh COMMIT [OUT_DIR] [RUNS]}
out=${2:-build/baseline}
runs=${3:-300}
mkdir -p "$out"
scratch=$(mktemp -d)
trap 'git worktree remove --force "$scratch/src" >/dev/null 2>&1 || true; rm -rf "$scratch"' EXIT
git worktree add --detach "$scratch/src" "$commit" >/dev/null
source .ci/build-env.sh
cmake -S "$scratch/src" -B "$scratch/build" -DCMAKE_BUILD_TYPE=Release -DONETIP_DDS=OFF >/dev/null
cmake --build "$scratch/build" --target bench_pose pose_campaign
cmake --build build --target bench_pose pose_campaign
filter='BM_ContactAndPose/0$|BM_Tracker/0$'
echo "round,who,benchmark,median_ns" > "$out/bench_pose_$commit.csv"
for round in 1 2 3; do
  for who in baseline this; do
    dir=build
    [ "$who" = baseline ] && dir="$scratch/build"
    taskset -c 0 "$dir/bench/bench_pose" --benchmark_filter="$filter" --benchmark_repetitions=3 \
      --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null |
      awk -F, -v r="$round" -v w="$who" '/_median/ {gsub(/"/, "", $1); print r "," w "," $1 "," $3}' \
      >> "$out/bench_pose_$commit.csv"
  done
done
"$scratch/build/bench/pose_campaign" --runs "$runs" --out "$out/campaign_$commit.csv"
build/bench/pose_campaign --runs "$runs" --out "$out/campaign_this.csv"
echo "wrote $out/bench_pose_$commit.csv, $out/campaign_$commit.csv and $out/campaign_this.csv"
