// kerf-dem: the 2D bonded-particle DEM with flat joints (issue 4).
//
//   kerf-dem run SCENE.json [--set key.path=value]... [--out DIR] [--threads N] [--checkpoint-every N] [--replicates N]
//   kerf-dem resume DIR [--threads N]
//
// Scene kinds: "specimen" (genesis, saved for reuse), "tension", "compression" (seed 000 calibration
// tests), "calibrate", "cut" (orthogonal cutting, seed 000 Section 4), "calibrate_cut" (bond strengths fitted to
// one measured cut). Exit status 2 for bad input (the message names the field, the value and what was expected),
// 3 when the model fails (e.g. an unstable run).
#include <fmt/format.h>
#include <omp.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>

#include "kerf/dem/calibration.hpp"
#include "kerf/dem/cut_calibration.hpp"
#include "kerf/dem/cutting.hpp"
#include "kerf/dem/lab_test.hpp"
#include "kerf/dem/material.hpp"
#include "kerf/dem/output.hpp"
#include "kerf/dem/png.hpp"
#include "kerf/dem/specimen.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/material.hpp"
#include "kerf/metrics.hpp"
#include "kerf/units.hpp"

namespace fs = std::filesystem;
using namespace kerf;
using namespace kerf::dem;

namespace {

struct Scene {
  std::string kind;
  Material material;
  std::optional<std::string> specimen_file;
  SpecimenSpec specimen;
  LoadingSpec loading;
  CutParams cut;
  EngineSettings engine;
  int frame_every_samples = 100;
  CalibrationSpec calibration;
  std::string calibrated_name = "calibrated";
  bool install_material = false;  ///< also write data/materials/<name>.json (the data directory in use)
  /// kind calibrate_cut: the bond-strength factor fitted to one measured cut (kerf/dem/cut_calibration.hpp).
  struct CutFit {
    double target_main_force_n = 0;
    std::string target_source;
    int replicates = 3;
    double tolerance = 0.10;
    int max_evaluations = 4;
    double start_factor = 1;
  } cut_fit;
};

/// calibration.material_name (a file name) and calibration.install_material, as calibrate and calibrate_cut read them.
void read_material_output(ObjectReader& cal, Scene& s, const std::string& fallback) {
  s.calibrated_name = cal.get_string_or("material_name", fallback);
  if (s.calibrated_name.empty() || s.calibrated_name.find_first_of("/\\. ") != std::string::npos)
    throw InputError(cal.key_path("material_name"), s.calibrated_name, "a file name without '/', '.', spaces");
  s.install_material = cal.get_bool_or("install_material", false);
}

/// Reads one row of a macro-property table (data/experiments/*.csv: '#' comment lines, a header with
/// youngs_modulus_GPa, tensile_strength_MPa, compressive_strength_MPa, poissons_ratio).
MacroProperties read_targets_csv(const std::string& path, const std::string& row, const std::string& field) {
  std::ifstream in(path);
  if (!in) throw InputError(field + ".file", path, "a readable CSV file");
  std::string line;
  std::vector<std::string> header;
  const auto split = [](const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    for (std::string cell; std::getline(ss, cell, ',');) out.push_back(cell);
    return out;
  };
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header.empty()) {
      header = split(line);
      continue;
    }
    const auto cells = split(line);
    if (cells.empty() || cells[0] != row) continue;
    const auto value = [&](const std::string& name) {
      const auto it = std::find(header.begin(), header.end(), name);
      if (it == header.end()) throw InputError(field + ".file", path, "a CSV with a column " + name);
      return std::stod(cells.at(static_cast<std::size_t>(it - header.begin())));
    };
    return {units::gpa_to_pa(value("youngs_modulus_GPa")), value("poissons_ratio"),
            units::mpa_to_pa(value("tensile_strength_MPa")), units::mpa_to_pa(value("compressive_strength_MPa"))};
  }
  throw InputError(field + ".row", row, "a row of " + path);
}

