// The Python module `kerf`: the analytic models and the DEM through the same library calls as kerf-forces and
// kerf-dem, with Python values in and out (docs/python.md).
//
//   import kerf
//   kerf.predict("data/scenes/psic_liu_li.json", **{"tool.edge_radius_um": 0.2})["cutting_force_N"]
//   kerf.sweep("data/scenes/psic_liu_li.json", vary={"cut.uncut_chip_thickness_um": [0.05, 0.1, 0.2]})
//   kerf.dem.run("data/scenes/dem_cut.json", out="out/cut", threads=2, cut__length_mm=0.2)["summary"]
//
// A scene is a path (str or os.PathLike) or a dict holding the scene itself. Overrides are keyword arguments:
// a dotted key (passed as **{"tool.rake_deg": 5}) or the same with "__" for each dot (tool__rake_deg=5); the
// value is any JSON-able Python value. kerf.InputError (a ValueError with .field, .value, .expected) and
// kerf.ModelError (a RuntimeError) carry the library's errors.
#include <omp.h>
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/analytic/sweep/scene_compare.hpp"
#include "kerf/analytic/sweep/sweep.hpp"
#include "kerf/csv_table.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/error.hpp"
#include "kerf/interval95.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/material.hpp"
#include "kerf/report.hpp"
#include "kerf/version.hpp"
#include "kerf_api.hpp"  // python/kerf_api.py as text (python/CMakeLists.txt)

namespace py = pybind11;

namespace {

using kerf::Json;

/// JSON text of a Python value through Python's json module (dicts, lists, numbers, strings, bools, None).
std::string json_dumps(const py::handle& value) {
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

py::object json_to_python(const Json& value) {
  return py::module_::import("json").attr("loads")(value.dump());
}

/// A scene given as a path or as a dict, with the keyword overrides applied; `file` is where it came from
/// ("<dict>" inside the current directory for a dict).
struct SceneInput {
  Json document;
  std::string file;
};

SceneInput scene_input(const py::object& scene, const py::kwargs& overrides) {
  SceneInput input;
  if (py::isinstance<py::dict>(scene)) {
    input.document = Json::parse(json_dumps(scene));
    input.file = (std::filesystem::current_path() / "scene.json").string();
  } else {
    input.file = py::str(py::module_::import("os").attr("fspath")(scene)).cast<std::string>();
    input.document = kerf::read_json_file(input.file);
  }
  for (const auto& [key, value] : overrides) {
    std::string path = py::str(key).cast<std::string>();
    for (std::size_t at = path.find("__"); at != std::string::npos; at = path.find("__", at + 1)) {
      path.replace(at, 2, ".");
    }
    kerf::apply_override(input.document, path + "=" + json_dumps(value));
  }
  return input;
}

/// A CSV cell as Python: a float when it is a number, None when empty, the text otherwise.
py::object cell_value(const std::string& text) {
  if (text.empty()) return py::none();
  double number = 0.0;
  if (kerf::parse_number(text, number)) return py::float_(number);
  return py::str(text);
}

py::dict columns_dict(const kerf::Columns& columns) {
  py::dict row;
  for (const auto& [name, text] : columns) {
    // Text columns are CSV-escaped by the library; unquote them.
    std::string plain = text;
    if (plain.size() >= 2 && plain.front() == '"' && plain.back() == '"') {
      plain = kerf::parse_csv("x\n" + plain + "\n", name).rows.at(0).at(0);
    }
    row[py::str(name)] = cell_value(plain);
  }
  return row;
}

/// Columns as numpy arrays: float64 where every cell is a number or empty (NaN), an object array otherwise
/// and for the `text` columns (an object array of None where every cell is empty: e.g. no point's error).
py::dict column_arrays(const std::vector<std::string>& names, const std::vector<std::vector<py::object>>& columns,
                       const std::vector<std::string>& text = {}) {
  py::module_ numpy = py::module_::import("numpy");
  py::dict out;
  for (std::size_t c = 0; c < names.size(); ++c) {
    bool numeric = std::find(text.begin(), text.end(), names[c]) == text.end();
    for (const auto& cell : columns[c]) numeric = numeric && (cell.is_none() || py::isinstance<py::float_>(cell));
    if (numeric) {
      py::array_t<double> array(static_cast<py::ssize_t>(columns[c].size()));
      auto view = array.mutable_unchecked<1>();
      for (std::size_t i = 0; i < columns[c].size(); ++i) {
        view(static_cast<py::ssize_t>(i)) =
            columns[c][i].is_none() ? std::numeric_limits<double>::quiet_NaN() : columns[c][i].cast<double>();
      }
      out[py::str(names[c])] = array;
    } else {
      // An object array filled cell by cell: a cell may be a list (guards, warnings), which numpy.array would
      // turn into a dimension; an absent value is None.
      py::object cells = numpy.attr("empty")(columns[c].size(), py::arg("dtype") = "object");
      for (std::size_t i = 0; i < columns[c].size(); ++i) cells[py::int_(i)] = columns[c][i];
      out[py::str(names[c])] = cells;
    }
  }
  return out;
}

py::dict table_arrays(const kerf::CsvTable& table) {
  std::vector<std::vector<py::object>> columns(table.header.size());
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) columns[c].push_back(cell_value(row[c]));
  }
  return column_arrays(table.header, columns);
}

