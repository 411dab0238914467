#!/usr/bin/python3
"""Charts and summary of the front end's tracking campaign (issue 16).

Reads docs/vision/data/campaign_baseline.csv (the tracker before issue 16)
and docs/vision/data/campaign.csv (today's), both written by
build/bench/bench_vision_campaign on the same rendered runs, one row per frame.
Draws docs/vision/campaign_motion.png (in-contact detection and gross-error
rate against the motion per frame, in squares) and prints the summary table
of docs/vision/README.md.

Figures: "in contact" markers touch the finger in the simulator's truth and
lie in both views; detected = reported within 0.4 of a square of the truth in
both views; a gross error is a (marker, view) reported beyond that. The
worst frame counts frames with at least MIN_CONTACT in-contact markers (a
frame with one touching marker is 0 % or 100 %).
"""
import csv
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE / "data"
MIN_CONTACT = 10
BIN = 0.1  # squares per frame
SLOW = 0.5  # the acceptance's bound on the motion per frame


def load(path):
    with open(path) as f:
        return [dict(row) for row in csv.DictReader(f)]


def summarise(rows, keep):
    contact = found = gross = frames = 0
    worst = 1.0
    for r in rows:
        if not keep(r):
            continue
        c, d = int(r["contact_markers"]), int(r["contact_detected"])
        contact, found, gross, frames = contact + c, found + d, gross + int(r["gross"]), frames + 1
        if c >= MIN_CONTACT:
            worst = min(worst, d / c)
    return {"frames": frames, "contact": contact, "rate": found / contact if contact else math.nan,
            "worst": worst, "gross": gross}


def by_motion(rows):
    bins = {}
    for r in rows:
        if int(r["frame"]) == 0:
            continue
        k = min(int(float(r["motion_sq"]) / BIN), 20)
        b = bins.setdefault(k, [0, 0, 0, 0])
        b[0] += int(r["contact_markers"])
        b[1] += int(r["contact_detected"])
        b[2] += int(r["gross"])
        b[3] += 2 * int(r["markers"])  # (marker, view) pairs
    keys = sorted(bins)
    x = [(k + 0.5) * BIN for k in keys]
    detection = [bins[k][1] / bins[k][0] if bins[k][0] else math.nan for k in keys]
    gross = [bins[k][2] / bins[k][3] for k in keys]
    return x, detection, gross, [bins[k][0] for k in keys]


def breakpoint(rows):
    """The lowest motion bin where detection falls below 99.5 % or a gross error appears."""
    x, detection, gross, n = by_motion(rows)
    for xi, d, g, c in zip(x, detection, gross, n):
        if c >= 50 and (d < 0.995 or g > 0):
            return xi - BIN / 2
    return None


def main():
    runs = {}
    for name, label in (("campaign_baseline.csv", "before (issue 3 tracker)"), ("campaign.csv", "now")):
        if (DATA / name).exists():
            runs[label] = load(DATA / name)
    if not runs:
        print("no campaign CSVs in", DATA)
        return 0
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for label, rows in runs.items():
        x, detection, gross, _ = by_motion(rows)
        ax1.plot(x, [100 * d for d in detection], "o-", label=label)
        ax2.plot(x, [100 * g for g in gross], "o-", label=label)
    for ax in (ax1, ax2):
        ax.axvline(SLOW, color="grey", ls=":")
        ax.set_xlabel("largest marker motion per frame (squares)")
        ax.grid(alpha=0.3)
        ax.legend()
    ax1.set_ylabel("in-contact markers detected (%)")
    ax1.axhline(99.5, color="grey", ls="--", lw=0.8)
    ax2.set_ylabel("gross errors (% of marker-view pairs)")
    fig.suptitle("front-end tracking campaign: rendered runs, every density 9x9-25x25, noise 1-6, blur 0-1.2 px")
    fig.tight_layout()
    fig.savefig(HERE / "campaign_motion.png", dpi=110)

    print("| tracker | subset | frames | in-contact (marker, frame) | detected | worst frame (>= %d in contact) | gross errors |" % MIN_CONTACT)
    print("|---|---|---|---|---|---|---|")
    subsets = [
        ("motion <= 0.5 sq/frame, all runs", lambda r: float(r["motion_sq"]) <= SLOW),
        ("all frames, all runs", lambda r: True),
        ("scripted runs, motion <= 0.5", lambda r: r["kind"] != "random" and float(r["motion_sq"]) <= SLOW),
        ("random runs (halfspace), motion <= 0.5",
         lambda r: r["kind"] == "random" and r["model"] == "halfspace" and float(r["motion_sq"]) <= SLOW),
        ("random runs (foundation), motion <= 0.5",
         lambda r: r["kind"] == "random" and r["model"] == "foundation" and float(r["motion_sq"]) <= SLOW),
    ]
    for name, keep in subsets:
        for label, rows in runs.items():
            s = summarise(rows, keep)
            print("| %s | %s | %d | %d | %.2f %% | %.1f %% | %d |" % (label, name, s["frames"], s["contact"],
                                                                    100 * s["rate"], 100 * s["worst"], s["gross"]))
    for label, rows in runs.items():
        b = breakpoint(rows)
        print("%s: breaks at %s squares per frame" % (label, "%.1f" % b if b is not None else "no bin"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