Scene read_scene(const Json& doc, const fs::path& scene_dir) {
  ObjectReader root(doc, "");
  Scene s;
  s.kind = root.get_choice("kind", {"specimen", "tension", "compression", "calibrate", "cut", "calibrate_cut"});
  root.ignore("description");
  s.material = read_scene_material(root);
  if (auto spec = root.find_object("specimen")) {
    if (spec->has("file")) {
      fs::path file = spec->get_string("file");
      if (file.is_relative()) file = scene_dir / file;
      if (!fs::exists(file)) throw InputError("specimen.file", file.string(), "an existing specimen file");
      s.specimen_file = file.string();
    } else {
      s.specimen = read_specimen_spec(*spec);
    }
    spec->finish();
  }
  s.engine = read_engine_settings(root);
  if (s.kind == "tension" || s.kind == "compression") {
    if (auto loading = root.find_object("loading")) {
      s.loading = read_loading_spec(*loading, s.kind);
      loading->finish();
    } else {
      static const Json empty = Json::object();
      ObjectReader none(empty, "loading");
      s.loading = read_loading_spec(none, s.kind);
    }
  }
  if (s.kind == "cut" || s.kind == "calibrate_cut") s.cut = read_cut_params(root);
  if (s.kind == "calibrate_cut") {
    auto& f = s.cut_fit;
    ObjectReader cal = root.get_object("calibration");
    f.target_main_force_n = cal.get_number("target_main_force_N", Range::positive(), "N");
    f.target_source = cal.get_string_or("target_source", "");
    f.replicates = cal.get_int_or("replicates", f.replicates, 2, 64);
    f.tolerance = cal.get_number_or("tolerance_percent", 100 * f.tolerance, Range::open(0.0, 100.0), "%") / 100;
    f.max_evaluations = cal.get_int_or("max_evaluations", f.max_evaluations, 1, 50);
    f.start_factor = cal.get_number_or("start_strength_factor", f.start_factor, Range::positive(), "");
    read_material_output(cal, s, "cut_calibrated");
    cal.finish();
  }
  if (s.kind == "calibrate") {
    auto& c = s.calibration;
    ObjectReader cal = root.get_object("calibration");
    if (auto targets = cal.find_object("targets")) {
      if (targets->has("file")) {
        fs::path file = targets->get_string("file");
        if (file.is_relative()) file = kerf::data_directory() / file;
        c.targets = read_targets_csv(file.string(), targets->get_string_or("row", "soda_lime_glass"), targets->path());
      }
      c.targets.youngs_modulus_pa = units::gpa_to_pa(targets->get_number_or(
          "youngs_modulus_GPa", units::pa_to_gpa(c.targets.youngs_modulus_pa), Range::positive(), "GPa"));
      c.targets.poissons_ratio = targets->get_number_or("poissons_ratio", c.targets.poissons_ratio, Range::open(0.0, 0.5), "");
      c.targets.tensile_strength_pa = units::mpa_to_pa(targets->get_number_or(
          "tensile_strength_MPa", units::pa_to_mpa(c.targets.tensile_strength_pa), Range::positive(), "MPa"));
      c.targets.compressive_strength_pa = units::mpa_to_pa(targets->get_number_or(
          "compressive_strength_MPa", units::pa_to_mpa(c.targets.compressive_strength_pa), Range::positive(), "MPa"));
      targets->finish();
    }
    if (const Json* free = cal.find("free")) {
      const std::vector<std::string> valid{"effective_modulus_GPa", "stiffness_ratio", "tensile_strength_MPa", "cohesion_MPa"};
      if (!free->is_array()) throw InputError(cal.key_path("free"), json_value_text(*free), "a list of parameter names");
      c.free_modulus = c.free_stiffness_ratio = c.free_tensile_strength = c.free_cohesion = false;
      for (const auto& item : *free) {
        const std::string name = item.is_string() ? item.get<std::string>() : json_value_text(item);
        if (std::find(valid.begin(), valid.end(), name) == valid.end())
          throw InputError(cal.key_path("free"), name, describe_choices(name, valid));
        c.free_modulus |= name == valid[0];
        c.free_stiffness_ratio |= name == valid[1];
        c.free_tensile_strength |= name == valid[2];
        c.free_cohesion |= name == valid[3];
      }
    }
    c.tolerance = cal.get_number_or("tolerance_percent", 3, Range::open(0.0, 100.0), "%") / 100;
    c.max_evaluations = cal.get_int_or("max_evaluations", 24, 1, 1000);
    c.method = cal.get_choice_or("method", "hybrid", {"hybrid", "secant"}) == "secant" ? CalibrationMethod::secant
                                                                                      : CalibrationMethod::hybrid;
    read_material_output(cal, s, "calibrated");
    cal.finish();
    LoadingSpec load;
    if (auto loading = root.find_object("loading")) {
      load = read_loading_spec(*loading, "compression");
      loading->finish();
    }
    load.quasi_static_check = false;
    c.compression = load;
    c.compression.test = "compression";
    c.tension = load;
    c.tension.test = "tension";
    c.tension.max_strain = std::min(load.max_strain, 0.005);
  }
  if (auto output = root.find_object("output")) {
    s.frame_every_samples = output->get_int_or("frame_every_samples", 100, 0, 100000000);
    output->finish();
  }
  root.finish();
  return s;
}

Simulation obtain_specimen(const Scene& scene, SpecimenSpec& spec, SpecimenReport& report, double& wall_s,
                           bool show_progress = true) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<Simulation> sim;
  if (scene.specimen_file) {
    sim.emplace(load_specimen(*scene.specimen_file, scene.material, spec, report));
  } else {
    spec = scene.specimen;
    std::optional<Progress> progress;
    std::int64_t shown = 0;
    sim.emplace(make_specimen(scene.material, spec, report, [&](std::int64_t done, std::int64_t total) {
      if (!show_progress) return;
      if (!progress) progress.emplace("specimen genesis", static_cast<std::size_t>(total), "steps");
      progress->advance(static_cast<std::size_t>(done - shown));
      shown = done;
    }));
    if (progress) progress->finish();
  }
  scene.engine.apply_to(*sim);
  wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::move(*sim);
}

Json specimen_json(const SpecimenSpec& spec, const SpecimenReport& report, double wall_s) {
  Json j = specimen_spec_to_json(spec);
  j.update(specimen_report_to_json(report));
  j["genesis_wall_time_s"] = wall_s;
  return j;
}

LabTestResult run_test(const Simulation& specimen, const LoadingSpec& loading, const std::string& label,
                       const std::function<void(const Simulation&, const CurveSample&)>& extra,
                       Simulation* final_state = nullptr) {
  // Progress against the step count that reaches max_strain (an upper bound: most runs stop earlier).
  const double height = [&] {
    double lo = 1e300, hi = -1e300;
    const auto& p = specimen.particles();
    for (std::size_t i = 0; i < p.size(); ++i) lo = std::min(lo, p.y[i] - p.radius[i]), hi = std::max(hi, p.y[i] + p.radius[i]);
    return hi - lo;
  }();
  const double n = static_cast<double>(specimen.particles().size());
  const double steps = loading.max_strain * height / (2 * loading.speed_m_per_s * specimen.time_step());
  Progress progress(label, static_cast<std::size_t>(n * steps), "particle-steps");
  auto result = run_lab_test(specimen, loading, [&](const Simulation& sim, const CurveSample& sample) {
    progress.advance(static_cast<std::size_t>(n * loading.sample_every_steps));
    if (extra) extra(sim, sample);
  }, final_state);
  progress.finish();
  return result;
}

Json macro_json(const MacroProperties& m) {
  return Json{{"youngs_modulus_GPa", units::pa_to_gpa(m.youngs_modulus_pa)},
              {"poissons_ratio", m.poissons_ratio},
              {"tensile_strength_MPa", units::pa_to_mpa(m.tensile_strength_pa)},
              {"compressive_strength_MPa", units::pa_to_mpa(m.compressive_strength_pa)}};
}

/// What a test needs to continue after a kill (written atomically every --checkpoint-every samples).
struct Checkpoint {
  Json scene, summary;
  std::vector<std::pair<double, std::vector<std::string>>> frames;
  int sample_index = 0, checkpoint_every = 0;
  std::string scene_dir, specimen, run;

