"""Issue 40 item 7: the module behaves as Python users expect: the same types in every call, signatures and
docstrings that help() and inspect read, the bundled scenes, the DEM's VTK frames as numpy arrays, pandas asked for
explicitly.

Run by ctest ("python: pytest") with PYTHONPATH at build/python.
"""
import importlib.util
import inspect
import json
import pathlib
import xml.etree.ElementTree as ElementTree

import numpy as np
import pytest

import kerf
from kerf.prediction_keys import PredictionColumns as P
from kerf.prediction_keys import TransitionColumns

SOURCE = pathlib.Path(__file__).resolve().parents[2]
ORTHOGONAL = SOURCE / "data" / "scenes" / "psic_orthogonal.json"
K9 = SOURCE / "validation" / "k9_trepanning" / "scene.json"
PUBLIC = [kerf.predict, kerf.sweep, kerf.compare, kerf.materials, kerf.models, kerf.scenes, kerf.scene_path,
          kerf.dem.run, kerf.dem.kinds, kerf.dem.read_frames]


@pytest.mark.parametrize("function", PUBLIC, ids=lambda f: f.__name__)
def test_every_public_function_has_a_signature_and_a_docstring(function):
    signature = inspect.signature(function)  # raises ValueError for a function without one
    assert function.__doc__ and len(function.__doc__.strip()) > 30
    for name, parameter in signature.parameters.items():  # every named argument is documented
        if parameter.kind not in (parameter.VAR_KEYWORD, parameter.VAR_POSITIONAL):
            assert name in function.__doc__, (function.__name__, name)


def test_signatures_name_the_arguments():
    assert list(inspect.signature(kerf.sweep).parameters) == ["scene", "vary", "frame", "overrides"]
    assert inspect.signature(kerf.sweep).parameters["frame"].default is False
    run = inspect.signature(kerf.dem.run).parameters
    assert run["threads"].default is None and run["replicates"].default == 1 and "out" in run
    assert kerf.dem.run.__module__ == "kerf.dem" and kerf.dem.read_frames.__name__ == "read_frames"


def test_exception_classes_have_docstrings():
    for error in (kerf.InputError, kerf.ModelError):
        assert error.__doc__ and len(error.__doc__) > 30
    assert issubclass(kerf.InputError, ValueError) and issubclass(kerf.ModelError, RuntimeError)


def test_predict_types_are_stable():
    plain = kerf.predict(ORTHOGONAL)
    warned = kerf.predict(ORTHOGONAL, tool__edge_radius_um=5)  # a blunt edge: a guard or a warning fires
    for row in (plain, warned):
        assert isinstance(row["guards"], list) and all(isinstance(g, str) for g in row["guards"])
        assert isinstance(row["warnings"], list) and all(isinstance(w, str) for w in row["warnings"])
        assert all(v is None or isinstance(v, (float, str, list)) for v in row.values())
        assert "" not in row.values()
    assert warned["guards"] or warned["warnings"]
    trepanning = kerf.predict(K9)
    assert trepanning["guards"] == [] and trepanning["warnings"] == []


def test_sweep_types_are_stable():
    table = kerf.sweep(ORTHOGONAL, vary={"tool.rake_deg": [0, 95], "tool.edge_radius_um": [0.1, 5]})
    assert isinstance(table, dict)
    assert table[P.cutting_force_N].dtype == np.float64
    refused = [e is not None for e in table["error"]]
    assert refused == [False, False, True, True]
    assert all(isinstance(e, str) and e for e in table["error"][2:])
    assert np.isnan(table[P.cutting_force_N][2:]).all()
    for column in ("guards", "warnings"):
        assert table[column].dtype == object and table[column].shape == (4,)
        assert all(isinstance(cell, list) for cell in table[column])
    assert table["guards"][2] == [] and table["warnings"][3] == []
    assert table["regime"][2] is None


