// Scene kind "toughness": the fracture-toughness test (kerf/dem/procedures/toughness.hpp), a single-edge-notched beam
// in three-point bending on one packing or, with --replicates N, on packings specimen.seed + 0..N-1 one after the other
// (mean and standard error), with the quasi-static check on the first packing.
#include "kerf/dem/procedures/toughness.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "common.hpp"
#include "kerf/dem/output/output.hpp"
#include "kerf/dem/output/png.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"
#include "kind_results.hpp"

namespace kerf::dem::kinds {

namespace {

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

/// A real of curve.csv: 9 significant digits.
std::string curve_real(double v) {
  return fmt::format("{:.9g}", v);
}

std::string curve_csv(const std::vector<std::pair<std::uint64_t, const ToughnessResult*>>& runs) {
  std::string out = results_csv_header(toughness_curve_columns());
  for (const auto& [seed, r] : runs)
    for (const auto& s : r->curve) out += results_csv_row(toughness_curve_columns(), {seed, s}, curve_real);
  return out;
}

class ToughnessKind final : public SceneKind {
 public:
  std::string name() const override { return "toughness"; }
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
      StartedRun started = start_from_specimen(packing, name(), t);
      if (common.specimen_file) check_toughness_spec(spec_, started.spec);
      if (k == 0) summary = started.summary;
      Simulation final_state(common.material, SimulationOptions{});
      const ToughnessResult r = run_one(started.specimen, spec_, name(), t, k == 0 ? &final_state : nullptr);
      total_wall_s += r.wall_time_s + started.summary["specimen"]["genesis_wall_time_s"].get<double>();
      if (k == 0) {
        first_final.emplace(std::move(final_state));
        if (spec_.quasi_static_check) quasi_static = check_quasi_static(started.specimen, r, t);
      }
      Json one = results_to_json(toughness_packing_results(), r);
      one[toughness_packing_keys::seed] = started.spec.seed;
      per_packing.push_back(one);
      results.push_back(r);
      seeds.push_back(started.spec.seed);
    }
    // Across packings: the mean and its standard error.
    std::vector<double> k_ic, g_c, wof, irwin;
    for (const auto& r : results) {
      k_ic.push_back(units::pa_to_mpa(r.fracture_toughness_Pa_sqrt_m));
      g_c.push_back(r.fracture_energy_J_per_m2);
      wof.push_back(r.work_of_fracture_J_per_m2);
      irwin.push_back(r.irwin_energy_J_per_m2);
    }
    const auto [k_mean, k_sem] = mean_and_sem(k_ic);
    const auto [g_mean, g_sem] = mean_and_sem(g_c);
    const auto [w_mean, w_sem] = mean_and_sem(wof);
    const auto [i_mean, i_sem] = mean_and_sem(irwin);
    const ToughnessResult& r0 = results.front();  // the first packing's beam: its geometry, figures and counts
    const ToughnessReport report{{k_mean, k_sem}, {g_mean, g_sem}, {w_mean, w_sem}, {i_mean, i_sem},
                                 packings,        results.front(), spec_,           per_packing};
    Json res = results_to_json(toughness_results(), report);
    if (!quasi_static.is_null()) res[toughness_keys::quasi_static_check] = quasi_static;
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
    const Json check = results_to_json(toughness_check_results(), {half.speed_m_per_s, slow, r});
    const double change = check[toughness_check_keys::peak_change_percent].get<double>();
    const bool quasi_static = check[toughness_check_keys::verdict] == "quasi-static";
    std::cout << fmt::format(
        "toughness: quasi-static check: the peak load changes {:+.2f} % at half the speed ({} m/s): {}\n", change,
        half.speed_m_per_s,
        quasi_static ? fmt::format("quasi-static (within {} %)", kQuasiStaticTolerancePercent)
                     : fmt::format("RATE-DEPENDENT (more than {} %): lower toughness.speed_m_per_s",
                                   kQuasiStaticTolerancePercent));
    return check;
  }
};

}  // namespace