  std::string bytes() const {
    Json head{{"scene", scene}, {"summary", summary}, {"frames", frames}, {"sample_index", sample_index},
              {"checkpoint_every", checkpoint_every}, {"scene_dir", scene_dir}};
    std::string out = "KERFCKP1";
    const std::string head_text = head.dump();
    for (const std::string* part : {&head_text, &specimen, &run}) {
      const auto n = static_cast<std::uint64_t>(part->size());
      out.append(reinterpret_cast<const char*>(&n), sizeof n);
      out += *part;
    }
    return out;
  }
  static Checkpoint parse(const std::string& bytes) {
    if (bytes.compare(0, 8, "KERFCKP1") != 0) throw ModelError("kerf-dem", "checkpoint.bin is not a kerf-dem checkpoint");
    std::size_t at = 8;
    std::string parts[3];
    for (auto& part : parts) {
      std::uint64_t n = 0;
      if (at + sizeof n > bytes.size()) throw ModelError("kerf-dem", "truncated checkpoint");
      std::memcpy(&n, bytes.data() + at, sizeof n);
      at += sizeof n;
      if (at + n > bytes.size()) throw ModelError("kerf-dem", "truncated checkpoint");
      part = bytes.substr(at, static_cast<std::size_t>(n));
      at += static_cast<std::size_t>(n);
    }
    const Json head = Json::parse(parts[0]);
    Checkpoint c;
    c.scene = head.at("scene");
    c.summary = head.at("summary");
    c.frames = head.at("frames").get<decltype(c.frames)>();
    c.sample_index = head.at("sample_index");
    c.checkpoint_every = head.at("checkpoint_every");
    c.scene_dir = head.at("scene_dir");
    c.specimen = std::move(parts[1]);
    c.run = std::move(parts[2]);
    return c;
  }
};

/// Writes the fitted material to DIR/<material_name>.json and, with install_material, to the data directory.
void write_material_output(const Scene& scene, const Json& material, const fs::path& out, Json& summary) {
  write_file_atomically(out / (scene.calibrated_name + ".json"), material.dump(2) + "\n");
  if (scene.install_material) {
    const fs::path installed = kerf::data_directory() / "materials" / (scene.calibrated_name + ".json");
    write_file_atomically(installed, material.dump(2) + "\n");
    summary["installed_material"] = installed.string();
  }
}

/// Runs (or, with `known` from a checkpoint, continues) a calibration. With checkpoint_every > 0 a checkpoint
/// is written after every evaluation (an evaluation is the unit of work that cannot be cut short).
int run_calibration(const Scene& scene, const Json& doc, const Simulation& specimen, Json summary, const fs::path& out,
                    int checkpoint_every, const std::string& scene_dir, const std::vector<CalibrationEvaluation>& known) {
  const auto start = std::chrono::steady_clock::now();
  const std::string specimen_bytes = checkpoint_every > 0 ? specimen.serialize() : std::string();
  std::vector<CalibrationEvaluation> done;
  std::string log = csv_line({"evaluation", "effective_modulus_GPa", "stiffness_ratio", "tensile_strength_MPa",
                              "cohesion_MPa", "youngs_modulus_GPa", "poissons_ratio", "macro_tensile_strength_MPa",
                              "macro_compressive_strength_MPa", "max_error_percent", "wall_time_s"});
  const CalibrationResult r = calibrate(specimen, scene.material, scene.calibration, [&](const CalibrationEvaluation& e) {
    const CalibratedParams m = calibrated_params(e.material);
    log += csv_line({std::to_string(e.index), csv_number(units::pa_to_gpa(m.contact_modulus_pa)),
                     csv_number(m.stiffness_ratio), csv_number(units::pa_to_mpa(m.tensile_strength_pa)),
                     csv_number(units::pa_to_mpa(m.cohesion_pa)), csv_number(units::pa_to_gpa(e.macro.youngs_modulus_pa)),
                     csv_number(e.macro.poissons_ratio), csv_number(units::pa_to_mpa(e.macro.tensile_strength_pa)),
                     csv_number(units::pa_to_mpa(e.macro.compressive_strength_pa)), csv_number(100 * e.max_relative_error),
                     csv_number(e.wall_time_s)});
    write_file_atomically(out / "calibration_log.csv", log);
    done.push_back(e);
    if (checkpoint_every > 0) {
      const Checkpoint c{doc, summary, {}, static_cast<int>(done.size()), checkpoint_every, scene_dir, specimen_bytes,
                         serialize_evaluations(done)};
      write_file_atomically(out / "checkpoint.bin", c.bytes());
    }
    std::cout << fmt::format("evaluation {}: E* {:.2f} GPa, kappa {:.3f}, sigma_c {:.1f} MPa, c {:.1f} MPa -> E {:.2f} GPa, "
                             "nu {:.3f}, sigma_t {:.1f} MPa, sigma_C {:.1f} MPa (max error {:.1f} %, {:.0f} s{})\n",
                             e.index, units::pa_to_gpa(m.contact_modulus_pa), m.stiffness_ratio,
                             units::pa_to_mpa(m.tensile_strength_pa), units::pa_to_mpa(m.cohesion_pa),
                             units::pa_to_gpa(e.macro.youngs_modulus_pa), e.macro.poissons_ratio,
                             units::pa_to_mpa(e.macro.tensile_strength_pa), units::pa_to_mpa(e.macro.compressive_strength_pa),
                             100 * e.max_relative_error, e.wall_time_s, e.from_checkpoint ? ", from the checkpoint" : "")
              << std::flush;
  }, known);
  Material calibrated = r.material;
  calibrated.name = scene.calibrated_name;
  const std::string description = fmt::format(
      "Calibrated by kerf-dem calibrate ({} evaluations, {}converged: max error {:.2f} % against targets E {:.1f} GPa, "
      "nu {:.3f}, sigma_t {:.1f} MPa, sigma_c {:.1f} MPa) on a {} specimen of {} disks.",
      r.log.size(), r.converged ? "" : "NOT ", 100 * r.max_relative_error, units::pa_to_gpa(scene.calibration.targets.youngs_modulus_pa),
      scene.calibration.targets.poissons_ratio, units::pa_to_mpa(scene.calibration.targets.tensile_strength_pa),
      units::pa_to_mpa(scene.calibration.targets.compressive_strength_pa), summary["specimen"]["packing"].get<std::string>(),
      specimen.particles().size());
  const Json material = library_material_json(calibrated, "Flat-joint DEM material calibrated by kerf-dem",
                                              description, "kerf-dem calibrate (see description)");
  write_material_output(scene, material, out, summary);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary["results"] = Json{{"converged", r.converged},
                            {"max_error_percent", 100 * r.max_relative_error},
                            {"evaluations", r.log.size()},
                            {"targets", macro_json(scene.calibration.targets)},
                            {"achieved", macro_json(r.macro)},
                            {"calibrated_material", material}};
  summary["n_particles"] = specimen.particles().size();
  summary["wall_time_s"] = wall;
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  std::error_code ignored;
  fs::remove(out / "checkpoint.bin", ignored);  // finished: nothing to resume
  std::cout << fmt::format("calibration {} after {} evaluations (max error {:.2f} %), {:.0f} s -> {}\n",
                           r.converged ? "converged" : "did NOT converge", r.log.size(), 100 * r.max_relative_error, wall,
                           (out / (scene.calibrated_name + ".json")).string());
  return r.converged ? 0 : kExitModelError;
}

