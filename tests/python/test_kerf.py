"""The Python module kerf (python/kerf_module.cpp) against the command-line programs and the stored references.

Run by ctest ("python: pytest") with PYTHONPATH at build/python and KERF_TOOLS at the built programs.
"""
import csv
import json
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

import kerf
from kerf.prediction_keys import PredictionColumns as P
from kerf.prediction_keys import TrepanningColumns as T
from kerf.result_keys import CutResults as R

SOURCE = pathlib.Path(__file__).resolve().parents[2]
TOOLS = pathlib.Path(os.environ.get("KERF_TOOLS", SOURCE / "build" / "tools"))
PSIC = SOURCE / "data" / "scenes" / "psic_liu_li.json"
ORTHOGONAL = SOURCE / "data" / "scenes" / "psic_orthogonal.json"
K9 = SOURCE / "validation" / "k9_trepanning" / "scene.json"
K9_CSV = SOURCE / "data" / "experiments" / "k9_trepanning.csv"
K9_MAP = {"cut.feed_rate_um_per_s": "feed_rate_um_s", T.axial_force_N: "axial_force_test_N",
          T.torque_N_m: "torque_test_Nm"}


def cli_predict_row(tmp_path, scene, *sets):
    out = tmp_path / "row.csv"
    args = [str(TOOLS / "kerf-forces"), "predict", str(scene), "--csv", str(out)]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True, capture_output=True)
    with open(out, newline="") as f:
        return next(csv.DictReader(f))


def test_version():
    assert kerf.__version__.count(".") == 2


def test_predict_equals_the_cli(tmp_path):
    row = kerf.predict(PSIC)
    cli = cli_predict_row(tmp_path, PSIC)
    assert set(row) == set(cli)
    for key, text in cli.items():
        if key in ("guards", "warnings"):  # lists in Python, joined text in the CSV
            assert (";" if key == "guards" else "; ").join(row[key]) == text, key
        elif text == "":
            assert row[key] is None, key
        elif isinstance(row[key], float):
            assert row[key] == float(text), key
        else:
            assert row[key] == text, key
    assert row[P.cutting_force_N] > 0


def test_predict_overrides_dotted_and_double_underscore(tmp_path):
    dotted = kerf.predict(str(PSIC), **{"tool.edge_radius_um": 0.2})
    underscored = kerf.predict(PSIC, tool__edge_radius_um=0.2)
    cli = cli_predict_row(tmp_path, PSIC, "tool.edge_radius_um=0.2")
    assert dotted[P.cutting_force_N] == underscored[P.cutting_force_N] == float(cli[P.cutting_force_N])
    assert dotted[P.cutting_force_N] != kerf.predict(PSIC)[P.cutting_force_N]


def test_predict_from_a_dict():
    scene = json.loads(PSIC.read_text())
    assert kerf.predict(scene)[P.cutting_force_N] == kerf.predict(PSIC)[P.cutting_force_N]


def test_input_error_carries_field_value_expected():
    with pytest.raises(kerf.InputError) as caught:
        kerf.predict(PSIC, tool__rake_deg=95)
    e = caught.value
    assert isinstance(e, ValueError)
    assert (e.field, e.value, e.expected) == ("tool.rake_deg", "95", "a value in (-90, 90) deg")
    assert str(e) == "tool.rake_deg = 95: expected a value in (-90, 90) deg"
    with pytest.raises(kerf.InputError) as caught:
        kerf.predict(SOURCE / "data" / "scenes" / "no_such_scene.json")
    assert "no_such_scene.json" in str(caught.value)


def test_model_error_is_a_python_exception():
    assert issubclass(kerf.ModelError, RuntimeError)
    assert not issubclass(kerf.ModelError, ValueError)


def test_sweep_columns_are_arrays():
    thickness = [0.05, 0.1, 0.2]
    table = kerf.sweep(ORTHOGONAL, vary={"cut.uncut_chip_thickness_um": thickness}, frame=False)
    assert isinstance(table, dict)
    assert table["cut.uncut_chip_thickness_um"].dtype == np.float64
    assert list(table["cut.uncut_chip_thickness_um"]) == thickness
    force = table[P.cutting_force_N]
    assert force.dtype == np.float64 and len(force) == 3
    assert all(np.diff(force) > 0)
    for i, t in enumerate(thickness):
        assert force[i] == kerf.predict(ORTHOGONAL, **{"cut.uncut_chip_thickness_um": t})[P.cutting_force_N]
    assert all(e is None for e in table["error"])