py::list string_list(const std::vector<std::string>& items) {
  py::list out;
  for (const auto& item : items) out.append(py::str(item));
  return out;
}

/// One scene's prediction as Python: the CSV row's columns (floats, str, None), with 'guards' and 'warnings'
/// as lists of str (the prediction's own, not the CSV's joined text, whose warnings may hold "; ").
py::dict evaluate_row(const Json& document, kerf::MaterialCache* cache) {
  const auto scene = kerf::parse_scene(document, cache);
  scene->predict();
  py::dict row = columns_dict(kerf::scene_columns(*scene));
  row["guards"] = string_list(scene->guard_names());
  row["warnings"] = string_list(scene->warnings());
  return row;
}

py::dict predict(const py::object& scene, const py::kwargs& overrides) {
  const SceneInput input = scene_input(scene, overrides);
  kerf::MaterialCache cache;
  return evaluate_row(input.document, &cache);
}

/// The values of one axis: a sequence of numbers (or of any JSON values).
std::vector<py::object> axis_values(const std::string& key, const py::handle& values) {
  if (py::isinstance<py::str>(values) || !py::isinstance<py::iterable>(values)) {
    throw kerf::InputError("vary." + key, py::str(values).cast<std::string>(), "a sequence of values");
  }
  std::vector<py::object> out;
  for (const auto& value : values) out.push_back(py::reinterpret_borrow<py::object>(value));
  if (out.empty()) throw kerf::InputError("vary." + key, "[]", "at least one value");
  return out;
}

