// Seed 000's orthogonal cutting of soda-lime glass (validation/soda_lime_cutting/): runs every condition of
// validation.json with kerf-dem (replicates on different packings), collects the forces, compares them through
// the report layer with the experiments (Table 6, 25.4 mm wide) and the paper's DEM (Table 4, 1 mm), and checks
// the acceptance bands. See validation/soda_lime_cutting/README.md. With "statistics": "within_cuts" (the
// steady-state case, validation/soda_lime_cutting_steady/) each condition's standard error comes from its cuts'
// own force signals instead of the spread between packings, and the acceptance checks trends against the
// experiments' with 95 % intervals (see validation/soda_lime_cutting_steady/README.md).
#include "soda_lime_cutting.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <optional>

#include "kerf/comparison_config.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/dem/study.hpp"
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

struct Condition {
  std::string name, surface, groove_shape;
  double depth_of_cut_mm = 0;
};

/// Packings per condition, in validation.json or from --replicates: at least two for a sample standard deviation
/// (statistics "replicates"); one long steady cut has its own standard error (statistics "within_cuts").
constexpr int kMinReplicates = 2, kMinReplicatesWithinCuts = 1, kMaxReplicates = 100;

/// Where a condition's standard error comes from: the spread between its packings (sample std / sqrt(n)), or
/// each cut's own batch-means standard error of its steady mean, sqrt(sum sem_k^2) / n.
enum class Statistics { replicates, within_cuts };

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// validation.json's "replicates" as an object (statistics "within_cuts" only): as many packings per condition as
/// its mean needs, the study's adaptive policy (kerf/dem/study.hpp): the smallest n in [min_count, max_count] at
/// which the between-packing relative standard error of every named force is at most the acceptance's
/// max_relative_sem_percent.
struct AdaptivePackings {
  int min_count = 8, max_count = 30;
  std::vector<std::string> results{"main_force_N", "thrust_force_N"};
};

/// The adaptive packings as the study's "replicates" section, without its target (the acceptance's).
Json adaptive_json(const AdaptivePackings& p) {
  return Json{{"policy", "adaptive"}, {"min_count", p.min_count}, {"max_count", p.max_count}, {"results", p.results}};
}

struct Spec {
  fs::path scene, experiments;
  std::string note;  ///< printed under the report's title (e.g. what a fitted material was fitted to)
  int replicates = 3;  ///< fixed packings per condition (adaptive: max_count)
  std::optional<AdaptivePackings> adaptive;
  /// within_cuts: from this many packings of a condition on, its standard error is the spread between its
  /// packings (sample std / sqrt(n), Student-t intervals) instead of the cuts' own; 0: never.
  int between_packings_from_replicates = 0;
  Statistics statistics = Statistics::replicates;
  int min_replicates() const { return statistics == Statistics::within_cuts ? kMinReplicatesWithinCuts : kMinReplicates; }
  std::vector<Condition> conditions;
  /// Replicates statistics: whether validation.json gives pass/fail bands (the fitted case's); without them the
  /// case is a reproduction of the paper's method, reported without a verdict of its own.
  bool bands = false;
  double regular_max_error_percent = 20, grooved_ratio_max = 1.0 / 3;
  /// The regular-workpiece force the material was fitted to (depth 0: none): its check is reported as
  /// FITTED, neither passed nor failed, since meeting it shows the fit, not the model.
  double fitted_depth_of_cut_mm = 0;
  std::string fitted_force;  ///< "main" or "thrust"
  /// within_cuts acceptance: every condition's mean main and thrust force resolved to this relative standard
  /// error (else the validation fails), and whether the trends against the experiments are reported.
  double max_relative_sem_percent = 5;
  bool trends = true;
};

/// The acceptance keys of each statistics mode: a key of the other mode is an error that says so.
const std::vector<std::string> kBandKeys{"regular_force_max_abs_error_vs_paper_dem_percent",
                                         "grooved_to_regular_main_force_ratio_max", "fitted"};
const std::vector<std::string> kWithinCutsKeys{"max_relative_sem_percent", "trends",
                                              "between_packings_from_replicates"};

