"""No result key is written or read as a literal outside its table (issue 56 item 1): kerf-dem's results (the cut's,
the lab tests', the toughness test's, the calibrations') and the columns of its CSV files, and kerf-forces' prediction
columns, are named once, in their result tables (dem/procedures/cut_results.cpp, dem/output/output.cpp, dem/kinds/,
analytic/kinds/predict.cpp, the model units' analytic/forces/chip_term.cpp, oxley_model.cpp and transition_model.cpp,
analytic/trepanning/trepanning_kind.cpp), and read by name, through the constants of
kerf/dem/procedures/cut_results.hpp, kerf/dem/output/output.hpp, dem/kinds/kind_results.hpp,
kerf/analytic/kinds/predict.hpp, the units' headers (edge_keys, oxley_keys, transition_keys) and
kerf/analytic/trepanning/trepanning_results.hpp (C++) or kerf.result_keys and kerf.prediction_keys (Python, generated
from the tables: tests/cli/dem_results_cli.sh, tests/cli/forces_results_cli.sh). A quoted key in any other C++, Python
or shell source (comments aside) fails here unless the file is in ALLOWED below, with the keys it may quote and why.
Data files (records, studies, docs) are not sources."""
import importlib.util
import pathlib
import re


ROOT = pathlib.Path(__file__).resolve().parents[2]
SOURCES = ("*.cpp", "*.hpp", "*.h", "*.py", "*.sh")
# Names other parts of kerf also use for something else, not checked: input keys (specimen.width_mm, tool.rake_deg,
# a law's friction_angle_deg, Johnson-Cook's strain_rate_per_s, the models' chip_ratio), the trepanning kind's own
# columns (critical_depth_nm, regime, guards, warnings), plain words.
SHARED = {"width_mm", "time_s", "samples", "steady", "force_model", "material", "rake_deg", "edge_radius_um",
          "clearance_deg", "speed_m_per_min", "workpiece_temperature_K", "scene_friction_angle_deg",
          "uncut_chip_thickness_um", "friction_angle_deg", "chip_ratio", "strain", "strain_rate_per_s", "temperature_K",
          "feed_um_per_rev", "depth_of_cut_um", "critical_depth_nm", "regime", "within_model_range", "guards",
          "warnings",
          # the trepanning scene's input keys, echoed in its row
          "outer_diameter_mm", "inner_diameter_mm", "feed_rate_um_per_s", "spindle_speed_rpm", "axial_group_MPa",
          "torque_group_MPa",
          # the chip term's input keys (models.friction_closure, cut.friction_factor: also the physics' argument
          # names), echoed in the edge's columns
          "friction_closure", "friction_factor",
          # the DEM kinds' results that are also input keys: calibration.targets' (and the analytic material's
          # elastic and brittle keys; toughness.youngs_modulus_GPa; a joint's tensile_strength_MPa), a softening
          # joint's fracture_energy_J_per_m2, the loading's, the toughness test's and the cut's speed_m_per_s,
          # cut.length_mm, toughness.peak_window_um, calibration.packings, calibrate_cut's calibration section, a
          # specimen file's bonds.strength_factor
          "youngs_modulus_GPa", "poissons_ratio", "tensile_strength_MPa", "compressive_strength_MPa",
          "fracture_toughness_MPa_sqrt_m", "fracture_energy_J_per_m2", "speed_m_per_s", "length_mm", "peak_window_um",
          "packings", "targets", "target_cutting_force_N", "target_main_force_N", "target_source",
          "tolerance_percent", "strength_factor",
          # every summary's and study record's own (wall time, time steps, also a progress unit), the validation
          # cases' own verdicts, a benchmark's own column
          "wall_time_s", "steps", "verdict", "converged"}
# CSV columns that are also input keys (the material's, the specimen's seed), VTK arrays (the frames' stress_MPa,
# the crack frames' place, which render_frames.py colours by under pvpython) or plain words.
SHARED_COLUMNS = {"seed", "mode", "bond", "element", "place", "evaluation", "directory", "stress_MPa",
                  "effective_modulus_GPa", "stiffness_ratio", "cohesion_MPa"}
