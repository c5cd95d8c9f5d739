#!/usr/bin/env python3
"""The steady main and thrust forces of a damping/speed study (data/studies/steady_damping.json) against the tool
speed, one line per damping (Cundall's local damping alpha; contact dashpots as open squares), error bars the
cuts' own standard errors (batch means): where the lines flatten and meet is the quasi-static limit. Reads the study's items.csv and each item's summary.json
and forces.csv, and prints a Markdown table with how intermittent each cut is: the share of the steady samples
in which the tool touches (main force above 0.1 N) and the share of the mean carried by the largest 5 % of them.

    python3 analysis/plot_steady_damping.py STUDY_DIR OUT.png
"""
import csv
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from kerf.records import cutting_force, intermittency  # noqa: E402
from kerf.result_keys import CutResults as R


def items(study_dir):
    rows = []
    with open(study_dir / "items.csv") as f:
        for row in csv.DictReader(f):
            if row["status"] != "ok":
                continue
            name = f"condition_{row['condition']}_seed_{row['seed']}"
            scene = json.loads((study_dir / "items" / name / "summary.json").read_text())
            material = scene["material"]
            rows.append({
                "speed": scene["cut"]["cut"]["speed_m_per_s"],
                "alpha": material["local_damping"],
                "beta": material.get("viscous_damping_ratio", 0.0),
                "main": float(cutting_force(row)), "main_sem": float(cutting_force(row, "sem_N")),
                "thrust": float(row[R.thrust_force_N]), "thrust_sem": float(row[R.thrust_force_sem_N]),
            })
            rows[-1].update(intermittency(study_dir / "items" / name, float(row[R.steady_from_travel_mm])))
    return rows


def damping_label(r):
    return f"alpha {r['alpha']:g}" + (f", dashpots {r['beta']:g}" if r["beta"] > 0 else "")


def main():
    study_dir, out = pathlib.Path(sys.argv[1]), sys.argv[2]
    rows = items(study_dir)
    fig, axes = plt.subplots(1, 2, figsize=(10.5, 4.4), sharex=True)
    dampings = sorted({(r["alpha"], r["beta"]) for r in rows}, key=lambda d: (-d[0], d[1]))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, key, title in ((axes[0], "main", "main force"), (axes[1], "thrust", "thrust force")):
        for k, (alpha, beta) in enumerate(dampings):
            line = sorted((r for r in rows if (r["alpha"], r["beta"]) == (alpha, beta)), key=lambda r: r["speed"])
            nudge = 1 + 0.025 * (k - (len(dampings) - 1) / 2)  # side by side at one speed
            ax.errorbar([r["speed"] * nudge for r in line], [r[key] for r in line], [r[key + "_sem"] for r in line],
                        marker="s" if beta > 0 else "o", mfc="none" if beta > 0 else None, capsize=3,
                        color=colours[k % len(colours)], label=damping_label(line[0]))
        ax.set_xscale("log")
        speeds = sorted({r["speed"] for r in rows})
        ax.set_xticks(speeds)
        ax.set_xticklabels([f"{s:g}" for s in speeds])
        ax.minorticks_off()
        ax.set_xlabel("tool speed (m/s)")
        ax.set_ylabel(f"steady {title} per 1 mm width (N)")
        ax.set_title(f"{title}: mean +- standard error of one cut")
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8, title="damping", title_fontsize=8)
    fig.suptitle("Regular 0.1 mm steady cut (12 mm workpiece, 4 mm travel, one packing): damping and tool speed")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("| speed (m/s) | damping | main force (N) | tool in contact | largest 5 % of samples carry |")
    print("|---:|---|---:|---:|---:|")
    for r in sorted(rows, key=lambda r: (-r["speed"], -r["alpha"])):
        print(f"| {r['speed']:g} | {damping_label(r)} | {r['main']:.2f} +- {r['main_sem']:.2f} | {100 * r['contact']:.0f} % "
              f"| {100 * r['top5']:.0f} % of the mean |")


if __name__ == "__main__":
    main()
