#!/usr/bin/env bash
# kerf-dem cut with an edge zone (issue 54 item 4; docs/dem.md "The edge zone"): bad keys exit 2 naming them (no
# window, one force of the two, a material without the edge model's data); on the shrunk steady scene the zone's
# force comes from the material's edge model or from the scene, its results are in the summary, and it is off by
# default (no edge_zone section, no edge_zone results).
# Usage: dem_edge_zone_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

steady="$src/data/scenes/dem_cut_steady.json"
# The five-target glass, 0.1 mm deep: in this shrunk cut the zone meets intact glass in about 13 % of the steady
# samples (0 % at 0.05 mm, where the glass at the tip is broken, or over a shorter travel).
small=(--set specimen.width_mm=0.8 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.1 --set cut.length_mm=0.3 --set cut.window_mm=0.05
       --set cut.entry_fraction=0.25 --set cut.speed_m_per_s=2 --set output.frame_every_samples=0
       --set material.base=soda_lime_glass_sfj_undamped_cut)
expect_input_error "edge_zone.enabled" run "$src/data/scenes/dem_cut.json" --set edge_zone.enabled=true --out "$work/x"
expect_input_error "edge_zone.thrust_force_N_per_mm" run "$steady" --set edge_zone.enabled=true \
    --set edge_zone.cutting_force_N_per_mm=0.5 --out "$work/x"
expect_input_error "edge_zone.friction_coefficient = -1" run "$steady" --set edge_zone.enabled=true \
    --set edge_zone.friction_coefficient=-1 --out "$work/x"
# A material of its own, without a hardness: the edge model has nothing to work with, the scene says which key.
python3 - "$steady" "$work/own.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["material"] = {"density_kg_per_m3": 2500}
s["edge_zone"] = {"enabled": True}
json.dump(s, open(sys.argv[2], "w"))
PY
expect_input_error "edge_zone.cutting_force_N_per_mm" run "$work/own.json" --out "$work/x"
[ ! -e "$work/x/summary.json" ] || fail "a rejected scene wrote output"

"$bin" run "$steady" "${small[@]}" --set edge_zone.enabled=true --out "$work/model" --threads 1 >/dev/null \
    2>"$work/err" || fail "edge zone, the material's model: $(cat "$work/err")"
"$bin" run "$steady" "${small[@]}" --set edge_zone.enabled=true --set edge_zone.cutting_force_N_per_mm=0.55 \
    --set edge_zone.thrust_force_N_per_mm=0.48 --out "$work/given" --threads 1 >/dev/null 2>"$work/err" ||
  fail "edge zone, given forces: $(cat "$work/err")"
"$bin" run "$steady" "${small[@]}" --out "$work/off" --threads 1 >/dev/null 2>"$work/err" ||
  fail "edge zone off: $(cat "$work/err")"
python3 - "$work" <<'PY' || fail "edge zone summaries"
import json, math, sys
d = sys.argv[1]
model, given, off = (json.load(open(f"{d}/{n}/summary.json")) for n in ("model", "given", "off"))
keys = ["edge_zone_samples_steady", "edge_zone_intact_share_steady", "edge_zone_cutting_force_N_per_mm",
        "edge_zone_thrust_force_N_per_mm", "edge_zone_removed_tied_disks", "edge_zone_removed_loose_disks",
        "edge_zone_removed_mass_kg", "energy_edge_zone_tool_work_steady_J", "energy_edge_zone_reaction_work_steady_J",
        "energy_edge_layer_steady_J"]
for s in (model, given):
    r, z = s["results"], s["cut"]["edge_zone"]
    missing = [k for k in keys if k not in r]
    assert not missing, missing
    assert r["edge_zone_samples_steady"] > 0 and 0 <= r["edge_zone_intact_share_steady"] <= 1, r
    assert r["edge_zone_cutting_force_N_per_mm"] == z["cutting_force_N_per_mm"] > 0, (r, z)
    assert r["edge_zone_thrust_force_N_per_mm"] == z["thrust_force_N_per_mm"] > 0, (r, z)
    # the reach resolved to the workpiece's largest diameter, stored with the cut
    assert 2 * s["specimen"]["radius_min_um"] < z["radius_um"] <= 2 * s["specimen"]["radius_max_um"], z
    layer = r["energy_edge_zone_tool_work_steady_J"] - r["energy_edge_zone_reaction_work_steady_J"]
    assert math.isclose(r["energy_edge_layer_steady_J"], layer, rel_tol=1e-12, abs_tol=1e-300), r
r = model["results"]  # the zone acted: it met intact glass, carried the layer's energy and removed what it reached
assert r["edge_zone_intact_share_steady"] > 0 and r["energy_edge_zone_tool_work_steady_J"] > 0, r
assert r["edge_zone_removed_tied_disks"] + r["edge_zone_removed_loose_disks"] > 0, r
assert given["cut"]["edge_zone"]["cutting_force_N_per_mm"] == 0.55
assert model["cut"]["edge_zone"]["cutting_force_N_per_mm"] != 0.55
assert "edge_zone" not in off["cut"] and not any(k.startswith("edge_zone") for k in off["results"]), off["results"]
PY
echo "dem edge zone cli: ok"
