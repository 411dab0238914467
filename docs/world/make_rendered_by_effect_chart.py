#!/usr/bin/python3
"""Each world effect alone on rendered runs, beside the same runs without it (issue 38, item 3).

Reads build/bench/pose_campaign runs over the same seeds, image level (rendered frames through the real
front end):
  PLAIN.csv        --world 0 (no effect)
  EFFECT=FILE.csv  --world-only EFFECT, for EFFECT in creep, shift, damage, light, drift
A seed draws the same motion and conditions with and without the effect (sim/random_scenario.hpp), so each
run differs from its twin by the one effect.

Writes docs/world/data/rendered_by_effect.csv (one row per effect), data/rendered_by_effect_runs.csv (one row
per run) and the chart docs/world/rendered_by_effect.png. A run's translation RMSE is the RMS over dx, dy, dz
of its per-axis RMSE (mm), its rotation RMSE the same over yaw, pitch, roll (deg); its ratio is that divided by
its twin's. Only twins that diverge in neither play are compared (a diverged run's RMSE measures where it
diverged, not the effect); the medians of both RMSEs over them are given too. Runs whose camera or mirror
moved between two frames the truth has in contact (the campaign's shift_while_touching) are drawn in red.

usage: make_rendered_by_effect_chart.py PLAIN.csv creep=C.csv shift=S.csv damage=D.csv light=L.csv drift=R.csv
"""
import csv
import math
import os
import statistics
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
WITHIN = 0.10  # issue 38: figures within 10 % of the run without the effect
SIZE = {  # the effect's size in a run, from the campaign's columns, and its label
    "creep": (lambda r: float(r["creep_relaxation"]), "relaxed fraction r"),
    "shift": (lambda r: float(r["shift_px"]), "camera or mirror shift (px)"),
    "damage": (lambda r: float(r["hidden_fraction"]), "hidden markers (fraction)"),
    "light": (lambda r: max(float(r["flicker"]), abs(float(r["exposure_step"]))),
              "larger of flicker and |exposure step|"),
    "drift": (lambda r: float(r["drift_mm"]), "rest drift, largest move (mm)"),
}


def load(path):
    with open(path, newline="") as f:
        return {int(r["seed"]): r for r in csv.DictReader(f) if r["level"] == "image"}


def rms(r, axes):
    return math.sqrt(sum(float(r["rmse_" + a]) ** 2 for a in axes) / len(axes))


