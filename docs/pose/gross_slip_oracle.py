#!/usr/bin/python3
"""What an estimator exact everywhere but in gross slip would still lose (decision record 0012, docs/decisions).

Reads the per-frame traces of the campaign's field runs (`pose_campaign --trace SEED --trace-out DIR/SEED.csv`
for each seed) and replays only their truth: the estimated turn is taken exact in every frame except those where
the truth slides as a whole (gt_state == slip), where the turn's increment is
  zero            (what a footprint model does),
  the rate        the truth's own mean turn per frame over the 3 frames before, held,
  decayed (tau)   that rate times exp(-t / tau), t the time since the gross slip began.
The error so made accumulates until the contact ends. A run diverges as campaign_score.hpp judges it: an axis
beyond 5 deg for more than 3 consecutive frames with the truth inside the working range
(|dx|, |dy| <= 4 mm, dz 0-3.5 mm, |yaw| <= 15 deg, |pitch|, |roll| <= 40 deg).

Usage: /usr/bin/python3 docs/pose/gross_slip_oracle.py TRACE_DIR
Prints, per prior, how many of the runs diverge.
"""
import csv
import glob
import math
import os
import sys

RATE_FRAMES = 3
LIMIT_DEG = 5.0
AXES = ["gt_yaw", "gt_pitch", "gt_roll"]


def in_working_range(r):
    return (abs(float(r["gt_dx"])) <= 4 and abs(float(r["gt_dy"])) <= 4 and 0 <= float(r["gt_dz"]) <= 3.5
            and abs(float(r["gt_yaw"])) <= 15 and abs(float(r["gt_pitch"])) <= 40 and abs(float(r["gt_roll"])) <= 40)


def diverges(frames, gain):
    """gain(seconds_in_gross_slip) -> share of the held rate applied; 0 holds the turn."""
    error = [0.0, 0.0, 0.0]
    rate = [0.0, 0.0, 0.0]
    run = 0
    in_slip = 0.0
    for j in range(1, len(frames)):
        now, before = frames[j], frames[j - 1]
        if now["gt_contact"] != "1" or before["gt_contact"] != "1":
            error, run = [0.0, 0.0, 0.0], 0
            continue
        turn = [float(now[a]) - float(before[a]) for a in AXES]
        if now["gt_state"] == "slip":
            in_slip += float(now["t"]) - float(before["t"])
            g = gain(in_slip)
            error = [e + d - g * r for e, d, r in zip(error, turn, rate)]
        else:
            in_slip = 0.0
            if j >= RATE_FRAMES and all(frames[j - q]["gt_contact"] == "1" for q in range(RATE_FRAMES + 1)):
                rate = [(float(now[a]) - float(frames[j - RATE_FRAMES][a])) / RATE_FRAMES for a in AXES]
        run = run + 1 if in_working_range(now) and max(abs(e) for e in error) > LIMIT_DEG else 0
        if run > 3:
            return True
    return False


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    files = sorted(glob.glob(os.path.join(sys.argv[1], "*.csv")))
    if not files:
        sys.exit(f"{sys.argv[1]}: no trace files")
    priors = [("turn held (zero rate)", lambda t: 0.0), ("truth's rate held", lambda t: 1.0),
              ("rate decaying, tau 0.25 s", lambda t: math.exp(-t / 0.25)),
              ("rate decaying, tau 1 s", lambda t: math.exp(-t / 1.0))]
    runs = [list(csv.DictReader(open(f))) for f in files]
    for name, gain in priors:
        print(f"{name}: {sum(diverges(r, gain) for r in runs)} of {len(runs)} runs diverge")


if __name__ == "__main__":
    main()
