// The K9 trepanning validation case (validation/k9_trepanning/, README.md there): Yu et al. 2023's Table 4 against
// the analytic library's Eqs. 21-22 (analytic/trepanning/trepanning.cpp), its acceptance bands and its report.
#include "k9_trepanning.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "kerf/analytic/kinds/material_models.hpp"
#include "kerf/csv_table.hpp"
#include "kerf/error.hpp"
#include "kerf/report.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

const Unit kRpm{"rev/min", "rpm", 1.0 / 60.0};  // SI: rev/s
const Unit kUmPerS{"µm/s", "um_per_s", 1e-6};
const Unit kNewton{"N", "N", 1.0};
const Unit kNewtonMetre{"N·m", "N_m", 1.0};

ComparisonSpec trepanning_spec(const TrepanningTool& tool) {
  ComparisonSpec spec;
  spec.title = "K9 glass, fixed-abrasive trepanning drill: axial force and torque (Yu et al. 2023, Table 4)";
  spec.description = fmt::format(
      "Eqs. 21–22 of Yu et al. (2023) for a diamond trepanning drill of outer diameter {} mm and inner diameter "
      "{} mm, against the measured axial force and torque (each the mean of two tests). The model's two lumped "
      "groups K_F = H tan φ and K_M = H (1 + π tan φ μ / 2) are fitted by least squares (see Calibration).",
      units::m_to_mm(tool.outer_diameter_m), units::m_to_mm(tool.inner_diameter_m));
  spec.conditions = {{"spindle_speed", "Spindle speed n#d0#u", kRpm, true},
                     {"feed_rate", "Feed rate v#df#u", kUmPerS, true}};
  spec.quantities = {{"axial_force", "Axial force F#dn#u", kNewton, {"N/mm", "N_per_mm", 1e3}},
                     {"torque", "Torque M", kNewtonMetre, {"N·m/mm", "N_m_per_mm", 1e3}}};
  spec.relative_tolerance = 1e-6;
  return spec;
}

std::vector<ConditionValue> conditions_of(const TrepanningCut& cut) {
  return {ConditionValue::number(cut.spindle_speed_rev_per_s), ConditionValue::number(cut.feed_rate_m_per_s)};
}

std::string pct(double v) {
  return fmt::format("{:.2f}", v);
}

}  // namespace

std::filesystem::path k9_trepanning_case_directory() {
  return data_directory().parent_path() / "validation" / "k9_trepanning";
}

TrepanningValidation run_k9_trepanning_validation(const std::filesystem::path& out_dir) {
  return run_trepanning_validation(k9_trepanning_case_directory(), out_dir);
}

