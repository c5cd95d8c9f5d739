// Scene kind "calibrate_cut": the bond-strength factor s (kerf/dem/procedures/cut_calibration.hpp) fitted so that the
// mean main force over `replicates` packings meets a measured one. Evaluation k runs its replicates in
// OUT/evaluation_k/ (as --replicates does); rerunning the same command after a kill reuses every finished
// replicate, and the factors that follow are the same (each is computed from the same forces, to the bit).
#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <iostream>

#include "common.hpp"
#include "kerf/dem/procedures/cut_calibration.hpp"
#include "kerf/dem/procedures/cut_results.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"
#include "kind_results.hpp"

namespace kerf::dem::kinds {

namespace {

/// The "calibration" section of a calibrate_cut scene (besides material_name and install_material).
struct CutFit {
  double target_main_force_N = 0;
  std::string target_source;
  int replicates = 3;
  double tolerance = 0.10;
  int max_evaluations = 4;
  double start_factor = 1;
};

const FieldTable<CutFit>& cut_fit_fields() {
  static const FieldTable<CutFit> table{
      required_number_field("target_cutting_force_N", units::kSi("N"), Range::positive(),
                            "the measured mean cutting force to meet (its old name target_main_force_N is read too, "
                            "deprecated until 0.3.0)",
                            &CutFit::target_main_force_N),
      int_field("replicates", 2, 64, "packings per evaluation (seeds specimen.seed + 0, 1, ...)", &CutFit::replicates),
      number_field("tolerance_percent", units::kPercent, Range::open(0.0, 100.0),
                   "relative error of the mean main force for convergence", &CutFit::tolerance),
      int_field("max_evaluations", 1, 50, "evaluations (each `replicates` cuts)", &CutFit::max_evaluations),
      number_field("start_strength_factor", units::kNone, Range::positive(), "the first evaluation's factor s",
                   &CutFit::start_factor),
      text_field("target_source", "where the target comes from (in the fitted material's description)",
                 &CutFit::target_source)};
  return table;
}

/// The calibration section, its target_main_force_N (target_cutting_force_N's old name, issue 55 item 5; deprecated,
/// removed in 0.3.0) renamed, with a warning; its value is checked under the name the user wrote.
Json calibration_section(ObjectReader& root) {
  const std::string old_key = "target_main_force_N", new_key = "target_cutting_force_N";
  ObjectReader cal = root.get_object("calibration");
  Json section = root.get("calibration");
  if (!cal.has(old_key)) return section;
  if (cal.has(new_key))
    throw InputError(cal.key_path(old_key), json_value_text(section[old_key]),
                     "no value beside calibration." + new_key + " (its old name)");
  cal.get_number(old_key, Range::positive(), "N");
  std::cerr << "kerf-dem: warning: calibration." << old_key << " is deprecated (removed in 0.3.0): call it calibration."
            << new_key << "\n";
  section[new_key] = section[old_key];
  section.erase(old_key);
  return section;
}

class CalibrateCutKind final : public SceneKind {
 public:
  std::string name() const override { return "calibrate_cut"; }
  void read(ObjectReader& root, const SceneCommon&) override {
    cut_ = read_cut_params(root);
    const Json section = calibration_section(root);
    ObjectReader cal(section, root.key_path("calibration"));
    fit_ = read_fields(cal, cut_fit_fields(), fit_);
    output_ = read_material_output(cal, "cut_calibrated");
    cal.finish();
  }

  void check_options(const RunOptions& options, const SceneCommon& common) const override {
    if (options.checkpoint_every > 0)
      throw InputError("--checkpoint-every", std::to_string(options.checkpoint_every),
                       "no checkpoints for calibrate_cut (rerun the command: finished replicates are reused)");
    if (common.specimen_file)
      throw InputError(
          "specimen.file", *common.specimen_file,
          "a scene that generates its specimen (calibrate_cut runs replicates on packings specimen.seed + k)");
    SceneKind::check_options(options, common);
  }

