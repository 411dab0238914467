#!/usr/bin/python3
"""Charts of the haptic renderer's objective evaluation (like Fig. 7 of the
journal paper) and the kNN benchmark, from the CSVs in this folder.

Inputs (made by the programs in tests/bench/haptics/, see README.md):
  objective_evaluation.csv, objective_summary.csv, bench_knn.csv
Outputs: objective_fig7.png, objective_by_interaction.png, knn_speed.png
Run: /usr/bin/python3 docs/haptics/make_charts.py
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def read(name):
    with open(os.path.join(HERE, name), newline="") as f:
        return list(csv.DictReader(f))


def fig7(summary):
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
    fig.suptitle("Objective evaluation in simulation, mean +- SEM over the six interactions")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "objective_fig7.png"), dpi=110)


def by_interaction(rows):
    """Like Fig. 6: error vs DoF per interaction for n = 1, step 3 deg."""
    fig, ax = plt.subplots(figsize=(6, 4))
    for name in sorted({r["interaction"] for r in rows}):
        sel = [r for r in rows if r["interaction"] == name and r["neighbors"] == "1" and r["step_deg"] == "3"]
        sel.sort(key=lambda r: int(r["dof"]))
        ax.plot([int(r["dof"]) for r in sel], [float(r["normalized_error"]) for r in sel], marker="o", label=name)
    ax.set_xticks((1, 2, 3))
    ax.set_xlabel("device DoF")
    ax.set_ylabel("normalised error (Eq. 9)")
    ax.set_title("n = 1, step 3 deg")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "objective_by_interaction.png"), dpi=110)


def knn_speed(bench):
    rows = [r for r in bench if r.get("name") and "Render" in r["name"] or "Flann" in r.get("name", "")]
    rows = [r for r in rows if "Build" not in r["name"]]
    fig, ax = plt.subplots(figsize=(7, 3.5))
    names = [r["name"].split("/iterations")[0] for r in rows]
    cpu_us = [float(r["cpu_time"]) for r in rows]
    ax.barh(names, cpu_us)
    ax.set_xscale("log")
    ax.set_xlabel("CPU time per query, us (mean; log scale)")
    ax.set_title("kNN on 166,375 x 20 (one core)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "knn_speed.png"), dpi=110)


def main():
    summary = read("objective_summary.csv")
    fig7(summary)
    by_interaction(read("objective_evaluation.csv"))
    if os.path.exists(os.path.join(HERE, "bench_knn.csv")):
        lines = open(os.path.join(HERE, "bench_knn.csv")).read().splitlines()
        start = next(i for i, l in enumerate(lines) if l.startswith("name,"))
        knn_speed(list(csv.DictReader(lines[start:])))


if __name__ == "__main__":
    main()