def test_sweep_frame_is_explicit():
    if importlib.util.find_spec("pandas") is None:
        with pytest.raises(ImportError, match="needs pandas.*frame=False"):
            kerf.sweep(ORTHOGONAL, vary={"tool.rake_deg": [0, 5]}, frame=True)
    else:
        import pandas
        frame = kerf.sweep(ORTHOGONAL, vary={"tool.rake_deg": [0, 5]}, frame=True)
        assert isinstance(frame, pandas.DataFrame) and len(frame) == 2
    assert isinstance(kerf.sweep(ORTHOGONAL, vary={"tool.rake_deg": [0, 5]}), dict)


def test_scenes_and_scene_path():
    listed = kerf.scenes()
    on_disk = sorted(p.stem for p in (SOURCE / "data" / "scenes").glob("*.json"))
    assert [s["name"] for s in listed] == on_disk
    for entry in listed:
        document = json.loads(pathlib.Path(entry["path"]).read_text())
        assert entry["kind"] == document.get("kind")
        assert entry["program"] == ("kerf-dem" if "kind" in document else "kerf-forces")
        assert kerf.scene_path(entry["name"]) == pathlib.Path(entry["path"])
    # The bundled scene, from the data kerf reads: the source tree's, or an installed copy (pip install .).
    assert kerf.scene_path("psic_orthogonal.json") == kerf.scene_path("psic_orthogonal")
    assert kerf.scene_path("psic_orthogonal.json").read_bytes() == ORTHOGONAL.read_bytes()
    assert kerf.predict(kerf.scene_path("psic_orthogonal"))[P.cutting_force_N] > 0
    with pytest.raises(kerf.InputError, match="did you mean 'dem_cut'"):
        kerf.scene_path("dem_cutt")


FRAMED_CUT = {
    "kind": "cut", "material": {"base": "soda_lime_glass_fj"},
    "specimen": {"width_mm": 0.4, "height_mm": 0.25, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
                 "growth_steps": 2000, "relax_steps": 500},
    "cut": {"depth_of_cut_mm": 0.05, "speed_m_per_s": 2, "length_mm": 0.02},
    "output": {"frame_every_samples": 1}}


def test_dem_run_progress_counts_are_ints_and_tables_always_present(tmp_path):
    seen = []
    done = kerf.dem.run(FRAMED_CUT, out=tmp_path / "cut", threads=1, progress=lambda *u: seen.append(u))
    assert seen and all(type(d) is int and type(t) is int for _stage, d, t, _unit in seen)
    assert set(done) >= {"forces", "cracks", "curve", "summary", "exit_status", "out"}
    assert done["curve"] is None and isinstance(done["forces"], dict)

    frames = kerf.dem.read_frames(tmp_path / "cut")
    pvd = ElementTree.parse(tmp_path / "cut" / "result.pvd").getroot()
    times = sorted({float(d.get("timestep")) for d in pvd.iter("DataSet")})
    assert [f["time_s"] for f in frames] == times and len(frames) >= 2
    particles = frames[-1]["particles"]
    n = done["summary"]["n_particles"]
    assert particles["position_mm"].shape == (n, 3) and particles["radius_mm"].shape == (n,)
    width = FRAMED_CUT["specimen"]["width_mm"]
    assert particles["position_mm"][:, 0].max() <= width * 1.5 and (particles["radius_mm"] > 0).all()
    assert particles["radius_mm"].max() <= FRAMED_CUT["specimen"]["radius_max_um"] * 1e-3 * (1 + 1e-9)
    assert particles["lines"].shape[1] == 2 and particles["lines"].max() < n
    assert particles["intact_elements"].shape == (len(particles["lines"]),)
    assert (particles["id"] == np.arange(n)).all()
    with pytest.raises(kerf.InputError, match="pvd"):
        kerf.dem.read_frames(tmp_path)


