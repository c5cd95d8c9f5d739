// Scene kind "toughness": the fracture-toughness test (kerf/dem/procedures/toughness.hpp), a single-edge-notched beam
// in three-point bending on one packing or, with --replicates N, on packings specimen.seed + 0..N-1 one after the other
// (mean and standard error), with the quasi-static check on the first packing.
#include "kerf/dem/procedures/toughness.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "common.hpp"
#include "kerf/dem/output/output.hpp"
#include "kerf/dem/output/png.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"

namespace kerf::dem::kinds {

namespace {

/// As the tension and compression tests: the largest change of the peak at half the speed for which a test
/// counts as quasi-static.
constexpr double kQuasiStaticTolerancePercent = 2.0;

SampleState toughness_sample(const ToughnessSample& s, double time_step_s, std::size_t n_particles) {
  SampleState state{std::llround(s.time_s / time_step_s), s.time_s, n_particles, s.n_cracks, {}, {}, {}, {}, {}};
  return state;
}

/// Mean and standard error of the mean (sample standard deviation / sqrt(n); 0 for one value).
std::pair<double, double> mean_and_sem(const std::vector<double>& v) {
  double mean = 0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  if (v.size() < 2) return {mean, 0};
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  return {mean, std::sqrt(ss / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()))};
}

std::string curve_csv(const std::vector<std::pair<std::uint64_t, const ToughnessResult*>>& runs) {
  std::ostringstream out;
  out << "seed,time_s,deflection_um,load_N,smoothed_load_N,support_load_N,external_work_J,stored_elastic_energy_J,"
         "kinetic_energy_J,n_cracks\n";
  for (const auto& [seed, r] : runs)
    for (const auto& s : r->curve)
      out << fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{}\n", seed, s.time_s,
                         units::m_to_um(s.deflection_m), s.load_n, s.smoothed_load_n, s.support_load_n,
                         s.external_work_j, s.stored_elastic_energy_j, s.kinetic_energy_j, s.n_cracks);
  return out.str();
}

Json result_json(const ToughnessResult& r) {
  return Json{
      {"fracture_toughness_MPa_sqrt_m", units::pa_to_mpa(r.fracture_toughness_pa_sqrt_m)},
      {"fracture_energy_J_per_m2", r.fracture_energy_j_per_m2},
      {"work_of_fracture_J_per_m2", r.work_of_fracture_j_per_m2},
      {"irwin_energy_J_per_m2", r.irwin_energy_j_per_m2},
      {"peak_load_N", r.peak_load_n},
      {"raw_peak_load_N", r.raw_peak_load_n},
      {"raw_peak_toughness_MPa_sqrt_m", units::pa_to_mpa(r.raw_peak_toughness_pa_sqrt_m)},
      {"deflection_at_peak_um", units::m_to_um(r.deflection_at_peak_m)},
      {"external_work_J", r.external_work_j},
      {"broken_through", r.through_sample >= 0},
      {"deflection_broken_through_um",
       r.through_sample >= 0 ? units::m_to_um(r.curve[static_cast<std::size_t>(r.through_sample)].deflection_m) : 0.0},
      {"n_cracks", r.curve.back().n_cracks},
      {"n_notch_disks_removed", r.n_notch_disks},
      {"n_notch_joints_retired", r.n_notch_joints_retired},
      {"stop_reason", r.stop_reason},
      {"steps", r.steps},
      {"wall_time_s", r.wall_time_s}};
}

class ToughnessKind final : public SceneKind {
 public:
  void read(ObjectReader& root, const SceneCommon& common) override {
    if (auto t = root.find_object("toughness")) {
      spec_ = read_fields(*t, toughness_fields(), ToughnessSpec{});
      t->finish();
    }
    if (!common.specimen_file)
      check_toughness_spec(spec_, common.specimen);
    else
      with_path("toughness", [&] { check_fields(toughness_fields(), spec_); });
  }

  void check_options(const RunOptions& options, const SceneCommon& common) const override {
    if (options.checkpoint_every > 0 || options.checkpoint_every_s > 0)
      throw InputError("--checkpoint-every", std::to_string(options.checkpoint_every),
                       "no checkpoints for toughness scenes (each packing's test runs in minutes)");
    if (options.replicates > 1 && common.specimen_file)
      throw InputError("--replicates", std::to_string(options.replicates), "1 with specimen.file (one saved packing)");
  }