OUTPUT_TESTS = "an end-to-end test of the written output: the literal is the format users read, a rename must fail it"
ALLOWED = {
    # What the keys are written in, and generated from.
    "python/kerf/result_keys.py": (None, "generated from the result tables (kerf-dem results --python)"),
    "python/kerf/prediction_keys.py": (None, "generated from the result table (kerf-forces results --python)"),
    # Input keys named as the results they stand for.
    "analytic/kinds/scene.cpp": ({"cutting_force_N", "thrust_force_N"}, "compare's measured forces (input keys)"),
    "dem/procedures/cut_params.cpp": ({"cutting_force_N_per_mm", "thrust_force_N_per_mm"},
                                      "the edge zone's given layer forces (input keys)"),
    # An error naming the quantity in the physics layer, which the prediction's table (kinds/) is built on.
    "analytic/forces/merchant.cpp": ({"shear_angle_deg"}, "an InputError naming the shear angle"),
    "analytic/forces/oxley.cpp": ({"strain_rate_constant_C0"}, "an InputError naming the solver's argument"),
    "analytic/trepanning/trepanning.cpp": ({"axial_force_N", "torque_N_m", "feed_per_rev_um"},
                                           "a ModelError naming the quantity beyond a double"),
    # Documentation in code.
    "python/kerf_api.py": ({"cutting_force_N"}, "a docstring's example of kerf.predict"),
    # A report that reads kerf-forces' CSV by the generated names, with records of its own named as the columns
    # they hold.
    "validation/glass_transition/report.py": ({"fracture_model", "ductile_layer_um"},
                                              "its own records' keys (predictions.csv, summary.json)"),
    # Own outputs named after a result, not reads of one.
    "analysis/strength_scan.py": ({"cracks_subsurface"}, "its own table's column (the steady count)"),
    # The tests of the written format.
    "tests/cli/*.sh": (None, OUTPUT_TESTS),
    "tests/bench/*.sh": (None, OUTPUT_TESTS),
    "tests/dem/*.cpp": (None, OUTPUT_TESTS),
    "tests/core/*.cpp": (None, OUTPUT_TESTS),
    "tests/analytic/*.cpp": (None, OUTPUT_TESTS),
    "tests/release/*.sh": (None, OUTPUT_TESTS),
    # This test.
    "tests/python/test_result_key_literals.py": (None, "the test itself"),
}


def generated(name):
    """A generated module of python/kerf/ (the source's: the build's copy may be older)."""
    spec = importlib.util.spec_from_file_location(name, ROOT / "python" / "kerf" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def result_keys():
    """Every key of every table of both generated modules (a class per table), but the shared columns."""
    keys = set()
    for module in (generated("result_keys"), generated("prediction_keys")):
        for table in (v for v in vars(module).values() if isinstance(v, type)):
            keys |= set(module.keys(table))
    return keys - SHARED_COLUMNS


def sources(root):
    for pattern in SOURCES:
        for path in root.rglob(pattern):
            rel = path.relative_to(root)
            if rel.parts[0].startswith(("build", ".")) or any(p.startswith(".") for p in rel.parts):
                continue
            yield rel


def allowed(rel, key):
    for pattern, (keys, _) in ALLOWED.items():
        if rel.match(pattern) and (keys is None or key in keys):
            return True
    return False


def code_of(rel, line):
    """The line without its comment (a comment may quote a key: it neither writes nor reads one)."""
    marker = "//" if rel.suffix in (".cpp", ".hpp", ".h") else "#"
    stripped = line.lstrip()
    if stripped.startswith(marker) or stripped.startswith("*"):
        return ""
    at = line.find(" " + marker + " ")
    return line if at < 0 else line[:at]


def offenders(keys, root=ROOT):
    quoted = re.compile(r'''(["'])(%s)\1''' % "|".join(sorted(map(re.escape, keys), key=len, reverse=True)))
    found = []
    for rel in sources(root):
        for number, line in enumerate((root / rel).read_text(errors="replace").splitlines(), 1):
            for m in quoted.finditer(code_of(rel, line)):
                if not allowed(rel, m.group(2)):
                    found.append(f"{rel}:{number}: {m.group(2)}")
    return found


def test_no_result_key_literal_outside_its_table():
    keys = result_keys() - SHARED
    found = offenders(keys)
    assert not found, ("result keys quoted outside their tables (use the constants of kerf/dem/procedures/"
                       "cut_results.hpp, dem/kinds/kind_results.hpp or kerf/analytic/kinds/predict.hpp, or "
                       "kerf.result_keys or kerf.prediction_keys; or list the file in ALLOWED with the reason):\n"
                       + "\n".join(found))


def test_the_check_finds_a_literal(tmp_path):
    keys = result_keys() - SHARED
    assert "subsurface_damage_depth_steady_um" in keys and "steady_from_travel_mm" in keys
    assert {"x_mm", "length_um", "smoothed_load_N", "axial_strain", "macro_tensile_strength_MPa"} <= keys
    assert {"strain_at_peak", "peak_change_percent", "raw_peak_toughness_MPa_sqrt_m", "per_packing",
            "work_of_fracture_sem_J_per_m2", "calibrated_material", "main_force_standard_error_N"} <= keys
    (tmp_path / "analysis").mkdir()
    (tmp_path / "analysis" / "reader.py").write_text(
        "depth = results['subsurface_damage_depth_steady_um']  # the steady damage\n"
        "# results['steady_from_travel_mm'] in a comment is no read\n"
        "start = results[R.steady_from_travel_mm]\n")
    (tmp_path / "reader.cpp").write_text('const double x = r.at("steady_from_travel_mm");  // "cracks_chip"\n')
    assert sorted(offenders(keys, tmp_path)) == ["analysis/reader.py:1: subsurface_damage_depth_steady_um",
                                         "reader.cpp:1: steady_from_travel_mm"]