def test_sweep_grid_and_refused_points():
    table = kerf.sweep(ORTHOGONAL, vary={"tool.rake_deg": [0, 95], "tool.edge_radius_um": [0.1, 0.2, 0.3]}, frame=False)
    assert len(table[P.cutting_force_N]) == 6
    assert list(table["tool.rake_deg"]) == [0, 0, 0, 95, 95, 95]
    assert not any(math.isnan(f) for f in table[P.cutting_force_N][:3])
    assert all(math.isnan(f) for f in table[P.cutting_force_N][3:])
    assert all("tool.rake_deg = 95" in e for e in table["error"][3:])


def test_sweep_is_a_dataframe_with_pandas():
    pandas = pytest.importorskip("pandas")
    frame = kerf.sweep(ORTHOGONAL, vary={"cut.uncut_chip_thickness_um": [0.1, 0.2]}, frame=True)
    assert isinstance(frame, pandas.DataFrame) and len(frame) == 2


def test_sweep_refuses_a_bad_axis():
    with pytest.raises(kerf.InputError) as caught:
        kerf.sweep(ORTHOGONAL, vary={"cut.uncut_chip_thickness_um": "0.1"})
    assert caught.value.field == "vary.cut.uncut_chip_thickness_um"


def test_sweep_refuses_a_key_the_scene_does_not_read():
    # A misspelt key would refuse every point (rows of NaN): an exception instead, with the did-you-mean.
    with pytest.raises(kerf.InputError) as caught:
        kerf.sweep(ORTHOGONAL, vary={"tool.rake_deg": [0, 5], "tool.edge_radius": [0.1, 0.2]}, frame=False)
    assert caught.value.field == "vary" and caught.value.value == "tool.edge_radius"
    assert "edge_radius_um" in str(caught.value)
    # A known key whose first value is refused is that point's error, as before.
    table = kerf.sweep(ORTHOGONAL, vary={"tool.rake_deg": [95, 0]}, frame=False)
    assert math.isnan(table[P.cutting_force_N][0]) and not math.isnan(table[P.cutting_force_N][1])


def test_sweep_is_the_cli_sweep():
    # One library sweep (issue 39): the same unknown-key refusal for either scene kind, and the same numbers as
    # kerf-forces sweep's CSV, refused points included.
    k9 = SOURCE / "validation" / "k9_trepanning" / "scene.json"
    with pytest.raises(kerf.InputError) as caught:
        kerf.sweep(k9, vary={"cut.feed_rate_um_per_min": [10, 20]})
    assert caught.value.field == "vary" and "feed_rate_um_per_s" in str(caught.value)
    out = pathlib.Path(os.environ.get("TMPDIR", "/tmp")) / f"kerf_sweep_{os.getpid()}.csv"
    subprocess.run([str(TOOLS / "kerf-forces"), "sweep", str(ORTHOGONAL), "--vary", "tool.rake_deg=95,0,10",
                    "--vary", "cut.uncut_chip_thickness_um=0.1,0.5", "--csv", str(out)], check=True,
                   capture_output=True)
    rows = list(csv.DictReader(out.open()))
    out.unlink()
    table = kerf.sweep(ORTHOGONAL, vary={"tool.rake_deg": [95, 0, 10], "cut.uncut_chip_thickness_um": [0.1, 0.5]})
    assert len(rows) == len(table["error"]) == 6
    for i, row in enumerate(rows):
        assert (table["error"][i] or "") == row["error"]
        for column in (P.cutting_force_N, P.thrust_force_N, P.shear_angle_deg):
            assert (math.isnan(table[column][i]) if row[column] == "" else table[column][i] == float(row[column]))


def test_compare_refuses_a_csv_without_conditions_unless_pooled(tmp_path):
    csv_path = tmp_path / "nocond.csv"
    csv_path.write_text("depth_um,cutting_force_N\n0.1,1.5\n0.2,2.5\n")
    with pytest.raises(kerf.InputError) as caught:
        kerf.compare(ORTHOGONAL, csv_path)
    assert "depth_um" in str(caught.value) and "--pool" in str(caught.value)
    pooled = kerf.compare(ORTHOGONAL, csv_path, pool=True)
    assert pooled["quantities"]["cutting_force"]["n"] == 1  # both rows at the scene's one condition


def test_materials_and_models():
    names = [m["name"] for m in kerf.materials()]
    assert "soda_lime_glass_fj" in names and names == sorted(names)
    glass = next(m for m in kerf.materials() if m["name"] == "soda_lime_glass_fj")
    assert "dem" in glass["groups"]
    models = kerf.models()
    assert {"kind": "force", "name": "liu_li"}.items() <= next(
        m for m in models if m["kind"] == "force" and m["name"] == "liu_li").items()


