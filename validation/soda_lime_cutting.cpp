// Seed 000's orthogonal cutting of soda-lime glass (validation/soda_lime_cutting/): runs every condition of
// validation.json with kerf-dem (replicates on different packings), collects the forces, compares them through
// the report layer with the experiments (Table 6, 25.4 mm wide) and the paper's DEM (Table 4, 1 mm), and checks
// the acceptance bands. See validation/soda_lime_cutting/README.md.
#include "soda_lime_cutting.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>


#include "kerf/comparison_config.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/dem/study.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/material.hpp"
#include "kerf/metrics.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace fs = std::filesystem;

namespace {

struct Condition {
  std::string name, surface, groove_shape;
  double depth_of_cut_mm = 0;
};

/// Packings per condition, in validation.json or from --replicates: at least two for a sample standard deviation.
constexpr int kMinReplicates = 2, kMaxReplicates = 100;

struct Spec {
  fs::path scene, experiments;
  std::string note;  ///< printed under the report's title (e.g. what a fitted material was fitted to)
  int replicates = 3;
  std::vector<Condition> conditions;
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
  s.regular_max_error_percent = a.get_number("regular_force_max_abs_error_vs_paper_dem_percent", Range::positive(), "%");
  s.grooved_ratio_max = a.get_number("grooved_to_regular_main_force_ratio_max", Range::positive(), "");
  if (auto fitted = a.find_object("fitted")) {
    s.fitted_depth_of_cut_mm = fitted->get_number("depth_of_cut_mm", Range::positive(), "mm");
    s.fitted_force = fitted->get_choice("force", {"main", "thrust"});
    fitted->finish();
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

/// A mean with its standard error.
struct Estimate {
  double value = 0, standard_error = 0;
};

/// The ratio of two independent estimates, its standard error propagated to first order:
/// se(a / b) = (a / b) hypot(se_a / a, se_b / b).
Estimate ratio_of(const Estimate& a, const Estimate& b) {
  const double r = a.value / b.value;
  return {r, r * std::hypot(a.standard_error / a.value, b.standard_error / b.value)};
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

/// Replicate results of one condition, from its study items' summaries.
struct ConditionResult {
  Condition condition;
  Json replicates;  ///< one row per replicate: replicate, seed and kReplicateColumns
  double main_n = 0, thrust_n = 0, main_std_n = 0, thrust_std_n = 0, width_mm = 1;
  /// The mean forces with their standard errors over the replicates (packings are independent samples).
  Estimate main() const { return {main_n, main_std_n / std::sqrt(static_cast<double>(replicates.size()))}; }
  Estimate thrust() const { return {thrust_n, thrust_std_n / std::sqrt(static_cast<double>(replicates.size()))}; }
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

}  // namespace

CuttingValidation run_soda_lime_cutting_validation(const fs::path& out_dir, const std::string& case_name,
                                                   int replicates) {
  const fs::path case_dir = data_directory().parent_path() / "validation" / case_name;
  Spec spec = read_spec(case_dir);
  if (replicates != 0) {
    if (replicates < kMinReplicates || replicates > kMaxReplicates)
      throw InputError("--replicates", std::to_string(replicates),
                       fmt::format("a number of packings from {} to {}", kMinReplicates, kMaxReplicates));
    spec.replicates = replicates;
  }
  CuttingValidation v;

  // 1. The runs: one study (kerf/dem/study.hpp) of the conditions, each on spec.replicates packings, in
  // OUT/study: items side by side, one thread each (18 cuts in 9 rounds on 2 cores), finished items reused, so
  // an interrupted validation resumes where it stopped. OUT/study/study.json is that study, for kerf-dem study.
  Json conditions = Json::array();
  for (const auto& c : spec.conditions)
    conditions.push_back(Json{{"cut.depth_of_cut_mm", c.depth_of_cut_mm}, {"grooves.shape", c.groove_shape}});
  const Json study_doc{
      {"description", fmt::format("The {} validation's cuts: each condition of validation.json on {} packings", case_name,
                                  spec.replicates)},
      {"scene", fs::absolute(spec.scene).string()},
      {"conditions", {{"list", conditions}}},
      {"replicates", {{"policy", "fixed"}, {"count", spec.replicates}}}};
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
  dem::run_study_local(study, options);
  std::map<std::string, ConditionResult> results;
  for (std::size_t ci = 0; ci < spec.conditions.size(); ++ci) {
    std::vector<Json> items;
    std::vector<fs::path> directories;
    for (int k = 0; k < spec.replicates; ++k) {
      const dem::StudyItem item = dem::study_item(study, static_cast<int>(ci), k);
      items.push_back(dem::read_study_item_summary(study_dir, item));
      directories.push_back(fs::path("study") / "items" / dem::study_item_name(item));
    }
    ConditionResult& r = results[spec.conditions[ci].name] = collect(spec.conditions[ci], items);
    r.directories = std::move(directories);
  }

  // 2. The kerf-dem table: one row per replicate, and the means that the report layer compares. Trapezoidal
  // grooves go beyond the paper (no measured counterpart): their rows carry their own source.
  std::vector<std::string> header{"source", "surface", "groove_shape", "depth_of_cut_mm", "replicate", "seed"};
  header.insert(header.end(), kReplicateColumns.begin(), kReplicateColumns.end());
  std::string rows = csv_line(header);
  std::string means =
      csv_line({"source", "surface", "groove_shape", "depth_of_cut_mm", "width_mm", "main_force_N",
                "main_force_replicate_std_N", "thrust_force_N", "thrust_force_replicate_std_N", "cracks_tensile",
                "cracks_shear", "cracks_chip", "cracks_subsurface", "subsurface_damage_depth_um",
                "cracks_subsurface_steady", "subsurface_damage_depth_steady_um"});
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
      rows += csv_line(fields);
    }
    means += csv_line({source, c.surface, c.groove_shape, csv_number(c.depth_of_cut_mm), csv_number(r.width_mm),
                       csv_number(r.main_n), csv_number(r.main_std_n), csv_number(r.thrust_n),
                       csv_number(r.thrust_std_n), csv_number(r.cracks_tensile), csv_number(r.cracks_shear),
                       csv_number(r.cracks_chip), csv_number(r.cracks_subsurface), csv_number(r.subsurface_depth_um),
                       csv_number(r.cracks_subsurface_steady), csv_number(r.subsurface_steady_depth_um)});
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
  const auto paper_dem_mean = [&](const std::string& key, const std::string& surface, double depth_mm) {
    return group_of(vs_dem, key, surface, depth_mm).measured_stats.mean;
  };

  // 4. Acceptance and the expected physics.
  std::string md = "# Validation: soda-lime glass, orthogonal cutting (seed 000)\n\n";
  md += fmt::format("kerf-dem, scene `{}` ({} replicates per condition, packing seeds 1..{}); forces per **1 mm** width "
                    "(the DEM's out-of-plane thickness) unless stated. Experiments: seed 000 Table 6, **25.4 mm** wide; "
                    "the paper's DEM: Table 4, 1 mm.\n\n",
                    spec.scene.filename().string(), spec.replicates, spec.replicates);
  if (!spec.note.empty()) md += spec.note + "\n\n";
  md +=
      "| condition | kerf-dem main (N) | kerf-dem thrust (N) | paper DEM main / thrust (N, 1 mm) | experiment main / "
      "thrust "
      "(N, 25.4 mm) | experiment per 1 mm (N) | cracks tension + shear (chip / subsurface) | subsurface depth (um) | "
      "under the steady cut: subsurface cracks, depth (um) | cut time, sum over replicates (s) |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& c : spec.conditions) {
    const ConditionResult& r = results.at(c.name);
    std::string paper = "—", experiment = "—", per_mm = "—";
    if (c.groove_shape != "trapezoidal") {
      paper = fmt::format("{:.2f} / {:.2f}", paper_dem_mean("main_force", c.surface, c.depth_of_cut_mm),
                          paper_dem_mean("thrust_force", c.surface, c.depth_of_cut_mm));
      const auto measured = [&](const std::string& key) {
        return group_of(vs_experiment, key, c.surface, c.depth_of_cut_mm).measured_stats.mean;
      };
      experiment = fmt::format("{:.2f} / {:.2f}", measured("main_force"), measured("thrust_force"));
      // The per-unit-width view is in N/m: per 1 mm of width is 1e-3 of it.
      per_mm = fmt::format("{:.3f} / {:.3f}", 1e-3 * measured("main_force_per_width"), 1e-3 * measured("thrust_force_per_width"));
    }
    md += fmt::format(
        "| {} | {:.2f} ± {:.2f} | {:.2f} ± {:.2f} | {} | {} | {} | {:.0f} + {:.0f} ({:.0f} / {:.0f}) | {:.0f} | "
        "{:.0f}, {:.0f} | "
        "{:.0f} |\n",
        c.name, r.main_n, r.main_std_n, r.thrust_n, r.thrust_std_n, paper, experiment, per_mm, r.cracks_tensile,
        r.cracks_shear, r.cracks_chip, r.cracks_subsurface, r.subsurface_depth_um, r.cracks_subsurface_steady,
        r.subsurface_steady_depth_um, r.wall_time_s);
  }
  md +=
      "\n± is the standard deviation over the replicates. Subsurface depth: the deepest crack below the cut line "
      "anywhere "
      "in the workpiece (often a breakout of its free corner at the entry); under the steady cut: the cracks below the "
      "surface machined during the steady part of the travel, the damage the steady cut leaves in the part.\n\n"
      "## Acceptance\n\n";
  md += fmt::format(
      "Each value with its standard error (kerf-dem's over its {} packings and, against the paper's DEM, "
      "the paper's over its three); a verdict less than two standard errors from the band's edge is not "
      "resolved by these packings (`run_validation CASE OUT --replicates N` runs more).\n\n",
      spec.replicates);
  Json checks = Json::array();
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
    if (!pass) v.failures.push_back(fmt::format("{} = {:.4g} (band: {})", what, value, band));
  };
  const auto find = [&](const std::string& shape, double depth) -> const ConditionResult* {
    for (const auto& [name, r] : results)
      if (r.condition.groove_shape == shape && std::abs(r.condition.depth_of_cut_mm - depth) < 1e-9) return &r;
    return nullptr;
  };
  for (double depth : {0.1, 0.2}) {
    const ConditionResult* regular = find("none", depth);
    const ConditionResult* grooved = find("rectangular", depth);
    if (regular) {
      for (const std::string label : {"main", "thrust"}) {
        const GroupComparison& g = group_of(vs_dem, label + "_force", "regular", depth);
        const double paper = g.measured_stats.mean, error = g.error_percent / 100, band = spec.regular_max_error_percent / 100;
        const Estimate paper_mean{
            paper, g.measured_stats.standard_deviation / std::sqrt(static_cast<double>(g.measured_stats.n))};
        // error = kerf / paper - 1: its standard error is the ratio's.
        const double error_se =
            ratio_of(label == "main" ? regular->main() : regular->thrust(), paper_mean).standard_error;
        check(fmt::format("regular {} mm: {} force vs the paper's DEM mean ({:.2f} N), relative error", depth, label,
                          paper),
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
  md += "\n## Expected physics and beyond the paper (reported, not bands)\n\n";
  Json physics = Json::object();
  if (const auto *a = find("none", 0.1), *b = find("none", 0.2); a && b) {
    const Estimate main = ratio_of(b->main(), a->main()), thrust = ratio_of(b->thrust(), a->thrust());
    md += fmt::format(
        "- Regular, 0.1 -> 0.2 mm: main force {} ± {:.0f} %, thrust {} ± {:.0f} % (standard errors; the "
        "paper's DEM: {}, {}).\n",
        pct(main.value - 1), 100 * main.standard_error, pct(thrust.value - 1), 100 * thrust.standard_error,
        pct(paper_dem_mean("main_force", "regular", 0.2) / paper_dem_mean("main_force", "regular", 0.1) - 1),
        pct(paper_dem_mean("thrust_force", "regular", 0.2) / paper_dem_mean("thrust_force", "regular", 0.1) - 1));
    physics["regular_main_force_change_0.1_to_0.2"] = b->main_n / a->main_n - 1;
  }
  for (double depth : {0.1, 0.2}) {
    const ConditionResult *regular = find("none", depth), *rect = find("rectangular", depth), *trap = find("trapezoidal", depth);
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
  md += fmt::format("\n**{}**\n", v.failures.empty() ? "PASSED" : "FAILED");
  write_file_atomically(out_dir / "report.md", md);
  write_file_atomically(out_dir / "summary.json",
                        Json{{"passed", v.failures.empty()}, {"checks", checks}, {"physics", physics}}.dump(2) + "\n");
  v.files.push_back(out_dir / "report.md");
  v.files.push_back(out_dir / "summary.json");
  return v;
}

}  // namespace kerf
