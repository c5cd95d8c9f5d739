"""No result key is written or read as a literal outside its table (issue 56 item 1): kerf-dem's results are named
once, in their result tables (dem/procedures/cut_result_table.cpp, dem/procedures/cut_results.cpp), and read by name,
through the constants of kerf/dem/procedures/cut_results.hpp (C++) or kerf.result_keys (Python, generated from the
tables: tests/cli/dem_results_cli.sh). A quoted key in any other C++, Python or shell source fails here unless the
file is in ALLOWED below, with the keys it may quote and why. Data files (records, studies, docs) are not sources."""
import importlib.util
import pathlib
import re


ROOT = pathlib.Path(__file__).resolve().parents[2]
SOURCES = ("*.cpp", "*.hpp", "*.h", "*.py", "*.sh")
# The keys other parts of kerf also use for something else: an input key (specimen.width_mm, grooves.width_mm), the
# analytic predictions' columns (kerf-forces: cutting_force_N, thrust_force_N, their per-mm forms, width_mm).
SHARED = {"width_mm", "cutting_force_N", "thrust_force_N", "cutting_force_N_per_mm", "thrust_force_N_per_mm",
          "time_s", "samples", "steady"}
ANALYTIC = "the analytic prediction's column of the same name (kerf-forces)"
OUTPUT_TESTS = "an end-to-end test of the written output: the literal is the format users read, a rename must fail it"
ALLOWED = {
    # What the keys are written in, and generated from.
    "python/kerf/result_keys.py": (None, "generated from the result tables (kerf-dem results --python)"),
    # Own outputs named after a result, not reads of one.
    "analysis/strength_scan.py": ({"cracks_subsurface"}, "its own table's column (the steady count)"),
    # The tests of the written format.
    "tests/cli/*.sh": (None, OUTPUT_TESTS),
    "tests/bench/*.sh": (None, OUTPUT_TESTS),
    "tests/dem/*.cpp": (None, OUTPUT_TESTS),
    "tests/core/*.cpp": (None, OUTPUT_TESTS),
    # This test.
    "tests/python/test_result_key_literals.py": (None, "the test itself"),
}


def result_keys():
    spec = importlib.util.spec_from_file_location("result_keys", ROOT / "python" / "kerf" / "result_keys.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    keys = set()
    for table in (module.CutResults, module.TravelWindowResults, module.ActiveWindowResults, module.ForcesCsvColumns):
        keys |= set(module.keys(table))
    return keys


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
    assert not found, ("result keys quoted outside their tables (use kerf/dem/procedures/cut_results.hpp's constants "
                       "or kerf.result_keys; or list the file in ALLOWED with the reason):\n" + "\n".join(found))


def test_the_check_finds_a_literal(tmp_path):
    keys = result_keys() - SHARED
    assert "subsurface_damage_depth_steady_um" in keys and "steady_from_travel_mm" in keys
    (tmp_path / "analysis").mkdir()
    (tmp_path / "analysis" / "reader.py").write_text(
        "depth = results['subsurface_damage_depth_steady_um']  # the steady damage\n"
        "# results['steady_from_travel_mm'] in a comment is no read\n"
        "start = results[R.steady_from_travel_mm]\n")
    (tmp_path / "reader.cpp").write_text('const double x = r.at("steady_from_travel_mm");  // "cracks_chip"\n')
    assert sorted(offenders(keys, tmp_path)) == ["analysis/reader.py:1: subsurface_damage_depth_steady_um",
                                         "reader.cpp:1: steady_from_travel_mm"]