namespace {

/// validation.json: the scene (into v.scene), the acceptance bands (into v.acceptance), the experiment table,
/// its columns and the residual weighting.
struct CaseInputs {
  CsvTable table;
  std::string speed_col, feed_col, axial_col, torque_col, axial_theory_col, torque_theory_col;
  std::string weighting_name;
  ResidualWeighting weighting = ResidualWeighting::relative;
};

CaseInputs read_case(const std::filesystem::path& case_dir, TrepanningValidation& v) {
  CaseInputs in;
  const Json config = read_json_file((case_dir / "validation.json").string());
  ObjectReader reader(config, "validation");
  v.scene = parse_trepanning_scene(read_json_file((case_dir / reader.get_string("scene")).string()));
  in.table = read_csv_file(case_dir / reader.get_string("experiment"));
  ObjectReader columns = reader.get_object("columns");
  in.speed_col = columns.get_string("spindle_speed_rpm");
  in.feed_col = columns.get_string("feed_rate_um_per_s");
  in.axial_col = columns.get_string("axial_force_measured_N");
  in.torque_col = columns.get_string("torque_measured_N_m");
  in.axial_theory_col = columns.get_string("axial_force_theory_N");
  in.torque_theory_col = columns.get_string("torque_theory_N_m");
  columns.finish();
  in.weighting_name = reader.get_choice_or("weighting", "relative", {"relative", "absolute"});
  in.weighting = in.weighting_name == "relative" ? ResidualWeighting::relative : ResidualWeighting::absolute;
  ObjectReader acceptance = reader.get_object("acceptance");
  v.acceptance.theory_column_max_abs_error_percent =
      acceptance.get_number("theory_column_max_abs_error_percent", Range::positive(), "%");
  ObjectReader fitted = acceptance.get_object("fitted_mean_abs_error_percent");
  v.acceptance.axial_mean_abs_error_percent = fitted.get_number("axial_force", Range::positive(), "%");
  v.acceptance.torque_mean_abs_error_percent = fitted.get_number("torque", Range::positive(), "%");
  fitted.finish();
  acceptance.finish();
  reader.finish();
  return in;
}

/// The acceptance bands that do not hold, as v.failures.
void check_acceptance(TrepanningValidation& v) {
  const auto& acc = v.acceptance;
  struct Band {
    const char* what;
    const char* metric;
    double value_percent, limit_percent;
  };
  const Band bands[] = {
      {"theory column, axial force", "max", v.theory_fit.axial.fit.max_abs_error_percent,
       acc.theory_column_max_abs_error_percent},
      {"theory column, torque", "max", v.theory_fit.torque.fit.max_abs_error_percent,
       acc.theory_column_max_abs_error_percent},
      {"fitted axial force", "mean", v.measured_fit.axial.fit.mean_abs_error_percent, acc.axial_mean_abs_error_percent},
      {"fitted torque", "mean", v.measured_fit.torque.fit.mean_abs_error_percent, acc.torque_mean_abs_error_percent},
  };
  for (const auto& band : bands) {
    if (band.value_percent > band.limit_percent) {
      v.failures.push_back(fmt::format("{}: {} |error| {:.2f} % > {:.2f} %", band.what, band.metric, band.value_percent,
                                       band.limit_percent));
    }
  }
}

/// Measured against the fitted model (with its curve), its leave-one-out predictions and the paper's theory.
Comparison trepanning_comparison(const TrepanningValidation& v, const CaseInputs& in,
                                 const std::vector<TrepanningObservation>& measured_rows,
                                 const std::vector<TrepanningObservation>& theory_rows) {
  const TrepanningTool& tool = v.scene.tool;
  const CsvTable& table = in.table;
  const std::string& weighting_name = in.weighting_name;
  const ComparisonSpec spec = trepanning_spec(tool);
  const WidthBasis wall = WidthBasis::total((tool.outer_diameter_m - tool.inner_diameter_m) / 2.0);
  const std::vector<WidthBasis> bases = {wall, WidthBasis::none()};
  const std::vector<std::string> citations = table.comments;
  const std::string source = std::filesystem::path(table.source).filename().string();
  DataSet measured{"measured (Table 4, mean of two tests)", source, citations, bases, {}};
  DataSet fit{
      "kerf Eqs. 21–22, fitted",
      "",
      {fmt::format("kerf: analytic/trepanning/trepanning.cpp with K_F = {:.4f} GPa and K_M = {:.4f} GPa, fitted "
                   "to the measured rows by {} least squares (GSL gsl_multifit_wlinear)",
                   units::pa_to_gpa(v.measured_fit.groups.axial_group_Pa),
                   units::pa_to_gpa(v.measured_fit.groups.torque_group_Pa), weighting_name)},
      bases,
      {}};
  DataSet loo{"kerf, leave-one-out", "", {"each row predicted with the groups fitted to the other rows"}, bases, {}};
  DataSet paper{"paper's theory (Table 4)",
                source,
                {"the theoretical column of Table 4 (Eqs. 21–22 with the paper's unprinted H, φ, μ)"},
                bases,
                {}};
  for (std::size_t i = 0; i < measured_rows.size(); ++i) {
    const auto cond = conditions_of(measured_rows[i].cut);
    const std::size_t line = table.row_lines[i];
    measured.rows.push_back({cond, {measured_rows[i].axial_force_N, measured_rows[i].torque_N_m}, line});
    fit.rows.push_back({cond, {v.measured_fit.axial.predicted[i], v.measured_fit.torque.predicted[i]}, 0});
    loo.rows.push_back({cond, {v.measured_fit.axial.loo_predicted[i], v.measured_fit.torque.loo_predicted[i]}, 0});
    paper.rows.push_back({cond, {theory_rows[i].axial_force_N, theory_rows[i].torque_N_m}, line});
  }
  const TrepanningGroups groups = v.measured_fit.groups;
  ModelCurve curve = [tool, groups](const std::vector<ConditionValue>& c) {
    const TrepanningCut cut{*c[1].si, *c[0].si};
    const auto f = trepanning_forces(tool, cut, groups);
    return std::vector<double>{f.axial_force_N, f.torque_N_m};
  };
  return compare(spec, measured, {{fit, curve}, {loo, {}}, {paper, {}}});
}

/// The report's calibration section: how the groups are fitted, the weighting and the other weighting's fit.
std::string weighting_markdown(const TrepanningValidation& v, const CaseInputs& in,
                               const std::vector<TrepanningObservation>& measured_rows,
                               const std::vector<double>& m_axial) {
  const ResidualWeighting other =
      in.weighting == ResidualWeighting::relative ? ResidualWeighting::absolute : ResidualWeighting::relative;
  const TrepanningCalibration alternative = calibrate_trepanning(v.scene.tool, measured_rows, other);
  const auto [min_axial, max_axial] = std::minmax_element(m_axial.begin(), m_axial.end());
  return fmt::format(
      "## Calibration\n\n"
      "The model is linear in each lumped group (F_n = (π/8) f (D − d) K_F, M = f (D² − d²) K_M / 16 with f = v_f / "
      "n), "
      "so each group is an exact weighted linear least-squares fit through the origin (GSL `gsl_multifit_wlinear`). "
      "Weighting: **{}** residuals. Relative residuals (weights 1/y²) are kerf's default: the acceptance metric is a "
      "relative error, the measured axial forces span {:.0f}–{:.0f} N, and a dynamometer's scatter grows with the "
      "load; "
      "ordinary (absolute) least squares lets the largest forces dominate. For comparison, {} residuals give "
      "K_F = {:.4f} GPa and K_M = {:.4f} GPa, with mean |error| {} % (axial) and {} % (torque).\n\n",
      in.weighting_name, *min_axial, *max_axial, residual_weighting_name(other),
      units::pa_to_gpa(alternative.groups.axial_group_Pa), units::pa_to_gpa(alternative.groups.torque_group_Pa),
      pct(alternative.axial.fit.mean_abs_error_percent), pct(alternative.torque.fit.mean_abs_error_percent));
}

/// The fitted groups (measured rows and theory column) with their errors, and the paper's theory column's.
std::string groups_markdown(const TrepanningValidation& v) {
  std::string md =
      "| group | fitted to | value (GPa) | standard error (GPa) | mean abs error (%) | max abs error (%) | bias (%) | "
      "LOO mean abs error (%) | LOO max abs error (%) | LOO bias (%) |\n|---|---|---|---|---|---|---|---|---|---|\n";
  const auto row = [&](const char* name, const char* to, const GroupFit& g) {
    md += fmt::format("| {} | {} | {:.4f} | {:.4f} | {} | {} | {:+.2f} | {} | {} | {:+.2f} |\n", name, to,
                      units::pa_to_gpa(g.value_Pa), units::pa_to_gpa(g.standard_error_Pa),
                      pct(g.fit.mean_abs_error_percent), pct(g.fit.max_abs_error_percent), g.fit.bias_percent,
                      pct(g.loo.mean_abs_error_percent), pct(g.loo.max_abs_error_percent), g.loo.bias_percent);
  };
  row("K_F = H tan φ", "measured axial force", v.measured_fit.axial);
  row("K_M = H (1 + π tan φ μ / 2)", "measured torque", v.measured_fit.torque);
  row("K_F", "paper's theory column", v.theory_fit.axial);
  row("K_M", "paper's theory column", v.theory_fit.torque);
  md += fmt::format(
      "\nThe paper's theory column against the measured rows: axial mean |error| {} % (max {} %), torque {} % "
      "(max {} %) — the paper quotes 5.0 % and 6.7 %.\n\n",
      pct(v.paper_axial.mean_abs_error_percent), pct(v.paper_axial.max_abs_error_percent),
      pct(v.paper_torque.mean_abs_error_percent), pct(v.paper_torque.max_abs_error_percent));
  return md;
}

/// What each fit's groups imply for the half angle and friction at the material's hardness, and for the hardness
/// at φ = 60°.
std::string implied_markdown(const TrepanningValidation& v) {
  std::string md = "What the groups imply (only K_F and K_M are identifiable from forces):\n\n";
  const auto implied = [&](const char* which, const ImpliedTrepanningMaterial& m, const TrepanningGroups& g) {
    md += fmt::format(
        "- {}: with H = {:.2f} GPa (material `{}`, brittle.hardness_GPa) the groups imply φ = {:.1f}° and μ = "
        "{:.3f}{}. "
        "Non-negative friction needs H ≤ K_M = {:.2f} GPa; with φ = 60° they imply H = {:.2f} GPa and μ = {:.3f}.\n",
        which, units::pa_to_gpa(m.hardness_Pa), v.scene.material.name, units::rad_to_deg(m.half_angle_rad),
        m.friction_coefficient, m.physical ? "" : " (negative: not physical)",
        units::pa_to_gpa(m.max_hardness_for_non_negative_friction_Pa),
        units::pa_to_gpa(g.axial_group_Pa / std::sqrt(3.0)),
        implied_trepanning_material(g, g.axial_group_Pa / std::sqrt(3.0)).friction_coefficient);
  };
  implied("Fitted to the measured rows", v.implied_measured, v.measured_fit.groups);
  implied("Fitted to the paper's theory column", v.implied_theory, v.theory_fit.groups);
  return md;
}

/// Each row's groups fitted without it and its leave-one-out error (the header in PLplot's escapes, as the plots').
std::string leave_one_out_markdown(const TrepanningValidation& v,
                                   const std::vector<TrepanningObservation>& measured_rows) {
  const auto& mf = v.measured_fit;
  std::string md =
      "\n### Leave-one-out\n\n| n#d0#u (rev/min) | v#df#u (µm/s) | K_F without the row (GPa) | axial LOO error (%) | "
      "K_M without the row (GPa) | torque LOO error (%) |\n|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < measured_rows.size(); ++i) {
    md += fmt::format("| {:.4g} | {:.4g} | {:.4f} | {:+.2f} | {:.4f} | {:+.2f} |\n",
                      measured_rows[i].cut.spindle_speed_rev_per_s * 60.0,
                      units::m_to_um(measured_rows[i].cut.feed_rate_m_per_s),
                      units::pa_to_gpa(mf.axial.loo_value_Pa[i]), mf.axial.loo_error_percent[i],
                      units::pa_to_gpa(mf.torque.loo_value_Pa[i]), mf.torque.loo_error_percent[i]);
  }
  return md;
}