struct TestProgress {
  std::vector<std::pair<double, std::vector<std::string>>> frames;
  int sample_index = 0;
  std::string scene_dir;
  bool show_progress = true;  ///< false for replicates run side by side (one bar each would garble the terminal)
};

/// Writes the next VTK frame (particles and bonds, cracks) and records it for the .pvd series.
void write_frame_files(const fs::path& out, const Simulation& sim, TestProgress& tp) {
  const std::string name = fmt::format("frame_{:04d}.vtp", tp.frames.size());
  const std::string cracks = fmt::format("cracks_{:04d}.vtp", tp.frames.size());
  write_vtp_frame(out / name, sim);
  write_cracks_vtp(out / cracks, sim.cracks());
  tp.frames.push_back({sim.time(), {name, cracks}});
}

/// Runs (or continues) a tension or compression test to its end, then the quasi-static check and outputs.
int continue_test(const Scene& scene, const Json& doc, const Simulation& specimen, Json summary, const fs::path& out,
                  int checkpoint_every, LabTestRun run, TestProgress tp) {
  // Frames: every frame_every_samples samples, plus the final state.
  const auto write_frame = [&](const Simulation& sim) { write_frame_files(out, sim, tp); };
  if (scene.frame_every_samples > 0 && tp.sample_index == 0) write_frame(specimen);
  const double n = static_cast<double>(specimen.particles().size());
  const double steps = scene.loading.max_strain * run.result().height_m / (2 * scene.loading.speed_m_per_s * run.simulation().time_step());
  Progress progress(scene.kind, static_cast<std::size_t>(n * steps), "particle-steps");
  progress.advance(static_cast<std::size_t>(n * scene.loading.sample_every_steps * tp.sample_index));
  while (run.advance()) {
    ++tp.sample_index;
    progress.advance(static_cast<std::size_t>(n * scene.loading.sample_every_steps));
    if (scene.frame_every_samples > 0 && tp.sample_index % scene.frame_every_samples == 0) write_frame(run.simulation());
    if (checkpoint_every > 0 && tp.sample_index % checkpoint_every == 0) {
      Checkpoint c{doc, summary, tp.frames, tp.sample_index, checkpoint_every, tp.scene_dir, specimen.serialize(), run.serialize()};
      write_file_atomically(out / "checkpoint.bin", c.bytes());
    }
  }
  progress.finish();
  const LabTestResult& res = run.result();
  if (scene.frame_every_samples > 0) write_frame(run.simulation());
  const bool tension = scene.kind == "tension";
  Json results{{"youngs_modulus_GPa", units::pa_to_gpa(res.youngs_modulus_pa)},
               {"poissons_ratio", res.poissons_ratio},
               {tension ? "tensile_strength_MPa" : "compressive_strength_MPa", units::pa_to_mpa(res.peak_stress_pa)},
               {"strain_at_peak", res.strain_at_peak},
               {"n_tension_cracks", res.curve.back().n_tension_cracks},
               {"n_shear_cracks", res.curve.back().n_shear_cracks},
               {"stop_reason", res.stop_reason},
               {"speed_m_per_s", res.speed_m_per_s},
               {"specimen_width_mm", units::m_to_mm(res.width_m)},
               {"gauge_length_mm", units::m_to_mm(res.height_m)}};
  if (scene.loading.quasi_static_check) {
    LoadingSpec half = scene.loading;
    half.speed_m_per_s *= 0.5;
    half.quasi_static_check = false;  // this run is the check
    const LabTestResult slow = run_test(specimen, half, scene.kind + " (quasi-static check, half speed)", {});
    results["quasi_static_check"] = Json{
        {"speed_m_per_s", half.speed_m_per_s},
        {"peak_stress_MPa", units::pa_to_mpa(slow.peak_stress_pa)},
        {"peak_change_percent", 100 * (slow.peak_stress_pa - res.peak_stress_pa) / res.peak_stress_pa},
        {"youngs_modulus_change_percent", 100 * (slow.youngs_modulus_pa - res.youngs_modulus_pa) / res.youngs_modulus_pa},
        {"wall_time_s", slow.wall_time_s}};
  }
  summary["results"] = results;
  summary["n_particles"] = res.n_particles;
  summary["steps"] = res.steps;
  summary["wall_time_s"] = res.wall_time_s;
  summary["particle_steps_per_s"] = static_cast<double>(res.n_particles) * static_cast<double>(res.steps) / res.wall_time_s;
  write_file_atomically(out / "curve.csv", curve_csv(res));
  write_file_atomically(out / "cracks.csv", cracks_csv(run.simulation().cracks()));
  if (scene.frame_every_samples > 0) write_pvd(out / "result.pvd", tp.frames);
  write_specimen_png(out / "specimen.png", run.simulation(), scene.kind + ", final state");
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  std::error_code ignored;
  fs::remove(out / "checkpoint.bin", ignored);  // finished: nothing to resume
  std::cout << fmt::format("{}: E = {:.2f} GPa, nu = {:.3f}, {} strength = {:.1f} MPa, {} steps, {:.1f} s -> {}\n", scene.kind,
                           units::pa_to_gpa(res.youngs_modulus_pa), res.poissons_ratio, tension ? "tensile" : "compressive",
                           units::pa_to_mpa(res.peak_stress_pa), res.steps, res.wall_time_s, out.string());
  return 0;
}