const ResultTable<ToughnessResult>& toughness_packing_results() {
  namespace k = toughness_packing_keys;
  using T = ToughnessResult;
  static const ResultTable<T> table{
      result_number<T>(k::fracture_toughness_MPa_sqrt_m, units::kMPaSqrtM, "K_IC from the peak of the smoothed load",
                       [](const T& r) { return r.fracture_toughness_Pa_sqrt_m; }),
      result_value<T>(k::fracture_energy_J_per_m2, "J/m2", "G_c: (W_ext - dU - dK) / (B (W - a)), to broken through",
                      [](const T& r) { return r.fracture_energy_J_per_m2; }),
      result_value<T>(k::work_of_fracture_J_per_m2, "J/m2", "W_ext / (B (W - a)), to broken through",
                      [](const T& r) { return r.work_of_fracture_J_per_m2; }),
      result_value<T>(k::irwin_energy_J_per_m2, "J/m2", "K_IC^2 / E'",
                      [](const T& r) { return r.irwin_energy_J_per_m2; }),
      result_value<T>(k::peak_load_N, "N", "the peak of the smoothed load", [](const T& r) { return r.peak_load_N; }),
      result_value<T>(k::raw_peak_load_N, "N", "the largest sample's load, ringing included",
                      [](const T& r) { return r.raw_peak_load_N; }),
      result_number<T>(k::raw_peak_toughness_MPa_sqrt_m, units::kMPaSqrtM, "K from the raw peak, for comparison",
                       [](const T& r) { return r.raw_peak_toughness_Pa_sqrt_m; }),
      result_number<T>(k::deflection_at_peak_um, units::kUm, "the deflection at the smoothed peak",
                       [](const T& r) { return r.deflection_at_peak_m; }),
      result_value<T>(k::external_work_J, "J", "the load roller's work to the end",
                      [](const T& r) { return r.external_work_J; }),
      result_value<T>(k::broken_through, "", "whether the crack crossed the ligament",
                      [](const T& r) { return r.through_sample >= 0; }),
      result_value<T>(k::deflection_broken_through_um, "um", "the deflection when it had (0: never)",
                      [](const T& r) {
                        return r.through_sample >= 0
                                   ? units::m_to_um(r.curve[static_cast<std::size_t>(r.through_sample)].deflection_m)
                                   : 0.0;
                      }),
      result_value<T>(k::n_cracks, "", "broken joint elements at the end",
                      [](const T& r) { return r.curve.back().n_cracks; }),
      result_value<T>(k::n_notch_disks_removed, "", "disks removed to make the notch",
                      [](const T& r) { return r.n_notch_disks; }),
      result_value<T>(k::n_notch_joints_retired, "", "joints still crossing the notch's line, retired",
                      [](const T& r) { return r.n_notch_joints_retired; }),
      result_value<T>(k::stop_reason, "", "why the test stopped", [](const T& r) { return r.stop_reason; }),
      result_value<T>(k::steps, "", "time steps", [](const T& r) { return r.steps; }),
      result_value<T>(k::wall_time_s, "s", "the test's wall time", [](const T& r) { return r.wall_time_s; })};
  return table;
}

const ResultTable<ToughnessCurveRow>& toughness_curve_columns() {
  namespace k = toughness_curve_keys;
  using C = ToughnessCurveRow;
  static const ResultTable<C> table{
      result_value<C>(k::seed, "", "the packing's seed (results.per_packing's)", [](const C& c) { return c.seed; }),
      result_value<C>(k::time_s, "s", "time since the test began", [](const C& c) { return c.s.time_s; }),
      result_number<C>(k::deflection_um, units::kUm, "the load point's deflection (the load roller's travel)",
                       [](const C& c) { return c.s.deflection_m; }),
      result_value<C>(k::load_N, "N", "the load on the roller, the mean over the sample's steps",
                      [](const C& c) { return c.s.load_N; }),
      result_value<C>(k::smoothed_load_N, "N", "the load averaged over toughness.peak_window_um about this deflection",
                      [](const C& c) { return c.s.smoothed_load_N; }),
      result_value<C>(k::support_load_N, "N", "the two supports' reaction together (the load when quasi-static)",
                      [](const C& c) { return c.s.support_load_N; }),
      result_value<C>(k::external_work_J, "J", "the load roller's work so far",
                      [](const C& c) { return c.s.external_work_J; }),
      result_value<C>(k::stored_elastic_energy_J, "J", "the elastic energy stored in the joints and contacts",
                      [](const C& c) { return c.s.stored_elastic_energy_J; }),
      result_value<C>(k::kinetic_energy_J, "J", "the disks' kinetic energy",
                      [](const C& c) { return c.s.kinetic_energy_J; }),
      result_value<C>(k::n_cracks, "", "broken joint elements beyond the notch so far",
                      [](const C& c) { return c.s.n_cracks; })};
  return table;
}

