#!/usr/bin/python3
"""Charts and the summary table of the pose campaign (docs/pose/README.md, "Campaign").

Inputs (build/bench/pose_campaign, see README.md): docs/pose/data/campaign.csv
(this estimator) and docs/pose/data/campaign_baseline.csv (the first estimator,
constant thresholds, built from commit 182873e; same seeds, same simulator). Outputs:
  campaign_conditions.png   worst linear-range RMSE per run against each condition
  campaign_envelope.png     share of diverged runs per condition bin
  campaign_accuracy_time.png accuracy against time per frame, per contact model
  campaign_stick_truth.png  the stick labels against the simulator's per-marker truth, and what the
                            truth offered where each divergence began (this estimator's file only)
  data/campaign_summary.csv the figures docs/pose/README.md quotes
Run: /usr/bin/python3 docs/pose/make_campaign_charts.py [data_dir] [out_dir]
"""
import csv
import math
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
AXES = ["dx", "dy", "dz", "yaw", "pitch", "roll"]
ESTIMATORS = [("campaign_baseline.csv", "first estimator (constant thresholds)", "tab:gray"),
              ("campaign.csv", "this estimator (derived thresholds, rolling-aware, thin stick sets, way back, a region per finger)",
               "tab:blue")]


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def worst(r, kind):
    axes = AXES[:3] if kind == "mm" else AXES[3:]
    return max(float(r["rmse_" + a]) for a in axes)


def percentile(values, q):
    values = sorted(values)
    if not values:
        return float("nan")
    k = (len(values) - 1) * q
    lo, hi = math.floor(k), math.ceil(k)
    return values[lo] + (values[hi] - values[lo]) * (k - lo)


def summary(all_rows, name):
    out = []
    for level in ("field", "image"):
        rs = [r for r in all_rows if r["level"] == level and int(r["linear_frames"]) > 0]
        if not rs:
            continue
        row = {"estimator": name, "level": level, "runs": len(rs),
               "diverged": sum(r["diverged"] == "1" for r in rs)}
        for a in AXES:
            v = [float(r["rmse_" + a]) for r in rs]
            row["median_" + a] = statistics.median(v)
            row["p95_" + a] = percentile(v, 0.95)
        out.append(row)
    return out


CONDITIONS = [("noise_grey", "image noise (grey levels)", False), ("markers", "markers per side", False),
              ("fps", "frame rate (fps)", True), ("friction", "friction", False),
              ("peak_speed_mm_s", "fastest slide (mm/s)", False), ("peak_rate_deg_s", "fastest turn (deg/s)", False)]


def conditions_chart(data, out_dir):
    fig, grid = plt.subplots(2, len(CONDITIONS), figsize=(4 * len(CONDITIONS), 7), sharey="row")
    for col, (key, label, log) in enumerate(CONDITIONS):
        for row_i, kind in enumerate(("mm", "deg")):
            ax = grid[row_i][col]
            for (_, name, colour), rs in data:
                rs = [r for r in rs if r["level"] == "field" and int(r["linear_frames"]) > 0]
                x = [float(r[key]) for r in rs]
                y = [worst(r, kind) for r in rs]
                ax.scatter(x, y, s=6, alpha=0.5, color=colour, label=name)
            ax.set_yscale("log")
            if log:
                ax.set_xscale("log")
            ax.axhline(0.1 if kind == "mm" else 2.6, color="red", lw=0.8, ls="--")
            if row_i == 1:
                ax.set_xlabel(label)
            if col == 0:
                ax.set_ylabel("worst translation RMSE (mm)" if kind == "mm" else "worst rotation RMSE (deg)")
    fig.legend(*grid[0][0].get_legend_handles_labels(), fontsize=9, loc="lower center", ncol=2, markerscale=3)
    fig.suptitle("Pose campaign, field level: each run's worst axis in the linear range against its conditions "
                 "(red: the paper's worst figures)")
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    fig.savefig(os.path.join(out_dir, "campaign_conditions.png"), dpi=80)
    plt.close(fig)


TURN_BINS = [("0", 0, 1e-9), ("0-1", 1e-9, 1), ("1-5", 1, 5), ("5-15", 5, 15), (">= 15", 15, 1e9)]