/// Orthogonal cutting (seed 000 Section 4), forces against tool travel and cracks by mode and place:
/// runs (or continues, from a checkpoint) a cut to the end of its travel and writes the outputs.
Json continue_cut(const Scene& scene, const Json& doc, Json summary, const fs::path& out, int checkpoint_every, CutRun run,
                  TestProgress tp) {
  const auto write_frame = [&](const Simulation& sim) { write_frame_files(out, sim, tp); };
  if (scene.frame_every_samples > 0 && tp.sample_index == 0) write_frame(run.simulation());
  const double n = static_cast<double>(run.result().n_particles);
  const double steps = scene.cut.length_m / (scene.cut.speed_m_per_s * run.result().time_step_s);
  std::optional<Progress> progress;
  if (tp.show_progress) {
    progress.emplace("cut", static_cast<std::size_t>(n * steps), "particle-steps");
    progress->advance(static_cast<std::size_t>(n * scene.cut.sample_every_steps * tp.sample_index));
  }
  while (run.advance()) {
    ++tp.sample_index;
    if (progress) progress->advance(static_cast<std::size_t>(n * scene.cut.sample_every_steps));
    if (scene.frame_every_samples > 0 && tp.sample_index % scene.frame_every_samples == 0) write_frame(run.simulation());
    if (checkpoint_every > 0 && tp.sample_index % checkpoint_every == 0) {
      // The cut holds its own workpiece: the checkpoint's specimen part stays empty.
      Checkpoint c{doc, summary, tp.frames, tp.sample_index, checkpoint_every, tp.scene_dir, std::string(), run.serialize()};
      write_file_atomically(out / "checkpoint.bin", c.bytes());
    }
  }
  if (progress) progress->finish();
  if (scene.frame_every_samples > 0) write_frame(run.simulation());
  const CutResult& res = run.result();
  const auto& frames = tp.frames;
  summary["cut"] = cut_params_to_json(scene.cut);
  summary["results"] =
      Json{{"main_force_N", res.main_force_n},
           {"thrust_force_N", res.thrust_force_n},
           {"main_force_std_N", res.main_force_std_n},
           {"thrust_force_std_N", res.thrust_force_std_n},
           {"steady_from_travel_mm", units::m_to_mm(scene.cut.entry_fraction * scene.cut.length_m)},
           {"steady_samples", res.n_steady_samples},
           {"width_mm", units::m_to_mm(res.width_m)},
           {"cracks_tensile", res.cracks.tensile},
           {"cracks_shear", res.cracks.shear},
           {"cracks_chip", res.cracks.chip},
           {"cracks_subsurface", res.cracks.subsurface},
           {"subsurface_damage_depth_um", units::m_to_um(res.cracks.subsurface_damage_depth_m)},
           {"steady_machined_from_x_mm", units::m_to_mm(res.steady_machined_x_m[0])},
           {"steady_machined_to_x_mm", units::m_to_mm(res.steady_machined_x_m[1])},
           {"cracks_subsurface_steady", res.cracks.subsurface_steady},
           {"subsurface_damage_depth_steady_um", units::m_to_um(res.cracks.subsurface_steady_damage_depth_m)},
           {"surface_y_mm", units::m_to_mm(res.y_top_m)},
           {"cut_line_y_mm", units::m_to_mm(res.y_cut_m)},
           {"particles_removed_by_grooves", res.n_removed_by_grooves}};
  Json windows = Json::array();
  for (const auto& w : res.travel_windows)
    // Window ends to 1 pm, so that 3 x 0.1 mm reads 0.3, not 0.30000000000000004.
    windows.push_back({{"from_travel_mm", std::round(units::m_to_mm(w.from_m) * 1e9) / 1e9},
                       {"to_travel_mm", std::round(units::m_to_mm(w.to_m) * 1e9) / 1e9},
                       {"main_force_N", w.main_force_n}, {"thrust_force_N", w.thrust_force_n}, {"samples", w.n_samples}});
  summary["results"]["travel_windows"] = windows;
  summary["n_particles"] = res.n_particles;
  summary["steps"] = res.steps;
  summary["wall_time_s"] = res.wall_time_s;
  summary["particle_steps_per_s"] = static_cast<double>(res.n_particles) * static_cast<double>(res.steps) / res.wall_time_s;
  write_file_atomically(out / "forces.csv", cut_forces_csv(res));
  write_file_atomically(out / "cracks.csv", cracks_csv(run.simulation().cracks(), res.y_cut_m));
  if (scene.frame_every_samples > 0) write_pvd(out / "result.pvd", frames);
  // The workpiece with room for the tool on the right and the chip above.
  const auto& box = res.workpiece_box_m;
  const double margin = 2 * scene.cut.depth_of_cut_m;
  write_specimen_png(out / "specimen.png", run.simulation(), "cut, final state",
                     std::array<double, 4>{box[0], box[1] + margin, box[2], box[3] + margin});
  write_cut_forces_png(out / "forces.png", res, scene.cut.entry_fraction * scene.cut.length_m);
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  std::error_code ignored;
  fs::remove(out / "checkpoint.bin", ignored);  // finished: nothing to resume
#pragma omp critical(kerf_dem_stdout)
  std::cout << fmt::format("cut: main force {:.3g} N (std {:.2g}), thrust force {:.3g} N (std {:.2g}) per {:g} mm width; "
                           "{} tensile + {} shear cracks ({} chip, {} subsurface, damage depth {:.1f} um); {} steps, {:.1f} s -> {}\n",
                           res.main_force_n, res.main_force_std_n, res.thrust_force_n, res.thrust_force_std_n,
                           units::m_to_mm(res.width_m), res.cracks.tensile, res.cracks.shear, res.cracks.chip,
                           res.cracks.subsurface, units::m_to_um(res.cracks.subsurface_damage_depth_m), res.steps,
                           res.wall_time_s, out.string());
  return summary;
}

