#!/usr/bin/env python3
"""The load events of a steady cut and how deep the cracks each drives run below the cut line (issue 54 item 3).

    PYTHONPATH=build/python python3 analysis/cut_events.py DIR [DIR ...] [--events-csv OUT.csv] [--cuts-csv OUT.csv]
        [--figure OUT.png] [--toughness-MPa-sqrt-m 0.75]

Each DIR is a cut's output folder (summary.json, forces.csv, cracks.csv) or a study's (DIR/items/*/). Over the steady
part (the travel the summary's means cover) the tool is *loaded* where its cutting force exceeds --loaded-N-per-mm
(default 0.05 N/mm); an *event* is a stretch of loaded samples (stretches closer than --merge-um of travel joined) whose
peak cutting force exceeds --peak-N-per-mm (default 1 N/mm). An event's cracks are the joints broken from its first
sample to --merge-um of travel after its last; its depth is the deepest of them below the cut line (0 when none is
below it). Per cut: the loaded share of the steady samples, events per mm of travel, the share of the steady cutting
impulse the events carry, the share of events that crack deeper than --deep-um (default 25 um) below the cut line and
the median peak of those that do and of those that do not; per condition each with its 95 % interval over packings.

The scale a peak sets: a line load P per unit width opening a crack from its mouth drives it to the depth where its
stress intensity K = P sqrt(2 / (pi a)) (splitting forces on a semi-infinite crack; Tada, Paris & Irwin, The Stress
Analysis of Cracks Handbook, 3rd ed. 2000) falls to the glass's toughness: a = 2 P^2 / (pi K_IC^2), 12 um at 3.4 N/mm
and 170 um at 12.5 N/mm for K_IC 0.75 MPa sqrt(m). The figure draws each event's peak against its depth with that
curve: a scale, not a fit (the tool's load is not a pair of splitting forces).
"""
import argparse
import csv
import json
import math

import numpy as np

from kerf.records import condition_of, cutting_force_column, folders
from kerf.result_keys import CracksColumns as K
from kerf.result_keys import CutResults as R
from kerf.result_keys import ForcesCsvColumns as F
from kerf.stats import mean_of

CUT_MEASURES = ("loaded_share", "events_per_mm", "events_impulse_share", "deep_event_share", "deep_event_peak_N_per_mm",
                "shallow_event_peak_N_per_mm", "mean_cutting_N_per_mm")
EVENT_FIELDS = ("travel_mm", "peak_cutting_N_per_mm", "thrust_at_peak_N_per_mm", "impulse_share", "cracks",
                "deepest_crack_um")


def lefm_depth_um(peak_n_per_mm, toughness_mpa_sqrt_m):
    """The depth [um] to which a line load P [N/mm] at its mouth drives a crack against K_IC: a = 2 P^2 / (pi K^2)."""
    p = np.asarray(peak_n_per_mm, dtype=float) * 1e3
    return 2.0 * p**2 / (math.pi * (toughness_mpa_sqrt_m * 1e6) ** 2) * 1e6


def condition(summary):
    """condition_of's (glass, window, surface, depth) with the tool's rake, the edge zone and a finer region of disks
    named in the glass."""
    glass, window, surface, depth = condition_of(summary)
    if "rake_deg" in summary["cut"].get("tool", {}):
        glass += f", rake {summary['cut']['tool']['rake_deg']:g} deg"
    if summary["cut"].get("edge_zone", {}).get("enabled"):
        glass += ", edge zone"
    specimen = summary.get("specimen", {})
    if specimen.get("fine_radius_max_um", 0) > 0:
        glass += f", disks {specimen['fine_radius_min_um']:g}-{specimen['fine_radius_max_um']:g} um at the cut line"
    return glass, window, surface, depth


def stretches(mask, gap):
    """(first, last) index of each run of True in `mask`, runs fewer than `gap` samples apart joined."""
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return []
    breaks = np.flatnonzero(np.diff(idx) > gap)
    firsts = np.concatenate(([idx[0]], idx[breaks + 1]))
    lasts = np.concatenate((idx[breaks], [idx[-1]]))
    return list(zip(firsts.tolist(), lasts.tolist()))


