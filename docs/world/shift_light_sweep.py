#!/usr/bin/python3
"""A shifted camera or mirror, flicker and exposure steps, swept over their size (issue 38's acceptance lines for
them), rendered through `onetip demo`.

Every run plays one motion: 2 s of rest, a press to 1 mm, a slide of 1 mm along x, a lift-off (the contact that
follows a shift). Each effect is laid over it, and the run is compared with its twin without the effect and with
the spread of six twins that differ only in the image noise's seed (what "unchanged" can mean):
  shift   the camera (both views) or one mirror (left, right) moves by 1-5 px in one of three directions, as a
          step long before the touch (0.5 s), as a step 2 frames before it, or as a ramp over the second before it;
  light   frame-to-frame flicker of +-2 to +-10 % and an exposure step of -30 to +30 %, before the touch or while
          the finger presses.
Per run: false contact frames (the estimate in contact where the truth is not), the onset's delay against the
truth's (frames), the notices `onetip demo` prints (tools/sensor_notices.hpp: "the camera moved ...", "the left
mirror moved ..."), and the RMS error of each axis over the frames in contact beside the twin's.

Writes data/shift_light_sweep.csv and shift_light_sweep.png beside this file.
Run: /usr/bin/python3 docs/world/shift_light_sweep.py [path/to/onetip] [--jobs=N]   (about 10 minutes on 2 cores);
     --chart-only redraws the chart from the CSV.
"""
import csv
import math
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
AXES = ["dx", "dy", "dz", "yaw", "pitch", "roll"]
FPS = 30
TOUCH_S = 2.2  # the finger reaches the surface (depth 0) here
MOTION = f"""fps: {FPS}
indenters:
  - shape: ellipsoid
    semi_axes: [7, 9, 6]
    keyframes:
      - {{t: 0.0, x: 0, y: 0, depth: -0.3}}
      - {{t: 2.0, depth: -0.3}}
      - {{t: {TOUCH_S}, depth: 0.0}}
      - {{t: 3.0, depth: 1.0}}
      - {{t: 3.3, depth: 1.0}}
      - {{t: 4.8, x: 1.0}}
      - {{t: 5.1, x: 1.0}}
      - {{t: 5.8, depth: -0.3}}
"""


NOISE_SEEDS = range(1, 7)


def cases():
    for seed in NOISE_SEEDS:  # the first is the twin of every effect run (seed 1, the scenario default)
        yield {"effect": "none", "seed": seed, "yaml": f"seed: {seed}\n"}
    for view in ("both", "left", "right"):
        for size in (1, 2, 3, 4, 5):
            for angle in (0, 90, 225):
                px = [round(size * math.cos(math.radians(angle)), 3), round(size * math.sin(math.radians(angle)), 3)]
                for timing, at, ramp in (("step_early", 0.5, 0), ("step_late", TOUCH_S - 2.0 / FPS, 0),
                                         ("ramp", TOUCH_S - 1.0, 0.9)):
                    yield {"effect": "shift", "view": view, "size": size, "angle": angle, "timing": timing,
                           "yaml": f"camera_shift: {{px: {px}, at_s: {at}, ramp_s: {ramp}, view: {view}}}\n"}
    for flicker in (0.02, 0.05, 0.1):
        for step in (-0.3, -0.15, 0.15, 0.3):
            for timing, at in (("before", 1.0), ("pressing", 3.1)):
                yield {"effect": "light", "flicker": flicker, "step": step, "timing": timing,
                       "yaml": f"light: {{flicker: {flicker}, exposure_step: {step}, step_at_s: {at}}}\n"}


def play(onetip, work, index, case):
    scenario = os.path.join(work, f"run{index}.yaml")
    with open(scenario, "w") as f:
        f.write(f"%YAML:1.0\n---\nname: sweep{index}\n" + case["yaml"] + MOTION)
    out = os.path.join(work, f"run{index}")
    run = subprocess.run([onetip, "demo", "--scenario", scenario, "--out", out], capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"{scenario}: onetip demo failed: {run.stderr}")
    est = list(csv.DictReader(open(os.path.join(out, "est_pose.csv"))))
    gt = list(csv.DictReader(open(os.path.join(out, "gt_pose.csv"))))
    return est, gt, [line for line in run.stderr.splitlines() if "moved against the pad" in line]


def figures(est, gt, twin_rmse=None):
    both = [(e, g) for e, g in zip(est, gt) if e["contact"] == "1" and g["contact"] == "1"]
    out = {"false_contact_frames": sum(1 for e, g in zip(est, gt) if e["contact"] == "1" and g["contact"] == "0")}
    first = lambda rows: next((int(r["frame"]) for r in rows if r["contact"] == "1"), -1)  # noqa: E731
    out["onset_delay_frames"] = first(est) - first(gt)
    for a in AXES:
        out["rmse_" + a] = math.sqrt(sum((float(e[a]) - float(g[a])) ** 2 for e, g in both) / max(1, len(both)))
        if twin_rmse:
            out["twin_rmse_" + a] = twin_rmse["rmse_" + a]
    return out


def read_rows():
    """The CSV's rows with numbers as numbers, and the twin's figures (seed 1)."""
    rows = []
    for r in csv.DictReader(open(os.path.join(HERE, "data", "shift_light_sweep.csv"))):
        rows.append({k: (v if k in ("effect", "view", "timing") or v == "" else float(v)) for k, v in r.items()})
    return rows, {"rmse_" + a: rows[0]["rmse_" + a] for a in AXES}