  // Long (~100 lines) for a reason: the packings one after the other, then their mean and standard error, the
  // quasi-static check, the figures and the summary: stages in order over the same results.
  SceneOutcome run(const SceneCommon& common, const SceneRun& scene_run) override {
    const fs::path& out = scene_run.options.out;
    const int packings = scene_run.options.replicates;
    const ProgressTarget target = progress_target(scene_run.options);
    std::vector<ToughnessResult> results;
    std::vector<std::uint64_t> seeds;
    Json summary, per_packing = Json::array(), quasi_static;
    std::optional<Simulation> first_final;
    double total_wall_s = 0;
    for (int k = 0; k < packings; ++k) {
      SceneCommon packing = common;
      packing.specimen.seed += static_cast<std::uint64_t>(k);
      ProgressTarget t = target;
      if (packings > 1) t.prefix += fmt::format("packing {}: ", k + 1);
      StartedRun started = start_from_specimen(packing, "toughness", t);
      if (common.specimen_file) check_toughness_spec(spec_, started.spec);
      if (k == 0) summary = started.summary;
      Simulation final_state(common.material, SimulationOptions{});
      const ToughnessResult r = run_one(started.specimen, spec_, "toughness", t, k == 0 ? &final_state : nullptr);
      total_wall_s += r.wall_time_s + started.summary["specimen"]["genesis_wall_time_s"].get<double>();
      if (k == 0) {
        first_final.emplace(std::move(final_state));
        if (spec_.quasi_static_check) quasi_static = check_quasi_static(started.specimen, r, t);
      }
      Json one = result_json(r);
      one["seed"] = started.spec.seed;
      per_packing.push_back(one);
      results.push_back(r);
      seeds.push_back(started.spec.seed);
    }
    // Across packings: the mean and its standard error.
    std::vector<double> k_ic, g_c, wof, irwin;
    for (const auto& r : results) {
      k_ic.push_back(units::pa_to_mpa(r.fracture_toughness_pa_sqrt_m));
      g_c.push_back(r.fracture_energy_j_per_m2);
      wof.push_back(r.work_of_fracture_j_per_m2);
      irwin.push_back(r.irwin_energy_j_per_m2);
    }
    const auto [k_mean, k_sem] = mean_and_sem(k_ic);
    const auto [g_mean, g_sem] = mean_and_sem(g_c);
    const auto [w_mean, w_sem] = mean_and_sem(wof);
    const auto [i_mean, i_sem] = mean_and_sem(irwin);
    const ToughnessResult& r0 = results.front();
    Json res{{"fracture_toughness_MPa_sqrt_m", k_mean},
             {"fracture_energy_J_per_m2", g_mean},
             {"work_of_fracture_J_per_m2", w_mean},
             {"irwin_energy_J_per_m2", i_mean},
             {"fracture_energy_over_irwin_energy", i_mean > 0 ? g_mean / i_mean : 0.0},
             {"youngs_modulus_for_irwin_GPa", units::pa_to_gpa(spec_.youngs_modulus_pa)},
             {"packings", packings},
             {"depth_W_mm", units::m_to_mm(r0.depth_m)},
             {"span_S_mm", units::m_to_mm(r0.span_m)},
             {"length_mm", units::m_to_mm(r0.length_m)},
             {"thickness_B_mm", units::m_to_mm(r0.thickness_m)},
             {"notch_depth_a_mm", units::m_to_mm(r0.notch_m)},
             {"notch_over_depth", r0.notch_m / r0.depth_m},
             {"geometry_factor", senb_geometry_factor(r0.notch_m / r0.depth_m)},
             {"speed_m_per_s", spec_.speed_m_per_s},
             {"peak_window_um", units::m_to_um(spec_.peak_window_m)},
             {"per_packing", per_packing}};
    if (packings > 1) {
      res["fracture_toughness_sem_MPa_sqrt_m"] = k_sem;
      res["fracture_energy_sem_J_per_m2"] = g_sem;
      res["work_of_fracture_sem_J_per_m2"] = w_sem;
      res["irwin_energy_sem_J_per_m2"] = i_sem;
    }
    if (!quasi_static.is_null()) res["quasi_static_check"] = quasi_static;
    summary["results"] = res;
    summary["n_particles"] = r0.n_particles;
    summary["steps"] = r0.steps;
    summary["wall_time_s"] = total_wall_s;
    summary["particle_steps_per_s"] =
        static_cast<double>(r0.n_particles) * static_cast<double>(r0.steps) / r0.wall_time_s;
    std::vector<std::pair<std::uint64_t, const ToughnessResult*>> runs;
    for (std::size_t k = 0; k < results.size(); ++k) runs.emplace_back(seeds[k], &results[k]);
    write_file_atomically(out / "curve.csv", curve_csv(runs));
    write_file_atomically(out / "cracks.csv", cracks_csv(first_final->cracks()));
    write_load_deflection_png(
        out / "curve.png", results,
        fmt::format("toughness: SENB, W {:.3g} mm, a/W {:.2f}{}", units::m_to_mm(r0.depth_m), r0.notch_m / r0.depth_m,
                    packings > 1 ? fmt::format(", {} packings", packings) : std::string()));
    write_specimen_png(out / "specimen.png", *first_final, "toughness (SENB), final state");
    // The crack's neighbourhood: W either side of the notch, the whole depth.
    const double xc = r0.notch_x_m;
    double y0 = 1e300, y1 = -1e300;
    const auto& p = first_final->particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      y0 = std::min(y0, p.y[i] - p.radius[i]), y1 = std::max(y1, p.y[i] + p.radius[i]);
    write_specimen_png(out / "crack.png", *first_final, "toughness (SENB): the notch and the crack, final state",
                       std::array<double, 4>{xc - r0.depth_m, xc + r0.depth_m, y0, y1});
    write_summary(scene_run.options, scene_run.doc, summary);
    std::cout << fmt::format(
        "toughness: K_IC = {:.3f}{} MPa sqrt(m), G_c = {:.3g}{} J/m^2 (K_IC^2/E' = {:.3g} J/m^2), work of fracture "
        "{:.3g} J/m^2, {} packing{}, {:.1f} s -> {}\n",
        k_mean, packings > 1 ? fmt::format(" +- {:.3f}", k_sem) : "", g_mean,
        packings > 1 ? fmt::format(" +- {:.2g}", g_sem) : "", i_mean, w_mean, packings, packings > 1 ? "s" : "",
        total_wall_s, out.string());
    return {0, summary, {}};
  }

