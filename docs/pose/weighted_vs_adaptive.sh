#!/usr/bin/env bash
# Plays every shipped touch scenario at field level (the simulator's marker
# fields plus the front end's noise) through both estimators, the adaptive one
# (the default) and the one-objective prototype (ModelPolicy::weighted,
# decision record 0017), and writes each one's RMS error per axis over the
# frames in contact to docs/pose/data/weighted_vs_adaptive_shipped.csv.
# Usage: docs/pose/weighted_vs_adaptive.sh [path/to/pose_campaign] [out.csv]
set -euo pipefail
cd "$(dirname "$0")/../.."
campaign=${1:-build/bench/pose_campaign}
out=${2:-docs/pose/data/weighted_vs_adaptive_shipped.csv}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for file in samples/scenarios/*.yaml; do
  name=$(basename "$file" .yaml)
  [ "$name" = calibration ] && continue
  for policy in adaptive weighted; do
    "$campaign" --trace-scenario "$file" --policy "$policy" --trace-out "$scratch/$name.$policy.csv" > /dev/null
  done
done
/usr/bin/python3 - "$scratch" "$out" <<'PY'
import csv, glob, math, os, sys
scratch, out = sys.argv[1], sys.argv[2]
axes = ["dx", "dy", "dz", "yaw", "pitch", "roll"]
with open(out, "w") as f:
    f.write("scenario,estimator,frames," + ",".join(a + ("_mm" if a in ("dx", "dy", "dz") else "_deg") for a in axes) + "\n")
    for path in sorted(glob.glob(os.path.join(scratch, "*.adaptive.csv"))):
        name = os.path.basename(path).split(".")[0]
        for estimator in ("adaptive", "weighted"):
            rows = [r for r in csv.DictReader(open(os.path.join(scratch, f"{name}.{estimator}.csv")))
                    if r["gt_contact"] == "1" and r["contact"] == "1"]
            rmse = [math.sqrt(sum((float(r[a]) - float(r["gt_" + a])) ** 2 for r in rows) / max(1, len(rows)))
                    for a in axes]
            f.write(f"{name},{estimator},{len(rows)}," + ",".join(f"{v:.4f}" for v in rmse) + "\n")
PY
cat "$out"
