#!/usr/bin/env python3
"""Issue 37's lattice check: does K_IC scale as sqrt(R) when the disk radius is halved at fixed joint strength?

    python3 analysis/toughness_radius.py [RECORD.csv]

RECORD (default data/studies/results/toughness_hex_radius.csv) is what `kerf-dem study
data/studies/toughness_hex_radius.json` writes: one beam per row, disk_radius_um, lattice_offset_R, notch_offset_rows,
fracture_toughness_MPa_sqrt_m, fracture_energy_J_per_m2. A lattice has no packings; its replicates are the placings of
the notch against the lattice (the same placings, in units of R, at each radius), so the two radii pair by placing.
Prints K_IC per radius (mean and standard error over the placings), the paired ratio K(R_small) / K(R_large) (the mean
of the per-placing ratios, Student t on n - 1) against sqrt(R_small / R_large), and the same for G_c against
R_small / R_large (a joint's energy per unit crack area scales as sigma_c^2 R / Ebar*).
"""
import argparse
import csv
import math
import pathlib

from kerf.result_keys import ToughnessResults as T
from kerf.stats import mean_of


def read_record(path):
    """{radius_um: {(offset, rows): (K, G)}}."""
    out = {}
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            placing = (float(r["lattice_offset_R"]), float(r.get("notch_offset_rows", 0) or 0))
            out.setdefault(float(r["disk_radius_um"]), {})[placing] = (float(r[T.fracture_toughness_MPa_sqrt_m]),
                                                                       float(r[T.fracture_energy_J_per_m2]))
    return out


def scaling(beams):
    """(lines, ratio estimate of K, expected ratio) for the largest and smallest radius."""
    radii = sorted(beams)
    small, large = radii[0], radii[-1]
    placings = sorted(set(beams[small]) & set(beams[large]))
    lines = []
    for r in (large, small):
        k = mean_of([beams[r][p][0] for p in placings])
        g = mean_of([beams[r][p][1] for p in placings])
        lines.append(f"R = {r:g} um: K_IC {k.value:.4f} +- {k.se:.4f} MPa sqrt(m), G_c {g.value:.3f} +- {g.se:.3f} J/m^2 "
                     f"({len(placings)} placings)")
    k_ratio = mean_of([beams[small][p][0] / beams[large][p][0] for p in placings])
    g_ratio = mean_of([beams[small][p][1] / beams[large][p][1] for p in placings])
    expected = math.sqrt(small / large)
    lines.append(f"K(R = {small:g}) / K(R = {large:g}): {k_ratio.value:.4f} [{k_ratio.low:.4f}, {k_ratio.high:.4f}] "
                 f"against sqrt(R ratio) = {expected:.4f}: "
                 f"{'holds' if k_ratio.low <= expected <= k_ratio.high else 'differs'} within the placings' 95 % interval")
    lines.append(f"G_c ratio: {g_ratio.value:.4f} [{g_ratio.low:.4f}, {g_ratio.high:.4f}] against {small / large:.4f}")
    return lines, k_ratio, expected


def main():
    root = pathlib.Path(__file__).resolve().parents[1]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("record", nargs="?", default=root / "data/studies/results/toughness_hex_radius.csv",
                    type=pathlib.Path)
    print("\n".join(scaling(read_record(ap.parse_args().record))[0]))


if __name__ == "__main__":
    main()