/// Seed 000 Section 4 repeats each cut on three specimens with different random packings: replicate k
/// uses packing seed specimen.seed + k and writes DIR/replicate_k; DIR/summary.json has the per-replicate
/// results and their mean and (sample) standard deviation.
///
/// Replicates run side by side, one thread each, as long as there are threads to spare (a cut of a few
/// thousand disks scales better over replicates than over threads: no barrier per step); leftover threads
/// go to each replicate's force loops. A replicate whose DIR/replicate_k/summary.json already holds the same
/// material, specimen and cut is reused, so an interrupted study loses only the replicates in flight.
int run_cut_replicates(const Scene& scene, int replicates, Json summary, const fs::path& out) {
  // Each result with the name of its spread over the replicates.
  const std::vector<std::pair<std::string, std::string>> keys{
      {"main_force_N", "main_force_replicate_std_N"},
      {"thrust_force_N", "thrust_force_replicate_std_N"},
      {"cracks_tensile", "cracks_tensile_replicate_std"},
      {"cracks_shear", "cracks_shear_replicate_std"},
      {"subsurface_damage_depth_um", "subsurface_damage_depth_replicate_std_um"},
      {"cracks_subsurface_steady", "cracks_subsurface_steady_replicate_std"},
      {"subsurface_damage_depth_steady_um", "subsurface_damage_depth_steady_replicate_std_um"}};
  const auto start = std::chrono::steady_clock::now();
  const int threads = omp_get_max_threads();
  const int side_by_side = std::min(threads, replicates);
  const int inner_threads = std::max(1, threads / side_by_side);
  std::vector<Json> done(static_cast<std::size_t>(replicates));
  std::vector<std::exception_ptr> failed(static_cast<std::size_t>(replicates));
  const int max_levels = omp_get_max_active_levels();
  omp_set_max_active_levels(2);
#pragma omp parallel for schedule(dynamic, 1) num_threads(side_by_side)
  for (int k = 0; k < replicates; ++k) {
    try {
      omp_set_num_threads(inner_threads);
      Scene s = scene;
      s.specimen.seed = scene.specimen.seed + static_cast<std::uint64_t>(k);
      const fs::path dir = out / fmt::format("replicate_{}", k + 1);
      // What makes a replicate: reused only when all of it is unchanged.
      const Json inputs{{"material", material_to_json(s.material)}, {"specimen", specimen_spec_to_json(s.specimen)},
                        {"cut", cut_params_to_json(s.cut)}};
      if (fs::exists(dir / "summary.json")) {
        const Json old = read_json_file((dir / "summary.json").string());
        // A run from before a result was added lacks it: run again.
        const auto has_every_result = [&] {
          return std::all_of(keys.begin(), keys.end(),
                             [&](const auto& key) { return old.at("results").contains(key.first); });
        };
        if (old.value("replicate_inputs", Json()) == inputs && old.contains("results") && has_every_result()) {
#pragma omp critical(kerf_dem_stdout)
          std::cout << fmt::format("replicate {}: reusing the finished run in {}\n", k + 1, dir.string());
          done[static_cast<std::size_t>(k)] = old;
          continue;
        }
      }
      SpecimenSpec spec;
      SpecimenReport report;
      double genesis_s = 0;
      const bool show_progress = side_by_side == 1;
      const Simulation specimen = obtain_specimen(s, spec, report, genesis_s, show_progress);
      fs::create_directories(dir);
      Json one = summary;
      one["threads"] = inner_threads;
      one["replicate_inputs"] = inputs;
      one["specimen"] = specimen_json(spec, report, genesis_s);
      done[static_cast<std::size_t>(k)] =
          continue_cut(s, Json(), one, dir, 0, CutRun(specimen, s.cut), {{}, 0, std::string(), show_progress});
    } catch (...) {
      failed[static_cast<std::size_t>(k)] = std::current_exception();
    }
  }
  omp_set_max_active_levels(max_levels);
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
  Json list = Json::array();
  double wall = 0;
  for (int k = 0; k < replicates; ++k) {
    const Json& one = done[static_cast<std::size_t>(k)];
    Json row{{"replicate", k + 1}, {"seed", one["specimen"]["seed"]}, {"directory", fmt::format("replicate_{}", k + 1)}};
    for (const auto& key : keys) row[key.first] = one["results"][key.first];
    for (const char* key : {"main_force_std_N", "thrust_force_std_N", "width_mm"}) row[key] = one["results"][key];
    row["wall_time_s"] = one["wall_time_s"];
    wall += one["wall_time_s"].get<double>();
    list.push_back(row);
  }
  Json stats;
  for (const auto& [key, spread] : keys) {
    std::vector<double> values;
    for (const auto& row : list) values.push_back(row[key].get<double>());
    const SampleStatistics st = sample_statistics(values);  // replicates >= 2: a finite sample std
    stats[key] = st.mean;
    stats[spread] = st.standard_deviation;
  }
  stats["width_mm"] = list[0]["width_mm"];
  summary["cut"] = cut_params_to_json(scene.cut);
  summary["replicates"] = list;
  summary["results"] = stats;
  summary["replicates_side_by_side"] = side_by_side;
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary["wall_time_s_sum_over_replicates"] = wall;
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  std::cout << fmt::format("cut, {} replicates: main force {:.3g} N (replicate std {:.2g}), thrust force {:.3g} N "
                           "(replicate std {:.2g}) per {:g} mm width -> {}\n",
                           replicates, stats["main_force_N"].get<double>(), stats["main_force_replicate_std_N"].get<double>(),
                           stats["thrust_force_N"].get<double>(), stats["thrust_force_replicate_std_N"].get<double>(),
                           stats["width_mm"].get<double>(), out.string());
  return 0;
}