/// The acceptance bands, the values they judge and the verdict with the failures.
std::string acceptance_markdown(const TrepanningValidation& v) {
  const auto& acc = v.acceptance;
  const auto& mf = v.measured_fit;
  const auto& tf = v.theory_fit;
  std::string failures;
  for (const auto& f : v.failures) failures += (failures.empty() ? "" : "; ") + f;
  return fmt::format(
      "\n## Acceptance\n\n- theory column reproduced by one value of each group within {:.1f} %: axial max {} %, "
      "torque max {} %\n- fitted to the measured rows, mean |error| at most {:.1f} % (axial) and {:.1f} % (torque): "
      "{} % and {} %\n\n**{}**{}\n",
      acc.theory_column_max_abs_error_percent, pct(tf.axial.fit.max_abs_error_percent),
      pct(tf.torque.fit.max_abs_error_percent), acc.axial_mean_abs_error_percent, acc.torque_mean_abs_error_percent,
      pct(mf.axial.fit.mean_abs_error_percent), pct(mf.torque.fit.mean_abs_error_percent),
      v.passed() ? "PASSED" : "FAILED", v.passed() ? "" : ": " + failures);
}

/// The report's calibration, leave-one-out and acceptance sections (Markdown).
std::string calibration_markdown(const TrepanningValidation& v, const CaseInputs& in,
                                 const std::vector<TrepanningObservation>& measured_rows,
                                 const std::vector<double>& m_axial) {
  std::string md = weighting_markdown(v, in, measured_rows, m_axial) + groups_markdown(v) + implied_markdown(v) +
                   leave_one_out_markdown(v, measured_rows) + acceptance_markdown(v);
  // The LOO table header used PLplot escapes; plain text here.
  for (const char* escape : {"#d", "#u"}) {
    for (auto at = md.find(escape); at != std::string::npos; at = md.find(escape)) md.erase(at, 2);
  }
  return md;
}

