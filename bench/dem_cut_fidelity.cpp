// Speed against accuracy of the DEM cut (issue 5): mean main and thrust force, and the cost, against the
// four fidelity knobs a user turns — tool speed, particle size (radii scaled at fixed micro-parameters,
// i.e. at fixed calibrated macro-properties, see docs/performance.md), Cundall's local damping and the
// time-step safety factor (engine.time_step_safety) — each on several packings, since one cut's mean force
// scatters by tens of percent from packing to packing.
//
//   build/bench/bench_dem_cut_fidelity [--knob speed|radius|damping|time_step|all] [--replicates 3] [--threads 2]
//       [--out-dir bench-out/dem_cut_fidelity] [--scene validation/soda_lime_cutting/scene.json]
//
// The cuts are one kerf-dem study (kerf/dem/study/study.hpp) in --out-dir/study: each knob value is a condition
// (the base scene with that knob's keys overridden: cut.speed_m_per_s, specimen.radius_min_um and
// radius_max_um, material.local_damping, engine.time_step_safety), a setting two knobs share (the base case)
// is one condition, and each runs on --replicates packings (seeds: the scene's specimen.seed + 0..N-1), side by
// side, one thread each. Finished cuts are reused on a rerun, also when other knobs or values are asked for
// (the study moves them to their new condition numbers), so an interrupted benchmark loses only the cuts in
// flight; --out-dir/study/study.json reruns the same cuts with `kerf-dem study`.
//
// Writes, in --out-dir: runs.csv (one row per knob value and packing), summary.csv (per knob value: replicate
// mean, replicate std, standard error of the mean, change against the reference value, and the cut's wall
// time on its one thread, genesis excluded) and fidelity_<knob>.png (mean +- standard error).
//
// Base case: data/scenes/dem_cut.json at 0.25 m/s with no frames (1 mm x 0.5 mm, radii 10-13 um,
// soda_lime_glass_fj, rake -15 deg, clearance 15 deg, sharp, depth of cut 0.1 mm, travel 0.3 mm, entry 25 %
// excluded), or --scene: that kerf-dem cut scene. base_case.txt in --out-dir names the base case, and a
// directory holding the cuts of another one is refused. Before the study machinery (2026-11-26) the built-in
// case was built from SI literals, one ulp from the scene's radii: the published figures of
// docs/performance.md from that build are statistically like, not equal to, a rerun of this one.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "kerf/dem/procedures/cut_results.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/dem/study/study.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/material.hpp"
#include "kerf/metrics.hpp"
#include "kerf/plot.hpp"
#include "kerf/units.hpp"

namespace fs = std::filesystem;
using namespace kerf;
using namespace kerf::dem;