/// The library's sweep (sweep.hpp: the same grid, checks, parallel evaluation and error policy as kerf-forces
/// sweep), its rows as numpy columns.
py::dict sweep(const py::object& scene, const py::dict& vary, const py::kwargs& overrides) {
  const SceneInput input = scene_input(scene, overrides);
  std::vector<std::string> keys;
  std::vector<std::vector<py::object>> axes;
  std::vector<kerf::SweepAxis> grid_axes;
  for (const auto& [key, values] : vary) {
    keys.push_back(py::str(key).cast<std::string>());
    axes.push_back(axis_values(keys.back(), values));
    std::vector<std::string> texts;
    for (const auto& value : axes.back()) texts.push_back(json_dumps(value));
    grid_axes.push_back(kerf::sweep_axis_from_texts(keys.back(), std::move(texts)));
  }
  if (keys.empty()) throw kerf::InputError("vary", "{}", "at least one key with its values");
  const kerf::SweepGrid grid(input.document, std::move(grid_axes), "vary");
  std::vector<kerf::SweepRow> rows;
  {
    py::gil_scoped_release release;
    rows = grid.run(/*lists=*/true);
  }
  const std::vector<std::string>& names = grid.column_names();
  std::vector<std::string> header = grid.axis_column_names();  // a key that is also a column: key_varied
  header.insert(header.end(), names.begin(), names.end());
  for (const char* listed : {"guards", "warnings"})  // every row has them, trepanning's too
    if (std::find(header.begin(), header.end(), listed) == header.end()) header.emplace_back(listed);
  header.push_back("error");
  std::vector<std::vector<py::object>> columns(header.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const kerf::SweepRow& row = rows[i];
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const py::object& x = axes[a][grid.value_index(i, a)];
      columns[a].push_back(py::isinstance<py::int_>(x) ? py::float_(x.cast<double>()) : x);
    }
    py::dict cells;
    if (row.error.empty()) {
      kerf::Columns named;
      const auto fields = kerf::split_cells(row.cells);
      for (std::size_t c = 0; c < names.size(); ++c) named.emplace_back(names[c], std::string(fields.at(c)));
      cells = columns_dict(named);
      cells["guards"] = string_list(row.guards);
      cells["warnings"] = string_list(row.warnings);
    }
    for (std::size_t c = keys.size(); c + 1 < header.size(); ++c) {
      const bool listed = header[c] == "guards" || header[c] == "warnings";
      columns[c].push_back(cells.contains(header[c]) ? py::reinterpret_borrow<py::object>(cells[py::str(header[c])])
                           : listed                  ? py::object(py::list())  // a refused point: none fired
                                                     : py::object(py::none()));
    }
    columns.back().push_back(row.error.empty() ? py::object(py::none()) : py::object(py::str(row.error)));
  }
  return column_arrays(header, columns, {"error"});
}

py::list materials() {
  py::list out;
  for (const auto& m : kerf::library_materials()) {
    py::dict entry;
    entry["name"] = m.name;
    if (m.record) {
      entry["title"] = m.record->title;
      entry["groups"] = json_to_python(m.record->groups);
      entry["file"] = m.record->origin;
    } else {
      entry["error"] = m.error;
    }
    out.append(entry);
  }
  return out;
}

py::list models() {
  py::list out;
  for (const auto& m : kerf::analytic_models()) {
    py::dict entry;
    entry["kind"] = std::string(m.kind);
    entry["name"] = std::string(m.name);
    entry["summary"] = std::string(m.summary);
    entry["needs"] = std::string(m.needs);
    out.append(entry);
  }
  return out;
}

/// The bundled scenes: data/scenes/*.json (under $KERF_DATA_DIR when set), by name.
std::vector<std::filesystem::path> scene_files() {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(kerf::data_directory() / "scenes", error)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

py::list scenes() {
  py::list out;
  for (const auto& file : scene_files()) {
    py::dict entry;
    entry["name"] = file.stem().string();
    entry["path"] = py::module_::import("pathlib").attr("Path")(file.string());
    entry["program"] = "kerf-forces";
    entry["kind"] = py::none();
    entry["description"] = py::none();
    try {
      const Json document = kerf::read_json_file(file.string());
      if (document.contains("kind") && document["kind"].is_string()) {
        entry["program"] = "kerf-dem";
        entry["kind"] = document["kind"].get<std::string>();
      }
      if (document.contains("description") && document["description"].is_string()) {
        entry["description"] = document["description"].get<std::string>();
      }
    } catch (const kerf::InputError&) {
      // listed by its name all the same; reading it says what is wrong
    }
    out.append(entry);
  }
  return out;
}

std::string scene_path(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& file : scene_files()) {
    names.push_back(file.stem().string());
    if (name == names.back() || name == file.filename().string()) return file.string();
  }
  throw kerf::InputError("scene", name, kerf::describe_choices(name, names) + " (kerf.scenes() lists them)");
}