/// summary.json's calibration and acceptance.
Json calibration_summary(const TrepanningValidation& v, const std::string& weighting_name) {
  const auto& mf = v.measured_fit;
  const auto& tf = v.theory_fit;
  const auto& acc = v.acceptance;
  const auto fit_json = [](const GroupFit& g) {
    return Json{{"value_MPa", units::pa_to_mpa(g.value_Pa)},
                {"standard_error_MPa", units::pa_to_mpa(g.standard_error_Pa)},
                {"fit",
                 {{"n", g.fit.n},
                  {"mean_abs_error_percent", g.fit.mean_abs_error_percent},
                  {"max_abs_error_percent", g.fit.max_abs_error_percent},
                  {"bias_percent", g.fit.bias_percent}}},
                {"leave_one_out",
                 {{"n", g.loo.n},
                  {"mean_abs_error_percent", g.loo.mean_abs_error_percent},
                  {"max_abs_error_percent", g.loo.max_abs_error_percent},
                  {"bias_percent", g.loo.bias_percent},
                  {"error_percent", g.loo_error_percent}}}};
  };
  const auto implied_json = [](const ImpliedTrepanningMaterial& m) {
    return Json{
        {"hardness_GPa", units::pa_to_gpa(m.hardness_Pa)},
        {"half_angle_deg", units::rad_to_deg(m.half_angle_rad)},
        {"friction_coefficient", m.friction_coefficient},
        {"physical", m.physical},
        {"max_hardness_for_non_negative_friction_GPa", units::pa_to_gpa(m.max_hardness_for_non_negative_friction_Pa)}};
  };
  return {{"calibration",
           {{"weighting", weighting_name},
            {"measured",
             {{"axial_group", fit_json(mf.axial)},
              {"torque_group", fit_json(mf.torque)},
              {"implied", implied_json(v.implied_measured)}}},
            {"theory_column",
             {{"axial_group", fit_json(tf.axial)},
              {"torque_group", fit_json(tf.torque)},
              {"implied", implied_json(v.implied_theory)}}}}},
          {"acceptance",
           {{"theory_column_max_abs_error_percent", acc.theory_column_max_abs_error_percent},
            {"fitted_mean_abs_error_percent",
             {{"axial_force", acc.axial_mean_abs_error_percent}, {"torque", acc.torque_mean_abs_error_percent}}},
            {"passed", v.passed()},
            {"failures", v.failures}}}};
}

}  // namespace