def envelope_chart(data, out_dir):
    keys = [("model", "contact model"), ("indenter", "indenter"), ("markers", "markers per side"),
            ("fps", "frame rate"), ("gross_slip_turn_deg", "the truth's turn in gross slip (deg)"),
            ("gross_slip_turn_before_excess_deg", "the truth's turn in gross slip before it diverged (deg)")]
    fig, axes = plt.subplots(2, 3, figsize=(13.5, 8.5))
    grid = axes.flatten()
    for ax, (key, label) in zip(grid, keys):
        for offset, ((_, name, colour), rs) in zip((-0.2, 0.2), data):
            # The turn before the divergence depends on the estimator: files written
            # before it was a column have no bars there.
            rs = [r for r in rs if r["level"] == "field" and r.get(key, "nan") != "nan"]
            if not rs:
                continue
            if key == "fps":
                bins = [(15, 30), (30, 60), (60, 120), (120, 241)]
                groups = [("%d-%d" % b, [r for r in rs if b[0] <= float(r["fps"]) < b[1]]) for b in bins]
            elif key.startswith("gross_slip_turn"):
                groups = [(label_, [r for r in rs if lo <= float(r[key]) < hi]) for label_, lo, hi in TURN_BINS]
            else:
                values = sorted({r[key] for r in rs}, key=lambda v: (len(v), v))
                groups = [(v, [r for r in rs if r[key] == v]) for v in values]
            if key == "gross_slip_turn_before_excess_deg":  # the diverged runs, counted
                share = [sum(r["diverged"] == "1" for r in g) for _, g in groups]
                ax.set_ylabel("diverged runs")
            else:
                share = [100.0 * sum(r["diverged"] == "1" for r in g) / max(1, len(g)) for _, g in groups]
                ax.set_ylim(0, 100)
            ax.bar([i + offset for i in range(len(groups))], share, width=0.4, color=colour, label=name)
            ax.set_xticks(range(len(groups)))
            ax.set_xticklabels([g for g, _ in groups], rotation=45, fontsize=8)
        ax.set_xlabel(label)
    grid[0].set_ylabel("runs diverged (%)")
    grid[3].set_ylabel("runs diverged (%)")
    fig.legend(*grid[0].get_legend_handles_labels(), fontsize=9, loc="lower center", ncol=2)
    fig.suptitle("Failure envelope: share of runs with an axis beyond 1 mm / 5 deg for more than 3 frames")
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    fig.savefig(os.path.join(out_dir, "campaign_envelope.png"), dpi=80)
    plt.close(fig)


def accuracy_time_chart(data, out_dir):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.5))
    for (_, name, colour), rs in data:
        for model, marker in (("halfspace", "o"), ("foundation", "s")):
            g = [r for r in rs if r["level"] == "field" and r["model"] == model and int(r["linear_frames"]) > 0]
            if not g:
                continue
            ms = statistics.median(float(r["ms_per_frame"]) for r in g)
            a1.scatter(ms, statistics.median(worst(r, "mm") for r in g), color=colour, marker=marker, s=60,
                       label="%s, %s" % (name, model))
            a2.scatter(ms, statistics.median(worst(r, "deg") for r in g), color=colour, marker=marker, s=60)
    a1.set_xlabel("contact + pose per frame, median (ms)")
    a2.set_xlabel("contact + pose per frame, median (ms)")
    a1.set_ylabel("median of the runs' worst translation RMSE (mm)")
    a2.set_ylabel("median of the runs' worst rotation RMSE (deg)")
    fig.legend(*a1.get_legend_handles_labels(), fontsize=8, loc="lower center", ncol=2)
    fig.suptitle("Accuracy against time per frame, per contact model (field level; times as the campaign ran,\n"
                 "on a shared machine: bench_pose, alternating binaries, is the speed figure)")
    fig.tight_layout(rect=(0, 0.12, 1, 1))
    fig.savefig(os.path.join(out_dir, "campaign_accuracy_time.png"), dpi=80)
    plt.close(fig)


