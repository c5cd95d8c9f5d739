#!/usr/bin/env python3
"""Where a steady cut's work goes, from its own outputs (issue 41 item 4): the energy its broken joints took, and,
from the cut's energy books where it kept them, friction and what the disks leaving the window carried off.

    python3 analysis/cut_energy.py DIR [DIR ...] [--csv OUT.csv]

Each DIR is a cut's output folder (summary.json, cracks.csv) or a study's (DIR/items/*/). Per cut, over the steady
part only (the travel the summary's means cover, and the cracks of the stretch it machined, steady_machined_from_x_mm
to steady_machined_to_x_mm):

* the tool's work W = main force x steady travel (the force is per the cut's width; the work too);
* the energy of the broken joints, an estimate per broken element of the flat joint (k_n = Ebar* / L, k_s = k_n /
  kappa, L the joint's length, here 2 x the mean radius x the genesis's radius scale; A = l_e x thickness): the
  elastic energy of the element at its strength under a uniform stress, sigma_t^2 A L / (2 Ebar*) for a tensile
  break and c^2 A L kappa / (2 Ebar*) for a shear break, plus G_f A for a softening joint (its fracture energy). Not
  a bound: a bent element breaks at its edge with less energy stored, and the shear stored at a tensile break is
  left out.

* from the cut's energy books (summary results energy_*_steady_J, kerf-dem since 2026-11-29; CutEnergy in
  kerf/dem/procedures/cutting.hpp), where it has them: what the integrated disks dissipated, of which friction is
  taken as the rest after the broken joints' estimate (the integrator's error, 1e-4 of the work in the tests, is left
  in it), and the kinetic and strain energy the disks leaving the window carried off.

Per condition (glass and the tool's own friction if it has one, window in mm ahead/behind/below, surface, depth): each share of W with its 95 % interval over
packings (Student t on n - 1).
"""
import argparse
import csv
import json
import sys

from kerf.records import condition_of, cutting_force, folders
from kerf.result_keys import CracksColumns as C
from kerf.result_keys import CutResults as R
from kerf.stats import mean_of

def element_energy_j(material, mode, length_m, joint_length_m, thickness_m):
    """The estimate above for one broken element [J]."""
    e_bar = material["bond_effective_modulus_GPa"] * 1e9
    area = length_m * thickness_m
    if mode == "tension":
        stress, compliance = material["tensile_strength_MPa"] * 1e6, joint_length_m / e_bar
    else:
        stress = material["cohesion_MPa"] * 1e6
        compliance = joint_length_m * material["bond_stiffness_ratio"] / e_bar
    return 0.5 * stress * stress * area * compliance + material.get("fracture_energy_J_per_m2", 0.0) * area


def cut_energy(folder):
    """One cut: its condition, the tool's work and the broken joints' energy (chip, subsurface) over the steady part."""
    summary = json.loads((folder / "summary.json").read_text())
    results, material, spec = summary["results"], summary["material"], summary["specimen"]
    scene = summary.get("study_item", {}).get("scene", {})
    travel_m = (results[R.steady_to_travel_mm] - results[R.steady_from_travel_mm]) * 1e-3
    lo, hi = sorted((results[R.steady_machined_from_x_mm], results[R.steady_machined_to_x_mm]))
    thickness_m = spec["thickness_mm"] * 1e-3
    joint_m = (spec["radius_min_um"] + spec["radius_max_um"]) * 1e-6 * spec.get("radius_scale", 1.0)
    energy = {"chip": 0.0, "subsurface": 0.0}
    with open(folder / "cracks.csv", newline="") as f:
        for row in csv.DictReader(f):
            if lo <= float(row[C.x_mm]) <= hi and row[C.place] in energy:
                energy[row[C.place]] += element_energy_j(material, row[C.mode], float(row[C.length_um]) * 1e-6,
                                                         joint_m, thickness_m)
    key = condition_of(summary)
    work_j = cutting_force(results) * travel_m
    if R.energy_tool_work_steady_J in results:  # the books: their own work (the same samples, to one)
        work_j = results[R.energy_tool_work_steady_J]
        joints = energy["chip"] + energy["subsurface"]
        energy["friction"] = results[R.energy_dissipated_steady_J] - joints
        energy["carried_kinetic"] = results[R.energy_left_kinetic_steady_J]
        energy["carried_strain"] = results[R.energy_left_strain_steady_J]
    return key, scene.get("specimen", {}).get("seed", spec["seed"]), work_j, energy


