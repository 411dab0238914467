#!/usr/bin/python3
"""The reported uncertainty and the observable-truth judge on the pose campaign
(docs/pose/README.md, "Uncertainty").

Input: docs/pose/data/campaign_uncertainty.csv, from
  build/bench/pose_campaign --runs 300 --image-runs 40 --image-max-frames 200 \
    --out docs/pose/data/campaign_uncertainty.csv
(field level, seeds 1-300, and the first 40 seeds of at most 200 frames through rendered images). The sd options (pose::PoseUncertaintyOptions) were chosen on the odd seeds;
the even seeds are the acceptance set. Outputs:
  uncertainty_coverage.png       share of contact frames with |error| <= 2 sd per axis, odd and even field
                                 seeds and the rendered runs,
                                 and each run's median sd before gross slip against the limits
  data/uncertainty_summary.csv   the figures the README quotes
Run: /usr/bin/python3 docs/pose/make_uncertainty_charts.py [data_dir] [out_dir]
"""
import csv
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
AXES = ["dx", "dy", "dz", "yaw", "pitch", "roll"]
SD_LIMIT = [0.05] * 3 + [0.5] * 3  # median sd before gross slip, mm and deg


def load(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def coverage(runs, axis):
    frames = sum(int(r["sd_frames"]) for r in runs)
    return sum(float(r["within_2sd_" + axis]) * int(r["sd_frames"]) for r in runs) / frames


def median_sd(runs, axis):
    return statistics.median(float(r["median_sd_" + axis]) for r in runs if int(r["sd_frames_before_gross_slip"]) > 0)


def summary(runs):
    out = {"runs": len(runs),
           "diverged_full": sum(int(r["diverged"]) for r in runs),
           "diverged_observable": sum(int(r["observable_diverged"]) for r in runs),
           "diverged_both": sum(int(r["judged_diverged"]) for r in runs)}
    for a in AXES:
        out["within_2sd_" + a] = round(coverage(runs, a), 4)
        out["median_sd_" + a] = round(median_sd(runs, a), 4)
        linear = [float(r["obs_median_" + a]) for r in runs if int(r["linear_frames"]) > 0]
        out["obs_median_of_runs_" + a] = round(statistics.median(linear), 4)
        p95 = [float(r["obs_p95_" + a]) for r in runs if int(r["linear_frames"]) > 0]
        out["obs_p95_median_of_runs_" + a] = round(statistics.median(p95), 4)
    return out


def main():
    data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "data")
    out_dir = sys.argv[2] if len(sys.argv) > 2 else HERE
    runs = load(os.path.join(data, "campaign_uncertainty.csv"))
    field = [r for r in runs if r["level"] == "field"]
    sets = {"odd seeds (tuned on)": [r for r in field if int(r["seed"]) % 2 == 1],
            "even seeds (acceptance)": [r for r in field if int(r["seed"]) % 2 == 0],
            "rendered images (never tuned on)": [r for r in runs if r["level"] == "image"]}
    rows = []
    for name, subset in sets.items():
        s = summary(subset)
        s["set"] = name
        rows.append(s)
    with open(os.path.join(data, "uncertainty_summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["set"] + [k for k in rows[0] if k != "set"])
        w.writeheader()
        w.writerows(rows)

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    width = 0.27
    for i, (name, subset) in enumerate(sets.items()):
        xs = [k + (i - 1) * width for k in range(6)]
        left.bar(xs, [100 * coverage(subset, a) for a in AXES], width, label=name)
    left.axhspan(90, 99.5, color="tab:green", alpha=0.15, label="accepted band 90-99.5 %")
    left.set_xticks(range(6), AXES)
    left.set_ylim(80, 100)
    left.set_ylabel("contact frames with |error| <= 2 sd (%)")
    left.set_title("Is the reported sd honest? (against the full truth)")
    left.legend(loc="lower right", fontsize=8)
    even = sets["even seeds (acceptance)"]
    for k, a in enumerate(AXES):
        vals = [float(r["median_sd_" + a]) / SD_LIMIT[k] for r in even if int(r["sd_frames_before_gross_slip"]) > 0]
        right.boxplot(vals, positions=[k], widths=0.5, showfliers=True)
    right.axhline(1.0, color="tab:red", linestyle="--", label="limit: 0.05 mm, 0.5 deg")
    right.set_xticks(range(6), AXES)
    right.set_yscale("log")
    right.set_ylabel("median sd per run before gross slip / limit (log)")
    right.set_title("How wide is it? (even seeds, per run)")
    right.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "uncertainty_coverage.png"), dpi=110)
    for r in rows:
        print(r)


if __name__ == "__main__":
    main()
