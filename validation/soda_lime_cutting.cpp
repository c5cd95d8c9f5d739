// Seed 000's orthogonal cutting of soda-lime glass (validation/soda_lime_cutting/): runs every condition of
// validation.json with kerf-dem (replicates on different packings), collects the forces, compares them through
// the report layer with the experiments (Table 6, 25.4 mm wide) and the paper's DEM (Table 4, 1 mm), and checks
// the acceptance bands where validation.json gives them. See validation/soda_lime_cutting/README.md. (The
// steady-state case's acceptance is the seed-000 study's record, validation/soda_lime_cutting_steady/trends.py.)
#include "soda_lime_cutting.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <optional>

#include "kerf/comparison_config.hpp"
#include "kerf/dem/procedures/cut_results.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/dem/study/study.hpp"
#include "kerf/error.hpp"
#include "kerf/interval95.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/material.hpp"
#include "kerf/metrics.hpp"
#include "kerf/time_series.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace fs = std::filesystem;

namespace {

/// The cut's results as this validation reads and writes them: by their names in the cut's result table.
namespace k = dem::cut_keys;

struct Condition {
  std::string name, surface, groove_shape;
  double depth_of_cut_mm = 0;
};

/// Packings per condition, in validation.json or from --replicates: at least two for a sample standard deviation.
constexpr int kMinReplicates = 2, kMaxReplicates = 100;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Spec {
  fs::path scene, experiments;
  std::string note;    ///< printed under the report's title (e.g. what a fitted material was fitted to)
  int replicates = 3;  ///< packings per condition
  std::vector<Condition> conditions;
  /// Whether validation.json gives pass/fail bands (the fitted case's); without them the case is a reproduction
  /// of the paper's method, reported without a verdict of its own.
  bool bands = false;
  double regular_max_error_percent = 20, grooved_ratio_max = 1.0 / 3;
  /// The regular-workpiece force the material was fitted to (depth 0: none): its check is reported as
  /// FITTED, neither passed nor failed, since meeting it shows the fit, not the model.
  double fitted_depth_of_cut_mm = 0;
  std::string fitted_force;  ///< "main" or "thrust"
};

Spec read_spec(const fs::path& case_dir) {
  const Json doc = read_json_file(case_dir / "validation.json");
  ObjectReader r(doc, "validation");
  Spec s;
  s.scene = case_dir / r.get_string("scene");
  s.experiments = case_dir / r.get_string("experiments");
  s.note = r.get_string_or("note", "");
  s.replicates = r.get_int_or("replicates", 3, kMinReplicates, kMaxReplicates);
  const Json& list = r.get("conditions");
  if (!list.is_array() || list.empty())
    throw InputError("validation.conditions", list.dump(), "a non-empty list of conditions");
  for (std::size_t k = 0; k < list.size(); ++k) {
    ObjectReader c(list[k], fmt::format("validation.conditions[{}]", k));
    Condition cond{c.get_string("name"), c.get_choice("surface", {"regular", "grooved", "grooved_trapezoidal"}),
                   c.get_choice("groove_shape", {"none", "rectangular", "trapezoidal"}),
                   c.get_number("depth_of_cut_mm", Range::positive(), "mm")};
    c.finish();
    s.conditions.push_back(cond);
  }
  ObjectReader a = r.get_object("acceptance");
  if (a.has("regular_force_max_abs_error_vs_paper_dem_percent") || a.has("grooved_to_regular_main_force_ratio_max") ||
      a.has("fitted")) {
    s.bands = true;
    s.regular_max_error_percent =
        a.get_number("regular_force_max_abs_error_vs_paper_dem_percent", Range::positive(), "%");
    s.grooved_ratio_max = a.get_number("grooved_to_regular_main_force_ratio_max", Range::positive(), "");
    if (auto fitted = a.find_object("fitted")) {
      s.fitted_depth_of_cut_mm = fitted->get_number("depth_of_cut_mm", Range::positive(), "mm");
      s.fitted_force = fitted->get_choice("force", {"main", "thrust"});
      fitted->finish();
    }
  }
  a.finish();
  r.finish();
  return s;
}

std::string quoted(const fs::path& p) {
  std::string out = "'";
  for (char ch : p.string()) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

/// A mean with its standard error and the degrees of freedom of that error (n - 1 for the spread between n
/// packings; infinite for a reference without one).
struct Estimate {
  double value = 0, standard_error = 0;
  double degrees_of_freedom = std::numeric_limits<double>::infinity();
};

/// The ratio of two independent estimates, its standard error propagated to first order:
/// se(a / b) = (a / b) hypot(se_a / a, se_b / b), and its degrees of freedom by Welch-Satterthwaite on the two
/// relative variances: (v_a + v_b)^2 / (v_a^2 / df_a + v_b^2 / df_b).
Estimate ratio_of(const Estimate& a, const Estimate& b) {
  const double r = a.value / b.value;
  const double va = std::pow(a.standard_error / a.value, 2), vb = std::pow(b.standard_error / b.value, 2);
  const double spread = va * va / a.degrees_of_freedom + vb * vb / b.degrees_of_freedom;
  const double df = spread > 0 ? (va + vb) * (va + vb) / spread : std::numeric_limits<double>::infinity();
  return {r, r * std::hypot(a.standard_error / a.value, b.standard_error / b.value), df};
}

/// The per-replicate columns of kerf_dem_replicates.csv after the condition's: each a result of the item's
/// summary.json, but wall_time_s (the cut's own, genesis excluded; a reused item keeps that of the run that
/// made it).
const std::vector<std::string> kReplicateColumns{std::string(k::width_mm),
                                                 std::string(k::main_force_N),
                                                 std::string(k::thrust_force_N),
                                                 std::string(k::cracks_tensile),
                                                 std::string(k::cracks_shear),
                                                 std::string(k::cracks_chip),
                                                 std::string(k::cracks_subsurface),
                                                 std::string(k::subsurface_damage_depth_um),
                                                 std::string(k::cracks_subsurface_steady),
                                                 std::string(k::subsurface_damage_depth_steady_um),
                                                 "wall_time_s"};

/// Replicate results of one condition, from its study items' summaries.
struct ConditionResult {
  Condition condition;
  Json replicates;  ///< one row per replicate: replicate, seed and kReplicateColumns
  double main_N = 0, thrust_N = 0, main_std_N = 0, thrust_std_N = 0, width_mm = 1;
  /// The mean forces with their standard errors over the replicates (packings are independent samples): sample
  /// std / sqrt(n), n - 1 degrees of freedom.
  int n() const { return static_cast<int>(replicates.size()); }
  Estimate main() const { return {main_N, main_std_N / std::sqrt(n()), n() - 1.0}; }
  Estimate thrust() const { return {thrust_N, thrust_std_N / std::sqrt(n()), n() - 1.0}; }
  double cracks_tensile = 0, cracks_shear = 0, cracks_chip = 0, cracks_subsurface = 0, subsurface_depth_um = 0;
  /// Under the surface machined during the steady part (kerf-dem's *_steady results): the cut's own damage.
  double cracks_subsurface_steady = 0, subsurface_steady_depth_um = 0;
  double wall_time_s = 0;  ///< the replicates' own cut times, summed (a rerun that reuses them all takes ~0 s)
  std::vector<fs::path> directories;  ///< each replicate's run, relative to the validation's output directory
};

ConditionResult collect(const Condition& c, const std::vector<Json>& items) {
  ConditionResult r;
  r.condition = c;
  r.replicates = Json::array();
  std::vector<double> main, thrust;
  const double n = static_cast<double>(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Json& res = items[k].at("results");
    const Json& item = items[k].at("study_item");
    Json row{{"replicate", k + 1}, {"seed", item.at("seed")}};
    for (const auto& column : kReplicateColumns)
      row[column] = column == "wall_time_s" ? items[k].at("wall_time_s") : res.at(column);
    const auto value = [&row](std::string_view result) { return row.at(result).get<double>(); };
    main.push_back(value(k::main_force_N));
    thrust.push_back(value(k::thrust_force_N));
    r.cracks_tensile += value(k::cracks_tensile) / n;
    r.cracks_shear += value(k::cracks_shear) / n;
    r.cracks_chip += value(k::cracks_chip) / n;
    r.cracks_subsurface += value(k::cracks_subsurface) / n;
    r.subsurface_depth_um += value(k::subsurface_damage_depth_um) / n;
    r.cracks_subsurface_steady += value(k::cracks_subsurface_steady) / n;
    r.subsurface_steady_depth_um += value(k::subsurface_damage_depth_steady_um) / n;
    r.wall_time_s += row.at("wall_time_s").get<double>();
    r.replicates.push_back(row);
  }
  const SampleStatistics m = sample_statistics(main), t = sample_statistics(thrust);
  r.main_N = m.mean, r.main_std_N = m.standard_deviation;
  r.thrust_N = t.mean, r.thrust_std_N = t.standard_deviation;
  r.width_mm = r.replicates.at(0).at(k::width_mm).get<double>();
  return r;
}

/// The group of one condition (surface, depth of cut) in a comparison's result for `key` ("main_force",
/// "main_force_per_width", ...): the report layer's means of the replicates, SI in that view's basis.
const GroupComparison& group_of(const Comparison& comparison, const std::string& key, const std::string& surface,
                                double depth_mm) {
  const std::vector<ConditionValue> wanted{ConditionValue::label(surface),
                                           ConditionValue::number(units::mm_to_m(depth_mm))};
  for (const auto& g : comparison.result(key).groups)
    if (conditions_match(g.conditions, wanted, 1e-6)) return g;
  throw InputError("validation.experiments", fmt::format("{} {} mm", surface, depth_mm), "rows for this condition");
}

/// The measured side's mean of one condition in a comparison (the experiments in vs_experiment, the paper's DEM in
/// vs_paper_dem), SI in the basis of the result `key`.
double reference_mean(const Comparison& comparison, const std::string& key, const std::string& surface,
                      double depth_mm) {
  return group_of(comparison, key, surface, depth_mm).measured_stats.mean;
}

/// The condition tables' reference cells: the paper's DEM main / thrust (N, 1 mm), the experiment's (N, 25.4 mm)
/// and the experiment's per 1 mm of width; "—" for trapezoidal grooves, which neither has.
struct ReferenceCells {
  std::string paper = "—", experiment = "—", per_mm = "—";
};

ReferenceCells reference_cells(const Condition& c, const Comparison& vs_experiment, const Comparison& vs_dem) {
  ReferenceCells cells;
  if (c.groove_shape == "trapezoidal") return cells;
  const auto pair = [&](const Comparison& comparison, const std::string& suffix, double scale, const char* format) {
    return fmt::format(fmt::runtime(format),
                       scale * reference_mean(comparison, "main_force" + suffix, c.surface, c.depth_of_cut_mm),
                       scale * reference_mean(comparison, "thrust_force" + suffix, c.surface, c.depth_of_cut_mm));
  };
  cells.paper = pair(vs_dem, "", 1, "{:.2f} / {:.2f}");
  cells.experiment = pair(vs_experiment, "", 1, "{:.2f} / {:.2f}");
  // The per-unit-width view is in N/m: per 1 mm of width is 1e-3 of it.
  cells.per_mm = pair(vs_experiment, "_per_width", 1e-3, "{:.3f} / {:.3f}");
  return cells;
}

Json comparison_document(const fs::path& experiments, const fs::path& kerf_csv, const std::string& title,
                         bool against_paper_dem) {
  const Json conditions =
      Json::array({Json{{"key", "surface"}, {"label", "Surface"}, {"text", true}},
                   Json{{"key", "depth_of_cut"}, {"label", "Depth of cut a#dc#u"}, {"unit", "mm"}}});
  const Json quantities = Json::array({Json{{"key", "main_force"}, {"label", "Main force F#dc#u"}, {"unit", "N"}},
                                       Json{{"key", "thrust_force"}, {"label", "Thrust force F#dt#u"}, {"unit", "N"}}});
  const Json columns{{"surface", "surface"},
                     {"depth_of_cut", "depth_of_cut_mm"},
                     {"main_force", std::string(k::main_force_N)},
                     {"thrust_force", std::string(k::thrust_force_N)}};
  const auto set = [&](const fs::path& file, const std::string& name, const std::string& source) {
    return Json{{"file", file.string()},
                {"name", name},
                {"filter", {{"source", source}}},
                {"width", {{"column_mm", std::string(k::width_mm)}}},
                {"columns", columns}};
  };
  Json doc{{"title", title}, {"conditions", conditions}, {"quantities", quantities}};
  if (against_paper_dem) {
    doc["description"] =
        "kerf-dem (mean of the replicates) against the paper's DEM replicates (Yang et al. 2018, Table 4); both 1 mm "
        "wide.";
    doc["views"] = Json::array({"as_published"});
    doc["measured"] = set(experiments, "paper's DEM (Table 4)", "paper_dem");
    doc["predictions"] = Json::array({set(kerf_csv, "kerf-dem", "kerf_dem")});
  } else {
    doc["description"] =
        "Experiments (Yang et al. 2018, Table 6, 25.4 mm wide) against the paper's DEM (Table 4, 1 mm) "
        "and kerf-dem (1 mm): the paper's direct comparison and the per-unit-width one.";
    doc["views"] = Json::array({"as_published", "per_unit_width"});
    doc["measured"] = set(experiments, "experiment (Table 6)", "experiment");
    doc["predictions"] =
        Json::array({set(experiments, "paper's DEM (Table 4)", "paper_dem"), set(kerf_csv, "kerf-dem", "kerf_dem")});
  }
  return doc;
}

std::string pct(double x) {
  return fmt::format("{:+.1f} %", 100 * x);
}

/// The condition with these grooves and depth of cut, or null.
const ConditionResult* find_condition(const std::map<std::string, ConditionResult>& results, const std::string& shape,
                                      double depth) {
  for (const auto& [name, r] : results)
    if (r.condition.groove_shape == shape && std::abs(r.condition.depth_of_cut_mm - depth) < 1e-9) return &r;
  return nullptr;
}

/// "0.123" with enough digits for a ratio or force; "—" for NaN (no standard error).
std::string num(double x, int digits = 3) {
  return std::isfinite(x) ? fmt::format("{:.{}g}", x, digits) : "—";
}

/// One trend, a ratio of two condition means, against the experiments' same ratio: summary.json's row and the
/// report's line. The ratio's standard error to first order (ratio_of), its 95 % interval value +- q standard
/// errors (q: Student's t at the Welch-Satterthwaite degrees of freedom). AGREES: the experiment's ratio inside
/// the interval and the interval within +-kAgreementMargin of it (narrow enough to have seen a difference that
///  matters, the steady case's rule: validation/soda_lime_cutting_steady/trends.py); DISAGREES: outside it (resolved);
/// UNRESOLVED: no standard error, or an interval too wide to tell; REPORTED: no experiment to compare.
struct TrendCheck {
  Json row;
  std::string line, verdict;
};
constexpr double kAgreementMargin = 0.5;

TrendCheck trend_check(const std::string& id, const std::string& what, const Estimate& num_est, const Estimate& den_est,
                       std::optional<double> experiment, std::optional<double> paper_dem) {
  const Estimate e = ratio_of(num_est, den_est);
  const double q = quantile95(e.degrees_of_freedom);
  const double lo = e.value - q * e.standard_error, hi = e.value + q * e.standard_error;
  std::string verdict = "REPORTED";
  Json away;
  std::string detail;
  if (experiment) {
    if (!std::isfinite(e.standard_error)) {
      verdict = "UNRESOLVED";
      detail = "; no standard error";
    } else {
      const double sigmas = std::abs(*experiment - e.value) / e.standard_error;
      away = sigmas;
      const bool inside = *experiment >= lo && *experiment <= hi;
      const bool narrow = lo >= (1 - kAgreementMargin) * *experiment && hi <= (1 + kAgreementMargin) * *experiment;
      verdict = !inside ? "DISAGREES" : narrow ? "AGREES" : "UNRESOLVED";
      detail = fmt::format("; the experiment {:.2f} standard errors away{}", sigmas,
                           inside && !narrow ? ", inside an interval too wide to tell" : "");
    }
  }
  Json row{{"id", id},
           {"check", what},
           {"value", e.value},
           {"standard_error", finite_or_null(e.standard_error)},
           {"degrees_of_freedom", finite_or_null(e.degrees_of_freedom)},
           {"ci95_quantile", q},
           {"ci95_low", finite_or_null(lo)},
           {"ci95_high", finite_or_null(hi)},
           {"experiment", experiment ? Json(*experiment) : Json()},
           {"paper_dem", paper_dem ? Json(*paper_dem) : Json()},
           {"standard_errors_from_experiment", away},
           {"verdict", verdict}};
  std::string line =
      fmt::format("- {} **{}**: {:.3f} ± {} (95 % interval {} to {}{}); experiment {}, paper's DEM {}{}\n", verdict,
                  what, e.value, num(e.standard_error, 2), num(lo), num(hi),
                  std::isfinite(e.degrees_of_freedom) ? fmt::format(", df {:.1f}", e.degrees_of_freedom) : "",
                  experiment ? fmt::format("{:.3f}", *experiment) : "—",
                  paper_dem ? fmt::format("{:.3f}", *paper_dem) : "—", detail);
  return {row, line, verdict};
}

/// Seed 000's trends, each a ratio of two condition means passed to `trend(id, what, numerator, denominator,
/// experiment's ratio, paper DEM's ratio)`: the depth
/// effect of the regular cut, grooved (rectangular) / regular at each depth (main and thrust), trapezoidal /
/// rectangular thrust (beyond the paper); those whose conditions the case runs.
template <class Trend>
void seed000_trends(const std::map<std::string, ConditionResult>& results, const Comparison& vs_experiment,
                    const Comparison& vs_dem, Trend&& trend) {
  const std::vector<std::string> forces{"main", "thrust"};
  const auto force_of = [](const ConditionResult& r, const std::string& force) {
    return force == "main" ? r.main() : r.thrust();
  };
  const auto reference_ratio = [&](const Comparison& comparison, const std::string& force,
                                   const std::string& num_surface, double num_depth, const std::string& den_surface,
                                   double den_depth) {
    return reference_mean(comparison, force + "_force", num_surface, num_depth) /
           reference_mean(comparison, force + "_force", den_surface, den_depth);
  };
  if (const auto* a = find_condition(results, "none", 0.1), *b = find_condition(results, "none", 0.2); a && b)
    for (const auto& force : forces)
      trend(fmt::format("depth_effect_regular_{}_force", force),
            fmt::format("depth effect: regular {} force, 0.2 mm / 0.1 mm", force), force_of(*b, force),
            force_of(*a, force), reference_ratio(vs_experiment, force, "regular", 0.2, "regular", 0.1),
            reference_ratio(vs_dem, force, "regular", 0.2, "regular", 0.1));
  for (double depth : {0.1, 0.2}) {
    const ConditionResult *regular = find_condition(results, "none", depth),
                          *rect = find_condition(results, "rectangular", depth);
    if (!regular || !rect) continue;
    for (const auto& force : forces)
      trend(fmt::format("grooved_to_regular_{}_force_{}", force, depth),
            fmt::format("grooved (rectangular) / regular {} force at {} mm", force, depth), force_of(*rect, force),
            force_of(*regular, force),
            reference_ratio(vs_experiment, force, rect->condition.surface, depth, "regular", depth),
            reference_ratio(vs_dem, force, rect->condition.surface, depth, "regular", depth));
  }
  for (double depth : {0.1, 0.2}) {
    const ConditionResult *rect = find_condition(results, "rectangular", depth),
                          *trap = find_condition(results, "trapezoidal", depth);
    if (rect && trap)
      trend(fmt::format("trapezoidal_to_rectangular_thrust_force_{}", depth),
            fmt::format("trapezoidal / rectangular grooves, thrust force at {} mm (beyond the paper)", depth),
            trap->thrust(), rect->thrust(), std::nullopt, std::nullopt);
  }
}

/// A section of the report: its Markdown and its part of summary.json.
struct ReportSection {
  std::string md;
  Json json;
};

/// The report's opening: the scene and its packings, validation.json's note, and what this case compares and why.
std::string report_introduction(const Spec& spec) {
  std::string md = fmt::format(
      "kerf-dem, scene `{}` ({} replicates per condition, packing seeds 1..{}); forces per **1 mm** width (the DEM's "
      "out-of-plane thickness) unless stated. Experiments: Yang et al. 2018, Table 6, **25.4 mm** wide; the paper's "
      "DEM: Table 4, 1 mm.\n\n",
      spec.scene.filename().string(), spec.replicates, spec.replicates);
  if (!spec.note.empty()) md += spec.note + "\n\n";
  md +=
      "## What this case compares, and why\n\n"
      "It reproduces the paper's method: its workpiece, tool and four conditions (and trapezoidal grooves beyond "
      "it), a few packings per condition, kerf's glass calibrated to the paper's Table 2.\n\n"
      "- **The experiments, per unit width.** A 2D cut gives a force per unit of out-of-plane width; the "
      "experiments cut 25.4 mm wide workpieces. Levels are compared per mm of width (the table's last columns); the "
      "verdicts are on the **trends**, ratios between conditions, which the width cancels: each with its 95 % "
      "interval from the spread between the packings (Student's t).\n"
      "- **The paper's DEM, a reproduction reference, not a band.** Its level depends on settings the paper does not "
      "give: its local damping (kerf's regular 0.1 mm main force is 2.05 / 8.45 / 11.11 N at alpha 0.3 / 0.7 / 0.9; "
      "the paper names no value), its loading speed and the duration its means cover. kerf's level beside the "
      "paper's shows how close the reproduction comes, with no pass or fail.\n"
      "- **The acceptance of the DEM's trends** is the steady-cut case's (`../soda_lime_cutting_steady/`): long cuts "
      "with a standard error for each mean, in two domains. This case's cuts are 1 mm workpieces whose means are "
      "mostly the entry's.\n\n";
  return md;
}

/// One condition's row of the condition table (kerf-dem's forces with their spread over the packings, the
/// references, kerf-dem over them, the cracks, the cut time) and its row of summary.json's levels.
ReportSection condition_row(const Condition& c, const ConditionResult& r, const Comparison& vs_experiment,
                            const Comparison& vs_dem) {
  const auto [paper, experiment, per_mm] = reference_cells(c, vs_experiment, vs_dem);
  // Trapezoidal grooves have neither reference: both ratios NaN ("—").
  const bool has_reference = c.groove_shape != "trapezoidal";
  const auto ref = [&](const Comparison& comparison, const std::string& key) {
    return has_reference ? reference_mean(comparison, key, c.surface, c.depth_of_cut_mm) : kNaN;
  };
  const double exp_main = ref(vs_experiment, "main_force_per_width"),
               exp_thrust = ref(vs_experiment, "thrust_force_per_width");
  const double dem_main = ref(vs_dem, "main_force"), dem_thrust = ref(vs_dem, "thrust_force");
  const double kerf_main = r.main_N / units::mm_to_m(r.width_mm), kerf_thrust = r.thrust_N / units::mm_to_m(r.width_mm);
  ReportSection row;
  row.md = fmt::format(
      "| {} | {:.2f} ± {:.2f} | {:.2f} ± {:.2f} | {} | {} | {} | {}, {} | {}, {} | {:.0f} + {:.0f} ({:.0f} / {:.0f}) "
      "| "
      "{:.0f} | {:.0f}, {:.0f} | {:.0f} |\n",
      c.name, r.main_N, r.main_std_N, r.thrust_N, r.thrust_std_N, paper, experiment, per_mm,
      num(kerf_main / exp_main, 2), num(kerf_thrust / exp_thrust, 2), num(r.main_N / dem_main, 2),
      num(r.thrust_N / dem_thrust, 2), r.cracks_tensile, r.cracks_shear, r.cracks_chip, r.cracks_subsurface,
      r.subsurface_depth_um, r.cracks_subsurface_steady, r.subsurface_steady_depth_um, r.wall_time_s);
  row.json = Json{{"condition", c.name},
                  {"kerf_to_experiment_per_width_main", finite_or_null(kerf_main / exp_main)},
                  {"kerf_to_experiment_per_width_thrust", finite_or_null(kerf_thrust / exp_thrust)},
                  {"kerf_to_paper_dem_main", finite_or_null(r.main_N / dem_main)},
                  {"kerf_to_paper_dem_thrust", finite_or_null(r.thrust_N / dem_thrust)}};
  return row;
}

/// The condition table, one row per condition in validation.json's order, with the spread over the packings, per
/// unit width against the experiments and beside the paper's DEM; its json: summary.json's levels.
ReportSection condition_table(const Spec& spec, const std::map<std::string, ConditionResult>& results,
                              const Comparison& vs_experiment, const Comparison& vs_dem) {
  ReportSection table{
      "| condition | kerf-dem main (N) | kerf-dem thrust (N) | paper DEM main / thrust (N, 1 mm) | experiment main / "
      "thrust "
      "(N, 25.4 mm) | experiment per 1 mm (N) | kerf / experiment per mm: main, thrust | kerf / paper DEM: main, "
      "thrust | cracks tension + shear (chip / subsurface) | subsurface depth (um) | "
      "under the steady cut: subsurface cracks, depth (um) | cut time, sum over replicates (s) |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
      Json::array()};
  for (const auto& c : spec.conditions) {
    ReportSection row = condition_row(c, results.at(c.name), vs_experiment, vs_dem);
    table.md += row.md;
    table.json.push_back(std::move(row.json));
  }
  table.md +=
      "\n± is the standard deviation over the replicates. Subsurface depth: the deepest crack below the cut line "
      "anywhere "
      "in the workpiece (often a breakout of its free corner at the entry); under the steady cut: the cracks below the "
      "surface machined during the steady part of the travel, the damage the steady cut leaves in the part.\n\n";
  return table;
}

/// The trends against the experiments, the verdicts of a reproduction: the report's section, summary.json's trends
/// and the trends (their `what`) by verdict.
struct TrendsSection {
  std::string md;
  Json rows = Json::array();
  std::map<std::string, std::vector<std::string>> by_verdict;
};

TrendsSection trends_section(const Spec& spec, const std::map<std::string, ConditionResult>& results,
                             const Comparison& vs_experiment, const Comparison& vs_dem) {
  TrendsSection s;
  s.md = fmt::format(
      "## Trends against the experiments\n\n"
      "Each trend is a ratio of two condition means, its standard error propagated to first order (ratio × hypot of "
      "the two relative standard errors of the means over the {} packings), its 95 % interval value ± t standard "
      "errors at Welch-Satterthwaite's degrees of freedom (df). AGREES: the experiments' ratio (Table 6) inside the "
      "interval, and the interval within +-50 % of it (narrow enough to have seen a difference that matters); "
      "DISAGREES: outside it, a resolved difference; UNRESOLVED: no standard error, or an interval too wide to tell; "
      "REPORTED: no experiment to compare. The paper's DEM's ratio (Table 4) is shown beside.\n\n",
      spec.replicates);
  seed000_trends(results, vs_experiment, vs_dem,
                 [&s](const std::string& id, const std::string& what, const Estimate& a, const Estimate& b,
                      std::optional<double> experiment, std::optional<double> paper_dem) {
                   TrendCheck t = trend_check(id, what, a, b, experiment, paper_dem);
                   s.rows.push_back(t.row);
                   s.md += t.line;
                   s.by_verdict[t.verdict].push_back(what);
                 });
  return s;
}

/// The trends with this verdict (none: empty).
std::vector<std::string> trends_with(const TrendsSection& trends, const std::string& verdict) {
  const auto it = trends.by_verdict.find(verdict);
  return it == trends.by_verdict.end() ? std::vector<std::string>{} : it->second;
}

/// The acceptance bands' checks as they are made: the report's lines, summary.json's checks, and a line in
/// `failures` for each check failed. Each check carries the standard error of its value (from kerf-dem's packings
/// and, against the paper's DEM, from the paper's three), and says whether the verdict is resolved: the value lies
/// two standard errors or more from the band's edge. A verdict that is not resolved could turn with other packings.
struct BandChecks {
  explicit BandChecks(std::vector<std::string>& failed) : failures(failed) {}

  std::vector<std::string>& failures;
  std::string md;
  Json checks = Json::array();

  /// One check; `fitted`: the force the material was fitted to, reported as FITTED, neither passed nor failed.
  void add(const std::string& what, double value, double standard_error, double distance_to_edge, bool pass,
           const std::string& band, bool fitted = false) {
    const bool resolved = std::abs(distance_to_edge) >= 2 * standard_error;
    const std::string spread = fmt::format("{:.4g} ± {:.2g} (standard error; {})", value, standard_error,
                                           resolved ? "resolved: 2 or more of them from the band's edge"
                                                    : "not resolved: within 2 of them of the band's edge");
    Json row{
        {"check", what}, {"value", value}, {"standard_error", standard_error}, {"band", band}, {"resolved", resolved}};
    if (fitted) {
      row["fitted"] = true;
      checks.push_back(row);
      md += fmt::format(
          "- FITTED **{}**: {} (band: {}; the material was fitted to this force: it shows the fit, "
          "not the model, and counts neither way)\n",
          what, spread, band);
      return;
    }
    row["passed"] = pass;
    checks.push_back(row);
    md += fmt::format("- {} **{}**: {} (band: {})\n", pass ? "PASS" : "FAIL", what, spread, band);
    if (!pass) failures.push_back(fmt::format("{} = {:.4g} (band: {})", what, value, band));
  }
};

/// The regular cut's band at one depth: kerf-dem's main and thrust forces against the paper's DEM mean, the
/// relative error within spec.regular_max_error_percent (FITTED: the force validation.json says was fitted).
void regular_force_checks(const Spec& spec, const ConditionResult& regular, double depth, const Comparison& vs_dem,
                          BandChecks& bands) {
  for (const std::string label : {"main", "thrust"}) {
    const GroupComparison& g = group_of(vs_dem, label + "_force", "regular", depth);
    const double paper = g.measured_stats.mean, error = g.error_percent / 100,
                 band = spec.regular_max_error_percent / 100;
    const Estimate paper_mean{paper,
                              g.measured_stats.standard_deviation / std::sqrt(static_cast<double>(g.measured_stats.n))};
    // error = kerf / paper - 1: its standard error is the ratio's.
    const double error_se = ratio_of(label == "main" ? regular.main() : regular.thrust(), paper_mean).standard_error;
    bands.add(
        fmt::format("regular {} mm: {} force vs the paper's DEM mean ({:.2f} N), relative error", depth, label, paper),
        error, error_se, std::abs(error) - band, std::abs(error) <= band,
        fmt::format("|error| <= {:g} %", spec.regular_max_error_percent),
        label == spec.fitted_force && std::abs(depth - spec.fitted_depth_of_cut_mm) < 1e-9);
  }
}

/// The grooves' band at one depth: grooved / regular main force below spec.grooved_ratio_max.
void grooved_ratio_check(const Spec& spec, const ConditionResult& grooved, const ConditionResult& regular, double depth,
                         BandChecks& bands) {
  const Estimate ratio = ratio_of(grooved.main(), regular.main());
  bands.add(fmt::format("grooved / regular main force at {} mm", depth), ratio.value, ratio.standard_error,
            ratio.value - spec.grooved_ratio_max, ratio.value < spec.grooved_ratio_max,
            fmt::format("< {:.3f}", spec.grooved_ratio_max));
}

/// The acceptance bands where validation.json gives them (the fitted case; else an empty section): each check with
/// its standard error and whether its verdict is resolved, a failure outside its band added to `failures`; its
/// json: summary.json's checks.
ReportSection acceptance_bands(const Spec& spec, const std::map<std::string, ConditionResult>& results,
                               const Comparison& vs_dem, std::vector<std::string>& failures) {
  if (!spec.bands) return {"", Json::array()};
  BandChecks bands{failures};
  bands.md = "\n## Acceptance bands\n\n";
  bands.md += fmt::format(
      "Each value with its standard error (kerf-dem's over its {} packings and, against the paper's DEM, "
      "the paper's over its three); a verdict less than two standard errors from the band's edge is not "
      "resolved by these packings (`run_validation CASE OUT --replicates N` runs more).\n\n",
      spec.replicates);
  for (double depth : {0.1, 0.2}) {
    const ConditionResult* regular = find_condition(results, "none", depth);
    const ConditionResult* grooved = find_condition(results, "rectangular", depth);
    if (regular) regular_force_checks(spec, *regular, depth, vs_dem, bands);
    if (regular && grooved) grooved_ratio_check(spec, *grooved, *regular, depth, bands);
  }
  return {bands.md, bands.checks};
}

/// The regular cut's depth effect, 0.1 -> 0.2 mm, beside the paper's DEM's (where the case runs both depths).
void depth_effect_lines(const std::map<std::string, ConditionResult>& results, const Comparison& vs_dem,
                        ReportSection& physics) {
  const auto *a = find_condition(results, "none", 0.1), *b = find_condition(results, "none", 0.2);
  if (!a || !b) return;
  const Estimate main = ratio_of(b->main(), a->main()), thrust = ratio_of(b->thrust(), a->thrust());
  physics.md += fmt::format(
      "- Regular, 0.1 -> 0.2 mm: main force {} ± {:.0f} %, thrust {} ± {:.0f} % (standard errors; the "
      "paper's DEM: {}, {}).\n",
      pct(main.value - 1), 100 * main.standard_error, pct(thrust.value - 1), 100 * thrust.standard_error,
      pct(reference_mean(vs_dem, "main_force", "regular", 0.2) / reference_mean(vs_dem, "main_force", "regular", 0.1) -
          1),
      pct(reference_mean(vs_dem, "thrust_force", "regular", 0.2) /
              reference_mean(vs_dem, "thrust_force", "regular", 0.1) -
          1));
  physics.json["regular_main_force_change_0.1_to_0.2"] = b->main_N / a->main_N - 1;
}

/// At one depth: grooved (rectangular) vs regular cracks and damage, and trapezoidal vs rectangular grooves' forces
/// (the conditions the case runs).
void groove_effect_lines(const std::map<std::string, ConditionResult>& results, double depth, ReportSection& physics) {
  const ConditionResult *regular = find_condition(results, "none", depth),
                        *rect = find_condition(results, "rectangular", depth),
                        *trap = find_condition(results, "trapezoidal", depth);
  if (regular && rect)
    physics.md += fmt::format(
        "- {} mm, grooved vs regular: cracks {:.0f} vs {:.0f} (subsurface {:.0f} vs {:.0f}), subsurface depth "
        "{:.0f} vs {:.0f} um; under the steady cut {:.0f} vs {:.0f} subsurface cracks, {:.0f} vs {:.0f} um "
        "deep.\n",
        depth, rect->cracks_tensile + rect->cracks_shear, regular->cracks_tensile + regular->cracks_shear,
        rect->cracks_subsurface, regular->cracks_subsurface, rect->subsurface_depth_um, regular->subsurface_depth_um,
        rect->cracks_subsurface_steady, regular->cracks_subsurface_steady, rect->subsurface_steady_depth_um,
        regular->subsurface_steady_depth_um);
  if (regular && rect && regular->subsurface_steady_depth_um > 0)
    physics.json[fmt::format("grooved_vs_regular_steady_subsurface_depth_change_{}", depth)] =
        rect->subsurface_steady_depth_um / regular->subsurface_steady_depth_um - 1;
  if (rect && trap) {
    physics.md += fmt::format(
        "- {} mm, trapezoidal vs rectangular grooves (the paper's suspected cause of its thrust error): thrust "
        "{:.2f} vs {:.2f} N ({}), main {:.2f} vs {:.2f} N.\n",
        depth, trap->thrust_N, rect->thrust_N, pct(trap->thrust_N / rect->thrust_N - 1), trap->main_N, rect->main_N);
    physics.json[fmt::format("trapezoidal_vs_rectangular_thrust_change_{}", depth)] =
        trap->thrust_N / rect->thrust_N - 1;
  }
}

/// The expected physics and what goes beyond the paper, reported, not bands; its json: summary.json's physics.
ReportSection expected_physics(const std::map<std::string, ConditionResult>& results, const Comparison& vs_dem) {
  ReportSection physics{"\n## Expected physics and beyond the paper (reported, not bands)\n\n", Json::object()};
  depth_effect_lines(results, vs_dem, physics);
  for (double depth : {0.1, 0.2}) groove_effect_lines(results, depth, physics);
  return physics;
}

/// What holds and what does not, from the trends' verdicts (not fixed text).
std::string what_this_shows(const Spec& spec, const TrendsSection& trends) {
  const auto list = [&](const std::string& verdict) {
    std::string out;
    for (const auto& what : trends_with(trends, verdict)) out += (out.empty() ? "" : "; ") + what;
    return out.empty() ? std::string("none") : out;
  };
  std::string md = "\n## What this reproduction shows\n\n";
  md += fmt::format("- Agrees with the experiments within its 95 % interval: {}.\n", list("AGREES"));
  md += fmt::format("- Differs from the experiments, resolved: {}.\n", list("DISAGREES"));
  md += fmt::format("- Not resolved (no standard error, or an interval too wide to tell): {}.\n", list("UNRESOLVED"));
  if (!spec.bands)
    md +=
        "- No pass or fail: a reproduction of the paper's method (why: above). The acceptance of the trends is "
        "`../soda_lime_cutting_steady/`'s.\n";
  return md;
}

/// summary.json but its verdict ("passed", run_soda_lime_cutting_validation's): the case's role, the trends and
/// their verdicts, the levels (the condition table's), the band checks and the physics.
Json summary_document(const Spec& spec, const TrendsSection& trends, const Json& levels, const Json& checks,
                      const Json& physics) {
  Json verdicts = Json::object();
  for (const char* v : {"AGREES", "DISAGREES", "UNRESOLVED"}) verdicts[v] = trends_with(trends, v);
  return Json{{"role", spec.bands ? "bands" : "reproduction"},
              {"trends", trends.rows},
              {"trend_verdicts", verdicts},
              {"levels", levels},
              {"checks", checks},
              {"physics", physics}};
}

/// The seed case's statistics (validation/soda_lime_cutting/README.md), a reproduction of the paper's method, its
/// sections top to bottom: what is compared and why; the condition table with the spread over the packings, per
/// unit width against the experiments and beside the paper's DEM; the trends against the experiments with their
/// 95 % intervals (the verdicts); the bands where validation.json gives them (the fitted case: each check with its
/// standard error and whether its verdict is resolved, a failure outside its band); the expected physics
/// (reported); and a summary of what holds and what is not resolved. Returns the report's body (after the title)
/// and fills `summary` and `failures` (bands only: a reproduction fails nothing).
std::string replicates_report(const Spec& spec, const std::map<std::string, ConditionResult>& results,
                              const Comparison& vs_experiment, const Comparison& vs_dem,
                              std::vector<std::string>& failures, Json& summary) {
  const std::string introduction = report_introduction(spec);
  const ReportSection table = condition_table(spec, results, vs_experiment, vs_dem);
  const TrendsSection trends = trends_section(spec, results, vs_experiment, vs_dem);
  const ReportSection bands = acceptance_bands(spec, results, vs_dem, failures);
  const ReportSection physics = expected_physics(results, vs_dem);
  summary = summary_document(spec, trends, table.json, bands.json, physics.json);
  return introduction + table.md + trends.md + bands.md + physics.md + what_this_shows(spec, trends);
}

/// validation/<case_name>/validation.json, its packings per condition replaced by `replicates` unless 0.
Spec case_spec(const std::string& case_name, int replicates) {
  const fs::path case_dir = data_directory().parent_path() / "validation" / case_name;
  Spec spec = read_spec(case_dir);
  if (replicates != 0) {
    if (replicates < kMinReplicates || replicates > kMaxReplicates)
      throw InputError("--replicates", std::to_string(replicates),
                       fmt::format("a number of packings from {} to {}", kMinReplicates, kMaxReplicates));
    spec.replicates = replicates;
  }
  return spec;
}

/// The study of the cuts (OUT/study/study.json): each condition of validation.json on spec.replicates packings.
Json study_document(const Spec& spec, const std::string& case_name) {
  Json conditions = Json::array();
  for (const auto& c : spec.conditions)
    conditions.push_back(Json{{"cut.depth_of_cut_mm", c.depth_of_cut_mm}, {"grooves.shape", c.groove_shape}});
  return Json{{"description", fmt::format("The {} validation's cuts: each condition of validation.json on {} packings",
                                          case_name, spec.replicates)},
              {"scene", fs::absolute(spec.scene).string()},
              {"conditions", {{"list", conditions}}},
              {"replicates", {{"policy", "fixed"}, {"count", spec.replicates}}}};
}

/// Each condition's replicate results, by its name, from the summaries of the study's items.
std::map<std::string, ConditionResult> collect_results(const Spec& spec, const dem::StudySpec& study,
                                                       const dem::StudyOutcome& outcome, const fs::path& study_dir) {
  std::map<std::string, ConditionResult> results;
  for (std::size_t ci = 0; ci < spec.conditions.size(); ++ci) {
    std::vector<Json> items;
    std::vector<fs::path> directories;
    const int count = outcome.summary.at("conditions").at(ci).at("count").get<int>();
    for (int k = 0; k < count; ++k) {
      const dem::StudyItem item = dem::study_item(study, static_cast<int>(ci), k);
      items.push_back(dem::read_study_item_summary(study_dir, item));
      directories.push_back(fs::path("study") / "items" / dem::study_item_name(item));
    }
    ConditionResult& r = results[spec.conditions[ci].name] = collect(spec.conditions[ci], items);
    r.directories = std::move(directories);
  }
  return results;
}

/// 1. The runs: one study (kerf/dem/study/study.hpp) of the conditions, each on spec.replicates packings, in
/// OUT/study: items side by side, one thread each (18 cuts in 9 rounds on 2 cores), finished items reused, so
/// an interrupted validation resumes where it stopped. OUT/study/study.json is that study, for kerf-dem study.
std::map<std::string, ConditionResult> run_cuts(const Spec& spec, const std::string& case_name,
                                                const fs::path& out_dir) {
  const Json study_doc = study_document(spec, case_name);
  const fs::path study_dir = out_dir / "study";
  const dem::StudySpec study = dem::read_study(study_doc, study_dir / "study.json");
  fs::create_directories(study_dir);
  write_file_atomically(study_dir / "study.json", study_doc.dump(2) + "\n");
  dem::StudyOptions options;
  options.out = study_dir;
  options.stop_at_first_failure = true;  // the validation needs every cut
  options.log_lines = true;
  options.command_line = fmt::format("kerf-dem study {} --out {}", quoted(study_dir / "study.json"), quoted(study_dir));
  fmt::print("{}\n", options.command_line);  // the same runs from the command line
  std::fflush(stdout);
  const dem::StudyOutcome outcome = dem::run_study_local(study, options);
  return collect_results(spec, study, outcome, study_dir);
}

/// The source column of a condition's rows: trapezoidal grooves go beyond the paper (no measured counterpart), so
/// their rows carry their own.
std::string source_of(const Condition& c) {
  return c.groove_shape == "trapezoidal" ? "kerf_dem_trapezoidal" : "kerf_dem";
}

/// A condition's rows of kerf_dem_replicates.csv: one per replicate.
std::string replicate_rows(const Condition& c, const ConditionResult& r) {
  std::string rows;
  for (const auto& row : r.replicates) {
    std::vector<std::string> fields{source_of(c),
                                    c.surface,
                                    c.groove_shape,
                                    csv_number(c.depth_of_cut_mm),
                                    std::to_string(row.at("replicate").get<int>()),
                                    std::to_string(row.at("seed").get<long long>())};
    for (const auto& column : kReplicateColumns) fields.push_back(csv_number(row.at(column)));
    rows += csv_line(fields);
  }
  return rows;
}

/// A condition's row of kerf_dem_means.csv: the means that the report layer compares.
std::string means_row(const Condition& c, const ConditionResult& r) {
  return csv_line({source_of(c), c.surface, c.groove_shape, csv_number(c.depth_of_cut_mm), csv_number(r.width_mm),
                   csv_number(r.main_N), csv_number(r.main_std_N), csv_number(r.thrust_N), csv_number(r.thrust_std_N),
                   csv_number(r.cracks_tensile), csv_number(r.cracks_shear), csv_number(r.cracks_chip),
                   csv_number(r.cracks_subsurface), csv_number(r.subsurface_depth_um),
                   csv_number(r.cracks_subsurface_steady), csv_number(r.subsurface_steady_depth_um)});
}

/// 2. The kerf-dem tables: kerf_dem_replicates.csv, one row per replicate, and kerf_dem_means.csv, the means that
/// the report layer compares. Returns the two files.
std::vector<fs::path> write_kerf_dem_tables(const Spec& spec, const std::map<std::string, ConditionResult>& results,
                                            const fs::path& out_dir) {
  std::vector<std::string> header{"source", "surface", "groove_shape", "depth_of_cut_mm", "replicate", "seed"};
  header.insert(header.end(), kReplicateColumns.begin(), kReplicateColumns.end());
  std::string rows = csv_line(header);
  std::string means = csv_line(
      {"source", "surface", "groove_shape", "depth_of_cut_mm", std::string(k::width_mm), std::string(k::main_force_N),
       dem::replicate_spread_key(k::main_force_N), std::string(k::thrust_force_N),
       dem::replicate_spread_key(k::thrust_force_N), std::string(k::cracks_tensile), std::string(k::cracks_shear),
       std::string(k::cracks_chip), std::string(k::cracks_subsurface), std::string(k::subsurface_damage_depth_um),
       std::string(k::cracks_subsurface_steady), std::string(k::subsurface_damage_depth_steady_um)});
  for (const auto& c : spec.conditions) {
    rows += replicate_rows(c, results.at(c.name));
    means += means_row(c, results.at(c.name));
  }
  write_file_atomically(out_dir / "kerf_dem_replicates.csv", rows);
  write_file_atomically(out_dir / "kerf_dem_means.csv", means);
  return {out_dir / "kerf_dem_replicates.csv", out_dir / "kerf_dem_means.csv"};
}

/// 3. Through the report layer: against the experiments (both width views; "vs_experiment") and against the
/// paper's DEM ("vs_paper_dem"), each a comparison document OUT/<name>.json and its report in OUT/<name>/, whose
/// files are added to `files`. Measured: the experiments or the paper's DEM; prediction: kerf-dem (in the former,
/// beside the paper's DEM).
std::map<std::string, Comparison> compare_with_references(const Spec& spec, const fs::path& out_dir,
                                                          std::vector<fs::path>& files) {
  const fs::path means_csv = fs::absolute(out_dir / "kerf_dem_means.csv");
  std::map<std::string, Comparison> comparisons;
  for (const auto& [name, against_dem] :
       std::vector<std::pair<std::string, bool>>{{"vs_experiment", false}, {"vs_paper_dem", true}}) {
    const Json doc = comparison_document(
        fs::absolute(spec.experiments), means_csv,
        against_dem
            ? "Soda-lime glass, orthogonal cutting: kerf-dem vs the paper's DEM (Yang et al. 2018)"
            : "Soda-lime glass, orthogonal cutting: experiment vs the paper's DEM and kerf-dem (Yang et al. 2018)",
        against_dem);
    write_file_atomically(out_dir / (name + ".json"), doc.dump(2) + "\n");
    const Comparison& comparison = comparisons[name] = run_comparison(parse_comparison_config(doc, out_dir));
    for (const auto& f : write_report(comparison, out_dir / name)) files.push_back(f);
  }
  return comparisons;
}

/// The snapshots of regular_0.1 and grooved_0.1 (replicate 1's picture, where the case runs them and the run drew
/// one): copied beside report.md as snapshot_<name>.png, and the report's lines that show them.
std::string snapshots(const std::map<std::string, ConditionResult>& results, const fs::path& out_dir) {
  std::string md;
  for (const char* name : {"regular_0.1", "grooved_0.1"}) {
    const auto r = results.find(name);
    if (r == results.end() || r->second.directories.empty()) continue;
    const fs::path picture = out_dir / r->second.directories.front() / "specimen.png";
    if (!fs::exists(picture)) continue;
    fs::copy_file(picture, out_dir / fmt::format("snapshot_{}.png", name), fs::copy_options::overwrite_existing);
    md += fmt::format("\n![{}, replicate 1](snapshot_{}.png)\n", name, name);
  }
  return md;
}

/// 4. The report, OUT/report.md: the trends, the bands where there are, and the expected physics
/// (replicates_report), the links to the other outputs, the snapshots and the verdict; and OUT/summary.json. The
/// reference means come from the comparisons: measured = experiments (vs_experiment) or the paper's DEM
/// (vs_paper_dem), prediction = kerf-dem in the latter. Sets v.judged, fills v.failures and adds the two files.
void write_validation_report(const Spec& spec, const std::map<std::string, ConditionResult>& results,
                             const std::map<std::string, Comparison>& comparisons, const fs::path& out_dir,
                             CuttingValidation& v) {
  const Comparison& vs_experiment = comparisons.at("vs_experiment");
  const Comparison& vs_dem = comparisons.at("vs_paper_dem");
  Json summary_doc;
  std::string md = "# Validation: soda-lime glass, orthogonal cutting (Yang et al. 2018)\n\n" +
                   replicates_report(spec, results, vs_experiment, vs_dem, v.failures, summary_doc);
  md +=
      "\nReports through the report layer: [vs_experiment/report.md](vs_experiment/report.md) (the paper's direct "
      "comparison and the per-unit-width one), [vs_paper_dem/report.md](vs_paper_dem/report.md). Per-replicate "
      "results: `kerf_dem_replicates.csv`; each run's forces, cracks and picture: "
      "`study/items/condition_<c>_seed_<s>/` (the conditions in validation.json's order; `study/items.csv` lists "
      "them).\n";
  md += snapshots(results, out_dir);
  v.judged = spec.bands;
  md += v.judged ? fmt::format("\n**{}**\n", v.failures.empty() ? "PASSED" : "FAILED")
                 : std::string("\n**REPORTED** (a reproduction: no pass or fail)\n");
  write_file_atomically(out_dir / "report.md", md);
  summary_doc["passed"] = v.judged ? Json(v.failures.empty()) : Json();
  write_file_atomically(out_dir / "summary.json", summary_doc.dump(2) + "\n");
  v.files.push_back(out_dir / "report.md");
  v.files.push_back(out_dir / "summary.json");
}

}  // namespace

CuttingValidation run_soda_lime_cutting_validation(const fs::path& out_dir, const std::string& case_name,
                                                   int replicates) {
  // The four steps above, in order: the runs, the kerf-dem tables, the comparisons, the report.
  const Spec spec = case_spec(case_name, replicates);
  const std::map<std::string, ConditionResult> results = run_cuts(spec, case_name, out_dir);
  CuttingValidation v;
  v.files = write_kerf_dem_tables(spec, results, out_dir);
  const std::map<std::string, Comparison> comparisons = compare_with_references(spec, out_dir, v.files);
  write_validation_report(spec, results, comparisons, out_dir, v);
  return v;
}

}  // namespace kerf