/// kind calibrate_cut: fits the bond-strength factor s (kerf/dem/cut_calibration.hpp) so that the mean main
/// force over `replicates` packings meets the target. Evaluation k runs its replicates in DIR/evaluation_k/
/// (as --replicates does); rerunning the same command after a kill reuses every finished replicate, and the
/// factors that follow are the same (each is computed from the forces read back, exact to the bit).
int run_cut_calibration(const Scene& scene, const fs::path& out) {
  const auto start = std::chrono::steady_clock::now();
  const auto& fit = scene.cut_fit;
  std::vector<CutCalibrationPoint> history;
  Json evaluations = Json::array();
  // calibration_log.csv: the evaluation's number, these fields of its summary row, and its wall time.
  const std::vector<std::string> logged{"strength_factor",   "tensile_strength_MPa",       "cohesion_MPa",
                                        "main_force_N",      "main_force_replicate_std_N", "thrust_force_N",
                                        "thrust_force_replicate_std_N", "relative_error_percent"};
  std::vector<std::string> header{"evaluation"};
  header.insert(header.end(), logged.begin(), logged.end());
  header.push_back("wall_time_s");
  std::string log = csv_line(header);
  double s = fit.start_factor;
  std::size_t best = 0;
  bool converged = false;
  for (int k = 1; k <= fit.max_evaluations && !converged; ++k) {
    if (k > 1) s = next_strength_factor(history, fit.target_main_force_n);
    Scene e = scene;
    e.kind = "cut";
    e.material = scale_bond_strengths(scene.material, s, fmt::format("{}_bond_strength_x{:.6g}", scene.material.name, s));
    const fs::path dir = out / fmt::format("evaluation_{}", k);
    fs::create_directories(dir);
    std::cout << fmt::format("evaluation {}: bond strengths x {:.4g} (sigma_c {:.2f} MPa, c {:.2f} MPa), {} replicates\n", k,
                             s, units::pa_to_mpa(calibrated_params(e.material).tensile_strength_pa),
                             units::pa_to_mpa(calibrated_params(e.material).cohesion_pa), fit.replicates)
              << std::flush;
    run_cut_replicates(e, fit.replicates, Json{{"kind", "cut"}, {"material", material_to_json(e.material)},
                                               {"threads", omp_get_max_threads()}}, dir);
    const Json done = read_json_file((dir / "summary.json").string());
    const Json& r = done["results"];
    const double force = r["main_force_N"].get<double>();
    const double error = force / fit.target_main_force_n - 1;
    history.push_back({s, force});
    if (std::abs(error) < std::abs(history[best].main_force_n / fit.target_main_force_n - 1)) best = history.size() - 1;
    converged = std::abs(error) <= fit.tolerance;
    const Json row{{"evaluation", k},
                   {"strength_factor", s},
                   {"tensile_strength_MPa", units::pa_to_mpa(calibrated_params(e.material).tensile_strength_pa)},
                   {"cohesion_MPa", units::pa_to_mpa(calibrated_params(e.material).cohesion_pa)},
                   {"main_force_N", force},
                   {"main_force_replicate_std_N", r["main_force_replicate_std_N"]},
                   {"thrust_force_N", r["thrust_force_N"]},
                   {"thrust_force_replicate_std_N", r["thrust_force_replicate_std_N"]},
                   {"relative_error_percent", 100 * error},
                   {"directory", dir.filename().string()}};
    evaluations.push_back(row);
    std::vector<std::string> cells{std::to_string(k)};
    for (const auto& key : logged) cells.push_back(csv_number(row[key].get<double>()));
    cells.push_back(csv_number(done["wall_time_s"].get<double>()));
    log += csv_line(cells);
    write_file_atomically(out / "calibration_log.csv", log);
    std::cout << fmt::format("evaluation {}: main force {:.4g} N against {:.4g} N ({:+.1f} %, tolerance {:.0f} %)\n", k,
                             force, fit.target_main_force_n, 100 * error, 100 * fit.tolerance)
              << std::flush;
  }
  const CutCalibrationPoint& b = history[best];
  Material named = scale_bond_strengths(scene.material, b.strength_factor, scene.calibrated_name);
  named.name = scene.calibrated_name;  // factor 1 keeps the base's name
  const double sem = evaluations[best]["main_force_replicate_std_N"].get<double>() / std::sqrt(fit.replicates);
  const std::string description = fmt::format(
      "{} with both bond strengths (sigma_c, c) x {:.4g}, fitted by kerf-dem calibrate_cut to a mean main force of "
      "{:.4g} N{} ({} evaluations, {}converged: {:.4g} +- {:.2g} N, mean +- standard error over {} packings) on the "
      "cut: depth {:g} mm, speed {:g} m/s, travel {:g} mm, rake {:g} deg, grooves {}. The macro strengths scale by the "
      "same factor (exact trend), E and nu are those of the base material.",
      scene.material.name, b.strength_factor, fit.target_main_force_n,
      fit.target_source.empty() ? "" : " (" + fit.target_source + ")", history.size(), converged ? "" : "NOT ",
      b.main_force_n, sem, fit.replicates, units::m_to_mm(scene.cut.depth_of_cut_m), scene.cut.speed_m_per_s,
      units::m_to_mm(scene.cut.length_m), scene.cut.rake_deg, scene.cut.groove_shape);
  const Json material = library_material_json(named, "Flat-joint DEM material fitted to one measured cut by kerf-dem",
                                              description, "kerf-dem calibrate_cut (see description)");
  Json summary{{"kind", scene.kind}, {"material", material_to_json(scene.material)}, {"threads", omp_get_max_threads()}};
  summary["cut"] = cut_params_to_json(scene.cut);
  write_material_output(scene, material, out, summary);
  summary["results"] = Json{{"converged", converged},
                            {"target_main_force_N", fit.target_main_force_n},
                            {"target_source", fit.target_source},
                            {"strength_factor", b.strength_factor},
                            {"main_force_N", b.main_force_n},
                            {"main_force_standard_error_N", sem},
                            {"relative_error_percent", 100 * (b.main_force_n / fit.target_main_force_n - 1)},
                            {"evaluations", evaluations},
                            {"calibrated_material", material}};
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  std::cout << fmt::format("cut calibration {} after {} evaluations: bond strengths x {:.4g}, main force {:.4g} +- {:.2g} N "
                           "against {:.4g} N -> {}\n",
                           converged ? "converged" : "did NOT converge", history.size(), b.strength_factor,
                           b.main_force_n, sem, fit.target_main_force_n,
                           (out / (scene.calibrated_name + ".json")).string());
  return converged ? 0 : kExitModelError;
}

