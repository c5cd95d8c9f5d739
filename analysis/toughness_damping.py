#!/usr/bin/env python3
"""The notched beam's toughness against its damping (issue 54 item 1): one CSV row per finished toughness run.

    python3 analysis/toughness_damping.py RUN_DIR... --csv data/studies/results/sfj_toughness_damping.csv

Each RUN_DIR is a `kerf-dem run` of a toughness scene (one packing, or the first of several). A row holds the run's
command and overrides, its damping (local and viscous, from the material as run), loading speed, K_IC (the smoothed
peak's and the raw peak's), the books' G_c, the quasi-static check when it ran, and, read from curve.csv at the
smoothed peak, the broken elements before it and the beam's kinetic energy against its stored elastic energy (the
undamped lattice's ringing: what a damping takes away). Rows are appended to the CSV (written whole, the header
once); a run already in it (by its directory) is replaced.
"""
import argparse
import csv
import io
import json
import os
import sys

from kerf.result_keys import ToughnessCheckResults as Q
from kerf.result_keys import ToughnessCurveColumns as C
from kerf.result_keys import ToughnessPackingResults as P
from kerf.result_keys import ToughnessResults as T

COLUMNS = [
    "run", "seed", "material", "local_damping", "viscous_damping_ratio", T.speed_m_per_s,
    P.fracture_toughness_MPa_sqrt_m, P.raw_peak_toughness_MPa_sqrt_m, P.fracture_energy_J_per_m2, P.peak_load_N,
    P.deflection_at_peak_um, "cracks_before_peak", "kinetic_energy_at_peak_J", "stored_elastic_energy_at_peak_J",
    "kinetic_over_stored_at_peak", "kinetic_energy_before_first_crack_J", "half_speed_toughness_MPa_sqrt_m",
    "half_speed_change_percent", "wall_time_s", "command",
]


def material_of(summary):
    prov = summary.get("provenance", {})
    scene = prov.get("scene_as_run") or prov.get("scene") or {}
    if isinstance(scene, dict):
        return scene.get("material", {})
    return {}


def row_of(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    res = summary["results"]
    first = res[T.per_packing][0]
    seed = first["seed"]
    with open(os.path.join(run_dir, "curve.csv")) as f:
        curve = [r for r in csv.DictReader(f) if int(r[C.seed]) == seed]
    peak = max(curve, key=lambda r: float(r[C.smoothed_load_N]))
    before = [r for r in curve if int(r[C.n_cracks]) == 0]
    kinetic = float(peak[C.kinetic_energy_J])
    stored = float(peak[C.stored_elastic_energy_J])
    mat = material_of(summary)
    prov = summary.get("provenance", {})
    qs = res.get("quasi_static_check") or {}
    return {
        "run": os.path.basename(os.path.normpath(run_dir)),
        "seed": seed,
        "material": mat.get("base", summary.get("material", {}).get("name", "")) if isinstance(mat, dict) else "",
        "local_damping": mat.get("local_damping", 0) if isinstance(mat, dict) else "",
        "viscous_damping_ratio": mat.get("viscous_damping_ratio", 0) if isinstance(mat, dict) else "",
        T.speed_m_per_s: res[T.speed_m_per_s],
        **{key: first[key] for key in (P.fracture_toughness_MPa_sqrt_m, P.raw_peak_toughness_MPa_sqrt_m,
                                       P.fracture_energy_J_per_m2, P.peak_load_N, P.deflection_at_peak_um)},
        "cracks_before_peak": int(peak[C.n_cracks]),
        "kinetic_energy_at_peak_J": kinetic,
        "stored_elastic_energy_at_peak_J": stored,
        "kinetic_over_stored_at_peak": kinetic / stored if stored > 0 else "",
        "kinetic_energy_before_first_crack_J": float(before[-1][C.kinetic_energy_J]) if before else "",
        "half_speed_toughness_MPa_sqrt_m": qs.get("half_speed_toughness_MPa_sqrt_m", qs.get(Q.fracture_toughness_MPa_sqrt_m, "")),
        "half_speed_change_percent": qs.get(Q.peak_change_percent, ""),
        "wall_time_s": summary.get("wall_time_s", ""),
        "command": prov.get("command_line", ""),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--csv", required=True)
    a = ap.parse_args()
    rows = []
    if os.path.exists(a.csv):
        with open(a.csv) as f:
            rows = list(csv.DictReader(f))
    new = [row_of(d) for d in a.runs]
    names = {r["run"] for r in new}
    rows = [r for r in rows if r["run"] not in names] + new
    out = io.StringIO()
    w = csv.DictWriter(out, fieldnames=COLUMNS, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: r.get(k, "") for k in COLUMNS})
    tmp = a.csv + ".tmp"
    with open(tmp, "w") as f:
        f.write(out.getvalue())
    os.replace(tmp, a.csv)
    for r in new:
        print(f"{r['run']}: K_IC {float(r[P.fracture_toughness_MPa_sqrt_m]):.4f} MPa sqrt(m), cracks before peak "
              f"{r['cracks_before_peak']}, kinetic/stored at peak {r['kinetic_over_stored_at_peak']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