def main():
    if "--chart-only" in sys.argv:
        chart(*read_rows())
        return
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    onetip = args[0] if args else os.path.join(ROOT, "build", "bin", "onetip")
    jobs = next((int(a.split("=")[1]) for a in sys.argv[1:] if a.startswith("--jobs=")), os.cpu_count() or 1)
    all_cases = list(cases())
    with tempfile.TemporaryDirectory() as work, ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(lambda ic: play(onetip, work, *ic), enumerate(all_cases)))
    twin = figures(*results[0][:2])
    rows = []
    for case, (est, gt, moved) in zip(all_cases, results):
        row = {k: v for k, v in case.items() if k != "yaml"}
        row.update(figures(est, gt, twin))
        row["moved_notices"] = len(moved)
        row["first_notice_frame"] = moved[0].split("frame ")[1].split(":")[0] if moved else ""
        rows.append(row)
    keys = ["effect", "seed", "view", "size", "angle", "timing", "flicker", "step", "false_contact_frames",
            "onset_delay_frames", "moved_notices", "first_notice_frame"] + ["rmse_" + a for a in AXES] + \
        ["twin_rmse_" + a for a in AXES]
    os.makedirs(os.path.join(HERE, "data"), exist_ok=True)
    with open(os.path.join(HERE, "data", "shift_light_sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, restval="")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.5g}" if isinstance(v, float) else v) for k, v in r.items()})
    chart(rows, twin)


COLOURS = ("#08519c", "#3182bd", "#6baed6", "#e6550d", "#fd8d3c", "#31a354")


def noise_band(rows, twin):
    """Per axis, the smallest and largest RMS error of the noise twins over the twin's."""
    seeds = [r for r in rows if r["effect"] == "none"]
    return {a: (min(r["rmse_" + a] for r in seeds) / twin["rmse_" + a],
                max(r["rmse_" + a] for r in seeds) / twin["rmse_" + a]) for a in AXES}


def chart(rows, twin):
    band = noise_band(rows, twin)
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.8), gridspec_kw={"width_ratios": [1.1, 1.3, 1.3]})
    shifts = [r for r in rows if r["effect"] == "shift"]
    ax = axes[0]
    groups = [(v, t) for v in ("both", "left", "right") for t in ("step_early", "step_late", "ramp")]
    for offset, (what, colour, test) in zip((-0.27, 0, 0.27), (
            ("runs with a false contact frame", "#e6550d", lambda r: r["false_contact_frames"] > 0),
            ("runs whose onset is off the truth's", "#fd8d3c", lambda r: r["onset_delay_frames"] != 0),
            ("runs with no notice", "#756bb1", lambda r: r["moved_notices"] == 0))):
        counts = [sum(1 for r in shifts if (r["view"], r["timing"]) == g and test(r)) for g in groups]
        bars = ax.bar([i + offset for i in range(len(groups))], counts, width=0.27, color=colour, label=what)
        ax.bar_label(bars, fontsize=7)
    ax.set_xticks(range(len(groups)))
    ax.set_xticklabels([f"{v}\n{t.replace('step_', 'step, ')}" for v, t in groups], fontsize=6)
    ax.set_ylim(0, 15)
    ax.set_ylabel("runs (of 15: 1-5 px, three directions)")
    ax.set_title("A shifted camera (both views) or mirror (left, right)", fontsize=10)
    ax.legend(fontsize=7)
    for ax, sel, xlabel, x_of, title in (
            (axes[1], shifts, "shift (px); left to right per size: both, left, right",
             lambda r, k: r["size"] + (("both", "left", "right").index(r["view"]) - 1) * 0.25 + (k - 2.5) * 0.03,
             "The contact after the shift against its twin"),
            (axes[2], [r for r in rows if r["effect"] == "light"], "exposure step (%); flicker +-2, 5, 10 % side by side",
             lambda r, k: r["step"] * 100 + (r["flicker"] * 100 - 5) * 0.6 + (k - 2.5) * 0.3,
             "Flicker and exposure steps against the twin")):
        for k, (a, colour) in enumerate(zip(AXES, COLOURS)):
            ax.scatter([x_of(r, k) for r in sel], [r["rmse_" + a] / twin["rmse_" + a] for r in sel], s=10,
                       color=colour, label=f"{a} (noise twins {band[a][0]:.2f}-{band[a][1]:.2f})")
        ax.axhspan(0.9, 1.1, color="grey", alpha=0.2, label="within 10 %")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("RMS error over the twin's (seed 1)")
        ax.set_title(title, fontsize=10)
        ax.legend(fontsize=6, ncol=2)
    fig.suptitle(f"Twin without effects: RMS dx {twin['rmse_dx']:.3f}, dy {twin['rmse_dy']:.4f}, "
                 f"dz {twin['rmse_dz']:.4f} mm; yaw {twin['rmse_yaw']:.3f}, pitch {twin['rmse_pitch']:.3f}, "
                 f"roll {twin['rmse_roll']:.2f} deg (press 1 mm, slide 1 mm along x)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "shift_light_sweep.png"), dpi=110)


if __name__ == "__main__":
    main()
