#!/usr/bin/python3
"""Charts of the pose benchmarks (docs/pose/*.png) from the CSVs in docs/pose/data.

Inputs (written by build/bench/bench_pose and build/bench/pose_accuracy_table,
see README.md): solvers.csv, density.csv, noise.csv, bench_pose.csv.
Run: /usr/bin/python3 docs/pose/make_charts.py [data_dir] [out_dir]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def benchmark_rows(path):
    """Google Benchmark CSV: skip the context lines before the header."""
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("name,"))
    return list(csv.DictReader(lines[start:]))


def solvers_chart(data, out):
    table = rows(os.path.join(data, "solvers.csv"))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for row in table:
        marker = "o" if row["accumulation"] == "composed" else "x"
        label = f'{row["policy"]} / {row["accumulation"]}'
        ms = float(row["ms_per_frame"])
        axes[0].scatter(ms, float(row["trans_rmse_mm"]), marker=marker, label=label)
        axes[1].scatter(ms, float(row["rot_rmse_deg"]), marker=marker, label=label)
    axes[0].set_ylabel("translation RMSE (mm)")
    axes[1].set_ylabel("rotation RMSE (deg)")
    for ax in axes:
        ax.set_xlabel("contact + pose + accumulation, median ms per frame")
        ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=7, loc="best")
    fig.suptitle("Accuracy against time per frame, per solver and accumulation (17x17, noise 0.0006 mm)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "accuracy_vs_time.png"), dpi=120)
    plt.close(fig)


def panel(ax, x, y, ylabel, xlabel, target=None, target_label=None):
    ax.plot(x, y, "o-")
    if target is not None:
        ax.axhline(target, color="r", ls="--", lw=0.8, label=target_label)
        if target_label:
            ax.legend(fontsize=8)
    ax.set_ylabel(ylabel)
    ax.set_xlabel(xlabel)
    ax.grid(True, alpha=0.3)


def density_chart(data, out):
    table = rows(os.path.join(data, "density.csv"))
    n = [int(r["markers"]) for r in table]
    fig, ax = plt.subplots(1, 3, figsize=(12, 3.6))
    xlabel = "markers per side (same 19.2 mm pad)"
    panel(ax[0], n, [float(r["trans_rmse_mm"]) for r in table], "translation RMSE (mm)", xlabel, 0.05)
    panel(ax[1], n, [float(r["rot_rmse_deg"]) for r in table], "rotation RMSE (deg)", xlabel, 1.0)
    panel(ax[2], n, [float(r["ms_per_frame"]) for r in table], "median ms per frame", xlabel, 0.5)
    for a in ax:
        a.set_xticks(n)
    fig.suptitle("Marker density (noise 0.0006 mm)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "accuracy_vs_density.png"), dpi=120)
    plt.close(fig)


def noise_chart(data, out):
    table = rows(os.path.join(data, "noise.csv"))
    s = [float(r["noise_mm"]) for r in table]
    fig, ax = plt.subplots(1, 3, figsize=(12, 3.6))
    xlabel = "marker noise, mm per axis"
    panel(ax[0], s, [float(r["trans_rmse_mm"]) for r in table], "translation RMSE (mm)", xlabel, 0.05, "target 0.05 mm")
    panel(ax[1], s, [float(r["rot_rmse_deg"]) for r in table], "rotation RMSE (deg)", xlabel, 1.0, "target 1 deg")
    panel(ax[2], s, [float(r["slip_f1"]) for r in table], "slip F1 (slides)", xlabel, 0.9, "target 0.9")
    for a in ax:  # the rendered front end measures 0.0006 mm per axis
        a.set_xscale("symlog", linthresh=3e-4)
        a.set_xlim(0, 0.015)
        a.axvline(0.0006, color="grey", linestyle=":", linewidth=1)
    fig.suptitle("Measurement noise (17x17; dotted: the rendered front end's 0.0006 mm)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "accuracy_vs_noise.png"), dpi=120)
    plt.close(fig)


def timing_chart(data, out):
    table = [r for r in benchmark_rows(os.path.join(data, "bench_pose.csv")) if r["name"].endswith("_median")]
    names = [r["name"].replace("_median", "") + ("\n" + r["label"] if r.get("label") else "") for r in table]
    us = [float(r["real_time"]) / 1000.0 for r in table]
    fig, ax = plt.subplots(figsize=(10, 3.8))
    ax.barh(names, us)
    ax.axvline(500, color="r", ls="--", lw=0.8, label="budget 0.5 ms")
    ax.set_xlabel("median microseconds per frame (one core)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_per_frame.png"), dpi=120)
    plt.close(fig)


def main():
    data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "data")
    out = sys.argv[2] if len(sys.argv) > 2 else HERE
    solvers_chart(data, out)
    density_chart(data, out)
    noise_chart(data, out)
    timing_chart(data, out)


if __name__ == "__main__":
    main()
