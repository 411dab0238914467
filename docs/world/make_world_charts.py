#!/usr/bin/python3
"""The pose campaign with the world effects beside the campaign without them (issue 38, item 3).

Reads three runs of build/bench/pose_campaign over the same seeds (field level):
  plain.csv     the campaign as it was: no world effects (--world 0)
  world.csv     the same seeds with the world effects drawn (--world 1), the SDK as it is
  world_off.csv the same, without the gel-recovery rule (--world 1 --gel-recovery 0)
A seed draws the same motion and conditions with and without the effects (sim/random_scenario.hpp), so
each run is compared with its own twin. Figures are reported on the even seeds only (the odd ones were
looked at while the recovery rule was made).

Writes into docs/world/data/: summary.csv (one row per campaign and effect group) and per_run.csv
(each even seed's effects, its error against its plain twin and its contact events); and the charts
docs/world/world_error.png and docs/world/world_contact_events.png.

usage: make_world_charts.py PLAIN.csv WORLD.csv WORLD_OFF.csv
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
LATE = 2  # frames: issue 38's bound on a contact's end after the truth's lift-off


def load(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["level"] == "field" and int(r["seed"]) % 2 == 0]
    return {int(r["seed"]): r for r in rows}


def num(r, key):
    return float(r[key])


def median(values):
    return statistics.median(values) if values else float("nan")


def summarise(name, runs, group):
    seeds = [s for s in runs if group(runs[s])]
    rs = [runs[s] for s in seeds]
    out = {"campaign": name, "runs": len(rs),
           "diverged": sum(int(r["judged_diverged"]) for r in rs),
           "lift_offs": sum(int(r["lift_offs"]) for r in rs),
           "late_ends": sum(int(r["late_ends"]) for r in rs),
           "runs_with_late_end": sum(1 for r in rs if int(r["late_ends"]) > 0),
           "false_onsets": sum(int(r["false_onsets"]) for r in rs),
           "runs_with_false_onset": sum(1 for r in rs if int(r["false_onsets"]) > 0)}
    for a in AXES:
        out["median_rmse_" + a] = round(median([num(r, "rmse_" + a) for r in rs if int(r["linear_frames"]) > 0]), 4)
    return out


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    plain, world, off = (load(p) for p in sys.argv[1:4])
    seeds = sorted(set(plain) & set(world) & set(off))
    plain = {s: plain[s] for s in seeds}
    world = {s: world[s] for s in seeds}
    off = {s: off[s] for s in seeds}
    data = os.path.join(HERE, "data")
    os.makedirs(data, exist_ok=True)

    creep = lambda r: num(r, "creep_relaxation") > 0  # noqa: E731
    hidden = lambda r: num(r, "hidden_fraction") > 0  # noqa: E731
    drift = lambda r: num(r, "drift_mm") > 0  # noqa: E731
    groups = [("all", lambda r: True), ("creep", creep), ("no creep", lambda r: not creep(r)),
              ("hidden markers", hidden), ("drift", drift)]
    summary = []
    for gname, g in groups:
        # The group is chosen by the world run's effects; the plain twin is the same seed without them.
        members = {s for s in seeds if g(world[s])}
        for cname, runs in (("plain", plain), ("world", world), ("world, no gel recovery", off)):
            row = summarise(cname, {s: runs[s] for s in members}, lambda r: True)
            row["effects"] = gname
            summary.append(row)
    keys = ["effects", "campaign", "runs", "diverged", "lift_offs", "late_ends", "runs_with_late_end",
            "false_onsets", "runs_with_false_onset"] + ["median_rmse_" + a for a in AXES]
    with open(os.path.join(data, "summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(summary)

    per_run_keys = ["seed", "indenter", "fps", "creep_relaxation", "creep_time_s", "shift_px", "hidden_fraction",
                    "flicker", "exposure_step", "drift_mm", "lift_offs", "late_ends", "worst_end_lag",
                    "false_onsets", "worst_end_lag_no_recovery", "late_ends_no_recovery",
                    "false_onsets_no_recovery"] + ["rmse_%s_plain" % a for a in AXES] + ["rmse_%s_world" % a for a in AXES]
    with open(os.path.join(data, "per_run.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(per_run_keys)
        for s in seeds:
            r, o, p = world[s], off[s], plain[s]
            w.writerow([s, r["indenter"], r["fps"]] +
                       [r[k] for k in ("creep_relaxation", "creep_time_s", "shift_px", "hidden_fraction", "flicker",
                                       "exposure_step", "drift_mm", "lift_offs", "late_ends", "worst_end_lag",
                                       "false_onsets")] +
                       [o["worst_end_lag"], o["late_ends"], o["false_onsets"]] +
                       [p["rmse_" + a] for a in AXES] + [r["rmse_" + a] for a in AXES])

    # Error against each effect's size: each run's dz and roll RMSE with the effects minus its plain twin's.
    effects = [("creep_relaxation", "creep: relaxed fraction r"), ("creep_time_s", "creep: relaxation time (s)"),
               ("hidden_fraction", "hidden markers (fraction)"), ("drift_mm", "rest drift, largest move (mm)")]
    fig, axes = plt.subplots(2, len(effects), figsize=(4 * len(effects), 7), squeeze=False)
    for col, (key, label) in enumerate(effects):
        for row, axis in enumerate(("dz", "roll")):
            ax = axes[row][col]
            judged = [s for s in seeds if int(world[s]["linear_frames"]) > 0]
            is_creep = key.startswith("creep")
            # The creep moves every run it is in; the other effects are drawn apart from it.
            on = [s for s in judged if num(world[s], key) > 0 and (is_creep or not creep(world[s]))]
            with_creep = [s for s in judged if num(world[s], key) > 0 and not is_creep and creep(world[s])]
            offs = [s for s in judged if num(world[s], key) == 0 and not creep(world[s])]
            delta = lambda s: num(world[s], "rmse_" + axis) - num(plain[s], "rmse_" + axis)  # noqa: E731
            ax.scatter([num(world[s], key) for s in on], [delta(s) for s in on], s=12,
                       label="effect on" if is_creep else "effect on, no creep")
            if with_creep:
                ax.scatter([num(world[s], key) for s in with_creep], [delta(s) for s in with_creep], s=10,
                           color="orange", alpha=0.5, label="effect on, with creep")
            ax.scatter([0] * len(offs), [delta(s) for s in offs], s=12, color="grey", alpha=0.5,
                       label="no effect, no creep")
            ax.axhline(0, color="black", lw=0.5)
            ax.set_yscale("symlog", linthresh=0.01 if axis == "dz" else 0.1)
            ax.set_xlabel(label)
            ax.set_ylabel("RMSE %s - plain twin's (%s)" % (axis, "mm" if axis == "dz" else "deg"))
            if row == 0 and col in (0, 2):
                ax.legend(fontsize=7)
    fig.suptitle("Pose error against each world effect's size (field level, even seeds, each run minus its plain twin)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "world_error.png"), dpi=90)

    # Contact events against the effects that can cause them: the end lag against the creep, false onsets
    # against drift and creep, with and without the gel-recovery rule.
    fig, axes = plt.subplots(1, 4, figsize=(20, 4.5))
    lag = lambda r: min(int(r["worst_end_lag"]), 400)  # noqa: E731
    creeping = [s for s in seeds if creep(world[s]) and int(world[s]["lift_offs"]) > 0]
    for runs, name, marker in ((off, "without gel recovery", "x"), (world, "with gel recovery", "o")):
        axes[0].scatter([num(world[s], "creep_relaxation") for s in creeping], [max(lag(runs[s]), 0.5) for s in creeping],
                        s=16, marker=marker, label=name)
        axes[1].scatter([num(world[s], "creep_time_s") for s in creeping], [max(lag(runs[s]), 0.5) for s in creeping],
                        s=16, marker=marker, label=name)
        # Per frame the gel's recovery shrinks the field by dt / tau_c: at high frame rates by less than the noise.
        axes[3].scatter([num(world[s], "fps") for s in creeping], [max(lag(runs[s]), 0.5) for s in creeping],
                        s=16, marker=marker, label=name)
    for ax, label in ((axes[0], "creep: relaxed fraction r"), (axes[1], "creep: relaxation time (s)"),
                      (axes[3], "frame rate of the run (fps), creeping runs")):
        ax.axhline(LATE + 0.5, color="red", lw=0.8, ls="--", label="2 frames late")
        ax.set_yscale("log")
        ax.set_xlabel(label)
        ax.set_ylabel("worst end after the truth's lift-off (frames)")
        ax.legend(fontsize=8)
    axes[1].set_xscale("log")
    axes[3].set_xscale("log")
    ax = axes[2]
    for runs, name, dx in ((off, "without gel recovery", -0.15), (world, "with gel recovery", 0.15)):
        groups_x = [("none", lambda r: not creep(r) and not drift(r)), ("drift", lambda r: drift(r) and not creep(r)),
                    ("creep", lambda r: creep(r) and not drift(r)), ("both", lambda r: creep(r) and drift(r))]
        counts = [sum(int(runs[s]["false_onsets"]) for s in seeds if g(world[s])) for _, g in groups_x]
        ax.bar([i + dx for i in range(len(groups_x))], counts, width=0.3, label=name)
        ax.set_xticks(range(len(groups_x)), [n for n, _ in groups_x])
    ax.set_ylabel("false onsets (no marker touched)")
    ax.set_xlabel("world effects of the run")
    ax.legend(fontsize=8)
    fig.suptitle("Contact events with the world effects (field level, even seeds; an end lag <= 0 is drawn at 0.5,"
                 " one beyond 400 at 400)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "world_contact_events.png"), dpi=90)
    for row in summary:
        print(",".join(str(row[k]) for k in keys))


if __name__ == "__main__":
    main()
