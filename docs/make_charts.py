#!/usr/bin/python3
"""Draws the benchmark charts under docs/ from the CSVs in docs/data/.

Run by tests/bench/run_all.sh after the benchmarks. Each chart is made only if
its CSV exists; module-specific chart scripts (docs/<module>/make_charts.py)
are run too.
"""
import csv
import pathlib
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DOCS = pathlib.Path(__file__).resolve().parent
DATA = DOCS / "data"


def median_rows(path):
    """The *_median rows of a Google Benchmark CSV file, as dicts."""
    with open(path) as f:
        lines = f.readlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("name,"))
    return [row for row in csv.DictReader(lines[start:]) if row["name"].endswith("_median")]


def medians(path):
    """{(benchmark name without aggregate suffix, label): cpu_time in ms} for *_median rows."""
    out = {}
    for row in median_rows(path):
        unit = row.get("time_unit", "ns")
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[unit]
        name = row["name"].rsplit("/repeats", 1)[0]
        out[(name, row.get("label", ""))] = float(row["cpu_time"]) * scale
    return out


def median_counter(path, counter):
    """{label: value of a user counter} for *_median rows that carry it."""
    return {row.get("label", ""): float(row[counter]) for row in median_rows(path) if row.get(counter)}


def chart_simulator():
    path = DATA / "bench_sim_step.csv"
    if not path.exists():
        return
    m = medians(path)
    field = [(label, t) for (name, label), t in m.items() if name.startswith("BM_FieldStep")]
    worst = median_counter(path, "worst_step_ms")
    image = [(label, t) for (name, label), t in m.items() if name.startswith("BM_ImageFrame")]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    ax = axes[0]
    ax.barh([l for l, _ in field], [t for _, t in field], color="tab:blue", label="median step")
    if worst:
        ax.plot([worst.get(l, float("nan")) for l, _ in field], [l for l, _ in field], "k|", ms=14,
                label="slowest step (new contact set)")
    ax.axvline(1.0, color="tab:red", ls="--", label="budget 1 ms")
    ax.set_xscale("log")
    ax.set_xlabel("CPU time per field-level step (ms, median, one core)")
    ax.set_title("Contact model step, 17x17 markers")
    ax.legend(loc="lower right", fontsize=8)
    ax = axes[1]
    ax.barh([l for l, _ in image], [t for _, t in image], color="tab:green")
    ax.axvline(100.0, color="tab:red", ls="--", label="budget 100 ms")
    ax.set_xlabel("CPU time per 1920x1080 frame (ms, median, one core)")
    ax.set_title("Image-level frame (step + render)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(DOCS / "sim_speed.png", dpi=110)
    print("wrote", DOCS / "sim_speed.png")


def main():
    chart_simulator()
    for script in sorted(DOCS.glob("*/make_charts.py")):
        subprocess.run([sys.executable, str(script)], check=True)


if __name__ == "__main__":
    main()