  // Long (~100 lines) for a reason: the fit's loop (each evaluation a replicate cut with the scaled material), its
  // log and the fitted material's files share the loop's state, written in the order the files are.
  SceneOutcome run(const SceneCommon& common, const SceneRun& run) override {
    const fs::path& out = run.options.out;
    const auto start = std::chrono::steady_clock::now();
    const auto& fit = fit_;
    std::vector<CutCalibrationPoint> history;
    std::vector<CutCalibrationEvaluation> rows;
    Json evaluations = Json::array();
    // The replicated cut's results each evaluation reads and keeps (cut_results.hpp).
    const std::string main_N(cut_keys::main_force_N), thrust_N(cut_keys::thrust_force_N);
    const std::string main_std = replicate_spread_key(main_N), thrust_std = replicate_spread_key(thrust_N);
    std::string log = results_csv_header(calibrate_cut_log_columns());
    double s = fit.start_factor;
    std::size_t best = 0;
    bool converged = false;
    for (int k = 1; k <= fit.max_evaluations && !converged; ++k) {
      if (k > 1) s = next_strength_factor(history, fit.target_main_force_N);
      SceneCommon e = common;
      e.material =
          scale_bond_strengths(common.material, s, fmt::format("{}_bond_strength_x{:.6g}", common.material.name, s));
      const fs::path dir = out / fmt::format("evaluation_{}", k);
      fs::create_directories(dir);
      std::cout << fmt::format(
                       "evaluation {}: bond strengths x {:.4g} (joint tensile strength {:.2f} MPa, joint "
                       "cohesion {:.2f} MPa), {} replicates\n",
                       k, s, units::pa_to_mpa(calibrated_params(e.material).tensile_strength_Pa),
                       units::pa_to_mpa(calibrated_params(e.material).cohesion_Pa), fit.replicates)
                << std::flush;
      // The evaluation's cut: this scene as a cut with the scaled material, as its file will hold it.
      Json scene = run.doc;
      scene.erase("calibration");
      scene["kind"] = "cut";
      scene["material"] = material_to_json(e.material);
      e.material = read_material(scene["material"], "material");
      RunOptions options = run.options;
      options.out = dir;
      options.provenance = Json();  // an evaluation's summary carries none: the calibration's is the run's
      const Json done =
          run_cut_replicates(scene, run.scene_dir, cut_, fit.replicates, summary_head("cut", e.material), options)
              .summary;
      const Json& r = done["results"];
      const double force = r[main_N].get<double>();
      const double error = force / fit.target_main_force_N - 1;
      history.push_back({s, force});
      if (std::abs(error) < std::abs(history[best].main_force_N / fit.target_main_force_N - 1))
        best = history.size() - 1;
      converged = std::abs(error) <= fit.tolerance;
      const CalibratedParams joint = calibrated_params(e.material);
      rows.push_back({k, s, joint.tensile_strength_Pa, joint.cohesion_Pa, force, r[main_std].get<double>(),
                      r[thrust_N].get<double>(), r[thrust_std].get<double>(), error, dir.filename().string(),
                      done["wall_time_s"].get<double>()});
      evaluations.push_back(results_to_json(calibrate_cut_evaluation_results(), rows.back()));
      log += results_csv_row(calibrate_cut_log_columns(), rows.back());
      write_file_atomically(out / "calibration_log.csv", log);
      std::cout << fmt::format("evaluation {}: main force {:.4g} N against {:.4g} N ({:+.1f} %, tolerance {:.0f} %)\n",
                               k, force, fit.target_main_force_N, 100 * error, 100 * fit.tolerance)
                << std::flush;
    }
    const CutCalibrationPoint& b = history[best];
    Material named = scale_bond_strengths(common.material, b.strength_factor, output_.name);
    named.name = output_.name;  // factor 1 keeps the base's name
    const double sem = rows[best].main_force_spread_N / std::sqrt(fit.replicates);
    const std::string description = fmt::format(
        "{} with both bond strengths (joint tensile strength and cohesion) x {:.4g}, fitted by kerf-dem calibrate_cut "
        "to a mean main force of {:.4g} N{} ({} evaluations, {}converged: {:.4g} +- {:.2g} N, mean +- standard error "
        "over {} packings) on the cut: depth {:g} mm, speed {:g} m/s, travel {:g} mm, rake {:g} deg, grooves {}. The "
        "macro strengths scale by the same factor (exact trend), E and nu are those of the base material.",
        common.material.name, b.strength_factor, fit.target_main_force_N,
        fit.target_source.empty() ? "" : " (" + fit.target_source + ")", history.size(), converged ? "" : "NOT ",
        b.main_force_N, sem, fit.replicates, units::m_to_mm(cut_.cut.depth_of_cut_m), cut_.cut.speed_m_per_s,
        units::m_to_mm(cut_.cut.length_m), cut_.tool.rake_deg, groove_shape_names().name(cut_.grooves.shape));
    const Json material = library_material_json(named, "Flat-joint DEM material fitted to one measured cut by kerf-dem",
                                                description, "kerf-dem calibrate_cut (see description)");
    Json summary = summary_head(name(), common.material);
    summary["cut"] = cut_params_to_json(cut_);
    write_material_output(output_, material, out, summary);
    summary["results"] = results_to_json(calibrate_cut_results(), {converged, fit.target_main_force_N,
                                                                   fit.target_source, b, sem, evaluations, material});
    name_cut_forces(summary["results"]);
    for (auto& e : summary["results"][calibrate_cut_keys::evaluations]) name_cut_forces(e);
    summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_summary(run.options, run.doc, summary);
    std::cout << fmt::format(
        "cut calibration {} after {} evaluations: bond strengths x {:.4g}, main force {:.4g} +- {:.2g} N "
        "against {:.4g} N -> {}\n",
        converged ? "converged" : "did NOT converge", history.size(), b.strength_factor, b.main_force_N, sem,
        fit.target_main_force_N, (out / (output_.name + ".json")).string());
    return {converged ? 0 : kExitModelError, summary, {}};
  }