def cut_events(folder, loaded_n_per_mm=0.05, peak_n_per_mm=1.0, merge_um=2.0, deep_um=25.0):
    """One cut: (condition, seed, per-cut measures, list of events as dicts of EVENT_FIELDS)."""
    summary = json.loads((folder / "summary.json").read_text())
    results = summary["results"]
    with open(folder / "forces.csv") as f:
        names = next(csv.reader(f))
    forces = np.loadtxt(folder / "forces.csv", delimiter=",", skiprows=1, ndmin=2)
    col = {n: i for i, n in enumerate(names)}
    width_mm = results.get(R.width_mm, 1.0)
    travel, time = forces[:, col[F.tool_travel_mm]], forces[:, col[F.time_s]]
    fc = forces[:, col[cutting_force_column(names)]] / width_mm
    ft = forces[:, col[F.thrust_force_N]] / width_mm
    steady = (travel >= results[R.steady_from_travel_mm]) & (travel <= results[R.steady_to_travel_mm])
    travel, time, fc, ft = travel[steady], time[steady], fc[steady], ft[steady]
    cracks = np.genfromtxt(folder / "cracks.csv", delimiter=",", names=True, dtype=None, encoding=None, ndmin=1)
    crack_time = np.atleast_1d(cracks[K.time_s]) if cracks.size else np.zeros(0)
    crack_depth_um = 1e3 * (results[R.cut_line_y_mm] - np.atleast_1d(cracks[K.y_mm])) if cracks.size else np.zeros(0)
    step_mm = float(np.median(np.diff(travel)))
    gap = max(1, round(merge_um * 1e-3 / step_mm))
    total = fc[fc > 0].sum()  # the positive impulse (the force is negative at times between events)
    events = []
    for first, last in stretches(fc > loaded_n_per_mm, gap):
        peak_at = first + int(np.argmax(fc[first:last + 1]))
        if fc[peak_at] <= peak_n_per_mm:
            continue
        end = time[min(last + gap, time.size - 1)]
        born = (crack_time >= time[first]) & (crack_time <= end)
        below = crack_depth_um[born]
        events.append({"travel_mm": float(travel[first]), "peak_cutting_N_per_mm": float(fc[peak_at]),
                       "thrust_at_peak_N_per_mm": float(ft[peak_at]),
                       "impulse_share": float(fc[first:last + 1].sum() / total) if total > 0 else 0.0,
                       "cracks": int(born.sum()), "deepest_crack_um": float(max(0.0, below.max())) if below.size else 0.0})
    deep = [e["peak_cutting_N_per_mm"] for e in events if e["deepest_crack_um"] > deep_um]
    shallow = [e["peak_cutting_N_per_mm"] for e in events if e["deepest_crack_um"] <= deep_um]
    length_mm = travel[-1] - travel[0]
    measures = {"loaded_share": float(np.mean(fc > loaded_n_per_mm)), "events_per_mm": len(events) / length_mm,
                "events_impulse_share": sum(e["impulse_share"] for e in events),
                "deep_event_share": len(deep) / len(events) if events else math.nan,
                "deep_event_peak_N_per_mm": float(np.median(deep)) if deep else math.nan,
                "shallow_event_peak_N_per_mm": float(np.median(shallow)) if shallow else math.nan,
                "mean_cutting_N_per_mm": float(fc.mean())}
    seed = summary.get("study_item", {}).get("scene", {}).get("specimen", {}).get("seed", summary["specimen"]["seed"])
    return condition(summary), seed, measures, events


def table(cuts):
    """Per condition: {measure: Estimate over packings}."""
    by = {}
    for key, _, m, _ in cuts:
        by.setdefault(key, []).append(m)
    return {k: {name: mean_of([m[name] for m in rows]) for name in CUT_MEASURES} for k, rows in sorted(by.items())}


