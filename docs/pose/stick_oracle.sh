#!/usr/bin/env bash
# What the stick labels cost (tests/unit/pose/stick_oracle.hpp, decision records 0018, 0019 and 0020): the
# campaign's 300 field runs played by each estimator as it is, and by the stick-label oracle registering the
# truth's labels (its sliding markers' normal residuals with their slide's model error, with the noise alone,
# or none; the motion held or a constant rate as its prior), the estimator's own, and those of its own that
# are true. Writes one CSV per play to docs/pose/data/stick_oracle/ and the summary chart with
# make_stick_oracle_chart.py.
# Usage: docs/pose/stick_oracle.sh [path/to/pose_campaign]   (about 25 minutes on one core)
set -euo pipefail
cd "$(dirname "$0")/../.."
campaign=${1:-build/bench/pose_campaign}
out=docs/pose/data/stick_oracle
mkdir -p "$out"
"$campaign" --runs 300 --oracle truth --out "$out/truth.csv"
"$campaign" --runs 300 --oracle truth --oracle-sliding-error 0 --out "$out/truth.noise_only_slides.csv"
"$campaign" --runs 300 --oracle truth --oracle-slip-normals 0 --out "$out/truth.no_slip_normals.csv"
"$campaign" --runs 300 --oracle truth --oracle-prior-rate-tau inf --out "$out/truth.constant_rate.csv"
# Where the labels come from: the default's on the touched markers only; the truncated cost's reweighting
# after the labelled solve (with the default's labels, those on the touched markers, the truth's); and the
# truncated cost alone, frame to frame (none) or with the anchors as its memory (self). Decision record 0020.
"$campaign" --runs 300 --oracle truth --oracle-reweight 1 --out "$out/truth.reweighted.csv"
"$campaign" --runs 300 --oracle estimate --oracle-reweight 1 --out "$out/adaptive.labels.reweighted.csv"
"$campaign" --runs 300 --oracle estimate-touching --out "$out/adaptive.touching_labels.csv"
"$campaign" --runs 300 --oracle estimate-touching --oracle-reweight 1 --out "$out/adaptive.touching_labels.reweighted.csv"
"$campaign" --runs 300 --oracle none --oracle-reweight 1 --out "$out/none.reweighted.csv"
"$campaign" --runs 300 --oracle self --out "$out/self.csv"
for policy in adaptive weighted; do
  "$campaign" --runs 300 --policy "$policy" --out "$out/$policy.csv"
  "$campaign" --runs 300 --policy "$policy" --oracle estimate --out "$out/$policy.labels.csv"
  "$campaign" --runs 300 --policy "$policy" --oracle estimate-true --out "$out/$policy.true_labels.csv"
done
/usr/bin/python3 docs/pose/make_stick_oracle_chart.py "$out"