py::dict metrics_dict(const kerf::ErrorMetrics& m) {
  py::dict out;
  out["n"] = m.n;
  out["mean_abs_error_percent"] = m.mean_abs_error_percent;
  out["max_abs_error_percent"] = m.max_abs_error_percent;
  out["bias_percent"] = m.bias_percent;
  out["rms_error_percent"] = m.rms_error_percent;
  return out;
}

py::dict compare(const py::object& scene, const py::object& experiments, const py::dict& map, bool fit, bool pool,
                 const py::object& measured_width_mm, const py::object& out, const py::kwargs& overrides) {
  const SceneInput input = scene_input(scene, overrides);
  kerf::SceneComparisonOptions options;
  for (const auto& [key, column] : map) {
    options.mappings.push_back(py::str(key).cast<std::string>() + "=" + py::str(column).cast<std::string>());
  }
  options.fit = fit;
  options.pool = pool;
  if (!measured_width_mm.is_none()) options.measured_width_mm = measured_width_mm.cast<double>();
  const std::string csv = py::str(py::module_::import("os").attr("fspath")(experiments)).cast<std::string>();
  kerf::SceneComparison result = kerf::compare_scene(input.document, csv, options);
  py::dict answer;
  py::dict quantities;
  for (const auto& r : result.comparison.results) {
    py::dict q = metrics_dict(r.metrics);
    q["unit"] = r.unit.suffix;
    std::vector<double> measured, predicted;
    for (const auto& g : r.groups) {
      measured.push_back(g.measured_stats.mean / r.unit.si);
      predicted.push_back(g.predicted_stats.mean / r.unit.si);
    }
    q["measured"] = py::array_t<double>(static_cast<py::ssize_t>(measured.size()), measured.data());
    q["predicted"] = py::array_t<double>(static_cast<py::ssize_t>(predicted.size()), predicted.data());
    if (!r.note.empty()) q["note"] = r.note;
    quantities[py::str(r.key)] = q;
  }
  answer["quantities"] = quantities;
  answer["notes"] = result.notes;
  answer["unused_columns"] = result.unused_columns;
  py::list rows;
  for (const auto& r : result.rows) {
    py::dict row;
    row["line"] = r.line;
    row["regime"] = r.regime.empty() ? py::object(py::none()) : py::object(py::str(r.regime));
    row["guards"] = string_list(r.guards);
    row["warnings"] = string_list(r.warnings);
    rows.append(row);
  }
  answer["rows"] = rows;
  if (!out.is_none()) {
    result.comparison.spec.description = fmt::format("Scene {} against {}.", input.file, csv);
    std::vector<std::string> files;
    for (const auto& f : kerf::write_report(result.comparison,
                                            py::str(py::module_::import("os").attr("fspath")(out)).cast<std::string>(),
                                            result.report)) {
      files.push_back(f.string());
    }
    answer["files"] = files;
  }
  return answer;
}

py::dict dem_run(const py::object& scene, const py::object& out, const py::object& threads, int replicates,
                 int checkpoint_every, const py::object& progress, const py::kwargs& overrides) {
  const SceneInput input = scene_input(scene, overrides);
  kerf::dem::RunOptions options;
  options.out = py::str(py::module_::import("os").attr("fspath")(out)).cast<std::string>();
  options.replicates = replicates;
  options.checkpoint_every = checkpoint_every;
  options.show_progress = false;
  options.command_line = "kerf.dem.run (Python)";
  // A Python callable gets each progress report as (stage, done, total, unit), with the GIL held; an
  // exception it raises stops the run and reaches the caller.
  if (!progress.is_none()) {
    options.on_progress = [progress](const kerf::dem::ProgressUpdate& u) {
      py::gil_scoped_acquire acquire;
      // Counts of steps or particle-steps: ints, as a progress bar takes them.
      progress(u.stage, static_cast<long long>(std::llround(u.done)), static_cast<long long>(std::llround(u.total)),
               u.unit);
    };
  }
  for (const auto& [key, value] : overrides) {
    options.overrides.push_back(py::str(key).cast<std::string>() + "=" + json_dumps(value));
  }
  kerf::dem::SceneOutcome outcome;
  {
    const int previous_threads = omp_get_max_threads();
    if (!threads.is_none()) {
      const int n = threads.cast<int>();
      if (n < 1) throw kerf::InputError("threads", std::to_string(n), "a positive number of threads");
      omp_set_num_threads(n);
    }
    try {
      py::gil_scoped_release release;
      outcome = kerf::dem::run_scene(input.document, input.file, options);
    } catch (...) {
      omp_set_num_threads(previous_threads);
      throw;
    }
    omp_set_num_threads(previous_threads);
  }
  py::dict answer;
  answer["exit_status"] = outcome.exit_status;
  answer["summary"] = json_to_python(outcome.summary);
  answer["out"] = options.out.string();
  for (const char* table : {"forces", "cracks", "curve"}) {
    const auto file = options.out / (std::string(table) + ".csv");
    answer[table] = std::filesystem::exists(file) ? py::object(table_arrays(kerf::read_csv_file(file))) : py::none();
  }
  return answer;
}

}  // namespace