def figure(cuts, path, toughness):
    """Each event's peak cutting force against the deepest crack it drives below the cut line, one colour per condition,
    with the line-load crack's depth at the glass's toughness."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    keys = sorted({key for key, _, _, _ in cuts})
    # The glass's parts every condition shares go to the title, the others to the legend.
    parts = {key: key[0].split(", ") for key in keys}
    common = [x for x in parts[keys[0]] if all(x in parts[k] for k in keys)]
    fig, ax = plt.subplots(figsize=(7.5, 5.6 + 0.17 * len(keys)))
    for k, key in enumerate(keys):
        ev = [e for c in cuts if c[0] == key for e in c[3]]
        peak = [e["peak_cutting_N_per_mm"] for e in ev]
        depth = [max(e["deepest_crack_um"], 1.0) for e in ev]  # none below the cut line: drawn at 1 um
        own = ", ".join(x for x in parts[key] if x not in common)
        ax.scatter(peak, depth, s=10, alpha=0.6, color=f"C{k}",
                   label=f"{own + '; ' if own else ''}{key[2]}, {key[3]:g} mm ({len(ev)} events)")
    ax.set_title(", ".join(common), fontsize=9)
    p = np.geomspace(1.0, max(60.0, max((e["peak_cutting_N_per_mm"] for c in cuts for e in c[3]), default=60)), 50)
    ax.plot(p, lefm_depth_um(p, toughness), "k--", lw=1,
            label=f"a = 2 P$^2$ / ($\\pi$ K$_{{IC}}^2$), K$_{{IC}}$ = {toughness:g} MPa$\\sqrt{{m}}$")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(0.8, 2000)
    ax.set_xlabel("event's peak cutting force (N/mm)")
    ax.set_ylabel("deepest crack of the event below the cut line (um; none: 1)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12), frameon=False)
    fig.tight_layout()
    fig.savefig(path, dpi=130)


def fmt(e):
    return f"{e.value:.3g} [{e.low:.3g}, {e.high:.3g}]" if e.resolved() else f"{e.value:.3g}"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--loaded-N-per-mm", type=float, default=0.05)
    ap.add_argument("--peak-N-per-mm", type=float, default=1.0)
    ap.add_argument("--merge-um", type=float, default=2.0)
    ap.add_argument("--deep-um", type=float, default=25.0)
    ap.add_argument("--toughness-MPa-sqrt-m", type=float, default=0.75)
    ap.add_argument("--events-csv", help="one row per event")
    ap.add_argument("--cuts-csv", help="one row per cut")
    ap.add_argument("--figure", help="a PNG of the events' peaks against their cracks' depths")
    a = ap.parse_args(argv)
    cuts = [cut_events(f, a.loaded_N_per_mm, a.peak_N_per_mm, a.merge_um, a.deep_um) for f in folders(a.dirs)]
    if not cuts:
        raise SystemExit("no cut output folder (summary.json, forces.csv, cracks.csv) among the arguments")
    head = ["glass", "window", "surface", "depth_of_cut_mm", "seed"]
    if a.events_csv:
        with open(a.events_csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(head + list(EVENT_FIELDS))
            for key, seed, _, events in cuts:
                for e in events:
                    w.writerow([*key, seed, *(e[n] for n in EVENT_FIELDS)])
    if a.cuts_csv:
        with open(a.cuts_csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(head + list(CUT_MEASURES))
            for key, seed, m, _ in cuts:
                w.writerow([*key, seed, *(m[n] for n in CUT_MEASURES)])
    if a.figure:
        figure(cuts, a.figure, a.toughness_MPa_sqrt_m)
    print(f"steady part; loaded above {a.loaded_N_per_mm:g} N/mm; events peak above {a.peak_N_per_mm:g} N/mm; deep: a "
          f"crack deeper than {a.deep_um:g} um below the cut line; mean over packings [95 % interval]")
    for key, est in table(cuts).items():
        print(f"{key[0]} | {key[1]} | {key[2]}, {key[3]:g} mm | packings {est['loaded_share'].n}")
        for name in CUT_MEASURES:
            print(f"  {name}: {fmt(est[name])}")


if __name__ == "__main__":
    main()
