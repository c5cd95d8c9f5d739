// Scene kind "calibrate": the micro-parameters fitted to macro-properties by tension and compression tests
// (kerf/dem/procedures/calibration.hpp), with a checkpoint after every evaluation.
#include <fmt/format.h>

#include <chrono>
#include <cstdint>
#include <iostream>

#include "common.hpp"
#include "kerf/csv_table.hpp"
#include "kerf/dem/procedures/calibration.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/material.hpp"
#include "kerf/units.hpp"
#include "kind_results.hpp"

namespace kerf::dem::kinds {

namespace {

const EnumNames<CalibrationMethod>& method_names() {
  static constexpr std::string_view names[] = {"hybrid", "secant"};
  static const EnumNames<CalibrationMethod> table{names};
  return table;
}

constexpr std::string_view free_names[] = {"effective_modulus_GPa", "stiffness_ratio", "tensile_strength_MPa",
                                           "cohesion_MPa", "fracture_energy_J_per_m2"};

/// "calibration.toughness": the beam of the fifth test (its packing the specimen's, its size its own); the
/// test's own keys are the toughness scene's (toughness_fields()).
struct Beam {
  double depth_m = 0.5e-3, length_m = 2.2e-3;
  std::optional<double> local_damping;
};
const FieldTable<Beam>& beam_fields() {
  static const FieldTable<Beam> table{
      number_field("beam_depth_mm", units::kMm, Range::positive(), "the beam's depth W (the specimen's height)",
                   &Beam::depth_m),
      number_field("beam_length_mm", units::kMm, Range::positive(),
                   "the beam's length (at least 4.2 W: span 4 W and the overhangs)", &Beam::length_m),
      optional_number_field("local_damping", units::kNone, Range::closed(0.0, 1.0),
                            "the beam's local damping (a light one quietens the roller's ringing)",
                            &Beam::local_damping, "the material's")};
  return table;
}

/// "calibration.targets": a row of a table of macro-properties, which the section's own keys override.
struct TargetsFile {
  std::string file;  ///< relative: to the data directory; empty: none
  std::string row = "soda_lime_glass";
};
const FieldTable<TargetsFile>& targets_file_fields() {
  static const FieldTable<TargetsFile> table{
      text_field("file", "a table of macro-properties (data/experiments/*.csv, relative to the data directory)",
                 &TargetsFile::file),
      text_field("row", "the row of `file` (its first cell)", &TargetsFile::row)};
  return table;
}

/// The "calibration" section's own keys.
const FieldTable<CalibrationSpec>& calibration_fields() {
  static const FieldTable<CalibrationSpec> table{
      number_field("tolerance_percent", units::kPercent, Range::open(0.0, 100.0),
                   "largest relative error of each of E, nu, sigma_t, sigma_c for convergence",
                   &CalibrationSpec::tolerance),
      number_field("toughness_tolerance_percent", units::kPercent, Range::open(0.0, 100.0),
                   "largest relative error of K_IC for convergence (with a toughness target)",
                   &CalibrationSpec::toughness_tolerance),
      int_field("max_evaluations", 1, 1000,
                "DEM evaluations (a tension and a compression test each, and a beam with calibration.toughness)",
                &CalibrationSpec::max_evaluations),
      choice_field("method", method_names(), "root finder (kerf/dem/procedures/calibration.hpp)",
                   &CalibrationSpec::method),
      int_field("packings", 1, 64,
                "packings each candidate is evaluated on (seeds specimen.seed + 0..N-1); their mean is calibrated",
                &CalibrationSpec::packings),
      FlagsField<CalibrationSpec>{"free", free_names, "the micro-parameters the calibration may change",
                                  [](const CalibrationSpec& c) {
                                    return unsigned{c.free_modulus} | unsigned{c.free_stiffness_ratio} << 1 |
                                           unsigned{c.free_tensile_strength} << 2 | unsigned{c.free_cohesion} << 3 |
                                           unsigned{c.free_fracture_energy} << 4;
                                  },
                                  [](CalibrationSpec& c, unsigned flags) {
                                    c.free_modulus = flags & 1u, c.free_stiffness_ratio = flags & 2u;
                                    c.free_tensile_strength = flags & 4u, c.free_cohesion = flags & 8u;
                                    c.free_fracture_energy = flags & 16u;
                                  }}};
  return table;
}

/// "calibration.targets": the macro-properties to meet (after those of a "file" row, if given).
const FieldTable<MacroProperties>& target_fields() {
  static const FieldTable<MacroProperties> table{
      number_field("youngs_modulus_GPa", units::kGPa, Range::positive(), "Young's modulus E",
                   &MacroProperties::youngs_modulus_Pa),
      number_field("poissons_ratio", units::kNone, Range::open(0.0, 0.5), "Poisson's ratio nu",
                   &MacroProperties::poissons_ratio),
      number_field("tensile_strength_MPa", units::kMPa, Range::positive(), "tensile strength sigma_t",
                   &MacroProperties::tensile_strength_Pa),
      number_field("compressive_strength_MPa", units::kMPa, Range::positive(),
                   "unconfined compressive strength sigma_c", &MacroProperties::compressive_strength_Pa),
      number_field("fracture_toughness_MPa_sqrt_m", units::kMPaSqrtM, Range::non_negative(),
                   "fracture toughness K_IC of the calibration.toughness test (0: none)",
                   &MacroProperties::fracture_toughness_Pa_sqrt_m)};
  return table;
}

/// One row (first column = `row`) of a macro-property table (data/experiments/*.csv).
MacroProperties read_targets_csv(const fs::path& path, const std::string& row, const std::string& field) {
  if (!fs::exists(path)) throw InputError(field + ".file", path.string(), "a readable CSV file");
  const CsvTable t = read_csv_file(path);
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    if (t.rows[k].empty() || t.rows[k][0] != row) continue;
    const auto value = [&](const char* name) { return t.number(k, t.column_index(name)); };
    return {units::gpa_to_pa(value("youngs_modulus_GPa")), value("poissons_ratio"),
            units::mpa_to_pa(value("tensile_strength_MPa")), units::mpa_to_pa(value("compressive_strength_MPa"))};
  }
  throw InputError(field + ".row", row, "a row of " + path.string());
}

/// The macro-properties as JSON (K_IC only when measured or targeted).
Json macro_json(const MacroProperties& m) {
  Json j = fields_to_json(target_fields(), m);
  if (!(m.fracture_toughness_Pa_sqrt_m > 0)) j.erase("fracture_toughness_MPa_sqrt_m");
  return j;
}

/// The toughness section's defaults in a calibration: the quasi-static check off (too dear per candidate; it is
/// checked on the calibrated glass's own toughness scene).
ToughnessSpec beam_test_defaults() {
  ToughnessSpec test;
  test.quasi_static_check = false;
  return test;
}

/// The k-th beam's specimen: the calibration's specimen (radii, packing, its seed + k) at the beam's size.
SpecimenSpec beam_spec(const SpecimenSpec& specimen, const Beam& beam, int k) {
  SpecimenSpec s = specimen;
  s.height_m = beam.depth_m;
  s.width_m = beam.length_m;
  s.seed += static_cast<std::uint64_t>(k);
  return s;
}

/// The beams' packings (one per calibration packing), compacted once.
std::vector<SpecimenSource> beam_sources(const SceneCommon& common, const Beam& beam, int packings,
                                         ProgressTarget progress) {
  SceneCommon beams = common;
  beams.specimen = beam_spec(common.specimen, beam, 0);
  progress.prefix += "beam ";
  return start_specimen_sources(beams, "calibrate", packings, progress).sources;
}

/// One evaluation's log line(s) on stdout.
void print_evaluation(const CalibrationEvaluation& e, bool toughness) {
  const CalibratedParams m = calibrated_params(e.material);
  std::cout << fmt::format(
      "evaluation {}: E* {:.2f} GPa, kappa {:.3f}, joint tensile strength {:.1f} MPa, joint cohesion {:.1f} MPa -> "
      "E {:.2f} GPa, nu {:.3f}, sigma_t {:.1f} MPa, sigma_c {:.1f} MPa (max error {:.1f} %, {:.0f} s{})\n",
      e.index, units::pa_to_gpa(m.contact_modulus_Pa), m.stiffness_ratio, units::pa_to_mpa(m.tensile_strength_Pa),
      units::pa_to_mpa(m.cohesion_Pa), units::pa_to_gpa(e.macro.youngs_modulus_Pa), e.macro.poissons_ratio,
      units::pa_to_mpa(e.macro.tensile_strength_Pa), units::pa_to_mpa(e.macro.compressive_strength_Pa),
      100 * e.max_relative_error, e.wall_time_s, e.from_checkpoint ? ", from the checkpoint" : "");
  if (toughness)
    std::cout << fmt::format("evaluation {}: G_f {:.3g} J/m^2 -> K_IC {:.3f} MPa sqrt(m) (error {:.1f} %)\n", e.index,
                             m.fracture_energy_J_per_m2, units::pa_to_mpa(e.macro.fracture_toughness_Pa_sqrt_m),
                             100 * e.toughness_error);
  std::cout << std::flush;
}

class CalibrateKind final : public SceneKind {
 public:
  std::string name() const override { return "calibrate"; }
  bool writes_checkpoints() const override { return true; }
  void read(ObjectReader& root, const SceneCommon& common) override {
    auto& c = spec_;
    ObjectReader cal = root.get_object("calibration");
    if (auto targets = cal.find_object("targets")) {
      const TargetsFile source = read_fields(*targets, targets_file_fields(), TargetsFile{});
      if (!source.file.empty()) {
        fs::path file = source.file;
        if (file.is_relative()) file = kerf::data_directory() / file;
        c.targets = read_targets_csv(file, source.row, targets->path());
      }
      c.targets = read_fields(*targets, target_fields(), c.targets);
      targets->finish();
    }
    c = read_fields(cal, calibration_fields(), c);
    if (auto t = cal.find_object("toughness")) {
      beam_ = read_fields(*t, beam_fields(), Beam{});
      ToughnessCalibration tc{read_fields(*t, toughness_fields(), beam_test_defaults()), beam_.local_damping};
      if (tc.test.quasi_static_check)
        throw InputError(t->path() + ".quasi_static_check", "true",
                         "false (not run per candidate: run the toughness scene with the calibrated glass)");
      t->finish();
      if (common.specimen_file)
        throw InputError(t->path(), "a toughness test",
                         "a specimen from a genesis (not specimen.file): the beams are "
                         "built from the specimen's packing parameters");
      check_toughness_spec(tc.test, beam_spec(common.specimen, beam_, 0),
                           {t->path(), t->path() + ".beam_depth_mm", t->path() + ".beam_length_mm"});
      c.toughness = tc;
    }
    if (c.targets.fracture_toughness_Pa_sqrt_m > 0 && !c.toughness)
      throw InputError("calibration.targets.fracture_toughness_MPa_sqrt_m",
                       fmt::format("{}", units::pa_to_mpa(c.targets.fracture_toughness_Pa_sqrt_m)),
                       "a calibration.toughness test to measure it on");
    check_calibration_start(c, common.material);
    output_ = read_material_output(cal, "calibrated");
    cal.finish();
    LoadingSpec load;
    if (auto loading = root.find_object("loading")) {
      load = read_loading_spec(*loading, LabTest::compression);
      loading->finish();
    }
    load.quasi_static_check = false;
    c.compression = load;
    c.compression.test = LabTest::compression;
    c.tension = load;
    c.tension.test = LabTest::tension;
    c.tension.max_strain = std::min(load.max_strain, 0.005);
  }