def test_dem_read_frames_reads_the_steps_asked_for(tmp_path):
    kerf.dem.run(FRAMED_CUT, out=tmp_path / "cut", threads=1)
    every = kerf.dem.read_frames(tmp_path / "cut")
    chosen = kerf.dem.read_frames(tmp_path / "cut", steps=[len(every) - 1, 0])
    assert [f["time_s"] for f in chosen] == [every[-1]["time_s"], every[0]["time_s"]]
    assert np.array_equal(chosen[0]["particles"]["position_mm"], every[-1]["particles"]["position_mm"])
    with pytest.raises(kerf.InputError, match="steps"):
        kerf.dem.read_frames(tmp_path / "cut", steps=[len(every)])


def test_compare_rows_hold_each_rows_prediction_lists(tmp_path):
    # The rows' guards and warnings are the prediction's own lists at each row's condition (not the CSV's joined
    # text): the same lists kerf.predict gives at that edge radius.
    csv_path = tmp_path / "edges.csv"
    csv_path.write_text("edge_radius_um,cutting_force_N\n0.1,1.0\n5,2.0\n")
    result = kerf.compare(ORTHOGONAL, csv_path, map={"tool.edge_radius_um": "edge_radius_um"})
    assert len(result["rows"]) == 2
    for row, edge in zip(result["rows"], (0.1, 5)):
        alone = kerf.predict(ORTHOGONAL, tool__edge_radius_um=edge)
        assert row["guards"] == alone["guards"] and row["warnings"] == alone["warnings"]
        assert all(isinstance(w, str) for w in row["warnings"])
    assert result["rows"][1]["guards"] or result["rows"][1]["warnings"]


def test_glass_results_carry_the_regime_and_the_model_range():
    """Issue 53: a glass runs through kerf.predict and kerf.sweep; each row says its regime and whether its model
    holds there (a ductile-only model above d_c does not)."""
    glass = SOURCE / "data" / "scenes" / "soda_lime_transition.json"
    row = kerf.predict(glass)
    assert row["regime"] == "brittle" and row["within_model_range"] == "yes"
    assert row[TransitionColumns.layer_cutting_force_N] > 0 and row[TransitionColumns.fracture_cutting_force_N] > 0
    table = kerf.sweep(glass, vary={"cut.uncut_chip_thickness_um": [0.01, 0.1, 1.0]}, models__force="liu_li")
    dc_um = table["critical_depth_nm"][0] / 1e3
    assert list(table["regime"]) == ["ductile" if h < dc_um else "transition" if h < 3 * dc_um else "brittle"
                                     for h in table["uncut_chip_thickness_um"]]
    assert list(table["within_model_range"]) == ["yes" if h < dc_um else "no" for h in table["uncut_chip_thickness_um"]]


def test_categorical_sweeps_give_the_separate_predictions():
    """Issue 55 item 3: models and materials varied in kerf.sweep, crossed with a number: each row is the separate
    prediction's, every varied key its own column (material_varied beside the prediction's own material)."""
    glass = SOURCE / "data" / "scenes" / "soda_lime_transition.json"
    table = kerf.sweep(glass, vary={"models.force": ["merchant", "transition"], "material": ["soda_lime_glass", "k9_glass"],
                                    "cut.uncut_chip_thickness_um": [0.02, 5.0]})
    assert len(table["error"]) == 8 and all(e is None for e in table["error"])
    for i in range(8):
        one = kerf.predict(glass, models__force=table["models.force"][i], material=table["material_varied"][i],
                           cut__uncut_chip_thickness_um=table["cut.uncut_chip_thickness_um"][i])
        for key, value in one.items():
            cell = table[key][i]
            if value is None and isinstance(cell, float):  # an empty number: None in a dict, NaN in a float column
                value = float("nan")
            assert cell == value or (isinstance(value, float) and np.isnan(value) and np.isnan(cell)), (key, cell, value)
        assert table["material"][i] == table["material_varied"][i]
