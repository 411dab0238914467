#!/usr/bin/python3
"""Charts of the haptic renderer's objective evaluation (like Fig. 7 of the
journal paper), the choice of onetip's contact-field feature and the kNN
benchmark, from the CSVs in this folder.

Inputs (made by the programs in tests/bench/haptics/, see README.md):
  objective_<sensor>_evaluation.csv, objective_<sensor>_summary.csv  (sensor: biotac, onetip)
  onetip_features.csv, bench_knn.json (Google Benchmark JSON), neighbor_benefit.csv
Outputs: objective_fig7_<sensor>.png, objective_by_interaction_<sensor>.png,
  onetip_features.png, knn_speed.png, neighbor_benefit.png
Run: /usr/bin/python3 docs/haptics/make_charts.py
"""
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SENSORS = {"biotac": "BioTac-like (20 channels)", "onetip": "onetip pad, 5 x 5 marker grid (75 channels)"}


def read(name):
    with open(os.path.join(HERE, name), newline="") as f:
        return list(csv.DictReader(f))


def fig7(summary, sensor):
    """Mean +- SEM normalised error vs DoF (top, one panel per n) and vs step (bottom)."""
    fig, axes = plt.subplots(2, 3, figsize=(12, 7), sharey=True)
    key = lambda r: (float(r["step_deg"]), int(r["neighbors"]), int(r["dof"]))
    data = {key(r): (float(r["mean_normalized_error"]), float(r["sem_normalized_error"])) for r in summary}
    for col, n in enumerate((1, 4, 8)):
        ax = axes[0][col]
        for step in (3.0, 6.0, 9.0):
            ys = [data[(step, n, d)] for d in (1, 2, 3)]
            ax.errorbar((1, 2, 3), [y[0] for y in ys], yerr=[y[1] for y in ys], marker="o", capsize=3,
                        label=f"step {step:g} deg")
        ax.set_title(f"n = {n}")
        ax.set_xticks((1, 2, 3))
        ax.set_xlabel("device DoF")
        ax = axes[1][col]
        for dof in (1, 2, 3):
            ys = [data[(s, n, dof)] for s in (3.0, 6.0, 9.0)]
            ax.errorbar((3, 6, 9), [y[0] for y in ys], yerr=[y[1] for y in ys], marker="s", capsize=3,
                        label=f"{dof}-DoF")
        ax.set_xticks((3, 6, 9))
        ax.set_xlabel("step size (deg)")
    axes[0][0].set_ylabel("normalised error (Eq. 9)")
    axes[1][0].set_ylabel("normalised error (Eq. 9)")
    axes[0][0].legend(fontsize=8)
    axes[1][0].legend(fontsize=8)
    fig.suptitle(f"Objective evaluation in simulation, {SENSORS[sensor]}: mean +- SEM over the six interactions")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, f"objective_fig7_{sensor}.png"), dpi=110)
    plt.close(fig)


def by_interaction(rows, sensor):
    """Like Fig. 6: error vs DoF per interaction for n = 1, step 3 deg."""
    fig, ax = plt.subplots(figsize=(6, 4))
    for name in sorted({r["interaction"] for r in rows}):
        sel = [r for r in rows if r["interaction"] == name and r["neighbors"] == "1" and r["step_deg"] == "3"]
        sel.sort(key=lambda r: int(r["dof"]))
        ax.plot([int(r["dof"]) for r in sel], [float(r["normalized_error"]) for r in sel], marker="o", label=name)
    ax.set_xticks((1, 2, 3))
    ax.set_xlabel("device DoF")
    ax.set_ylabel("normalised error (Eq. 9)")
    ax.set_title(f"{SENSORS[sensor]}: n = 1, step 3 deg", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, f"objective_by_interaction_{sensor}.png"), dpi=110)
    plt.close(fig)


def onetip_features(rows):
    """Full-field error of each feature, per condition (3-DoF) and mean over all 27."""
    features = []
    for r in rows:
        if r["feature"] not in features:
            features.append(r["feature"])
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4))
    for f in features:
        sel = [r for r in rows if r["feature"] == f and r["dof"] == "3"]
        labels = [f"{float(r['step_deg']):g}/{r['neighbors']}" for r in sel]
        ax1.plot(labels, [float(r["field_eq9"]) for r in sel], marker="o", label=f)
    ax1.set_xlabel("step (deg) / neighbours, 3-DoF")
    ax1.set_ylabel("full-field Eq. 9 error")
    ax1.legend(fontsize=8)
    means = [sum(float(r["field_eq9"]) for r in rows if r["feature"] == f) / 27.0 for f in features]
    ax2.bar(features, means)
    ax2.set_ylabel("full-field Eq. 9 error, mean of 27 conditions")
    fig.suptitle("onetip: which fixed-length feature of the contact field renders best")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "onetip_features.png"), dpi=110)
    plt.close(fig)


