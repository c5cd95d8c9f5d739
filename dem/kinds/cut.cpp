// Scene kind "cut": orthogonal cutting (seed 000 Section 4; kerf/dem/procedures/cutting.hpp), forces against tool
// travel and cracks by mode and place; one run with checkpoints, or replicates on several packings side by side.
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <optional>

#include "common.hpp"
#include "kerf/analytic/forces/glass_edge.hpp"
#include "kerf/dem/output/output.hpp"
#include "kerf/dem/output/png.hpp"
#include "kerf/dem/procedures/cut_results.hpp"
#include "kerf/dem/study/study.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/metrics.hpp"
#include "kerf/time_series.hpp"
#include "kerf/units.hpp"

namespace kerf::dem::kinds {

namespace {

namespace k = cut_keys;

/// The cut's latest sample, for log lines.
SampleState cut_sample(const CutRun& run) {
  const CutResult& res = run.result();
  SampleState s{0, 0, run.simulation().particles().size(), static_cast<int>(run.n_cracks()), {}, {}, {}, {}, {}};
  if (!res.samples.empty()) {
    const CutSample& last = res.samples.back();
    s.step = std::llround(last.time_s / res.time_step_s);  // the cut's own steps (the workpiece's count from genesis)
    s.time_s = last.time_s;
    s.travel_mm = units::m_to_mm(last.travel_m);
    s.main_force_N = last.main_force_N;
    s.thrust_force_N = last.thrust_force_N;
  }
  return s;
}

/// The edge zone's force from the material's edge model when the scene does not give it (kerf::edge_force_per_width:
/// the ductile layer of the material file's E, H and K_c, cut at the tool's rake with the zone's friction).
void set_edge_zone_force(CutParams& cut, const Material& material) {
  if (!cut.edge_zone.enabled || cut.edge_zone.cutting_force_N_per_m >= 0) return;
  const EdgeTool tool{units::deg_to_rad(cut.tool.rake_deg), cut.tool.edge_radius_m, cut.edge_zone.friction_coefficient,
                      cut.edge_zone.layer_factor};
  EdgeForce f;
  try {
    f = edge_force_per_width(Json(material.name), tool);
  } catch (const InputError& e) {
    throw InputError("edge_zone.cutting_force_N_per_mm", "(absent)",
                     "a material file with the data of kerf-forces' edge model (material '" + material.name +
                         "': " + e.what() + "), or the layer's cutting_force_N_per_mm and thrust_force_N_per_mm");
  }
  cut.edge_zone.cutting_force_N_per_m = f.force.cutting_N_per_m;
  cut.edge_zone.thrust_force_N_per_m = f.force.thrust_N_per_m;
}

/// Runs (or continues, from a checkpoint) a cut to the end of its travel and writes the outputs; returns the
/// summary. `doc` and the options' checkpoint interval are for the checkpoints.
// Long (~110 lines) for a reason: each sample interleaves steps, the sample, checkpoints, frames and progress on
// one state (the run, its schedule, the progress); split, every part would take most of it as arguments.
Json continue_cut(const SceneCommon& common, const CutParams& cut, const Json& doc, Json summary,
                  const RunOptions& options, CutRun run, RunProgress tp) {
  const fs::path& out = options.out;
  CheckpointSchedule checkpoints(options);
  const int frame_every = common.output.frame_every_samples;
  // Every picture shows the workpiece's region with room for the tool on the right and the chip above.
  const auto& box = run.result().workpiece_box_m;
  const double margin = 2 * cut.cut.depth_of_cut_m;
  const std::array<double, 4> view_m{box[0], box[1] + margin, box[2], box[3] + margin};
  const auto write_frame = [&](const Simulation& sim) {
    write_frame_files(out, {sim, run.window(), run.result().y_cut_m, view_m, "cut"}, common.output, tp);
  };
  if (frame_every > 0 && tp.sample_index == 0) write_frame(run.simulation());
  const double n = static_cast<double>(run.simulation().particles().size());  // a window's: about the same all along
  const double steps = cut.cut.length_m / (cut.cut.speed_m_per_s * run.result().time_step_s);
  StageProgress progress(tp.progress, "cut", n * steps, "particle-steps");
  if (tp.sample_index > 0) progress.resume_at(n * cut.cut.sample_every_steps * tp.sample_index, cut_sample(run));
  // forces.csv as the cut goes (docs/dem.md, "A running cut's forces.csv"): whole rows, each sample's as it
  // comes; from a checkpoint, the rows of its samples again (a killed run's later rows are dropped, the resumed
  // run computes them anew). The finished cut replaces it whole below, with the same bytes.
  std::optional<GrowingFile> running_forces;
  std::size_t rows_written = 0;
  const auto write_rows = [&] {
    std::string rows;
    const auto& samples = run.result().samples;
    for (; rows_written < samples.size(); ++rows_written)
      rows += cut_forces_csv_row(samples[rows_written], run.result().width_m);
    if (!rows.empty()) running_forces->append(rows);
  };
  running_forces.emplace(out / "forces.csv", cut_forces_csv_header());
  write_rows();
  while (run.advance()) {
    ++tp.sample_index;
    write_rows();
    progress.advance(n * cut.cut.sample_every_steps, cut_sample(run));
    if (frame_every > 0 && tp.sample_index % frame_every == 0) write_frame(run.simulation());
    if (checkpoints.due(tp.sample_index))
      // The cut holds its own workpiece: the checkpoint's specimen part stays empty.
      write_checkpoint(out, {doc, summary, tp.frames, tp.sample_index, options.checkpoint_every, tp.scene_dir,
                             std::string(), run.serialize(), options.provenance});
  }
  progress.finish(cut_sample(run));  // the last sample (advance returned false)
  running_forces.reset();
  if (frame_every > 0) write_frame(run.simulation());
  const CutResult& res = run.result();
  summary["cut"] = cut_params_to_json(run.params());  // the cut's own: the edge zone's reach resolved
  const CutReport report{run.params(), res};
  summary["results"] = results_to_json(cut_results(), report);  // cut_results.hpp: its keys, units, meanings
  name_cut_forces(summary["results"]);
  summary["n_particles"] = res.n_particles;
  summary["steps"] = res.steps;
  summary["wall_time_s"] = res.wall_time_s;
  summary["particle_steps_per_s"] = res.particle_steps / res.wall_time_s;  // the disks integrated: a window's
  if (cut.window.enabled) summary["active_window"] = results_to_json(active_window_results(), report);
  write_file_atomically(out / "forces.csv", cut_forces_csv(res));
  write_file_atomically(out / "cracks.csv", cracks_csv(run.cracks(), res.y_cut_m));
  if (frame_every > 0) write_pvd(out / "result.pvd", tp.frames);
  write_specimen_png(out / "specimen.png", run.workpiece(), "cut, final state", view_m);
  write_cut_forces_png(out / "forces.png", res);
  write_summary(options, doc, summary);
  remove_checkpoint(out);  // finished: nothing to resume
  // The log line from the results as written (their table's units).
  const Json& r = summary["results"];
  const auto number = [&r](std::string_view key) { return r.at(key).get<double>(); };
  const auto count = [&r](std::string_view key) { return r.at(key).get<long long>(); };
#pragma omp critical(kerf_dem_stdout)
  std::cout << fmt::format(
      "cut: cutting force {:.3g} N (std {:.2g}), thrust force {:.3g} N (std {:.2g}) per {:g} mm width, "
      "means over {:.4g}-{:.4g} mm of travel{}; {} tensile + {} shear cracks ({} chip, {} "
      "subsurface, damage depth {:.1f} um); {} steps, {:.1f} s -> {}\n",
      number(k::main_force_N), number(k::main_force_std_N), number(k::thrust_force_N), number(k::thrust_force_std_N),
      number(k::width_mm), number(k::steady_from_travel_mm), number(k::steady_to_travel_mm),
      r.at(k::steady) == true ? "" : " (NOT STEADY: " + r.at(k::not_steady_reason).get<std::string>() + ")",
      count(k::cracks_tensile), count(k::cracks_shear), count(k::cracks_chip), count(k::cracks_subsurface),
      number(k::subsurface_damage_depth_um), res.steps, res.wall_time_s, out.string());
  return summary;
}

class CutKind final : public SceneKind {
 public:
  std::string name() const override { return "cut"; }
  void read(ObjectReader& root, const SceneCommon& common) override {
    cut_ = read_cut_params(root);
    set_edge_zone_force(cut_, common.material);
  }
  bool writes_checkpoints() const override { return true; }