def main():
    if len(sys.argv) != 7 or any("=" not in a for a in sys.argv[2:]):
        sys.exit(__doc__)
    plain = load(sys.argv[1])
    plays = [(a.split("=", 1)[0], load(a.split("=", 1)[1])) for a in sys.argv[2:]]
    unknown = [name for name, _ in plays if name not in SIZE]
    if unknown:
        sys.exit("unknown effect %s; expected one of %s" % (", ".join(unknown), ", ".join(SIZE)))
    data = os.path.join(HERE, "data")
    os.makedirs(data, exist_ok=True)

    summary, per_run = [], []
    fig, axes = plt.subplots(2, len(plays), figsize=(4.2 * len(plays), 7.5), squeeze=False)
    for col, (name, runs) in enumerate(plays):
        size, label = SIZE[name]
        seeds = sorted(set(runs) & set(plain))
        both_judged = [s for s in seeds if int(runs[s]["judged_diverged"]) == 0 and int(plain[s]["judged_diverged"]) == 0
                       and int(runs[s]["linear_frames"]) > 0]
        ratio = {}
        for s in both_judged:
            ratio[s] = (rms(runs[s], ("dx", "dy", "dz")) / max(rms(plain[s], ("dx", "dy", "dz")), 1e-6),
                        rms(runs[s], ("yaw", "pitch", "roll")) / max(rms(plain[s], ("yaw", "pitch", "roll")), 1e-6))
        total = lambda rs, k: sum(int(r[k]) for r in rs)  # noqa: E731
        effect_rows, twin_rows = [runs[s] for s in seeds], [plain[s] for s in seeds]
        row = {"effect": name, "runs": len(seeds),
               "diverged": total(effect_rows, "judged_diverged"), "diverged_twin": total(twin_rows, "judged_diverged"),
               "lift_offs": total(effect_rows, "lift_offs"), "late_ends": total(effect_rows, "late_ends"),
               "late_ends_twin": total(twin_rows, "late_ends"), "false_onsets": total(effect_rows, "false_onsets"),
               "false_onsets_twin": total(twin_rows, "false_onsets"),
               "contact_missed": total(effect_rows, "contact_missed"),
               "contact_missed_twin": total(twin_rows, "contact_missed"),
               "compared": len(both_judged)}
        for kind, axes_of_kind in (("translation", ("dx", "dy", "dz")), ("rotation", ("yaw", "pitch", "roll"))):
            row["median_rmse_" + kind] = round(statistics.median(rms(runs[s], axes_of_kind) for s in both_judged), 4)
            row["median_rmse_%s_twin" % kind] = round(statistics.median(rms(plain[s], axes_of_kind)
                                                                         for s in both_judged), 4)
        for i, kind in enumerate(("translation", "rotation")):
            values = [ratio[s][i] for s in both_judged]
            row["median_ratio_" + kind] = round(statistics.median(values), 3) if values else float("nan")
            row["within_10pct_" + kind] = sum(1 for v in values if abs(v - 1) <= WITHIN)
        summary.append(row)
        for s in seeds:
            r, p = runs[s], plain[s]
            per_run.append([name, s, r["indenter"], r["fps"], round(size(r), 4), r["judged_diverged"],
                            p["judged_diverged"], r["lift_offs"], r["late_ends"], r["worst_end_lag"], r["false_onsets"],
                            r["contact_missed"], p["contact_missed"], r.get("shift_while_touching", "0"),
                            round(rms(r, ("dx", "dy", "dz")), 4), round(rms(p, ("dx", "dy", "dz")), 4),
                            round(rms(r, ("yaw", "pitch", "roll")), 4), round(rms(p, ("yaw", "pitch", "roll")), 4)])
        touching = {s for s in seeds if runs[s].get("shift_while_touching") == "1"}
        row["shift_while_touching"] = len(touching)
        row["late_ends_shift_while_touching"] = sum(int(runs[s]["late_ends"]) for s in touching)
        for i, kind in enumerate(("translation (dx, dy, dz)", "rotation (yaw, pitch, roll)")):
            ax = axes[i][col]
            ax.axhspan(1 - WITHIN, 1 + WITHIN, color="green", alpha=0.15, label="within 10 %")
            apart = [s for s in both_judged if s not in touching]
            ax.scatter([size(runs[s]) for s in apart], [ratio[s][i] for s in apart], s=14, label="run / its twin")
            if touching:
                moved = [s for s in both_judged if s in touching]
                ax.scatter([size(runs[s]) for s in moved], [ratio[s][i] for s in moved], s=14, color="red",
                           label="shifted while touching")
            ax.set_yscale("log")
            ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
            low, high = ax.get_ylim()  # within a decade the minor ticks carry the labels
            ax.yaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%.3g") if high / low < 10
                                         else matplotlib.ticker.NullFormatter())
            ax.set_xlabel(label)
            ax.set_ylabel("RMSE %s, ratio to the twin" % kind)
            if i == 0:
                ax.set_title("%s: %d of %d runs compared\nlate ends %d / %d lift-offs, false onsets %d"
                             % (name, len(both_judged), len(seeds), row["late_ends"], row["lift_offs"],
                                row["false_onsets"]), fontsize=9)
                ax.legend(fontsize=7)
    fig.suptitle("Each world effect alone, rendered runs through the real front end, against the same seed without it"
                 " (twins that diverge in neither play)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "rendered_by_effect.png"), dpi=80)

    keys = list(summary[0].keys())
    with open(os.path.join(data, "rendered_by_effect.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(summary)
    with open(os.path.join(data, "rendered_by_effect_runs.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["effect", "seed", "indenter", "fps", "size", "diverged", "diverged_twin", "lift_offs", "late_ends",
                    "worst_end_lag", "false_onsets", "contact_missed", "contact_missed_twin", "shift_while_touching",
                    "rmse_translation_mm",
                    "rmse_translation_twin_mm", "rmse_rotation_deg", "rmse_rotation_twin_deg"])
        w.writerows(per_run)
    for row in summary:
        print(",".join(str(row[k]) for k in keys))


if __name__ == "__main__":
    main()