 private:
  CutParams cut_;
  CutFit fit_;
  MaterialOutput output_;
};

}  // namespace

const ResultTable<CalibrateCutReport>& calibrate_cut_results() {
  namespace k = calibrate_cut_keys;
  using R = CalibrateCutReport;
  static const ResultTable<R> table{
      result_value<R>(k::converged, "", "whether the best evaluation's main force is within the tolerance",
                      [](const R& c) { return c.converged; }),
      result_value<R>(k::target_cutting_force_N, "N",
                      "the measured main force fitted to (calibration.target_main_force_N)",
                      [](const R& c) { return c.target_main_force_N; }),
      result_value<R>(k::target_main_force_N, "N", "target_cutting_force_N's old name (deprecated, until 0.3.0)",
                      [](const R& c) { return c.target_main_force_N; }),
      result_value<R>(k::target_source, "", "where the target comes from", [](const R& c) { return c.target_source; }),
      result_value<R>(k::strength_factor, "", "the best factor of both bond strengths",
                      [](const R& c) { return c.best.strength_factor; }),
      result_value<R>(cut_keys::main_force_N, "N", "the best evaluation's mean main force over its replicates",
                      [](const R& c) { return c.best.main_force_N; }),
      result_value<R>(k::main_force_standard_error_N, "N", "its standard error (replicate std / sqrt(n))",
                      [](const R& c) { return c.sem; }),
      result_value<R>(k::relative_error_percent, "%", "its relative error against the target",
                      [](const R& c) { return 100 * (c.best.main_force_N / c.target_main_force_N - 1); }),
      result_value<R>(k::evaluations, "", "each evaluation's row (a list; its keys below)",
                      [](const R& c) { return c.evaluations; }),
      result_value<R>(k::calibrated_material, "", "the calibrated material (as its file holds it)",
                      [](const R& c) { return c.material; })};
  return table;
}

const ResultTable<CutCalibrationEvaluation>& calibrate_cut_evaluation_results() {
  namespace k = cut_calibration_keys;
  using E = CutCalibrationEvaluation;
  static const ResultTable<E> table{
      result_value<E>(k::evaluation, "", "the evaluation's number, from 1", [](const E& e) { return e.evaluation; }),
      result_value<E>(k::strength_factor, "", "the factor s of both bond strengths",
                      [](const E& e) { return e.strength_factor; }),
      result_number<E>(k::tensile_strength_MPa, units::kMPa, "the joints' tensile strength, scaled",
                       [](const E& e) { return e.tensile_strength_Pa; }),
      result_number<E>(k::cohesion_MPa, units::kMPa, "the joints' cohesion, scaled",
                       [](const E& e) { return e.cohesion_Pa; }),
      result_value<E>(cut_keys::main_force_N, "N", "the mean main force over the replicates",
                      [](const E& e) { return e.main_force_N; }),
      result_value<E>(replicate_spread_key(cut_keys::main_force_N), "N", "its spread over the replicates",
                      [](const E& e) { return e.main_force_spread_N; }),
      result_value<E>(cut_keys::thrust_force_N, "N", "the mean thrust force over the replicates",
                      [](const E& e) { return e.thrust_force_N; }),
      result_value<E>(replicate_spread_key(cut_keys::thrust_force_N), "N", "its spread over the replicates",
                      [](const E& e) { return e.thrust_force_spread_N; }),
      result_value<E>(k::relative_error_percent, "%", "the mean main force's relative error against the target",
                      [](const E& e) { return 100 * e.relative_error; }),
      result_value<E>(k::directory, "", "the evaluation's replicates: evaluation_k/ in the run's directory",
                      [](const E& e) { return e.directory; })};
  return table;
}

const ResultTable<CutCalibrationEvaluation>& calibrate_cut_log_columns() {
  using E = CutCalibrationEvaluation;
  static const ResultTable<E> table = [] {
    ResultTable<E> columns;
    for (const auto& f : calibrate_cut_evaluation_results())
      if (f.key != cut_calibration_keys::directory) columns.push_back(f);
    columns.push_back(result_value<E>(cut_calibration_keys::wall_time_s, "s", "the evaluation's wall time",
                                      [](const E& e) { return e.wall_time_s; }));
    return columns;
  }();
  return table;
}

std::unique_ptr<SceneKind> make_calibrate_cut_kind() {
  return std::make_unique<CalibrateCutKind>();
}

}  // namespace kerf::dem::kinds

namespace kerf::dem::kinds {

std::string calibrate_cut_keys_markdown() {
  return fields_markdown(cut_fit_fields()) +
         fields_markdown(material_output_fields(), {"cut_calibrated", false}, false);
}

}  // namespace kerf::dem::kinds