  void check_options(const RunOptions& options, const SceneCommon& common) const override {
    if (options.replicates > 1 && common.specimen_file)
      throw InputError("--replicates", std::to_string(options.replicates),
                       "a scene that generates its specimen (replicates differ in specimen.seed), not specimen.file");
  }

  SceneOutcome run(const SceneCommon& common, const SceneRun& run) override {
    const RunOptions& o = run.options;
    if (o.replicates > 1)
      return run_cut_replicates(run.doc, run.scene_dir, cut_, o.replicates, summary_head(name(), common.material), o);
    StartedRun started = start_from_specimen(common, name(), progress_target(o));
    const Simulation& specimen = started.specimen;
    Json& summary = started.summary;
    // CutRun checks the cut against the workpiece and the time step before the first step.
    CutRun cut(specimen, cut_);
    // The broken layer's joints, counted here: the summary travels in the checkpoints, the counts do not.
    if (cut_.grooves.damage_depth_m > 0 && cut_.grooves.damage_model == GrooveDamageModel::broken_joints) {
      const auto joints = cut.result().groove_damage_joints;
      summary["groove_damage"] = Json{{"joints_in_layer", joints[0]}, {"joints_pre_broken", joints[1]}};
    }
    if (cut_.edge_zone.lateral_crack == LateralCrack::whole_cut_line)
      summary["lateral_crack"] = Json{{"cut_line_joints_broken", cut.result().cut_line_joints_broken}};
    return {0,
            continue_cut(common, cut_, run.doc, std::move(summary), o, std::move(cut),
                         {{}, 0, run.scene_dir, progress_target(o), {}}),
            {}};
  }