SHARES = ("joints", "chip", "subsurface", "friction", "carried_kinetic", "carried_strain")


def table(cuts):
    """Per condition: {share: Estimate} of the work, over the packings that have it (the books' shares only
    from cuts that kept books)."""
    by = {}
    for key, _, work, energy in cuts:
        if work <= 0:
            continue
        row = {"joints": (energy["chip"] + energy["subsurface"]) / work}
        row.update({k: v / work for k, v in energy.items()})
        by.setdefault(key, []).append(row)
    return {k: {name: mean_of([r[name] for r in rows if name in r]) for name in SHARES if any(name in r for r in rows)}
            for k, rows in sorted(by.items())}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--csv", help="also write one row per cut here")
    ap.add_argument("--figure", help="also draw the shares of the conditions with books as stacked bars (PNG)")
    a = ap.parse_args(argv)
    cuts = [cut_energy(f) for f in folders(a.dirs)]
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            books = ("friction", "carried_kinetic", "carried_strain")
            w.writerow(["glass", "window", "surface", "depth_of_cut_mm", "seed", "tool_work_J", "chip_joints_J",
                        "subsurface_joints_J"] + [f"{b}_J" for b in books])
            for key, seed, work, e in cuts:
                w.writerow([*key, seed, work, e["chip"], e["subsurface"]] + [e.get(b, "") for b in books])
    print("share of the tool's work (steady part; mean over packings [95 % interval]): broken joints (chip, subsurface),")
    print("and from the books where kept: friction (the dissipated rest), carried off by disks leaving (kinetic, strain)")
    for key, shares in table(cuts).items():
        def fmt(e):
            return f"{e.value:.3f}" + (f" [{e.low:.3f}, {e.high:.3f}]" if e.resolved() else "")
        text = ", ".join(f"{name} {fmt(e)}" for name, e in shares.items())
        print(f"  {' '.join(map(str, key))}: n {shares['joints'].n}, {text}")
    if a.figure:
        plot(table(cuts), a.figure)
    return 0


PARTS = [("chip", "broken joints, chip", "#b2182b"), ("subsurface", "broken joints, subsurface", "#ef8a62"),
         ("friction", "friction (the dissipated rest)", "#4d4d4d"),
         ("carried_kinetic", "carried off, kinetic", "#67a9cf"), ("carried_strain", "carried off, strain", "#2166ac")]


def plot(shares_by_condition, path):
    """One bar per condition with books: its shares of the tool's work stacked, each with its 95 % interval."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    order = {"regular": 0, "rectangular": 1, "trapezoidal": 2}
    rows = sorted(((k, v) for k, v in shares_by_condition.items() if "friction" in v),
                  key=lambda kv: (", tool mu" in kv[0][0], kv[0][1], kv[0][3], order.get(kv[0][2], 3)))
    fig, ax = plt.subplots(figsize=(10, 0.55 * len(rows) + 1.8))
    for y, (key, shares) in enumerate(rows):
        left = 0.0
        for name, label, colour in PARTS:
            e = shares[name]
            ax.barh(y, e.value, left=left, color=colour, edgecolor="white", label=label if y == 0 else None)
            if e.resolved():
                ax.errorbar(left + e.value, y, xerr=[[e.value - e.low], [e.high - e.value]], color="black",
                            capsize=2, lw=0.8)
            left += e.value
    ax.set_yticks(range(len(rows)))
    glass_mu = "tool with the glass's mu"
    ax.set_yticklabels([f"{k[2]}, {k[0].split(', ', 1)[1] if ', ' in k[0] else glass_mu} "
                        f"({v['joints'].n} packings)" for k, v in rows])
    ax.invert_yaxis()
    ax.set_xlim(0, 1.05)
    ax.set_xlabel("share of the tool's work, steady part (whiskers: 95 % intervals over packings)")
    ax.set_title(f"{rows[0][0][0].split(',')[0]}, window {rows[0][0][1]}, depth of cut {rows[0][0][3]} mm", fontsize=9)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.35 if len(rows) < 4 else -0.2), ncol=3, fontsize=8,
              frameon=False)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