 private:
  ToughnessSpec spec_;

  static ToughnessResult run_one(const Simulation& specimen, const ToughnessSpec& spec, const std::string& label,
                                 const ProgressTarget& target, Simulation* final_state) {
    // Progress against the steps that reach max_deflection (an upper bound: most runs stop earlier).
    const double n = static_cast<double>(specimen.particles().size());
    const double steps = spec.max_deflection_m / (spec.speed_m_per_s * specimen.time_step());
    StageProgress progress(target, label, n * steps, "particle-steps");
    ToughnessResult r = run_toughness_test(
        specimen, spec,
        [&](const Simulation& sim, const ToughnessSample& s) {
          progress.advance(n * spec.sample_every_steps, toughness_sample(s, sim.time_step(), sim.particles().size()));
        },
        final_state);
    progress.finish();
    return r;
  }

  Json check_quasi_static(const Simulation& specimen, const ToughnessResult& r, const ProgressTarget& target) const {
    ToughnessSpec half = spec_;
    half.speed_m_per_s *= 0.5;
    half.quasi_static_check = false;  // this run is the check
    const ToughnessResult slow = run_one(specimen, half, "toughness (quasi-static check, half speed)", target, nullptr);
    const double change = 100 * (slow.peak_load_n - r.peak_load_n) / r.peak_load_n;
    const bool quasi_static = std::abs(change) <= kQuasiStaticTolerancePercent;
    std::cout << fmt::format(
        "toughness: quasi-static check: the peak load changes {:+.2f} % at half the speed ({} m/s): {}\n", change,
        half.speed_m_per_s,
        quasi_static ? fmt::format("quasi-static (within {} %)", kQuasiStaticTolerancePercent)
                     : fmt::format("RATE-DEPENDENT (more than {} %): lower toughness.speed_m_per_s",
                                   kQuasiStaticTolerancePercent));
    return Json{{"speed_m_per_s", half.speed_m_per_s},
                {"peak_load_N", slow.peak_load_n},
                {"peak_change_percent", change},
                {"fracture_toughness_MPa_sqrt_m", units::pa_to_mpa(slow.fracture_toughness_pa_sqrt_m)},
                {"fracture_energy_J_per_m2", slow.fracture_energy_j_per_m2},
                {"fracture_energy_change_percent",
                 100 * (slow.fracture_energy_j_per_m2 - r.fracture_energy_j_per_m2) / r.fracture_energy_j_per_m2},
                {"tolerance_percent", kQuasiStaticTolerancePercent},
                {"verdict", quasi_static ? "quasi-static" : "rate-dependent"},
                {"wall_time_s", slow.wall_time_s}};
  }
};

}  // namespace

std::unique_ptr<SceneKind> make_toughness_kind() {
  return std::make_unique<ToughnessKind>();
}

}  // namespace kerf::dem::kinds