def stick_truth_chart(data, out_dir):
    rs = [r for (file, _, _), rows_ in data if file == "campaign.csv" for r in rows_
          if r["level"] == "field" and "stick_precision" in r]
    if not rs:
        return
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.5))
    models = ("halfspace", "foundation")
    for i, model in enumerate(models):
        g = [r for r in rs if r["model"] == model and int(r["contact_frames"]) > 0]
        for offset, key, colour in ((-0.2, "stick_precision", "tab:blue"), (0.2, "stick_recall", "tab:orange")):
            v = [float(r[key]) for r in g]
            a1.boxplot(v, positions=[i + offset], widths=0.3, patch_artist=True,
                       boxprops={"facecolor": colour, "alpha": 0.6}, medianprops={"color": "black"})
    a1.set_xticks(range(len(models)))
    a1.set_xticklabels(models)
    a1.set_xlim(-0.6, len(models) - 0.4)
    a1.set_ylim(0, 1.02)
    a1.set_ylabel("per run")
    a1.legend(handles=[plt.Rectangle((0, 0), 1, 1, color="tab:blue", alpha=0.6),
                       plt.Rectangle((0, 0), 1, 1, color="tab:orange", alpha=0.6)],
              labels=["precision: labelled stick that truly touch and stick",
                      "recall: truly touching and sticking labelled stick"], fontsize=8, loc="lower center")
    a1.set_title("Stick labels against the simulator's truth", fontsize=10)
    bins = [("0", lambda n: n == 0), ("1-2", lambda n: 1 <= n <= 2), (">= 3", lambda n: n >= 3)]
    states = [("stick", "tab:green"), ("partial_slip", "tab:olive"), ("slip", "tab:red")]
    diverged = [r for r in rs if r["diverged"] == "1"]
    bottom = [0] * len(bins)
    for state, colour in states:
        h = [sum(1 for r in diverged if r["excess_truth_state"] == state and test(int(r["excess_true_stick"])))
             for _, test in bins]
        a2.bar(range(len(bins)), h, bottom=bottom, color=colour, label="truth " + state)
        bottom = [b + x for b, x in zip(bottom, h)]
    a2.set_ylim(0, 1.12 * max(max(bottom), 1))
    a2.set_xticks(range(len(bins)))
    a2.set_xticklabels([b for b, _ in bins])
    a2.set_xlabel("markers truly touching and sticking where the divergence began")
    a2.set_ylabel("diverged runs")
    a2.legend(fontsize=8)
    a2.set_title("What the truth offered: fewer than 3 cannot fix a rotation", fontsize=10)
    fig.suptitle("Field level, this estimator (%d runs, %d diverged)" % (len(rs), len(diverged)))
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "campaign_stick_truth.png"), dpi=80)
    plt.close(fig)


def main():
    data_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "data")
    out_dir = sys.argv[2] if len(sys.argv) > 2 else HERE
    data = []
    table = []
    for file, name, colour in ESTIMATORS:
        path = os.path.join(data_dir, file)
        if os.path.exists(path):
            rs = rows(path)
            data.append(((file, name, colour), rs))
            table += summary(rs, name)
    # The truth's turn in gross slip is a condition of the seed (same simulator,
    # same seeds): runs from files written before it was a column borrow it.
    turn = {(r["level"], r["seed"]): r["gross_slip_turn_deg"] for _, rs in data for r in rs
            if r.get("gross_slip_turn_deg")}
    for _, rs in data:
        for r in rs:
            r.setdefault("gross_slip_turn_deg", turn.get((r["level"], r["seed"]), "nan"))
    conditions_chart(data, out_dir)
    envelope_chart(data, out_dir)
    accuracy_time_chart(data, out_dir)
    stick_truth_chart(data, out_dir)
    fields = list(table[0].keys())
    with open(os.path.join(data_dir, "campaign_summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for row in table:
            w.writerow({k: ("%.4g" % v if isinstance(v, float) else v) for k, v in row.items()})
    for row in table:
        print(row["estimator"], row["level"], "runs", row["runs"], "diverged", row["diverged"],
              "median", " ".join("%.3f" % row["median_" + a] for a in AXES),
              "p95", " ".join("%.3f" % row["p95_" + a] for a in AXES))
    for (_, name, _), rs in data:
        for level in ("field", "image"):
            for label_, lo, hi in TURN_BINS:
                g = [r for r in rs if r["level"] == level and lo <= float(r["gross_slip_turn_deg"]) < hi]
                if g:
                    print("%s %s, truth turns %s deg in gross slip: %d runs, %d diverged" % (
                        name, level, label_, len(g), sum(r["diverged"] == "1" for r in g)))
            diverged = [r for r in rs if r["level"] == level and r["diverged"] == "1"
                        and r.get("gross_slip_turn_before_excess_deg", "nan") != "nan"]
            for label_, lo, hi in TURN_BINS if diverged else []:
                n = sum(lo <= float(r["gross_slip_turn_before_excess_deg"]) < hi for r in diverged)
                print("%s %s, diverged after the truth turned %s deg in gross slip: %d of %d" % (
                    name, level, label_, n, len(diverged)))


if __name__ == "__main__":
    main()