namespace {

/// The cut's results as this bench reads and writes them: by their names in the cut's result table.
namespace ck = kerf::dem::cut_keys;

/// One knob: its name (--knob), what the plot calls it, the values to cut, and the overrides of one value.
struct Knob {
  std::string name, subject, axis_label;
  std::vector<double> values;
};

/// The settings the knobs move, read from the base scene as kerf-dem reads it.
struct BaseSettings {
  double speed_m_per_s = 0, radius_min_um = 0, radius_max_um = 0, local_damping = 0, time_step_safety = 0;
};

BaseSettings base_settings(const Json& scene, const fs::path& scene_dir) {
  const dem::Scene s = dem::read_scene(scene, scene_dir);
  BaseSettings b;
  b.speed_m_per_s = scene.at("cut").value("speed_m_per_s", 0.0);
  if (b.speed_m_per_s <= 0) throw InputError("cut.speed_m_per_s", "(missing)", "the base scene's tool speed");
  b.radius_min_um = units::m_to_um(s.common.specimen.radius_min_m);
  b.radius_max_um = units::m_to_um(s.common.specimen.radius_max_m);
  b.local_damping = s.common.material.local_damping;
  b.time_step_safety = s.common.engine.time_step_safety;
  return b;
}

/// The overrides of one knob value: only the keys whose value differs from the base scene's, so that the base
/// setting of every knob is the same condition (the scene itself).
std::vector<std::pair<std::string, Json>> overrides_of(const std::string& knob, double v, const BaseSettings& b) {
  std::vector<std::pair<std::string, Json>> o;
  if (knob == "speed" && v != b.speed_m_per_s) o.emplace_back("cut.speed_m_per_s", v);
  if (knob == "radius" && v != 1) {
    o.emplace_back("specimen.radius_min_um", b.radius_min_um * v);
    o.emplace_back("specimen.radius_max_um", b.radius_max_um * v);
  }
  if (knob == "damping" && v != b.local_damping) o.emplace_back("material.local_damping", v);
  if (knob == "time_step" && v != b.time_step_safety) o.emplace_back("engine.time_step_safety", v);
  return o;
}

struct Stats {
  double mean = 0, std = 0, sem = 0;
};
Stats stats_of(const std::vector<double>& v) {
  if (v.size() < 2) return {v.empty() ? 0 : v[0], 0, 0};  // one packing: no spread to report
  const SampleStatistics st = sample_statistics(v);
  return {st.mean, st.standard_deviation, st.standard_deviation / std::sqrt(static_cast<double>(v.size()))};
}

/// The reference of each knob: the finest setting (lowest speed, smallest disks, smallest step); damping has none that
/// is "converged" (it is a model parameter), so its changes are against the default 0.7.
double reference_value(const std::string& knob, const std::vector<double>& values) {
  if (knob == "damping") return 0.7;
  return *std::min_element(values.begin(), values.end());
}

/// One cut of the study, from its item's summary.json.
struct Run {
  int n_particles = 0;
  std::int64_t steps = 0;
  double main_force_N = 0, thrust_force_N = 0, cut_wall_s = 0;
};

/// The command line.
struct Options {
  std::string knob = "all", out_dir = "bench-out/dem_cut_fidelity", scene_path;
  int replicates = 3, threads = 2;
  double base_speed = 0;
  std::array<Knob, 4> knobs{{{"speed", "speed", "tool speed (m/s)", {2, 1, 0.5, 0.25, 0.125}},
                             {"radius", "radius", "radius scale (1: the base case's radii)", {1.5, 1.0, 0.75}},
                             {"damping", "damping", "local damping", {0.3, 0.5, 0.7, 0.9}},
                             {"time_step", "time step", "time-step safety factor f", {0.4, 0.8, 1.0}}}};
  bool selected(const Knob& k) const { return knob == "all" || knob == k.name; }
};

void add_options(CLI::App& app, Options& o) {
  auto& [speeds, radius_scales, dampings, time_step_safeties] = o.knobs;
  std::vector<std::string> knob_choices{"all"};
  for (const auto& k : o.knobs) knob_choices.push_back(k.name);
  app.add_option("--knob", o.knob, "speed, radius, damping, time_step or all")->check(CLI::IsMember(knob_choices));
  app.add_option("--replicates", o.replicates, "packings per setting (seeds: the scene's + 0..N-1)")
      ->check(CLI::Range(1, 100));
  app.add_option("--threads", o.threads, "cuts run side by side")->check(CLI::Range(1, 256));
  app.add_option("--out-dir", o.out_dir, "output directory");
  app.add_option("--scene", o.scene_path,
                 "a kerf-dem cut scene as the base case (its workpiece, cut and material; seed k = its replicate k); "
                 "default: data/scenes/dem_cut.json at 0.25 m/s")
      ->check(CLI::ExistingFile);
  app.add_option("--speeds", speeds.values, "tool speeds, m/s")->check(CLI::PositiveNumber);
  app.add_option("--radius-scales", radius_scales.values, "radius scales (1: the base case's radii)")
      ->check(CLI::PositiveNumber);
  app.add_option("--dampings", dampings.values, "local damping values")->check(CLI::Range(0.0, 0.99));
  app.add_option("--time-step-safeties", time_step_safeties.values,
                 "time-step safety factors f (engine.time_step_safety: dt = f * the critical-step estimate)")
      ->check(CLI::Range(0.01, 1.0));
  app.add_option("--base-speed", o.base_speed,
                 "tool speed of the radius, damping and time-step studies, m/s (default: the base scene's)")
      ->check(CLI::PositiveNumber);
}

/// The base case: its scene (the other knobs' studies hold its speed, radii, damping and time step), folder,
/// settings and name.
struct BaseCase {
  Json scene;
  fs::path scene_dir;
  BaseSettings settings;
  std::string name;
};

BaseCase base_case(const Options& o) {
  const fs::path scene_file =
      o.scene_path.empty() ? data_directory() / "scenes" / "dem_cut.json" : fs::path(o.scene_path);
  Json scene = read_json_file(scene_file);
  if (!scene.is_object() || scene.value("kind", "") != "cut")
    throw InputError("kind", scene.is_object() ? scene.value("kind", "(missing)") : "(not an object)",
                     "'cut' (a cut scene for --scene)");
  if (o.scene_path.empty()) {
    scene["cut"]["speed_m_per_s"] = 0.25;
    scene["output"]["frame_every_samples"] = 0;
  }
  if (o.base_speed > 0) scene["cut"]["speed_m_per_s"] = o.base_speed;
  if (scene.contains("material") && scene["material"].is_string())  // so that material.local_damping applies
    scene["material"] = Json{{"base", scene["material"]}};
  const fs::path scene_dir = fs::absolute(scene_file).parent_path();
  const BaseSettings settings = base_settings(scene, scene_dir);
  return {scene, scene_dir, settings, o.scene_path.empty() ? "built-in" : o.scene_path};
}

/// One directory, one base case: the study would replace another base case's cuts (base_case.txt names it).
void claim_out_dir(const std::string& out_dir, const std::string& base_name) {
  fs::create_directories(out_dir);
  const fs::path base_file = fs::path(out_dir) / "base_case.txt";
  if (std::ifstream in(base_file); in) {
    std::string recorded;
    std::getline(in, recorded);
    if (recorded != base_name)
      throw InputError("--out-dir", out_dir,
                       fmt::format("a directory without runs of another base case (it holds runs of '{}', "
                                   "this run's base is '{}')",
                                   recorded, base_name));
  }
  write_file_atomically(base_file, base_name);
}

std::string value_key(double v) {
  return fmt::format("{:.6g}", v);
}

/// The study's conditions: each selected knob value, a setting two knobs share being one condition.
struct Conditions {
  Json list = Json::array();
  std::map<std::pair<std::string, std::string>, int> of;  // (knob, value_key) -> condition
};

Conditions conditions(const Options& o, const BaseSettings& base) {
  Conditions c;
  std::map<std::string, int> condition_of_overrides;
  for (const auto& k : o.knobs) {
    if (!o.selected(k)) continue;
    for (double v : k.values) {
      Json overrides = Json::object();
      for (const auto& [key, value] : overrides_of(k.name, v, base)) overrides[key] = value;
      const auto [it, fresh] = condition_of_overrides.try_emplace(overrides.dump(), static_cast<int>(c.list.size()));
      if (fresh) c.list.push_back(overrides);
      c.of[{k.name, value_key(v)}] = it->second;
    }
  }
  return c;
}

/// Runs (or reuses) every cut as one study in OUT/study; each cut by (condition, packing).
std::map<std::pair<int, int>, Run> run_cuts(const Options& o, const BaseCase& base, const Conditions& c,
                                            dem::StudySpec& study) {
  // The dearest cuts are not sorted first any more: the study hands out replicate-major, every condition's
  // first packing before any second one.
  const Json study_doc{{"description", fmt::format("bench_dem_cut_fidelity: knob {}, base case {}", o.knob, base.name)},
                       {"scene", base.scene},
                       {"conditions", {{"list", c.list}}},
                       {"replicates", {{"policy", "fixed"}, {"count", o.replicates}}}};
  const fs::path study_dir = fs::path(o.out_dir) / "study";
  study = dem::read_study(study_doc, base.scene_dir / "fidelity.json");
  fs::create_directories(study_dir);
  write_file_atomically(study_dir / "study.json", study_doc.dump(2) + "\n");
  std::fprintf(stderr, "%zu conditions x %d packings (finished cuts in %s are reused)\n", c.list.size(), o.replicates,
               study_dir.c_str());
  dem::StudyOptions options;
  options.out = study_dir;
  options.threads = o.threads;
  options.log_lines = !is_terminal(stdout);
  options.stop_at_first_failure = true;
  dem::run_study_local(study, options);
  std::map<std::pair<int, int>, Run> cut;
  for (int i = 0; i < static_cast<int>(c.list.size()); ++i)
    for (int k = 0; k < o.replicates; ++k) {
      const Json one = dem::read_study_item_summary(study_dir, dem::study_item(study, i, k));
      cut[{i, k}] = Run{one.at("n_particles").get<int>(), one.at("steps").get<std::int64_t>(),
                        one.at("results").at(ck::main_force_N).get<double>(),
                        one.at("results").at(ck::thrust_force_N).get<double>(), one.at("wall_time_s").get<double>()};
    }
  return cut;
}

/// One knob's rows of runs.csv and summary.csv, in the order the options list its values, and its figure.
void knob_report(const Options& o, const Knob& k, const Conditions& c, const dem::StudySpec& study,
                 const std::map<std::pair<int, int>, Run>& cut, std::string& runs, std::string& summary) {
  struct Row {
    double value;
    Stats main, thrust, cost;
    int particles;
  };
  std::vector<Row> rows;
  for (double v : k.values) {
    const int condition = c.of.at({k.name, value_key(v)});
    std::vector<double> fm, ft, cost;
    int particles = 0;
    for (int r = 0; r < o.replicates; ++r) {
      const Run& run = cut.at({condition, r});
      fm.push_back(run.main_force_N), ft.push_back(run.thrust_force_N), cost.push_back(run.cut_wall_s);
      particles = run.n_particles;
      runs += csv_line({k.name, csv_number(v), std::to_string(r + 1),
                        std::to_string(dem::study_item(study, condition, r).seed), std::to_string(condition + 1),
                        std::to_string(run.n_particles), std::to_string(run.steps), csv_number(run.main_force_N),
                        csv_number(run.thrust_force_N), csv_number(run.cut_wall_s)});
    }
    rows.push_back({v, stats_of(fm), stats_of(ft), stats_of(cost), particles});
  }
  std::vector<double> vs;
  for (const auto& r : rows) vs.push_back(r.value);
  const double ref = reference_value(k.name, vs);
  const auto ref_row = std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.value == ref; });
  FigureSpec fig;
  fig.title = fmt::format("DEM cut, {} replicates: forces against {}", o.replicates, k.subject);
  fig.x_label = k.axis_label;
  fig.y_label = "force per 1 mm width (N)";
  PlotSeries main{"main force", {}, {}, {}, {}, SeriesStyle::points_and_line, 0, 0};
  PlotSeries thrust{"thrust force", {}, {}, {}, {}, SeriesStyle::points_and_line, 1, 2};
  for (const auto& r : rows) {
    const double dm = ref_row == rows.end() ? NAN : r.main.mean / ref_row->main.mean - 1;
    const double dt = ref_row == rows.end() ? NAN : r.thrust.mean / ref_row->thrust.mean - 1;
    const double dc = ref_row == rows.end() ? NAN : r.cost.mean / ref_row->cost.mean;
    summary += csv_line({k.name, csv_number(r.value), std::to_string(o.replicates), std::to_string(r.particles),
                         csv_number(r.main.mean), csv_number(r.main.std), csv_number(r.main.sem),
                         csv_number(r.thrust.mean), csv_number(r.thrust.std), csv_number(r.thrust.sem), csv_number(dm),
                         csv_number(dt), csv_number(r.cost.mean), csv_number(dc)});
    main.x.push_back(r.value), main.y.push_back(r.main.mean), main.y_error.push_back(r.main.sem);
    thrust.x.push_back(r.value), thrust.y.push_back(r.thrust.mean), thrust.y_error.push_back(r.thrust.sem);
  }
  for (PlotSeries* s : {&main, &thrust}) sort_by_x(*s);
  fig.series = {main, thrust};
  fig.y_min = 0;
  render_png(fig, fs::path(o.out_dir) / ("fidelity_" + k.name + ".png"));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"DEM cut: forces and cost against tool speed, particle size, local damping and time step"};
  Options o;
  add_options(app, o);
  CLI11_PARSE(app, argc, argv);
  try {
    const BaseCase base = base_case(o);
    claim_out_dir(o.out_dir, base.name);
    const Conditions c = conditions(o, base.settings);
    dem::StudySpec study;
    const auto cut = run_cuts(o, base, c, study);
    std::string runs = csv_line({"knob", "value", "replicate", "seed", "condition", "n_particles", "steps",
                                 std::string(ck::main_force_N), std::string(ck::thrust_force_N), "cut_wall_s"});
    std::string summary = csv_line({"knob", "value", "replicates", "n_particles", std::string(ck::main_force_N),
                                    dem::replicate_spread_key(ck::main_force_N), std::string(ck::main_force_sem_N),
                                    std::string(ck::thrust_force_N), dem::replicate_spread_key(ck::thrust_force_N),
                                    std::string(ck::thrust_force_sem_N), "main_force_change_vs_reference",
                                    "thrust_force_change_vs_reference", "cut_wall_s_per_cut", "cost_vs_reference"});
    for (const auto& k : o.knobs)
      if (o.selected(k)) knob_report(o, k, c, study, cut, runs, summary);
    write_file_atomically(fs::path(o.out_dir) / "runs.csv", runs);
    write_file_atomically(fs::path(o.out_dir) / "summary.csv", summary);
    std::printf("%s", summary.c_str());
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "bench_dem_cut_fidelity: %s\n", e.what());
    return kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_dem_cut_fidelity: %s\n", e.what());
    return kExitModelError;
  }
}