  SceneOutcome run(const SceneCommon& common, const SceneRun& run) override {
    StartedSources started = start_specimen_sources(common, name(), spec_.packings, progress_target(run.options));
    return calibrate_from(common, run, started.sources, std::move(started.summary), {}, beams(common, run));
  }

  /// The specimens are built again (a genesis or a specimen file is deterministic); the checkpoint holds the
  /// summary's head and the evaluations.
  SceneOutcome resume(const SceneCommon& common, const SceneRun& run, const Checkpoint& c) override {
    StartedSources started = start_specimen_sources(common, name(), spec_.packings, progress_target(run.options));
    return calibrate_from(common, run, started.sources, c.summary, deserialize_evaluations(c.run), beams(common, run));
  }

 private:
  CalibrationSpec spec_;
  Beam beam_;
  MaterialOutput output_;

  std::vector<SpecimenSource> beams(const SceneCommon& common, const SceneRun& run) const {
    if (!spec_.toughness) return {};
    return beam_sources(common, beam_, spec_.packings, progress_target(run.options));
  }

  /// The calibrated material's description: how it was calibrated and how close it came.
  std::string description(const CalibrationResult& r, const Json& summary, std::size_t n_disks,
                          std::size_t n_sources) const {
    const auto& t = spec_.targets;
    const std::int64_t seed = summary["specimen"]["seed"].get<std::int64_t>();
    std::string out = fmt::format(
        "Calibrated by kerf-dem calibrate ({} evaluations, {}converged: max error {:.2f} % against targets E {:.1f} "
        "GPa, "
        "nu {:.3f}, sigma_t {:.1f} MPa, sigma_c {:.1f} MPa) on a {} specimen of {} disks{}.",
        r.log.size(), r.converged ? "" : "NOT ", 100 * r.max_relative_error, units::pa_to_gpa(t.youngs_modulus_Pa),
        t.poissons_ratio, units::pa_to_mpa(t.tensile_strength_Pa), units::pa_to_mpa(t.compressive_strength_Pa),
        summary["specimen"]["packing"].get<std::string>(), n_disks,
        n_sources > 1 ? fmt::format(" (the mean over {} packings, seeds {} to {})", n_sources, seed,
                                    seed + static_cast<std::int64_t>(n_sources) - 1)
                      : std::string());
    if (spec_.toughness && t.fracture_toughness_Pa_sqrt_m > 0)
      out.insert(out.size() - 1,
                 fmt::format(", and on K_IC {:.3f} MPa sqrt(m) (error {:.1f} %, tolerance {:.0f} %) of a notched beam "
                             "W = {:.2f} mm, a/W = {:.2f} (seeds as the specimen's)",
                             units::pa_to_mpa(t.fracture_toughness_Pa_sqrt_m), 100 * r.toughness_error,
                             100 * spec_.toughness_tolerance, units::m_to_mm(beam_.depth_m),
                             spec_.toughness->test.notch_depth_m / beam_.depth_m));
    return out;
  }