def knn_speed(bench):
    """Per-query CPU medians of the leaf-size sweep and tree vs brute force (same run)."""
    leaf = [r for r in bench if r["name"].startswith("BM_KdTreeLeafSizeCpu/")]
    pair = [r for r in bench if r["name"].startswith("BM_TreeVsBruteCpu/") and r.get("aggregate_name") == "median"]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 3.8))
    ax1.plot([int(r["name"].split("/")[1]) for r in leaf], [float(r["median_us"]) for r in leaf], marker="o",
             label="median")
    ax1.plot([int(r["name"].split("/")[1]) for r in leaf], [float(r["mean_us"]) for r in leaf], marker="s",
             label="mean")
    ax1.set_xscale("log", base=2)
    ax1.set_xlabel("leaf size")
    ax1.set_ylabel("CPU us per query (n = 8)")
    ax1.legend(fontsize=8)
    names = []
    values = []
    for r in pair:
        leaf_size = r["name"].split("/")[2]
        names += [f"tree, leaf {leaf_size}", f"brute force (leaf {leaf_size} run)"]
        values += [float(r["tree_median_us"]), float(r["brute_median_us"])]
    ax2.barh(names, values)
    ax2.set_xscale("log")
    ax2.set_xlabel("median CPU us per query, n = 8 (log)")
    fig.suptitle("kNN on 166,375 x 20, one core")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "knn_speed.png"), dpi=110)
    plt.close(fig)


def neighbor_benefit(rows):
    """Change of the mean Eq. 9 error from n = 1 to n = 4 and 8, per DoF: against the side interactions'
    tilt (top), and at the default 30 deg tilt with more sensor noise or the paper's servos (bottom)."""
    error = {(float(r["side_tilt_deg"]), float(r["noise_counts"]), int(r["servo_dynamics"]), int(r["dof"]),
              int(r["neighbors"])): float(r["mean_normalized_error"]) for r in rows}
    change = lambda run, dof, n: 100.0 * (error[run + (dof, n)] / error[run + (dof, 1)] - 1.0)
    tilts = sorted({k[0] for k in error if k[1:3] == (2.0, 0)})
    variants = [((30.0, 2.0, 0), "2 counts\n(docs)"), ((30.0, 10.0, 0), "10 counts"), ((30.0, 30.0, 0), "30 counts"),
                ((30.0, 2.0, 1), "2 counts,\npaper's servos")]
    fig, axes = plt.subplots(2, 3, figsize=(12, 6.8), sharey="row")
    for col, dof in enumerate((1, 2, 3)):
        ax = axes[0][col]
        for n, style in ((4, "o-"), (8, "s-")):
            ax.plot(tilts, [change((t, 2.0, 0), dof, n) for t in tilts], style, label=f"n = {n}")
        ax.axhline(0.0, color="k", lw=0.8)
        ax.set_title(f"{dof}-DoF display")
        ax.set_xlabel("side interactions' plate tilt (deg)")
        ax.grid(alpha=0.3)
        ax = axes[1][col]
        xs = range(len(variants))
        for n, offset in ((4, -0.18), (8, 0.18)):
            ax.bar([x + offset for x in xs], [change(v, dof, n) for v, _ in variants], width=0.34, label=f"n = {n}")
        ax.axhline(0.0, color="k", lw=0.8)
        ax.set_xticks(list(xs))
        ax.set_xticklabels([label for _, label in variants], fontsize=8)
        ax.set_xlabel("at 30 deg tilt: sensor noise / device model")
        ax.grid(alpha=0.3, axis="y")
    axes[0][0].set_ylabel("e_f change vs n = 1 (%)\n(below 0: neighbours help)")
    axes[1][0].set_ylabel("e_f change vs n = 1 (%)")
    axes[0][0].legend(fontsize=8)
    axes[1][0].legend(fontsize=8)
    fig.suptitle("BioTac-like model: more neighbours help while the remote contacts stay reachable;\n"
                 "noise and servo dynamics do not change that")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "neighbor_benefit.png"), dpi=110)
    plt.close(fig)


def main():
    for sensor in SENSORS:
        if os.path.exists(os.path.join(HERE, f"objective_{sensor}_summary.csv")):
            fig7(read(f"objective_{sensor}_summary.csv"), sensor)
            by_interaction(read(f"objective_{sensor}_evaluation.csv"), sensor)
    if os.path.exists(os.path.join(HERE, "onetip_features.csv")):
        onetip_features(read("onetip_features.csv"))
    if os.path.exists(os.path.join(HERE, "neighbor_benefit.csv")):
        neighbor_benefit(read("neighbor_benefit.csv"))
    if os.path.exists(os.path.join(HERE, "bench_knn.json")):
        with open(os.path.join(HERE, "bench_knn.json")) as f:
            knn_speed(json.load(f)["benchmarks"])


if __name__ == "__main__":
    main()
