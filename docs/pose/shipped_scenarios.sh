#!/usr/bin/env bash
# Plays every shipped touch scenario through `onetip demo` (rendered frames,
# the whole SDK) and writes the RMS error lines it prints to
# docs/pose/data/shipped_scenarios.csv:
#   scenario,frames,dx_mm,dy_mm,dz_mm,yaw_deg,pitch_deg,roll_deg
# Usage: docs/pose/shipped_scenarios.sh [path/to/onetip] [out.csv]
set -euo pipefail
cd "$(dirname "$0")/../.."
cli=${1:-build/bin/onetip}
out=${2:-docs/pose/data/shipped_scenarios.csv}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
echo "scenario,frames,dx_mm,dy_mm,dz_mm,yaw_deg,pitch_deg,roll_deg" > "$scratch/table.csv"
for file in samples/scenarios/*.yaml; do
  name=$(basename "$file" .yaml)
  [ "$name" = calibration ] && continue
  line=$("$cli" demo --scenario "$file" --out "$scratch/$name" | grep '^RMS error over')
  # "RMS error over N frames in contact: dx A mm dy B mm dz C mm yaw D deg pitch E deg roll F deg"
  echo "$line" | awk -v n="$name" '{print n "," $4 "," $9 "," $12 "," $15 "," $18 "," $21 "," $24}' >> "$scratch/table.csv"
done
mv "$scratch/table.csv" "$out"
cat "$out"