Spec read_spec(const fs::path& case_dir) {
  const Json doc = read_json_file(case_dir / "validation.json");
  ObjectReader r(doc, "validation");
  Spec s;
  s.scene = case_dir / r.get_string("scene");
  s.experiments = case_dir / r.get_string("experiments");
  s.note = r.get_string_or("note", "");
  s.statistics = r.get_choice_or("statistics", "replicates", {"replicates", "within_cuts"}) == "within_cuts"
                     ? Statistics::within_cuts
                     : Statistics::replicates;
  if (const Json* n = r.find("replicates");
      n && n->is_number_integer() && n->get<long long>() == 1 && s.statistics == Statistics::replicates)
    throw InputError("validation.replicates", "1",
                     fmt::format("an integer in [{}, {}] (one packing per condition needs \"statistics\": "
                                 "\"within_cuts\", the cuts' own standard errors)",
                                 kMinReplicates, kMaxReplicates));
  if (const Json* rep = r.find("replicates"); rep && rep->is_object()) {
    ObjectReader a(*rep, "validation.replicates");
    if (s.statistics != Statistics::within_cuts)
      throw InputError("validation.replicates", rep->dump(),
                       "an integer (packings by the error reached need \"statistics\": \"within_cuts\")");
    AdaptivePackings p;
    a.get_choice("policy", {"adaptive"});
    // At least two packings: the rule is the spread between them.
    p.min_count = a.get_int_or("min_count", p.min_count, 2, kMaxReplicates);
    p.max_count = a.get_int_or("max_count", std::max(p.max_count, p.min_count), p.min_count, kMaxReplicates);
    if (const Json* names = a.find("results")) {
      const auto bad = [&] {
        return InputError(a.key_path("results"), names->dump(),
                          "a non-empty list of \"main_force_N\" and \"thrust_force_N\"");
      };
      if (!names->is_array() || names->empty()) throw bad();
      p.results.clear();
      for (const Json& name : *names) {
        if (!name.is_string() || (name != "main_force_N" && name != "thrust_force_N")) throw bad();
        p.results.push_back(name.get<std::string>());
      }
    }
    a.finish();
    s.adaptive = p;
    s.replicates = p.max_count;
  } else {
    s.replicates = r.get_int_or("replicates", 3, s.min_replicates(), kMaxReplicates);
  }
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
  const bool within_cuts = s.statistics == Statistics::within_cuts;
  for (const auto& key : within_cuts ? kBandKeys : kWithinCutsKeys)
    if (const Json* value = a.find(key))
      throw InputError(a.key_path(key), value->dump(),
                       within_cuts ? "no band under \"statistics\": \"within_cuts\" (its acceptance: "
                                     "max_relative_sem_percent and trends)"
                                   : "a key of \"statistics\": \"within_cuts\" only (the replicates acceptance: "
                                     "regular_force_max_abs_error_vs_paper_dem_percent, "
                                     "grooved_to_regular_main_force_ratio_max, fitted)");
  if (within_cuts) {
    s.max_relative_sem_percent = a.get_number("max_relative_sem_percent", Range::positive(), "%");
    s.trends = a.get_bool_or("trends", true);
    s.between_packings_from_replicates = a.get_int_or("between_packings_from_replicates", 0, 2, kMaxReplicates);
    if (s.adaptive && s.max_relative_sem_percent > 100)  // it is the adaptive packings' target too
      throw InputError(a.key_path("max_relative_sem_percent"), fmt::format("{:g}", s.max_relative_sem_percent),
                       "a percentage in (0, 100] with adaptive packings (\"replicates\": {\"policy\": \"adaptive\"})");
  } else if (a.has("regular_force_max_abs_error_vs_paper_dem_percent") ||
             a.has("grooved_to_regular_main_force_ratio_max") || a.has("fitted")) {
    s.bands = true;
    s.regular_max_error_percent = a.get_number("regular_force_max_abs_error_vs_paper_dem_percent", Range::positive(), "%");
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

/// A mean with its standard error and the degrees of freedom of that error: n - 1 for the spread between n
/// packings, infinite for a cut's own batch-means error (a long signal's; the normal quantile).
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
const std::vector<std::string> kReplicateColumns{"width_mm",
                                                 "main_force_N",
                                                 "thrust_force_N",
                                                 "cracks_tensile",
                                                 "cracks_shear",
                                                 "cracks_chip",
                                                 "cracks_subsurface",
                                                 "subsurface_damage_depth_um",
                                                 "cracks_subsurface_steady",
                                                 "subsurface_damage_depth_steady_um",
                                                 "wall_time_s"};

/// The columns that statistics "within_cuts" appends to kerf_dem_replicates.csv: the cut's own standard errors
/// of its steady means (batch means of its force signal; empty when the signal is too short for them), the
/// depth below the cut line to which an active window sees cracks, and whether the steady damage depth reaches
/// it (1: censored, the damage may go deeper).
const std::vector<std::string> kWithinCutColumns{"main_force_sem_N", "thrust_force_sem_N", "damage_depth_limit_um",
                                                 "subsurface_damage_depth_steady_censored"};

/// A csv field of a result that may be null (empty) or a boolean (1 / 0).
std::string csv_field(const Json& value) {
  if (value.is_boolean()) return value.get<bool>() ? "1" : "0";
  return value.is_number() ? csv_number(value.get<double>()) : std::string();
}

/// Replicate results of one condition, from its study items' summaries.
struct ConditionResult {
  Condition condition;
  Json replicates;  ///< one row per replicate: replicate, seed and kReplicateColumns (within_cuts: kWithinCutColumns too)
  double main_n = 0, thrust_n = 0, main_std_n = 0, thrust_std_n = 0, width_mm = 1;
  bool within_cuts = false;  ///< main() and thrust() carry the within-cut standard errors...
  int between_from = 0;      ///< ...but from this many packings on (0: never) the between-packing ones
  /// sqrt(sum sem_k^2) / n of the cuts' own standard errors (NaN when a cut has none, or not within_cuts).
  double main_sem_within_n = kNaN, thrust_sem_within_n = kNaN;
  /// The mean forces with their standard errors over the replicates (packings are independent samples): sample
  /// std / sqrt(n), NaN for one packing.
  int n() const { return static_cast<int>(replicates.size()); }
  Estimate main_between() const { return {main_n, main_std_n / std::sqrt(n()), n() - 1.0}; }
  Estimate thrust_between() const { return {thrust_n, thrust_std_n / std::sqrt(n()), n() - 1.0}; }
  /// Whether the acceptance uses the between-packing standard errors: the replicates mode always, within_cuts
  /// from between_from packings on.
  bool uses_between() const { return !within_cuts || (between_from > 0 && n() >= between_from); }
  /// The mean forces with the standard errors the acceptance uses.
  Estimate main() const { return uses_between() ? main_between() : Estimate{main_n, main_sem_within_n}; }
  Estimate thrust() const { return uses_between() ? thrust_between() : Estimate{thrust_n, thrust_sem_within_n}; }
  /// The active window's depth limit of the crack search (NaN: no window), and how many replicates' steady
  /// damage depth reaches it (censored).
  double damage_depth_limit_um = kNaN;
  int damage_censored_replicates = 0;
  double cracks_subsurface_steady_std = kNaN, subsurface_steady_depth_std_um = kNaN;  ///< over the replicates
  double cracks_tensile = 0, cracks_shear = 0, cracks_chip = 0, cracks_subsurface = 0, subsurface_depth_um = 0;
  /// Under the surface machined during the steady part (kerf-dem's *_steady results): the cut's own damage.
  double cracks_subsurface_steady = 0, subsurface_steady_depth_um = 0;
  double wall_time_s = 0;  ///< the replicates' own cut times, summed (a rerun that reuses them all takes ~0 s)
  std::vector<fs::path> directories;  ///< each replicate's run, relative to the validation's output directory
};

ConditionResult collect(const Condition& c, const std::vector<Json>& items, bool within_cuts, int between_from) {
  ConditionResult r;
  r.condition = c;
  r.within_cuts = within_cuts;
  r.between_from = between_from;
  r.replicates = Json::array();
  std::vector<double> main, thrust, main_sems, thrust_sems, steady_cracks, steady_depths;
  const double n = static_cast<double>(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Json& res = items[k].at("results");
    const Json& item = items[k].at("study_item");
    Json row{{"replicate", k + 1}, {"seed", item.at("seed")}};
    for (const auto& column : kReplicateColumns)
      row[column] = column == "wall_time_s" ? items[k].at("wall_time_s") : res.at(column);
    if (within_cuts) {
      // A null standard error (a signal too short for batch means) makes the condition's NaN: not resolved.
      for (const char* sem : {"main_force_sem_N", "thrust_force_sem_N"}) row[sem] = res.value(sem, Json());
      main_sems.push_back(row["main_force_sem_N"].is_number() ? row["main_force_sem_N"].get<double>() : kNaN);
      thrust_sems.push_back(row["thrust_force_sem_N"].is_number() ? row["thrust_force_sem_N"].get<double>() : kNaN);
      // Cracks exist only inside an active window: a steady damage depth within a largest disk diameter of its
      // floor is censored by it (dem/kinds/cut.cpp, active_window.damage_depth_limit_um).
      const Json window = items[k].value("active_window", Json::object());
      row["damage_depth_limit_um"] = window.value("damage_depth_limit_um", Json());
      bool censored = false;
      if (row["damage_depth_limit_um"].is_number()) {
        const double limit = row["damage_depth_limit_um"].get<double>();
        const double diameter = 2 * items[k].value("specimen", Json::object()).value("radius_max_um", 0.0);
        censored = row.at("subsurface_damage_depth_steady_um").get<double>() >= limit - diameter;
        r.damage_depth_limit_um = limit;
      }
      row["subsurface_damage_depth_steady_censored"] = censored;
      r.damage_censored_replicates += censored ? 1 : 0;
      steady_cracks.push_back(row.at("cracks_subsurface_steady").get<double>());
      steady_depths.push_back(row.at("subsurface_damage_depth_steady_um").get<double>());
    }
    main.push_back(row.at("main_force_N").get<double>());
    thrust.push_back(row.at("thrust_force_N").get<double>());
    r.cracks_tensile += row.at("cracks_tensile").get<double>() / n;
    r.cracks_shear += row.at("cracks_shear").get<double>() / n;
    r.cracks_chip += row.at("cracks_chip").get<double>() / n;
    r.cracks_subsurface += row.at("cracks_subsurface").get<double>() / n;
    r.subsurface_depth_um += row.at("subsurface_damage_depth_um").get<double>() / n;
    r.cracks_subsurface_steady += row.at("cracks_subsurface_steady").get<double>() / n;
    r.subsurface_steady_depth_um += row.at("subsurface_damage_depth_steady_um").get<double>() / n;
    r.wall_time_s += row.at("wall_time_s").get<double>();
    r.replicates.push_back(row);
  }
  const SampleStatistics m = sample_statistics(main), t = sample_statistics(thrust);
  r.main_n = m.mean, r.main_std_n = m.standard_deviation;
  r.thrust_n = t.mean, r.thrust_std_n = t.standard_deviation;
  r.width_mm = r.replicates.at(0).at("width_mm").get<double>();
  if (within_cuts) {
    r.main_sem_within_n = standard_error_of_mean(main_sems);
    r.thrust_sem_within_n = standard_error_of_mean(thrust_sems);
    r.cracks_subsurface_steady_std = sample_statistics(steady_cracks).standard_deviation;
    r.subsurface_steady_depth_std_um = sample_statistics(steady_depths).standard_deviation;
  }
  return r;
}

/// The group of one condition (surface, depth of cut) in a comparison's result for `key` ("main_force",
/// "main_force_per_width", ...): the report layer's means of the replicates, SI in that view's basis.
const GroupComparison& group_of(const Comparison& comparison, const std::string& key, const std::string& surface,
                                double depth_mm) {
  const std::vector<ConditionValue> wanted{ConditionValue::label(surface), ConditionValue::number(units::mm_to_m(depth_mm))};
  for (const auto& g : comparison.result(key).groups)
    if (conditions_match(g.conditions, wanted, 1e-6)) return g;
  throw InputError("validation.experiments", fmt::format("{} {} mm", surface, depth_mm), "rows for this condition");
}

/// The measured side's mean of one condition in a comparison (the experiments in vs_experiment, the paper's DEM in
/// vs_paper_dem), SI in the basis of the result `key`.
double reference_mean(const Comparison& comparison, const std::string& key, const std::string& surface, double depth_mm) {
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
    return fmt::format(fmt::runtime(format), scale * reference_mean(comparison, "main_force" + suffix, c.surface, c.depth_of_cut_mm),
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
  const Json conditions = Json::array({Json{{"key", "surface"}, {"label", "Surface"}, {"text", true}},
                                       Json{{"key", "depth_of_cut"}, {"label", "Depth of cut a#dc#u"}, {"unit", "mm"}}});
  const Json quantities = Json::array({Json{{"key", "main_force"}, {"label", "Main force F#dc#u"}, {"unit", "N"}},
                                       Json{{"key", "thrust_force"}, {"label", "Thrust force F#dt#u"}, {"unit", "N"}}});
  const Json columns{{"surface", "surface"}, {"depth_of_cut", "depth_of_cut_mm"}, {"main_force", "main_force_N"},
                     {"thrust_force", "thrust_force_N"}};
  const auto set = [&](const fs::path& file, const std::string& name, const std::string& source) {
    return Json{{"file", file.string()}, {"name", name}, {"filter", {{"source", source}}},
                {"width", {{"column_mm", "width_mm"}}}, {"columns", columns}};
  };
  Json doc{{"title", title}, {"conditions", conditions}, {"quantities", quantities}};
  if (against_paper_dem) {
    doc["description"] = "kerf-dem (mean of the replicates) against the paper's DEM replicates (seed 000 Table 4); both 1 mm wide.";
    doc["views"] = Json::array({"as_published"});
    doc["measured"] = set(experiments, "paper's DEM (Table 4)", "paper_dem");
    doc["predictions"] = Json::array({set(kerf_csv, "kerf-dem", "kerf_dem")});
  } else {
    doc["description"] = "Experiments (seed 000 Table 6, 25.4 mm wide) against the paper's DEM (Table 4, 1 mm) and kerf-dem "
                         "(1 mm): the paper's direct comparison and the per-unit-width one.";
    doc["views"] = Json::array({"as_published", "per_unit_width"});
    doc["measured"] = set(experiments, "experiment (Table 6)", "experiment");
    doc["predictions"] = Json::array({set(experiments, "paper's DEM (Table 4)", "paper_dem"), set(kerf_csv, "kerf-dem", "kerf_dem")});
  }
  return doc;
}

std::string pct(double x) { return fmt::format("{:+.1f} %", 100 * x); }

/// The condition with these grooves and depth of cut, or null.
const ConditionResult* find_condition(const std::map<std::string, ConditionResult>& results, const std::string& shape,
                                      double depth) {
  for (const auto& [name, r] : results)
    if (r.condition.groove_shape == shape && std::abs(r.condition.depth_of_cut_mm - depth) < 1e-9) return &r;
  return nullptr;
}

/// "0.123" with enough digits for a ratio or force; "—" for NaN (no standard error).
std::string num(double x, int digits = 3) { return std::isfinite(x) ? fmt::format("{:.{}g}", x, digits) : "—"; }

/// One trend, a ratio of two condition means, against the experiments' same ratio: summary.json's row and the
/// report's line. The ratio's standard error to first order (ratio_of), its 95 % interval value +- q standard
/// errors (q: Student's t at the Welch-Satterthwaite degrees of freedom, 1.96 for the cuts' own errors). AGREES:
/// the experiment's ratio inside the interval; DISAGREES: outside it (resolved); UNRESOLVED: no standard error;
/// REPORTED: no experiment to compare. `*_between`: the same ratio with the between-packing errors, shown beside.
struct TrendCheck {
  Json row;
  std::string line, verdict;
};
TrendCheck trend_check(const std::string& id, const std::string& what, const Estimate& num_est,
                       const Estimate& den_est, const Estimate& num_between, const Estimate& den_between,
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
      verdict = *experiment >= lo && *experiment <= hi ? "AGREES" : "DISAGREES";
      detail = fmt::format("; the experiment {:.2f} standard errors away", sigmas);
    }
  }
  const double between_se = ratio_of(num_between, den_between).standard_error;
  Json row{{"id", id},
           {"check", what},
           {"value", e.value},
           {"standard_error", finite_or_null(e.standard_error)},
           {"standard_error_between_packings", finite_or_null(between_se)},
           {"degrees_of_freedom", finite_or_null(e.degrees_of_freedom)},
           {"ci95_quantile", q},
           {"ci95_low", finite_or_null(lo)},
           {"ci95_high", finite_or_null(hi)},
           {"experiment", experiment ? Json(*experiment) : Json()},
           {"paper_dem", paper_dem ? Json(*paper_dem) : Json()},
           {"standard_errors_from_experiment", away},
           {"verdict", verdict}};
  std::string line =
      fmt::format("- {} **{}**: {:.3f} ± {} (95 % interval {} to {}{}{}); experiment {}, paper's DEM {}{}\n", verdict,
                  what, e.value, num(e.standard_error, 2), num(lo), num(hi),
                  std::isfinite(e.degrees_of_freedom) ? fmt::format(", df {:.1f}", e.degrees_of_freedom) : "",
                  std::isfinite(between_se) ? fmt::format("; between packings ± {}", num(between_se, 2)) : "",
                  experiment ? fmt::format("{:.3f}", *experiment) : "—", paper_dem ? fmt::format("{:.3f}", *paper_dem) : "—",
                  detail);
  return {row, line, verdict};
}

/// Seed 000's trends, each a ratio of two condition means passed to `trend(id, what, numerator, denominator,
/// numerator between packings, denominator between packings, experiment's ratio, paper DEM's ratio)`: the depth
/// effect of the regular cut, grooved (rectangular) / regular at each depth (main and thrust), trapezoidal /
/// rectangular thrust (beyond the paper); those whose conditions the case runs.
template <class Trend>
void seed000_trends(const std::map<std::string, ConditionResult>& results, const Comparison& vs_experiment,
                    const Comparison& vs_dem, Trend&& trend) {
  const std::vector<std::string> forces{"main", "thrust"};
  const auto force_of = [](const ConditionResult& r, const std::string& force, bool between) {
    if (between) return force == "main" ? r.main_between() : r.thrust_between();
    return force == "main" ? r.main() : r.thrust();
  };
  const auto reference_ratio = [&](const Comparison& comparison, const std::string& force, const std::string& num_surface,
                                   double num_depth, const std::string& den_surface, double den_depth) {
    return reference_mean(comparison, force + "_force", num_surface, num_depth) /
           reference_mean(comparison, force + "_force", den_surface, den_depth);
  };
  if (const auto *a = find_condition(results, "none", 0.1), *b = find_condition(results, "none", 0.2); a && b)
    for (const auto& force : forces)
      trend(fmt::format("depth_effect_regular_{}_force", force),
            fmt::format("depth effect: regular {} force, 0.2 mm / 0.1 mm", force), force_of(*b, force, false),
            force_of(*a, force, false), force_of(*b, force, true), force_of(*a, force, true),
            reference_ratio(vs_experiment, force, "regular", 0.2, "regular", 0.1),
            reference_ratio(vs_dem, force, "regular", 0.2, "regular", 0.1));
  for (double depth : {0.1, 0.2}) {
    const ConditionResult *regular = find_condition(results, "none", depth),
                          *rect = find_condition(results, "rectangular", depth);
    if (!regular || !rect) continue;
    for (const auto& force : forces)
      trend(fmt::format("grooved_to_regular_{}_force_{}", force, depth),
            fmt::format("grooved (rectangular) / regular {} force at {} mm", force, depth), force_of(*rect, force, false),
            force_of(*regular, force, false), force_of(*rect, force, true), force_of(*regular, force, true),
            reference_ratio(vs_experiment, force, rect->condition.surface, depth, "regular", depth),
            reference_ratio(vs_dem, force, rect->condition.surface, depth, "regular", depth));
  }
  for (double depth : {0.1, 0.2}) {
    const ConditionResult *rect = find_condition(results, "rectangular", depth),
                          *trap = find_condition(results, "trapezoidal", depth);
    if (rect && trap)
      trend(fmt::format("trapezoidal_to_rectangular_thrust_force_{}", depth),
            fmt::format("trapezoidal / rectangular grooves, thrust force at {} mm (beyond the paper)", depth),
            trap->thrust(), rect->thrust(), trap->thrust_between(), rect->thrust_between(), std::nullopt, std::nullopt);
  }
}

/// Statistics "within_cuts" (validation/soda_lime_cutting_steady/README.md): the condition table with both
/// standard errors, each mean's resolution (the acceptance: relative standard error at most
/// spec.max_relative_sem_percent, else a failure), the trends against the experiments' and the paper's DEM's with
/// their 95 % intervals (reported, not failures), and the damage under the steady cut (reported). Returns the
/// report's body (after the title) and fills `summary` and `failures`.
std::string within_cuts_report(const Spec& spec, const std::map<std::string, ConditionResult>& results,
                               const Comparison& vs_experiment, const Comparison& vs_dem,
                               std::vector<std::string>& failures, Json& summary) {
  const int n = spec.replicates, from = spec.between_packings_from_replicates;
  const std::string packings =
      spec.adaptive
          ? fmt::format("as many packings per condition as its mean needs: the smallest n from {} to {} at which the "
                        "between-packing relative standard error of the {} is at most {:g} %, packing seeds 1..n",
                        spec.adaptive->min_count, spec.adaptive->max_count,
                        spec.adaptive->results.size() == 2 ? "main and thrust forces"
                        : spec.adaptive->results.front() == "main_force_N" ? "main force"
                                                                            : "thrust force",
                        spec.max_relative_sem_percent)
          : fmt::format("{} packing{} per condition, packing seed{} 1{}", n, n == 1 ? "" : "s", n == 1 ? "" : "s",
                        n == 1 ? "" : fmt::format("..{}", n));
  std::string md = fmt::format(
      "kerf-dem, scene `{}` ({}); steady-state cuts: each cut's means are "
      "over its steady part (after the entry), with their standard errors from the batch means of its own force "
      "signal; a condition's mean is the mean over its packings of its cuts' steady means, and its standard error "
      "sqrt(sum sem_k^2) / n from the cuts' own (`main_force_sem_N`, `thrust_force_sem_N`){}{}. Forces per **1 mm** "
      "width (the DEM's out-of-plane thickness) unless stated. Experiments: seed 000 Table 6, **25.4 mm** wide; the "
      "paper's DEM: Table 4, 1 mm.\n\n",
      spec.scene.filename().string(), packings,
      n >= 2 ? "; beside it the between-packing standard error, sample std / sqrt(n)" : "",
      from > 0 ? fmt::format("; from {} packings on, the acceptance and the trends use the between-packing one "
                             "(marked *)",
                             from)
               : "");
  if (!spec.note.empty()) md += spec.note + "\n\n";
  md +=
      "| condition | kerf-dem main (N) | kerf-dem thrust (N) | between packings: main / thrust (N) | paper DEM main / "
      "thrust (N, 1 mm) | experiment main / thrust (N, 25.4 mm) | experiment per 1 mm (N) | under the steady cut: "
      "subsurface cracks, depth (um) | cut time, sum over packings (s) |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  Json conditions = Json::array(), damage = Json::array();
  std::string resolution;
  const double max_rel = spec.max_relative_sem_percent;
  for (const auto& c : spec.conditions) {
    const ConditionResult& r = results.at(c.name);
    const auto [paper, experiment, per_mm] = reference_cells(c, vs_experiment, vs_dem);
    const Estimate main = r.main(), thrust = r.thrust();
    const double main_rel = 100 * main.standard_error / std::abs(main.value);
    const double thrust_rel = 100 * thrust.standard_error / std::abs(thrust.value);
    const std::string mark = r.uses_between() ? "*" : "";
    const auto cell = [&](const Estimate& e, double rel) {
      return fmt::format("{:.2f} ± {}{} ({} %)", e.value, num(e.standard_error, 2), mark, num(rel, 2));
    };
    const bool censored = r.damage_censored_replicates > 0;
    md += fmt::format("| {} (n = {}) | {} | {} | {} / {} | {} | {} | {} | {:.0f}, {:.0f}{} | {:.0f} |\n", c.name, r.n(),
                      cell(main, main_rel), cell(thrust, thrust_rel), num(r.main_between().standard_error, 2),
                      num(r.thrust_between().standard_error, 2), paper, experiment, per_mm, r.cracks_subsurface_steady,
                      r.subsurface_steady_depth_um, censored ? " (censored)" : "", r.wall_time_s);
    // Resolved: both means to max_relative_sem_percent (a NaN standard error, a cut without one, is not).
    std::vector<std::string> unresolved;
    for (const auto& [force, rel] : {std::pair<std::string, double>{"main", main_rel}, {"thrust", thrust_rel}})
      if (!(rel <= max_rel))
        unresolved.push_back(std::isfinite(rel) ? fmt::format("{} force relative standard error {:.1f} % > {:g} %", force,
                                                              rel, max_rel)
                                                : fmt::format("{} force without a standard error (a cut's signal too "
                                                              "short for batch means)", force));
    const bool resolved = unresolved.empty();
    std::string why;
    for (const auto& u : unresolved) why += (why.empty() ? "" : ", ") + u;
    const std::string source = fmt::format("{} packing{}, {}", r.n(), r.n() == 1 ? "" : "s",
                                           r.uses_between() ? "between-packing errors" : "the cuts' own errors");
    resolution += fmt::format("- {} **{}**: main {:.3g} ± {} N ({} %), thrust {:.3g} ± {} N ({} %); {}{}\n",
                              resolved ? "RESOLVED" : "NOT RESOLVED", c.name, main.value, num(main.standard_error, 2),
                              num(main_rel, 2), thrust.value, num(thrust.standard_error, 2), num(thrust_rel, 2), source,
                              resolved ? "" : ": " + why);
    if (!resolved) failures.push_back(fmt::format("{} NOT RESOLVED: {}", c.name, why));
    conditions.push_back(Json{{"condition", c.name},
                              {"surface", c.surface},
                              {"groove_shape", c.groove_shape},
                              {"depth_of_cut_mm", c.depth_of_cut_mm},
                              {"replicates", r.n()},
                              {"standard_error_from", r.uses_between() ? "between_packings" : "within_cuts"},
                              {"main_force_N", main.value},
                              {"main_force_sem_N", finite_or_null(main.standard_error)},
                              {"main_force_between_packings_sem_N", finite_or_null(r.main_between().standard_error)},
                              {"main_force_relative_sem_percent", finite_or_null(main_rel)},
                              {"thrust_force_N", thrust.value},
                              {"thrust_force_sem_N", finite_or_null(thrust.standard_error)},
                              {"thrust_force_between_packings_sem_N", finite_or_null(r.thrust_between().standard_error)},
                              {"thrust_force_relative_sem_percent", finite_or_null(thrust_rel)},
                              {"resolved", resolved}});
    damage.push_back(Json{{"condition", c.name},
                          {"cracks_subsurface_steady", r.cracks_subsurface_steady},
                          {"subsurface_damage_depth_steady_um", r.subsurface_steady_depth_um},
                          {"damage_depth_limit_um", finite_or_null(r.damage_depth_limit_um)},
                          {"censored_replicates", r.damage_censored_replicates},
                          {"censored", censored}});
  }
  md += fmt::format(
      "\n± is the standard error of the mean from the cuts' own force signals (in brackets: relative to the mean), "
      "or, marked *, from the spread between the packings; "
      "between packings: sample std / sqrt(n) over the packings (— for one packing). Under the steady cut: the "
      "subsurface cracks below the surface machined during the steady part of the travel and the deepest of them; "
      "(censored): an active window sees cracks only down to its floor, and the deepest crack is within a disk "
      "diameter of it, so the damage may go deeper.\n\n"
      "## Acceptance\n\n"
      "Acceptance is statistical: each trend either agrees with the experiments' within its 95 % interval, or the "
      "report shows, resolved, that it does not. What fails the validation is a mean that is not resolved: every "
      "condition's mean main and thrust force must have a relative standard error of at most {:g} % (else run more "
      "travel or `--replicates N` packings){}. Whether the trends agree with the experiments is the finding, reported "
      "below and in summary.json, not the exit status.\n\n",
      max_rel,
      from > 0 ? fmt::format("; the standard error is the cuts' own below {} packings and the spread between "
                             "the packings from {} on (`acceptance.between_packings_from_replicates`: the batch-means "
                             "error of one cut is conservative for the main force, docs/performance.md)",
                             from, from)
               : "");
  md += "### Resolution of the means\n\n" + resolution;

  Json checks = Json::array();
  if (spec.trends) {
    md += fmt::format(
        "\n### Trends\n\n"
        "Each trend is a ratio of two condition means, its standard error propagated to first order (delta method: "
        "ratio × hypot of the two relative standard errors), its 95 % interval value ± q standard errors: q = {:g} "
        "for the cuts' own errors, Student's t quantile where a between-packing error enters, with Welch-"
        "Satterthwaite's degrees of freedom (given as df). Beside "
        "it the same ratio of the experiments' means (Table 6; a ratio of two forces on the same 25.4 mm width does "
        "not depend on the width) and of the paper's DEM (Table 4). AGREES: the experiment's value inside the 95 % "
        "interval; DISAGREES: outside it, a resolved disagreement, by the number of standard errors given; REPORTED: "
        "no experiment to compare.\n\n", kZ95);
    const auto trend = [&](const std::string& id, const std::string& what, const Estimate& num_est,
                           const Estimate& den_est, const Estimate& num_between, const Estimate& den_between,
                           std::optional<double> experiment, std::optional<double> paper_dem) {
      TrendCheck t = trend_check(id, what, num_est, den_est, num_between, den_between, experiment, paper_dem);
      checks.push_back(t.row);
      md += t.line;
    };
    seed000_trends(results, vs_experiment, vs_dem, trend);
  }

  // The damage under the steady cut: reported, no experiment to compare (the paper describes it, Table 6 does
  // not measure it). Differences grooved - regular, with the between-packing standard error where there is one.
  md += "\n## Subsurface damage under the steady cut (reported)\n\n";
  Json damage_trends = Json::array();
  bool any_censored = false;
  for (const auto& c : spec.conditions) any_censored = any_censored || results.at(c.name).damage_censored_replicates > 0;
  for (const std::string shape : {"rectangular", "trapezoidal"})
    for (double depth : {0.1, 0.2}) {
      const ConditionResult *regular = find_condition(results, "none", depth), *grooved = find_condition(results, shape, depth);
      if (!regular || !grooved) continue;
      const double ng = std::sqrt(grooved->n()), nr = std::sqrt(regular->n());
      const double depth_change = grooved->subsurface_steady_depth_um - regular->subsurface_steady_depth_um;
      const double depth_se =
          std::hypot(grooved->subsurface_steady_depth_std_um / ng, regular->subsurface_steady_depth_std_um / nr);
      const double cracks_change = grooved->cracks_subsurface_steady - regular->cracks_subsurface_steady;
      const double cracks_se =
          std::hypot(grooved->cracks_subsurface_steady_std / ng, regular->cracks_subsurface_steady_std / nr);
      const bool censored = grooved->damage_censored_replicates > 0 || regular->damage_censored_replicates > 0;
      md += fmt::format(
          "- {} mm, {} grooves vs regular: {:.0f} vs {:.0f} subsurface cracks ({:+.0f}{}), deepest {:.0f} vs {:.0f} um "
          "({:+.0f} um{}){}.\n",
          depth, shape, grooved->cracks_subsurface_steady, regular->cracks_subsurface_steady, cracks_change,
          std::isfinite(cracks_se) ? fmt::format(" ± {:.0f}", cracks_se) : "", grooved->subsurface_steady_depth_um,
          regular->subsurface_steady_depth_um, depth_change,
          std::isfinite(depth_se) ? fmt::format(" ± {:.0f}", depth_se) : "",
          censored ? "; censored by the active window: the depths are lower bounds and their difference is not a finding"
                   : "");
      damage_trends.push_back(Json{{"depth_of_cut_mm", depth},
                                   {"groove_shape", shape},
                                   {"cracks_subsurface_steady_change", cracks_change},
                                   {"cracks_subsurface_steady_change_standard_error", finite_or_null(cracks_se)},
                                   {"subsurface_damage_depth_steady_change_um", depth_change},
                                   {"subsurface_damage_depth_steady_change_standard_error_um", finite_or_null(depth_se)},
                                   {"censored", censored}});
    }
  if (any_censored)
    md += "\nThe steady damage depth of at least one condition reaches the active window's floor "
          "(`active_window.damage_depth_limit_um` in the cut's summary.json; `damage_depth_limit_um` and "
          "`subsurface_damage_depth_steady_censored` in kerf_dem_replicates.csv): it is censored, a lower bound. A "
          "window as deep as the damage (`active_window.below_depths`) measures it.\n";
  summary = Json{{"statistics", "within_cuts"},
                 {"replicates", spec.adaptive ? adaptive_json(*spec.adaptive) : Json(n)},
                 {"between_packings_from_replicates", from > 0 ? Json(from) : Json()},
                 {"max_relative_sem_percent", max_rel},
                 {"conditions", conditions},
                 {"checks", checks},
                 {"damage", Json{{"conditions", damage}, {"grooved_vs_regular", damage_trends}, {"censored", any_censored}}}};
  return md;
}

/// The seed case's statistics (validation/soda_lime_cutting/README.md), a reproduction of the paper's method: what
/// is compared and why; the condition table with the spread over the packings, per unit width against the
/// experiments and beside the paper's DEM; the trends against the experiments with their 95 % intervals (the
/// verdicts); the bands where validation.json gives them (the fitted case: each check with its standard error and
/// whether its verdict is resolved, a failure outside its band); the expected physics (reported); and a summary
/// of what holds and what is not resolved. Returns the report's body (after the title) and fills `summary` and
/// `failures` (bands only: a reproduction fails nothing).
std::string replicates_report(const Spec& spec, const std::map<std::string, ConditionResult>& results,
                              const Comparison& vs_experiment, const Comparison& vs_dem,
                              std::vector<std::string>& failures, Json& summary) {
  std::string md = fmt::format(
      "kerf-dem, scene `{}` ({} replicates per condition, packing seeds 1..{}); forces per **1 mm** width (the DEM's "
      "out-of-plane thickness) unless stated. Experiments: seed 000 Table 6, **25.4 mm** wide; the paper's DEM: "
      "Table 4, 1 mm.\n\n",
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
  md +=
      "| condition | kerf-dem main (N) | kerf-dem thrust (N) | paper DEM main / thrust (N, 1 mm) | experiment main / "
      "thrust "
      "(N, 25.4 mm) | experiment per 1 mm (N) | kerf / experiment per mm: main, thrust | kerf / paper DEM: main, "
      "thrust | cracks tension + shear (chip / subsurface) | subsurface depth (um) | "
      "under the steady cut: subsurface cracks, depth (um) | cut time, sum over replicates (s) |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  Json levels = Json::array();
  for (const auto& c : spec.conditions) {
    const ConditionResult& r = results.at(c.name);
    const auto [paper, experiment, per_mm] = reference_cells(c, vs_experiment, vs_dem);
    // Trapezoidal grooves have neither reference: both ratios NaN ("—").
    const bool has_reference = c.groove_shape != "trapezoidal";
    const auto ref = [&](const Comparison& comparison, const std::string& key) {
      return has_reference ? reference_mean(comparison, key, c.surface, c.depth_of_cut_mm) : kNaN;
    };
    const double exp_main = ref(vs_experiment, "main_force_per_width"),
                 exp_thrust = ref(vs_experiment, "thrust_force_per_width");
    const double dem_main = ref(vs_dem, "main_force"), dem_thrust = ref(vs_dem, "thrust_force");
    const double kerf_main = r.main_n / units::mm_to_m(r.width_mm), kerf_thrust = r.thrust_n / units::mm_to_m(r.width_mm);
    md += fmt::format(
        "| {} | {:.2f} ± {:.2f} | {:.2f} ± {:.2f} | {} | {} | {} | {}, {} | {}, {} | {:.0f} + {:.0f} ({:.0f} / {:.0f}) | "
        "{:.0f} | {:.0f}, {:.0f} | {:.0f} |\n",
        c.name, r.main_n, r.main_std_n, r.thrust_n, r.thrust_std_n, paper, experiment, per_mm,
        num(kerf_main / exp_main, 2), num(kerf_thrust / exp_thrust, 2), num(r.main_n / dem_main, 2),
        num(r.thrust_n / dem_thrust, 2), r.cracks_tensile, r.cracks_shear, r.cracks_chip, r.cracks_subsurface,
        r.subsurface_depth_um, r.cracks_subsurface_steady, r.subsurface_steady_depth_um, r.wall_time_s);
    levels.push_back(Json{{"condition", c.name},
                          {"kerf_to_experiment_per_width_main", finite_or_null(kerf_main / exp_main)},
                          {"kerf_to_experiment_per_width_thrust", finite_or_null(kerf_thrust / exp_thrust)},
                          {"kerf_to_paper_dem_main", finite_or_null(r.main_n / dem_main)},
                          {"kerf_to_paper_dem_thrust", finite_or_null(r.thrust_n / dem_thrust)}});
  }
  md +=
      "\n± is the standard deviation over the replicates. Subsurface depth: the deepest crack below the cut line "
      "anywhere "
      "in the workpiece (often a breakout of its free corner at the entry); under the steady cut: the cracks below the "
      "surface machined during the steady part of the travel, the damage the steady cut leaves in the part.\n\n";

  // The trends against the experiments: the verdicts of a reproduction.
  md += fmt::format(
      "## Trends against the experiments\n\n"
      "Each trend is a ratio of two condition means, its standard error propagated to first order (ratio × hypot of "
      "the two relative standard errors of the means over the {} packings), its 95 % interval value ± t standard "
      "errors at Welch-Satterthwaite's degrees of freedom (df). AGREES: the experiments' ratio (Table 6) inside the "
      "interval; DISAGREES: outside it, a resolved difference; UNRESOLVED: no standard error; REPORTED: no "
      "experiment to compare. The paper's DEM's ratio (Table 4) is shown beside.\n\n",
      spec.replicates);
  Json trends = Json::array();
  std::map<std::string, std::vector<std::string>> by_verdict;
  seed000_trends(results, vs_experiment, vs_dem,
                 [&](const std::string& id, const std::string& what, const Estimate& a, const Estimate& b,
                     const Estimate& a_between, const Estimate& b_between, std::optional<double> experiment,
                     std::optional<double> paper_dem) {
                   TrendCheck t = trend_check(id, what, a, b, a_between, b_between, experiment, paper_dem);
                   trends.push_back(t.row);
                   md += t.line;
                   by_verdict[t.verdict].push_back(what);
                 });

  Json checks = Json::array();
  if (spec.bands) {
    md += "\n## Acceptance bands\n\n";
    md += fmt::format(
        "Each value with its standard error (kerf-dem's over its {} packings and, against the paper's DEM, "
        "the paper's over its three); a verdict less than two standard errors from the band's edge is not "
        "resolved by these packings (`run_validation CASE OUT --replicates N` runs more).\n\n",
        spec.replicates);
    // Each check carries the standard error of its value (from kerf-dem's packings and, against the paper's DEM,
    // from the paper's three), and says whether the verdict is resolved: the value lies two standard errors or
    // more from the band's edge. A verdict that is not resolved could turn with other packings.
    const auto check = [&](const std::string& what, double value, double standard_error, double distance_to_edge,
                           bool pass, const std::string& band, bool fitted = false) {
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
    };
    for (double depth : {0.1, 0.2}) {
      const ConditionResult* regular = find_condition(results, "none", depth);
      const ConditionResult* grooved = find_condition(results, "rectangular", depth);
      if (regular) {
        for (const std::string label : {"main", "thrust"}) {
          const GroupComparison& g = group_of(vs_dem, label + "_force", "regular", depth);
          const double paper = g.measured_stats.mean, error = g.error_percent / 100,
                       band = spec.regular_max_error_percent / 100;
          const Estimate paper_mean{
              paper, g.measured_stats.standard_deviation / std::sqrt(static_cast<double>(g.measured_stats.n))};
          // error = kerf / paper - 1: its standard error is the ratio's.
          const double error_se =
              ratio_of(label == "main" ? regular->main() : regular->thrust(), paper_mean).standard_error;
          check(fmt::format("regular {} mm: {} force vs the paper's DEM mean ({:.2f} N), relative error", depth,
                            label, paper),
                error, error_se, std::abs(error) - band, std::abs(error) <= band,
                fmt::format("|error| <= {:g} %", spec.regular_max_error_percent),
                label == spec.fitted_force && std::abs(depth - spec.fitted_depth_of_cut_mm) < 1e-9);
        }
      }
      if (regular && grooved) {
        const Estimate ratio = ratio_of(grooved->main(), regular->main());
        check(fmt::format("grooved / regular main force at {} mm", depth), ratio.value, ratio.standard_error,
              ratio.value - spec.grooved_ratio_max, ratio.value < spec.grooved_ratio_max,
              fmt::format("< {:.3f}", spec.grooved_ratio_max));
      }
    }
  }
  md += "\n## Expected physics and beyond the paper (reported, not bands)\n\n";
  Json physics = Json::object();
  if (const auto *a = find_condition(results, "none", 0.1), *b = find_condition(results, "none", 0.2); a && b) {
    const Estimate main = ratio_of(b->main(), a->main()), thrust = ratio_of(b->thrust(), a->thrust());
    md += fmt::format(
        "- Regular, 0.1 -> 0.2 mm: main force {} ± {:.0f} %, thrust {} ± {:.0f} % (standard errors; the "
        "paper's DEM: {}, {}).\n",
        pct(main.value - 1), 100 * main.standard_error, pct(thrust.value - 1), 100 * thrust.standard_error,
        pct(reference_mean(vs_dem, "main_force", "regular", 0.2) / reference_mean(vs_dem, "main_force", "regular", 0.1) - 1),
        pct(reference_mean(vs_dem, "thrust_force", "regular", 0.2) / reference_mean(vs_dem, "thrust_force", "regular", 0.1) - 1));
    physics["regular_main_force_change_0.1_to_0.2"] = b->main_n / a->main_n - 1;
  }
  for (double depth : {0.1, 0.2}) {
    const ConditionResult *regular = find_condition(results, "none", depth),
                          *rect = find_condition(results, "rectangular", depth),
                          *trap = find_condition(results, "trapezoidal", depth);
    if (regular && rect)
      md += fmt::format(
          "- {} mm, grooved vs regular: cracks {:.0f} vs {:.0f} (subsurface {:.0f} vs {:.0f}), subsurface depth "
          "{:.0f} vs {:.0f} um; under the steady cut {:.0f} vs {:.0f} subsurface cracks, {:.0f} vs {:.0f} um "
          "deep.\n",
          depth, rect->cracks_tensile + rect->cracks_shear, regular->cracks_tensile + regular->cracks_shear,
          rect->cracks_subsurface, regular->cracks_subsurface, rect->subsurface_depth_um, regular->subsurface_depth_um,
          rect->cracks_subsurface_steady, regular->cracks_subsurface_steady, rect->subsurface_steady_depth_um,
          regular->subsurface_steady_depth_um);
    if (regular && rect && regular->subsurface_steady_depth_um > 0)
      physics[fmt::format("grooved_vs_regular_steady_subsurface_depth_change_{}", depth)] =
          rect->subsurface_steady_depth_um / regular->subsurface_steady_depth_um - 1;
    if (rect && trap) {
      md += fmt::format("- {} mm, trapezoidal vs rectangular grooves (the paper's suspected cause of its thrust error): thrust "
                        "{:.2f} vs {:.2f} N ({}), main {:.2f} vs {:.2f} N.\n",
                        depth, trap->thrust_n, rect->thrust_n, pct(trap->thrust_n / rect->thrust_n - 1), trap->main_n, rect->main_n);
      physics[fmt::format("trapezoidal_vs_rectangular_thrust_change_{}", depth)] = trap->thrust_n / rect->thrust_n - 1;
    }
  }
  // What holds and what does not, from the trends' verdicts above (not fixed text).
  md += "\n## What this reproduction shows\n\n";
  const auto list = [&](const std::string& verdict) {
    std::string out;
    for (const auto& what : by_verdict[verdict]) out += (out.empty() ? "" : "; ") + what;
    return out.empty() ? std::string("none") : out;
  };
  md += fmt::format("- Agrees with the experiments within its 95 % interval: {}.\n", list("AGREES"));
  md += fmt::format("- Differs from the experiments, resolved: {}.\n", list("DISAGREES"));
  md += fmt::format("- Not resolved (no standard error): {}.\n", list("UNRESOLVED"));
  if (!spec.bands)
    md += "- No pass or fail: a reproduction of the paper's method (why: above). The acceptance of the trends is "
          "`../soda_lime_cutting_steady/`'s.\n";
  Json verdicts = Json::object();
  for (const char* v : {"AGREES", "DISAGREES", "UNRESOLVED"}) verdicts[v] = by_verdict[v];
  summary = Json{{"role", spec.bands ? "bands" : "reproduction"},
                 {"trends", trends},
                 {"trend_verdicts", verdicts},
                 {"levels", levels},
                 {"checks", checks},
                 {"physics", physics}};
  return md;
}

}  // namespace

CuttingValidation run_soda_lime_cutting_validation(const fs::path& out_dir, const std::string& case_name,
                                                   int replicates) {
  const fs::path case_dir = data_directory().parent_path() / "validation" / case_name;
  Spec spec = read_spec(case_dir);
  if (replicates != 0) {
    if (replicates < spec.min_replicates() || replicates > kMaxReplicates)
      throw InputError("--replicates", std::to_string(replicates),
                       fmt::format("a number of packings from {} to {}", spec.min_replicates(), kMaxReplicates));
    spec.replicates = replicates;
  }
  CuttingValidation v;

  // 1. The runs: one study (kerf/dem/study.hpp) of the conditions, each on spec.replicates packings, in
  // OUT/study: items side by side, one thread each (18 cuts in 9 rounds on 2 cores), finished items reused, so
  // an interrupted validation resumes where it stopped. OUT/study/study.json is that study, for kerf-dem study.
  Json conditions = Json::array();
  for (const auto& c : spec.conditions)
    conditions.push_back(Json{{"cut.depth_of_cut_mm", c.depth_of_cut_mm}, {"grooves.shape", c.groove_shape}});
  Json study_replicates{{"policy", "fixed"}, {"count", spec.replicates}};
  if (spec.adaptive) {
    study_replicates = adaptive_json(*spec.adaptive);
    study_replicates["target_relative_sem_percent"] = spec.max_relative_sem_percent;
  }
  const Json study_doc{
      {"description", fmt::format("The {} validation's cuts: each condition of validation.json on {}{} packings",
                                  case_name, spec.adaptive ? "up to " : "", spec.replicates)},
      {"scene", fs::absolute(spec.scene).string()},
      {"conditions", {{"list", conditions}}},
      {"replicates", study_replicates}};
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
  std::map<std::string, ConditionResult> results;
  for (std::size_t ci = 0; ci < spec.conditions.size(); ++ci) {
    std::vector<Json> items;
    std::vector<fs::path> directories;
    // The condition's packings: fixed, or as many as the adaptive rule decided.
    const int count = outcome.summary.at("conditions").at(ci).at("count").get<int>();
    for (int k = 0; k < count; ++k) {
      const dem::StudyItem item = dem::study_item(study, static_cast<int>(ci), k);
      items.push_back(dem::read_study_item_summary(study_dir, item));
      directories.push_back(fs::path("study") / "items" / dem::study_item_name(item));
    }
    ConditionResult& r = results[spec.conditions[ci].name] =
        collect(spec.conditions[ci], items, spec.statistics == Statistics::within_cuts,
                spec.between_packings_from_replicates);
    r.directories = std::move(directories);
  }

  // 2. The kerf-dem table: one row per replicate, and the means that the report layer compares. Trapezoidal
  // grooves go beyond the paper (no measured counterpart): their rows carry their own source. within_cuts
  // appends the cuts' own standard errors (and the window's censoring of the damage depth) to both tables.
  const bool within_cuts = spec.statistics == Statistics::within_cuts;
  std::vector<std::string> header{"source", "surface", "groove_shape", "depth_of_cut_mm", "replicate", "seed"};
  header.insert(header.end(), kReplicateColumns.begin(), kReplicateColumns.end());
  if (within_cuts) header.insert(header.end(), kWithinCutColumns.begin(), kWithinCutColumns.end());
  std::string rows = csv_line(header);
  std::vector<std::string> means_header{
      "source", "surface", "groove_shape", "depth_of_cut_mm", "width_mm", "main_force_N",
      "main_force_replicate_std_N", "thrust_force_N", "thrust_force_replicate_std_N", "cracks_tensile",
      "cracks_shear", "cracks_chip", "cracks_subsurface", "subsurface_damage_depth_um",
      "cracks_subsurface_steady", "subsurface_damage_depth_steady_um"};
  if (within_cuts)
    // main_force_sem_N: sqrt(sum sem_k^2) / n of the cuts' own; *_between_packings_sem_N: std / sqrt(n) (n >= 2).
    means_header.insert(means_header.end(),
                        {"main_force_sem_N", "thrust_force_sem_N", "main_force_between_packings_sem_N",
                         "thrust_force_between_packings_sem_N", "damage_depth_limit_um",
                         "subsurface_damage_depth_steady_censored_replicates"});
  std::string means = csv_line(means_header);
  for (const auto& c : spec.conditions) {
    const ConditionResult& r = results.at(c.name);
    const std::string source = c.groove_shape == "trapezoidal" ? "kerf_dem_trapezoidal" : "kerf_dem";
    for (const auto& row : r.replicates) {
      std::vector<std::string> fields{source,
                                      c.surface,
                                      c.groove_shape,
                                      csv_number(c.depth_of_cut_mm),
                                      std::to_string(row.at("replicate").get<int>()),
                                      std::to_string(row.at("seed").get<long long>())};
      for (const auto& column : kReplicateColumns) fields.push_back(csv_number(row.at(column)));
      if (within_cuts)
        for (const auto& column : kWithinCutColumns) fields.push_back(csv_field(row.at(column)));
      rows += csv_line(fields);
    }
    std::vector<std::string> mean_fields{
        source, c.surface, c.groove_shape, csv_number(c.depth_of_cut_mm), csv_number(r.width_mm),
        csv_number(r.main_n), csv_number(r.main_std_n), csv_number(r.thrust_n),
        csv_number(r.thrust_std_n), csv_number(r.cracks_tensile), csv_number(r.cracks_shear),
        csv_number(r.cracks_chip), csv_number(r.cracks_subsurface), csv_number(r.subsurface_depth_um),
        csv_number(r.cracks_subsurface_steady), csv_number(r.subsurface_steady_depth_um)};
    if (within_cuts)
      mean_fields.insert(mean_fields.end(),
                         {csv_number(r.main_sem_within_n), csv_number(r.thrust_sem_within_n),
                          csv_number(r.main_between().standard_error), csv_number(r.thrust_between().standard_error),
                          csv_number(r.damage_depth_limit_um), std::to_string(r.damage_censored_replicates)});
    means += csv_line(mean_fields);
  }
  write_file_atomically(out_dir / "kerf_dem_replicates.csv", rows);
  write_file_atomically(out_dir / "kerf_dem_means.csv", means);
  v.files = {out_dir / "kerf_dem_replicates.csv", out_dir / "kerf_dem_means.csv"};

  // 3. Through the report layer: against the experiments (both width views) and against the paper's DEM.
  const fs::path means_csv = fs::absolute(out_dir / "kerf_dem_means.csv");
  std::map<std::string, Comparison> comparisons;
  for (const auto& [name, against_dem] : std::vector<std::pair<std::string, bool>>{{"vs_experiment", false}, {"vs_paper_dem", true}}) {
    const Json doc = comparison_document(fs::absolute(spec.experiments), means_csv,
                                         against_dem ? "Soda-lime glass, orthogonal cutting: kerf-dem vs the paper's DEM (seed 000)"
                                                     : "Soda-lime glass, orthogonal cutting: experiment vs the paper's DEM and kerf-dem (seed 000)",
                                         against_dem);
    write_file_atomically(out_dir / (name + ".json"), doc.dump(2) + "\n");
    const Comparison& comparison = comparisons[name] = run_comparison(parse_comparison_config(doc, out_dir));
    for (const auto& f : write_report(comparison, out_dir / name)) v.files.push_back(f);
  }
  // The reference means below come from these comparisons: measured = experiments (vs_experiment) or the
  // paper's DEM (vs_paper_dem), prediction = kerf-dem in the latter.
  const Comparison& vs_experiment = comparisons.at("vs_experiment");
  const Comparison& vs_dem = comparisons.at("vs_paper_dem");

  // 4. Acceptance and the expected physics.
  // within_cuts: the conditions' resolution and the trends (within_cuts_report); otherwise the bands.
  std::string md;
  Json summary_doc;
  if (within_cuts) {
    md = "# Validation: soda-lime glass, orthogonal cutting, steady state (seed 000)\n\n";
    md += within_cuts_report(spec, results, vs_experiment, vs_dem, v.failures, summary_doc);
  } else {
    md = "# Validation: soda-lime glass, orthogonal cutting (seed 000)\n\n";
    md += replicates_report(spec, results, vs_experiment, vs_dem, v.failures, summary_doc);
  }
  md += "\nReports through the report layer: [vs_experiment/report.md](vs_experiment/report.md) (the paper's direct "
        "comparison and the per-unit-width one), [vs_paper_dem/report.md](vs_paper_dem/report.md). Per-replicate "
        "results: `kerf_dem_replicates.csv`; each run's forces, cracks and picture: "
        "`study/items/condition_<c>_seed_<s>/` (the conditions in validation.json's order; `study/items.csv` lists "
        "them).\n";
  for (const char* name : {"regular_0.1", "grooved_0.1"}) {
    const auto r = results.find(name);
    if (r == results.end() || r->second.directories.empty()) continue;
    const fs::path picture = out_dir / r->second.directories.front() / "specimen.png";
    if (!fs::exists(picture)) continue;
    fs::copy_file(picture, out_dir / fmt::format("snapshot_{}.png", name), fs::copy_options::overwrite_existing);
    md += fmt::format("\n![{}, replicate 1](snapshot_{}.png)\n", name, name);
  }
  v.judged = within_cuts || spec.bands;
  md += v.judged ? fmt::format("\n**{}**\n", v.failures.empty() ? "PASSED" : "FAILED")
                 : std::string("\n**REPORTED** (a reproduction: no pass or fail)\n");
  write_file_atomically(out_dir / "report.md", md);
  summary_doc["passed"] = v.judged ? Json(v.failures.empty()) : Json();
  write_file_atomically(out_dir / "summary.json", summary_doc.dump(2) + "\n");
  v.files.push_back(out_dir / "report.md");
  v.files.push_back(out_dir / "summary.json");
  return v;
}

}  // namespace kerf