int run_command(const std::string& scene_path, const std::vector<std::string>& sets, const fs::path& out, int threads,
                int checkpoint_every, int replicates) {
  if (threads > 0) omp_set_num_threads(threads);
  Json doc = read_json_file(scene_path);
  for (const auto& s : sets) apply_override(doc, s);
  const Scene scene = read_scene(doc, fs::path(scene_path).parent_path());
  if (checkpoint_every > 0 && scene.kind == "specimen")
    throw InputError("--checkpoint-every", std::to_string(checkpoint_every),
                     "checkpoints only for tension, compression, calibrate and cut scenes");
  if (checkpoint_every > 0 && replicates > 1)
    throw InputError("--checkpoint-every", std::to_string(checkpoint_every), "no checkpoints with --replicates");
  if (replicates > 1 && scene.kind != "cut")
    throw InputError("--replicates", std::to_string(replicates),
                     "replicates only for cut scenes (calibrate_cut: calibration.replicates)");
  if (checkpoint_every > 0 && scene.kind == "calibrate_cut")
    throw InputError("--checkpoint-every", std::to_string(checkpoint_every),
                     "no checkpoints for calibrate_cut (rerun the command: finished replicates are reused)");
  if (scene.kind == "calibrate_cut" && scene.specimen_file)
    throw InputError("specimen.file", *scene.specimen_file,
                     "a scene that generates its specimen (calibrate_cut runs replicates on packings specimen.seed + k)");
  if (replicates > 1 && scene.specimen_file)
    throw InputError("--replicates", std::to_string(replicates),
                     "a scene that generates its specimen (replicates differ in specimen.seed), not specimen.file");
  fs::create_directories(out);
  if (scene.kind == "calibrate_cut") return run_cut_calibration(scene, out);
  if (replicates > 1) {
    const Json summary{{"kind", scene.kind}, {"material", material_to_json(scene.material)},
                       {"threads", omp_get_max_threads()}};
    return run_cut_replicates(scene, replicates, summary, out);
  }
  SpecimenSpec spec;
  SpecimenReport report;
  double genesis_s = 0;
  Simulation specimen = obtain_specimen(scene, spec, report, genesis_s);
  Json summary{{"kind", scene.kind}, {"material", material_to_json(scene.material)},
               {"specimen", specimen_json(spec, report, genesis_s)}, {"threads", omp_get_max_threads()},
               {"time_step_s", specimen.time_step()}};
  if (scene.kind == "specimen") {
    save_specimen((out / "specimen.json").string(), specimen, spec, report);
    write_vtp_frame(out / "specimen.vtp", specimen);
    write_specimen_png(out / "specimen.png", specimen, "specimen");
    summary["n_particles"] = report.n_particles;
    summary["steps"] = report.genesis_steps;
    summary["wall_time_s"] = genesis_s;
    summary["particle_steps_per_s"] = report.n_particles * static_cast<double>(report.genesis_steps) / genesis_s;
    write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
    std::cout << fmt::format("specimen: {} disks, {} joints, packing fraction {:.4f}, coordination {:.3f}, residual "
                             "stress ({:.3g}, {:.3g}) MPa -> {}\n",
                             report.n_particles, report.n_bonds, report.packing_fraction, report.coordination_number,
                             units::pa_to_mpa(report.residual_stress_xx_pa), units::pa_to_mpa(report.residual_stress_yy_pa),
                             (out / "specimen.json").string());
    return 0;
  }
  if (scene.kind == "calibrate")
    return run_calibration(scene, doc, specimen, summary, out, checkpoint_every,
                           fs::absolute(scene_path).parent_path().string(), {});
  if (scene.kind == "cut") {
    continue_cut(scene, doc, summary, out, checkpoint_every, CutRun(specimen, scene.cut),
                 {{}, 0, fs::absolute(scene_path).parent_path().string()});
    return 0;
  }
  LabTestRun run(specimen, scene.loading);
  return continue_test(scene, doc, specimen, summary, out, checkpoint_every, std::move(run),
                       {{}, 0, fs::absolute(scene_path).parent_path().string()});
}

int resume_command(const fs::path& dir, int threads) {
  if (threads > 0) omp_set_num_threads(threads);
  const fs::path file = dir / "checkpoint.bin";
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError("DIR", dir.string(), "a directory with a checkpoint.bin written by --checkpoint-every");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Checkpoint c = Checkpoint::parse(bytes);
  const Scene scene = read_scene(c.scene, c.scene_dir);
  if (scene.kind == "cut") {
    continue_cut(scene, c.scene, c.summary, dir, c.checkpoint_every, CutRun::deserialize(c.run),
                 {c.frames, c.sample_index, c.scene_dir});
    return 0;
  }
  const Simulation specimen = Simulation::deserialize(c.specimen);
  if (scene.kind == "calibrate")
    return run_calibration(scene, c.scene, specimen, c.summary, dir, c.checkpoint_every, c.scene_dir,
                           deserialize_evaluations(c.run));
  return continue_test(scene, c.scene, specimen, c.summary, dir, c.checkpoint_every, LabTestRun::deserialize(c.run),
                       {c.frames, c.sample_index, c.scene_dir});
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"kerf-dem: 2D bonded-particle DEM with Potyondy's flat joint"};
  app.require_subcommand(1);
  std::string scene_path;
  std::vector<std::string> sets;
  std::string out_dir = "out";
  int threads = 0, checkpoint_every = 0, replicates = 1;
  std::string resume_dir;
  auto* run = app.add_subcommand("run", "run a scene (kind: specimen, tension, compression, calibrate, cut, calibrate_cut)");
  run->add_option("scene", scene_path, "scene JSON file")->required();
  run->add_option("--set", sets, "override a scene value: key.path=value (repeatable)");
  run->add_option("--out", out_dir, "output directory (default: out)");
  run->add_option("--threads", threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  run->add_option("--checkpoint-every", checkpoint_every, "write DIR/checkpoint.bin every N samples (tension, compression, cut; calibrate: after every evaluation)")
      ->check(CLI::Range(1, 100000000));
  run->add_option("--replicates", replicates, "cut scenes: repeat on N packings (seeds specimen.seed + 0..N-1)")
      ->check(CLI::Range(1, 1000));
  auto* resume = app.add_subcommand("resume", "continue a killed test, cut or calibration from DIR/checkpoint.bin");
  resume->add_option("dir", resume_dir, "output directory of the killed run")->required();
  resume->add_option("--threads", threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitInputError;
  }
  try {
    if (resume->parsed()) return resume_command(resume_dir, threads);
    return run_command(scene_path, sets, out_dir, threads, checkpoint_every, replicates);
  } catch (const InputError& e) {
    std::cerr << "kerf-dem: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const ModelError& e) {
    std::cerr << "kerf-dem: model error: " << e.what() << "\n";
    return kExitModelError;
  } catch (const std::exception& e) {
    std::cerr << "kerf-dem: error: " << e.what() << "\n";
    return 1;
  }
}