PYBIND11_MODULE(kerf, m) {
  // numpy first, with a message of one line: without it pybind11 would report only "initialization failed".
  try {
    py::module_::import("numpy");
  } catch (const py::error_already_set&) {
    const auto sys = py::module_::import("sys");
    const auto info = sys.attr("version_info");
    const std::string executable = py::str(sys.attr("executable")).cast<std::string>();
    const std::string built_for = KERF_PYTHON_EXECUTABLE;
    throw std::runtime_error("kerf needs numpy, which " + executable + " (Python " +
                             py::str(info.attr("major")).cast<std::string>() + "." +
                             py::str(info.attr("minor")).cast<std::string>() +
                             ") cannot import: install it (Debian: apt install python3-numpy)" +
                             (executable == built_for ? "" : ", or run " + built_for + ", which kerf was built for"));
  }
  m.doc() = "kerf: cutting forces for hard, brittle materials (analytic models and the 2D bonded-particle DEM)";
  m.attr("__version__") = std::string(kerf::version());
  m.attr("__git_commit__") = std::string(kerf::git_commit());

  static py::exception<kerf::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<kerf::ModelError> model_error(m, "ModelError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const kerf::InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(input_error.ptr())(py::str(e.what()));
      error.attr("field") = e.field();
      error.attr("value") = e.value();
      error.attr("expected") = e.expected();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    } catch (const kerf::ModelError& e) {
      model_error(e.what());
    } catch (const Json::exception& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  // The C++ functions under private names; python/kerf_api.py (compiled in as text) defines the public ones
  // over them with Python signatures and docstrings, so that help(), inspect.signature and Jupyter's tooltips
  // work (a C++ function has no signature Python can read).
  m.def("_predict", &predict, py::arg("scene"));
  m.def("_sweep", &sweep, py::arg("scene"), py::arg("vary"));
  m.def("_materials", &materials);
  m.def("_models", &models);
  m.def("_scenes", &scenes);
  m.def("_scene_path", &scene_path, py::arg("name"));
  m.def("_compare", &compare, py::arg("scene"), py::arg("experiments"), py::arg("map"), py::arg("fit"), py::arg("pool"),
        py::arg("measured_width_mm"), py::arg("out"));
  m.def("_dem_run", &dem_run, py::arg("scene"), py::arg("out"), py::arg("threads"), py::arg("replicates"),
        py::arg("checkpoint_every"), py::arg("progress"));
  m.def("_dem_kinds", &kerf::dem::scene_kind_names);
  // The one two-sided 95 % Student t quantile (GSL's), which kerf.stats' intervals use as the C++ ones do.
  m.def("_quantile95", &kerf::quantile95, py::arg("degrees_of_freedom"));
  m.def_submodule("dem", "the 2D bonded-particle DEM (kerf-dem): run, kinds, read_frames");
  py::exec(kKerfApiPy, m.attr("__dict__"));
}