const ResultTable<ToughnessReport>& toughness_results() {
  namespace k = toughness_keys;
  using R = ToughnessReport;
  const auto sem = [](const R& r) { return r.packings > 1; };
  static const ResultTable<R> table{
      result_value<R>(k::fracture_toughness_MPa_sqrt_m, units::kMPaSqrtM.symbol, "K_IC, the mean over the packings",
                      [](const R& r) { return r.toughness_MPa_sqrt_m.mean; }),
      result_value<R>(k::fracture_energy_J_per_m2, "J/m2", "G_c, the mean over the packings",
                      [](const R& r) { return r.fracture_energy.mean; }),
      result_value<R>(k::work_of_fracture_J_per_m2, "J/m2", "the work of fracture, the mean over the packings",
                      [](const R& r) { return r.work_of_fracture.mean; }),
      result_value<R>(k::irwin_energy_J_per_m2, "J/m2", "K_IC^2 / E', the mean over the packings",
                      [](const R& r) { return r.irwin_energy.mean; }),
      result_value<R>(
          k::fracture_energy_over_irwin_energy, "", "G_c / (K_IC^2 / E') of the means",
          [](const R& r) { return r.irwin_energy.mean > 0 ? r.fracture_energy.mean / r.irwin_energy.mean : 0.0; }),
      result_number<R>(k::youngs_modulus_for_irwin_GPa, units::kGPa, "the E of E' (toughness.youngs_modulus_GPa)",
                       [](const R& r) { return r.spec.youngs_modulus_Pa; }),
      result_value<R>(k::packings, "", "packings tested (--replicates)", [](const R& r) { return r.packings; }),
      result_number<R>(k::depth_W_mm, units::kMm, "the beam's depth W (the first packing's, measured)",
                       [](const R& r) { return r.first.depth_m; }),
      result_number<R>(k::span_S_mm, units::kMm, "the span S", [](const R& r) { return r.first.span_m; }),
      result_number<R>(k::length_mm, units::kMm, "the beam's length L", [](const R& r) { return r.first.length_m; }),
      result_number<R>(k::thickness_B_mm, units::kMm, "the thickness B",
                       [](const R& r) { return r.first.thickness_m; }),
      result_number<R>(k::notch_depth_a_mm, units::kMm, "the notch's depth a",
                       [](const R& r) { return r.first.notch_m; }),
      result_value<R>(k::notch_over_depth, "", "a / W", [](const R& r) { return r.first.notch_m / r.first.depth_m; }),
      result_value<R>(k::geometry_factor, "", "Srawley's geometry factor at a / W",
                      [](const R& r) { return senb_geometry_factor(r.first.notch_m / r.first.depth_m); }),
      result_value<R>(k::speed_m_per_s, "m/s", "the load roller's speed",
                      [](const R& r) { return r.spec.speed_m_per_s; }),
      result_number<R>(k::peak_window_um, units::kUm, "the smoothing window of the load's peak",
                       [](const R& r) { return r.spec.peak_window_m; }),
      result_value<R>(k::per_packing, "", "each packing's results (a list; their keys below)",
                      [](const R& r) { return r.per_packing; }),
      result_if(
          result_value<R>(k::fracture_toughness_sem_MPa_sqrt_m, units::kMPaSqrtM.symbol,
                          "the standard error of K_IC's mean", [](const R& r) { return r.toughness_MPa_sqrt_m.sem; }),
          sem),
      result_if(result_value<R>(k::fracture_energy_sem_J_per_m2, "J/m2", "the standard error of G_c's mean",
                                [](const R& r) { return r.fracture_energy.sem; }),
                sem),
      result_if(
          result_value<R>(k::work_of_fracture_sem_J_per_m2, "J/m2", "the standard error of the work of fracture's mean",
                          [](const R& r) { return r.work_of_fracture.sem; }),
          sem),
      result_if(result_value<R>(k::irwin_energy_sem_J_per_m2, "J/m2", "the standard error of K_IC^2 / E''s mean",
                                [](const R& r) { return r.irwin_energy.sem; }),
                sem)};
  return table;
}

const ResultTable<ToughnessCheck>& toughness_check_results() {
  namespace k = toughness_check_keys;
  using C = ToughnessCheck;
  const auto change = [](const C& c) { return 100 * (c.slow.peak_load_N - c.res.peak_load_N) / c.res.peak_load_N; };
  static const ResultTable<C> table{
      result_value<C>(k::speed_m_per_s, "m/s", "the check's speed (half the test's)",
                      [](const C& c) { return c.speed_m_per_s; }),
      result_value<C>(k::peak_load_N, "N", "the check's peak load", [](const C& c) { return c.slow.peak_load_N; }),
      result_value<C>(k::peak_change_percent, "%", "the change of the peak load at half the speed", change),
      result_number<C>(k::fracture_toughness_MPa_sqrt_m, units::kMPaSqrtM, "the check's K_IC",
                       [](const C& c) { return c.slow.fracture_toughness_Pa_sqrt_m; }),
      result_value<C>(k::fracture_energy_J_per_m2, "J/m2", "the check's G_c",
                      [](const C& c) { return c.slow.fracture_energy_J_per_m2; }),
      result_value<C>(k::fracture_energy_change_percent, "%", "the change of G_c at half the speed",
                      [](const C& c) {
                        return 100 * (c.slow.fracture_energy_J_per_m2 - c.res.fracture_energy_J_per_m2) /
                               c.res.fracture_energy_J_per_m2;
                      }),
      result_value<C>(k::tolerance_percent, "%", "the largest change of the peak of a quasi-static test",
                      [](const C&) { return kQuasiStaticTolerancePercent; }),
      result_value<C>(k::verdict, "", "`quasi-static` within the tolerance, else `rate-dependent`",
                      [change](const C& c) { return std::string(quasi_static_verdict(change(c))); }),
      result_value<C>(k::wall_time_s, "s", "the check's wall time", [](const C& c) { return c.slow.wall_time_s; })};
  return table;
}

std::unique_ptr<SceneKind> make_toughness_kind() {
  return std::make_unique<ToughnessKind>();
}

}  // namespace kerf::dem::kinds