  /// Runs (or, with `known` from a checkpoint, continues) the calibration. With checkpoints a checkpoint is
  /// written after every evaluation (an evaluation is the unit of work that cannot be cut short).
  SceneOutcome calibrate_from(const SceneCommon& common, const SceneRun& run,
                              const std::vector<SpecimenSource>& sources, Json summary,
                              const std::vector<CalibrationEvaluation>& known,
                              const std::vector<SpecimenSource>& beams) const {
    const Simulation& specimen = sources.front().disks();
    const fs::path& out = run.options.out;
    const auto start = std::chrono::steady_clock::now();
    std::vector<CalibrationEvaluation> done;
    const bool toughness = spec_.toughness.has_value();
    std::string log = results_csv_header(calibration_log_columns(), {nullptr, toughness});
    const auto on_evaluation = [&](const CalibrationEvaluation& e) {
      log += results_csv_row(calibration_log_columns(), {&e, toughness});
      write_file_atomically(out / "calibration_log.csv", log);
      done.push_back(e);
      if (run.options.checkpoints())
        write_checkpoint(out, {run.doc,
                               summary,
                               {},
                               static_cast<int>(done.size()),
                               run.options.checkpoint_every,
                               run.scene_dir,
                               std::string(),
                               serialize_evaluations(done),
                               run.options.provenance});
      print_evaluation(e, toughness);
    };
    const CalibrationResult r = calibrate(sources, common.material, spec_, on_evaluation, known, beams);
    Material calibrated = r.material;
    calibrated.name = output_.name;
    const auto& t = spec_.targets;
    const std::string described = description(r, summary, specimen.particles().size(), sources.size());
    const Json material = library_material_json(calibrated, "Flat-joint DEM material calibrated by kerf-dem", described,
                                                "kerf-dem calibrate (see description)");
    write_material_output(output_, material, out, summary);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summary["results"] = results_to_json(calibrate_results(), {r, t, material, toughness});
    summary["n_particles"] = specimen.particles().size();
    summary["wall_time_s"] = wall;
    write_summary(run.options, run.doc, summary);
    remove_checkpoint(out);  // finished: nothing to resume
    std::cout << fmt::format("calibration {} after {} evaluations (max error {:.2f} %), {:.0f} s -> {}\n",
                             r.converged ? "converged" : "did NOT converge", r.log.size(), 100 * r.max_relative_error,
                             wall, (out / (output_.name + ".json")).string());
    return {r.converged ? 0 : kExitModelError, summary, {}};
  }
};

}  // namespace