def test_compare_like_the_cli(tmp_path):
    result = kerf.compare(K9, K9_CSV, map=K9_MAP, fit=True, out=tmp_path / "k9")
    axial = result["quantities"]["axial_force"]
    assert axial["n"] == 8 and axial["mean_abs_error_percent"] <= 5.0
    assert len(axial["measured"]) == len(axial["predicted"]) == 8
    summary = json.loads((tmp_path / "k9" / "summary.json").read_text())
    assert summary["quantities"]["axial_force"]["mean_abs_error_percent"] == axial["mean_abs_error_percent"]


SMALL_CUT = {  # tests/dem/scene_test.cpp 'small cut regression through run_scene'
    "kind": "cut", "material": {"base": "soda_lime_glass_fj"},
    "specimen": {"width_mm": 0.4, "height_mm": 0.25, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
                 "growth_steps": 2000, "relax_steps": 500},
    "cut": {"depth_of_cut_mm": 0.05, "speed_m_per_s": 2, "length_mm": 0.1},
    "grooves": {"shape": "rectangular", "pitch_mm": 0.08, "width_mm": 0.03},
    "output": {"frame_every_samples": 0}}


def test_dem_run_small_cut(tmp_path):
    done = kerf.dem.run(SMALL_CUT, out=tmp_path / "cut", threads=1)
    assert done["exit_status"] == 0
    reference = json.loads((SOURCE / "tests" / "dem" / "reference" / "cut_small.json").read_text())
    summary = done["summary"]
    assert summary["n_particles"] == reference["values"]["n_particles"]
    assert summary == json.loads((tmp_path / "cut" / "summary.json").read_text())
    main = summary["results"][R.main_force_N]
    assert main == pytest.approx(reference["values"][R.main_force_N], rel=reference["relative_tolerance"])
    forces, cracks = done["forces"], done["cracks"]
    with open(tmp_path / "cut" / "forces.csv", newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    assert list(forces) == rows[0]
    assert len(rows) - 1 == len(next(iter(forces.values())))
    assert all(v.dtype == np.float64 for v in forces.values())
    assert len(next(iter(cracks.values()))) > 0


def test_dem_run_reports_progress_to_a_callable(tmp_path):
    seen = []
    scene = dict(SMALL_CUT, cut=dict(SMALL_CUT["cut"], length_mm=0.02))
    kerf.dem.run(scene, out=tmp_path / "cut", threads=1, progress=lambda *update: seen.append(update))
    stages = [s for k, (s, *_rest) in enumerate(seen) if k == 0 or seen[k - 1][0] != s]
    assert stages == ["specimen genesis", "cut"]
    stage, done, total, unit = seen[-1]
    assert (stage, unit) == ("cut", "particle-steps") and done == total > 0


def test_dem_run_stops_when_the_progress_callable_raises(tmp_path):
    def stop(*update):
        raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        kerf.dem.run(SMALL_CUT, out=tmp_path / "cut", threads=1, progress=stop)


def test_dem_input_error_names_the_key(tmp_path):
    with pytest.raises(kerf.InputError) as caught:
        kerf.dem.run(SMALL_CUT, out=tmp_path / "x", cut__depth_of_cut_mn=0.1)
    assert caught.value.field == "cut.depth_of_cut_mn"
    assert "depth_of_cut_mm" in caught.value.expected
    assert "cut" in kerf.dem.kinds()


def test_ploughing_parts_beside_the_totals():
    # Inside the ploughed layer (r = 0.2 um: h_s = 0.037 um) the chip term is zero and the total is the ploughing
    # term alone; 'none' keeps the chip term only (issue 38).
    inside = {"cut.uncut_chip_thickness_um": 0.01}
    wave = kerf.predict(ORTHOGONAL, **inside)
    none = kerf.predict(ORTHOGONAL, **inside, **{"models.ploughing": "none"})
    assert none[P.cutting_force_N] == 0 and none[P.ploughing_cutting_force_N] == 0
    assert wave[P.ploughing_cutting_force_N] > 0 and wave[P.ploughing_thrust_force_N] > 0
    assert wave[P.cutting_force_N] == wave[P.ploughing_cutting_force_N]
    assert wave[P.thrust_force_N] == wave[P.ploughing_thrust_force_N]
    # Above it the totals are the chip term plus the ploughing term.
    above = {"cut.uncut_chip_thickness_um": 0.5}
    wave, none = kerf.predict(ORTHOGONAL, **above), kerf.predict(ORTHOGONAL, **above, **{"models.ploughing": "none"})
    for part in ("cutting", "thrust"):
        total = none[f"{part}_force_N"] + wave[f"ploughing_{part}_force_N"]
        assert math.isclose(wave[f"{part}_force_N"], total, rel_tol=1e-12)