  SceneOutcome resume(const SceneCommon& common, const SceneRun& run, const Checkpoint& c) override {
    return {0,
            continue_cut(common, cut_, c.scene, c.summary, run.options, CutRun::deserialize(c.run),
                         {c.frames, c.sample_index, c.scene_dir, progress_target(run.options), {}}),
            {}};
  }

 private:
  CutParams cut_;
};

}  // namespace

/// The replicates are a study of one condition (kerf/dem/study/study.hpp) in OUT/replicates: items side by side, one
/// thread each while there are items to spare (a cut of a few thousand disks scales better over replicates
/// than over threads: no barrier per step), finished items reused on a rerun, the first failure (a cut the
/// workpiece cannot hold) rethrown as it was. OUT/replicates/study.json is that study: `kerf-dem study` reruns
/// it. OUT/summary.json keeps the replicate rows and their means, spreads and standard errors.
// Long (~95 lines) for a reason: the replicates' study is built, run and folded into one summary (rows, means,
// spreads, errors of the means) in that summary's order.
SceneOutcome run_cut_replicates(const Json& cut_scene, const std::string& scene_dir, const CutParams& cut,
                                int replicates, Json summary, const RunOptions& options) {
  // Each replicated result with the name of its spread over the replicates (cut_results.hpp).
  std::vector<std::pair<std::string, std::string>> keys;
  for (const auto key : cut_replicated_results()) keys.emplace_back(key, replicate_spread_key(key));
  const auto start = std::chrono::steady_clock::now();
  const Json study_doc{
      {"description", fmt::format("{} replicates of a cut (kerf-dem run --replicates {})", replicates, replicates)},
      {"scene", cut_scene},
      {"replicates", {{"policy", "fixed"}, {"count", replicates}}}};
  const StudySpec spec = read_study(study_doc, fs::path(scene_dir) / "replicates.json");
  StudyOptions study;
  study.out = options.out / "replicates";
  study.threads = omp_get_max_threads();
  study.show_progress = options.show_progress;
  study.log_lines = true;  // a line per replicate run or reused
  study.command_line = options.command_line;
  study.stop_at_first_failure = true;
  study.hold_output_directory = false;  // run_scene holds OUT
  study.on_progress = options.on_progress;
  fs::create_directories(study.out);
  write_file_atomically(study.out / "study.json", study_doc.dump(2) + "\n");
  const StudyOutcome ran = run_study_local(spec, study);
  std::vector<Json> done;
  Json list = Json::array();
  double wall = 0;
  for (int i = 0; i < replicates; ++i) {
    const StudyItem item = study_item(spec, 0, i);
    done.push_back(read_study_item_summary(study.out, item));
    const Json& one = done.back();
    Json row{{"replicate", i + 1},
             {"seed", one["study_item"]["seed"]},
             {"directory", (fs::path("replicates") / "items" / study_item_name(item)).generic_string()}};
    for (const auto& [result, spread] : keys) row[result] = one["results"][result];
    for (const auto result : cut_replicate_row_results()) row[result] = one["results"].value(result, Json());
    row["wall_time_s"] = one["wall_time_s"];  // the cut's own (genesis excluded)
    wall += row["wall_time_s"].get<double>();
    list.push_back(row);
  }
  // Means, sample standard deviations and the standard errors of the main and thrust means (std / sqrt(n)):
  // the study's table of its one condition, beside each replicate's own within-cut standard errors
  // (replicates[k].main_force_sem_N, from its force signal).
  const Json& table = ran.summary["conditions"][0]["results"];
  Json stats;
  for (const auto& [result, spread] : keys) {
    stats[result] = table[result]["mean"];
    stats[spread] = table[result]["std"];  // replicates >= 2: a finite sample std
  }
  stats[k::main_force_sem_N] = table[k::main_force_N]["sem"];
  stats[k::thrust_force_sem_N] = table[k::thrust_force_N]["sem"];
  // And from the cuts' own signals, sqrt(sum sem_k^2) / n: the error of the mean of long steady cuts, which
  // (unlike the replicate spread of a few cuts) has many batches behind it; null when a cut has none.
  for (const auto& [sem, within] : {std::pair{k::main_force_sem_N, k::main_force_sem_within_cuts_N},
                                    std::pair{k::thrust_force_sem_N, k::thrust_force_sem_within_cuts_N}}) {
    std::vector<double> sems;
    for (const auto& row : list) sems.push_back(row[sem].is_number() ? row[sem].get<double>() : std::nan(""));
    stats[within] = finite_or_null(standard_error_of_mean(sems));
  }
  stats[k::width_mm] = list[0][k::width_mm];
  // Steady when every replicate's means are; else the first replicate that is not, and why.
  const std::string_view steady = k::steady, why = k::not_steady_reason;
  stats[steady] = true;
  stats[why] = Json();
  for (const auto& row : list) {
    if (row[steady] == true) continue;
    stats[steady] = false;
    stats[why] = fmt::format("replicate {}: {}", row["replicate"].get<int>(),
                             row[why].is_string() ? row[why].get<std::string>() : std::string("no steady verdict"));
    break;
  }
  name_cut_forces(stats);
  for (auto& row : list) name_cut_forces(row);
  summary["cut"] = cut_params_to_json(cut);
  summary["replicates"] = list;
  summary["results"] = stats;
  summary["replicates_side_by_side"] = ran.summary["workers"];
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary["wall_time_s_sum_over_replicates"] = wall;
  write_summary(options, cut_scene, summary);
  std::cout << fmt::format(
      "cut, {} replicates: cutting force {:.3g} N (replicate std {:.2g}), thrust force {:.3g} N "
      "(replicate std {:.2g}) per {:g} mm width{} -> {}\n",
      replicates, stats[k::main_force_N].get<double>(), stats[replicate_spread_key(k::main_force_N)].get<double>(),
      stats[k::thrust_force_N].get<double>(), stats[replicate_spread_key(k::thrust_force_N)].get<double>(),
      stats[k::width_mm].get<double>(),
      stats[steady] == true ? "" : " (NOT STEADY: " + stats[why].get<std::string>() + ")", options.out.string());
  return {0, summary, std::move(done)};
}

std::unique_ptr<SceneKind> make_cut_kind() {
  return std::make_unique<CutKind>();
}

}  // namespace kerf::dem::kinds