std::unique_ptr<SceneKind> make_calibrate_kind() {
  return std::make_unique<CalibrateKind>();
}

}  // namespace kerf::dem::kinds

namespace kerf::dem::kinds {

const ResultTable<CalibrateReport>& calibrate_results() {
  namespace k = calibrate_keys;
  using R = CalibrateReport;
  static const ResultTable<R> table{
      result_value<R>(k::converged, "", "whether every target was met within the tolerance",
                      [](const R& c) { return c.r.converged; }),
      result_value<R>(k::max_error_percent, "%", "the largest relative error of the four lab-test properties",
                      [](const R& c) { return 100 * c.r.max_relative_error; }),
      result_value<R>(k::evaluations, "", "materials evaluated", [](const R& c) { return c.r.log.size(); }),
      result_value<R>(k::targets, "", "the targets (calibration.targets' keys)",
                      [](const R& c) { return macro_json(c.targets); }),
      result_value<R>(k::achieved, "", "what the calibrated material gives (the same keys)",
                      [](const R& c) { return macro_json(c.r.macro); }),
      result_value<R>(k::calibrated_material, "", "the calibrated material (as its file holds it)",
                      [](const R& c) { return c.material; }),
      result_if(result_value<R>(k::toughness_error_percent, "%", "with a toughness target: K_IC's relative error",
                                [](const R& c) { return 100 * c.r.toughness_error; }),
                [](const R& c) { return c.toughness; })};
  return table;
}

const ResultTable<CalibrationLogRow>& calibration_log_columns() {
  namespace k = calibration_log_keys;
  using L = CalibrationLogRow;
  const auto joint = [](const L& l) { return calibrated_params(l.e->material); };
  const auto toughness = [](const L& l) { return l.toughness; };
  static const ResultTable<L> table{
      result_value<L>(k::evaluation, "", "the evaluation's number, from 0", [](const L& l) { return l.e->index; }),
      result_number<L>(k::effective_modulus_GPa, units::kGPa, "the contacts' effective modulus",
                       [joint](const L& l) { return joint(l).contact_modulus_Pa; }),
      result_value<L>(k::stiffness_ratio, "", "the joints' normal to shear stiffness ratio",
                      [joint](const L& l) { return joint(l).stiffness_ratio; }),
      result_number<L>(k::tensile_strength_MPa, units::kMPa, "the joints' tensile strength",
                       [joint](const L& l) { return joint(l).tensile_strength_Pa; }),
      result_number<L>(k::cohesion_MPa, units::kMPa, "the joints' cohesion",
                       [joint](const L& l) { return joint(l).cohesion_Pa; }),
      result_number<L>(k::youngs_modulus_GPa, units::kGPa, "what it gives: Young's modulus E",
                       [](const L& l) { return l.e->macro.youngs_modulus_Pa; }),
      result_value<L>(k::poissons_ratio, "", "Poisson's ratio nu",
                      [](const L& l) { return l.e->macro.poissons_ratio; }),
      result_number<L>(k::macro_tensile_strength_MPa, units::kMPa, "the tensile strength",
                       [](const L& l) { return l.e->macro.tensile_strength_Pa; }),
      result_number<L>(k::macro_compressive_strength_MPa, units::kMPa, "the compressive strength",
                       [](const L& l) { return l.e->macro.compressive_strength_Pa; }),
      result_number<L>(k::max_error_percent, units::kPercent, "the largest relative error of the four",
                       [](const L& l) { return l.e->max_relative_error; }),
      result_value<L>(k::wall_time_s, "s",
                      "the evaluation's wall time (one read from a checkpoint: the run's that made it)",
                      [](const L& l) { return l.e->wall_time_s; }),
      result_if(result_value<L>(k::fracture_energy_J_per_m2, "J/m2", "with a toughness target: the joints' G_c",
                                [joint](const L& l) { return joint(l).fracture_energy_J_per_m2; }),
                toughness),
      result_if(result_number<L>(k::macro_fracture_toughness_MPa_sqrt_m, units::kMPaSqrtM, "the beam's K_IC",
                                 [](const L& l) { return l.e->macro.fracture_toughness_Pa_sqrt_m; }),
                toughness),
      result_if(result_number<L>(k::toughness_error_percent, units::kPercent, "K_IC's relative error",
                                 [](const L& l) { return l.e->toughness_error; }),
                toughness)};
  return table;
}

std::string calibrate_keys_markdown() {
  return fields_markdown(calibration_fields()) +
         fields_markdown(material_output_fields(), {"calibrated", false}, false) +
         "| `targets` | - | an object | Yang et al. 2018, Table 2 | the macro-properties to meet "
         "(`calibration.targets`) |\n"
         "| `toughness` | - | an object | none | the fifth test, K_IC on a notched beam (`calibration.toughness`) |\n";
}

std::string calibrate_toughness_keys_markdown() {
  return fields_markdown(beam_fields(), Beam{}) + fields_markdown(toughness_fields(), beam_test_defaults(), false);
}

std::string calibrate_targets_keys_markdown() {
  return fields_markdown(target_fields(), CalibrationSpec{}.targets) +
         fields_markdown(targets_file_fields(), {}, false);
}

}  // namespace kerf::dem::kinds