TrepanningValidation run_trepanning_validation(const std::filesystem::path& case_dir,
                                               const std::filesystem::path& out_dir) {
  TrepanningValidation v;
  const CaseInputs in = read_case(case_dir, v);
  const CsvTable& table = in.table;

  // The rows, measured and the paper's theory.
  std::vector<TrepanningObservation> measured_rows, theory_rows;
  const std::size_t c_speed = table.column_index(in.speed_col), c_feed = table.column_index(in.feed_col),
                    c_axial = table.column_index(in.axial_col), c_torque = table.column_index(in.torque_col),
                    c_axial_theory = table.column_index(in.axial_theory_col),
                    c_torque_theory = table.column_index(in.torque_theory_col);
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto cut = TrepanningCut::from_user_units(table.number(r, c_feed), table.number(r, c_speed));
    measured_rows.push_back({cut, table.number(r, c_axial), table.number(r, c_torque)});
    theory_rows.push_back({cut, table.number(r, c_axial_theory), table.number(r, c_torque_theory)});
  }

  v.measured_fit = calibrate_trepanning(v.scene.tool, measured_rows, in.weighting);
  v.theory_fit = calibrate_trepanning(v.scene.tool, theory_rows, in.weighting);
  std::vector<double> m_axial, m_torque, t_axial, t_torque;
  for (std::size_t i = 0; i < measured_rows.size(); ++i) {
    m_axial.push_back(measured_rows[i].axial_force_N);
    m_torque.push_back(measured_rows[i].torque_N_m);
    t_axial.push_back(theory_rows[i].axial_force_N);
    t_torque.push_back(theory_rows[i].torque_N_m);
  }
  v.paper_axial = error_metrics(t_axial, m_axial);
  v.paper_torque = error_metrics(t_torque, m_torque);
  v.scene.material.require_group("brittle", "material", "the implied half angle and friction");
  const double hardness_Pa = brittle_group_from_material(v.scene.material, "material").hardness_Pa.value();
  v.implied_measured = implied_trepanning_material(v.measured_fit.groups, hardness_Pa);
  v.implied_theory = implied_trepanning_material(v.theory_fit.groups, hardness_Pa);

  check_acceptance(v);
  if (out_dir.empty()) return v;

  ReportOptions options;
  options.extra_markdown = calibration_markdown(v, in, measured_rows, m_axial);
  options.extra_summary = calibration_summary(v, in.weighting_name);
  v.files = write_report(trepanning_comparison(v, in, measured_rows, theory_rows), out_dir, options);
  return v;
}

}  // namespace kerf
