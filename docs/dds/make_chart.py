#!/usr/bin/python3
"""Draws docs/dds/latency.png from docs/dds/bench_dds_latency.json (the
Google Benchmark JSON of tests/bench/dds/bench_dds_latency, median of the
repetitions): one-way latency median and p99 per stream and link."""
import json
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = pathlib.Path(__file__).resolve().parent


def rows():
    runs = json.loads((here / "bench_dds_latency.json").read_text())["benchmarks"]
    out = {}
    for r in runs:
        if r.get("aggregate_name", "median") == "median":
            out["/".join(r["name"].split("/")[:2])] = r
    return out


def main():
    data = rows()
    streams = [("joy", "Frames30Hz", "joy 30 Hz"), ("pose", "Frames30Hz", "pose 30 Hz"),
               ("markers", "Frames30Hz", "markers 30 Hz\n(11.6 kB)"), ("events", "Frames30Hz", "events 30 Hz\n(reliable)"),
               ("sensed", "Frames30Hz", "sensed 30 Hz\n(75 ch)"), ("sensed", "Sensed1kHz", "sensed 1 kHz\n(20 ch)")]
    links = [("BM_InProcess", "in process (Cyclone)", "#999999"), ("BM_Loopback", "loopback (Cyclone -> Fast DDS)", "#1f77b4"),
             ("BM_Namespaces", "two netns, veth (Cyclone -> Fast DDS)", "#ff7f0e")]
    fig, ax = plt.subplots(figsize=(10, 4.5))
    width = 0.27
    for j, (bench, label, color) in enumerate(links):
        p50, p99, xs = [], [], []
        for i, (topic, load, _) in enumerate(streams):
            r = data.get(f"{bench}/{load}")
            if not r or not r.get(f"{topic}_p50_us"):
                continue
            xs.append(i + (j - 1) * width)
            p50.append(float(r[f"{topic}_p50_us"]))
            p99.append(float(r[f"{topic}_p99_us"]))
        ax.bar(xs, p50, width, color=color, label=label + ": median")
        ax.scatter(xs, p99, color=color, marker="_", s=300, linewidths=2, label=label + ": p99")
    ax.set_xticks(range(len(streams)))
    ax.set_xticklabels([s[2] for s in streams], fontsize=8)
    ax.set_ylabel("publisher -> subscriber latency (us)")
    ax.set_title("onetip over DDS: one-way latency per stream (2-core machine)")
    ax.legend(fontsize=7, ncol=2)
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(here / "latency.png", dpi=110)


if __name__ == "__main__":
    main()
