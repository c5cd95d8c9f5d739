// Scene kinds "tension" and "compression": the calibration tests of Yang et al. 2018's Section 3 on a specimen, with
// the quasi-static check (the same test at half the speed), checkpoints and VTK frames.
#include "kerf/dem/procedures/lab_test.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "common.hpp"
#include "kerf/dem/output/output.hpp"
#include "kerf/dem/output/png.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"
#include "kind_results.hpp"

namespace kerf::dem::kinds {

namespace {

/// A test's sample, for log lines (steps counted from the test's start, not the specimen's genesis).
SampleState test_sample(const CurveSample& sample, double time_step_s, std::size_t n_particles) {
  return {std::llround(sample.time_s / time_step_s),
          sample.time_s,
          n_particles,
          sample.n_tension_cracks + sample.n_shear_cracks,
          {},
          {},
          {},
          sample.axial_strain,
          units::pa_to_mpa(sample.stress_Pa)};
}

/// Runs one test on a copy of the specimen with a progress bar (the quasi-static check).
LabTestResult run_test(const Simulation& specimen, const LoadingSpec& loading, const std::string& label,
                       const ProgressTarget& target) {
  // Progress against the step count that reaches max_strain (an upper bound: most runs stop earlier).
  const double height = [&] {
    double lo = 1e300, hi = -1e300;
    const auto& p = specimen.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      lo = std::min(lo, p.y[i] - p.radius[i]), hi = std::max(hi, p.y[i] + p.radius[i]);
    return hi - lo;
  }();
  const double n = static_cast<double>(specimen.particles().size());
  const double steps = loading.max_strain * height / (2 * loading.speed_m_per_s * specimen.time_step());
  StageProgress progress(target, label, n * steps, "particle-steps");
  auto result = run_lab_test(specimen, loading, [&](const Simulation& sim, const CurveSample& sample) {
    progress.advance(n * loading.sample_every_steps, test_sample(sample, sim.time_step(), sim.particles().size()));
  });
  progress.finish();
  return result;
}

class LabTestKind final : public SceneKind {
 public:
  explicit LabTestKind(LabTest test) : test_(test) {}
  std::string name() const override { return lab_test_names().name(test_); }
  bool writes_checkpoints() const override { return true; }

  void read(ObjectReader& root, const SceneCommon&) override {
    if (auto loading = root.find_object("loading")) {
      loading_ = read_loading_spec(*loading, test_);
      loading->finish();
    } else {
      static const Json empty = Json::object();
      ObjectReader none(empty, "loading");
      loading_ = read_loading_spec(none, test_);
    }
  }

  SceneOutcome run(const SceneCommon& common, const SceneRun& run) override {
    StartedRun started = start_from_specimen(common, name(), progress_target(run.options));
    const Simulation& specimen = started.specimen;
    Json& summary = started.summary;
    return continue_test(common, run, specimen, std::move(summary), LabTestRun(specimen, loading_),
                         {{}, 0, run.scene_dir, progress_target(run.options), {}});
  }

  SceneOutcome resume(const SceneCommon& common, const SceneRun& run, const Checkpoint& c) override {
    const Simulation specimen = Simulation::deserialize(c.specimen);
    return continue_test(common, run, specimen, c.summary, LabTestRun::deserialize(c.run),
                         {c.frames, c.sample_index, c.scene_dir, progress_target(run.options), {}});
  }

 private:
  LabTest test_;
  LoadingSpec loading_;

  /// Runs (or continues) the test to its end, then the quasi-static check and the outputs.
  // Long (~80 lines) for a reason: each sample interleaves steps, the sample, checkpoints, frames and progress on
  // one state, as continue_cut does (kinds/cut.cpp).
  SceneOutcome continue_test(const SceneCommon& common, const SceneRun& scene_run, const Simulation& specimen,
                             Json summary, LabTestRun run, RunProgress tp) const {
    const fs::path& out = scene_run.options.out;
    CheckpointSchedule checkpoints(scene_run.options);
    const int frame_every = common.output.frame_every_samples;
    // Frames: every frame_every_samples samples, plus the final state.
    const auto write_frame = [&](const Simulation& sim) {
      write_frame_files(out, {sim, nullptr, std::nullopt, std::nullopt, name()}, common.output, tp);
    };
    if (frame_every > 0 && tp.sample_index == 0) write_frame(specimen);
    const double n = static_cast<double>(specimen.particles().size());
    const double steps =
        loading_.max_strain * run.result().height_m / (2 * loading_.speed_m_per_s * run.simulation().time_step());
    StageProgress progress(tp.progress, name(), n * steps, "particle-steps");
    const auto last_sample = [&] {
      return test_sample(run.result().curve.back(), run.simulation().time_step(), specimen.particles().size());
    };
    if (tp.sample_index > 0)
      progress.resume_at(n * loading_.sample_every_steps * tp.sample_index,
                         run.result().curve.empty() ? std::nullopt : std::optional<SampleState>(last_sample()));
    while (run.advance()) {
      ++tp.sample_index;
      progress.advance(n * loading_.sample_every_steps, last_sample());
      if (frame_every > 0 && tp.sample_index % frame_every == 0) write_frame(run.simulation());
      if (checkpoints.due(tp.sample_index))
        write_checkpoint(out, {scene_run.doc, summary, tp.frames, tp.sample_index, scene_run.options.checkpoint_every,
                               tp.scene_dir, specimen.serialize(), run.serialize(), scene_run.options.provenance});
    }
    // The last sample (advance returned false).
    progress.finish(last_sample());
    const LabTestResult& res = run.result();
    if (frame_every > 0) write_frame(run.simulation());
    const bool tension = test_ == LabTest::tension;
    Json results = results_to_json(lab_test_results(), {test_ == LabTest::tension, res});
    if (loading_.quasi_static_check) {
      LoadingSpec half = loading_;
      half.speed_m_per_s *= 0.5;
      half.quasi_static_check = false;  // this run is the check
      const LabTestResult slow = run_test(specimen, half, name() + " (quasi-static check, half speed)", tp.progress);
      const Json& check = results[lab_test_keys::quasi_static_check] =
          results_to_json(lab_test_check_results(), {half.speed_m_per_s, slow, res});
      const double change = check[lab_test_check_keys::peak_change_percent].get<double>();
      const bool quasi_static = check[lab_test_check_keys::verdict] == "quasi-static";
      std::cout << fmt::format("{}: quasi-static check: the peak changes {:+.2f} % at half the speed ({} m/s): {}\n",
                               name(), change, half.speed_m_per_s,
                               quasi_static
                                   ? fmt::format("quasi-static (within {} %)", kQuasiStaticTolerancePercent)
                                   : fmt::format("RATE-DEPENDENT (more than {} %): lower loading.speed_m_per_s",
                                                 kQuasiStaticTolerancePercent));
    }
    summary["results"] = results;
    summary["n_particles"] = res.n_particles;
    summary["steps"] = res.steps;
    summary["wall_time_s"] = res.wall_time_s;
    summary["particle_steps_per_s"] =
        static_cast<double>(res.n_particles) * static_cast<double>(res.steps) / res.wall_time_s;
    write_file_atomically(out / "curve.csv", curve_csv(res));
    write_file_atomically(out / "cracks.csv", cracks_csv(run.simulation().cracks()));
    if (frame_every > 0) write_pvd(out / "result.pvd", tp.frames);
    write_specimen_png(out / "specimen.png", run.simulation(), name() + ", final state");
    write_stress_strain_png(out / "curve.png", res, name() + ": stress-strain curve");
    write_summary(scene_run.options, scene_run.doc, summary);
    remove_checkpoint(out);  // finished: nothing to resume
    std::cout << fmt::format("{}: E = {:.2f} GPa, nu = {:.3f}, {} strength = {:.1f} MPa, {} steps, {:.1f} s -> {}\n",
                             name(), units::pa_to_gpa(res.youngs_modulus_Pa), res.poissons_ratio,
                             tension ? "tensile" : "compressive", units::pa_to_mpa(res.peak_stress_Pa), res.steps,
                             res.wall_time_s, out.string());
    return {0, summary, {}};
  }
};

}  // namespace

const ResultTable<LabTestReport>& lab_test_results() {
  namespace k = lab_test_keys;
  using R = LabTestReport;
  static const ResultTable<R> table{
      result_number<R>(k::youngs_modulus_GPa, units::kGPa, "Young's modulus E (secant at 50 % of the peak)",
                       [](const R& r) { return r.res.youngs_modulus_Pa; }),
      result_value<R>(k::poissons_ratio, "", "Poisson's ratio nu (secant at 50 % of the peak)",
                      [](const R& r) { return r.res.poissons_ratio; }),
      result_if(result_number<R>(k::tensile_strength_MPa, units::kMPa, "tension: the peak stress",
                                 [](const R& r) { return r.res.peak_stress_Pa; }),
                [](const R& r) { return r.tension; }),
      result_if(result_number<R>(k::compressive_strength_MPa, units::kMPa, "compression: the peak stress",
                                 [](const R& r) { return r.res.peak_stress_Pa; }),
                [](const R& r) { return !r.tension; }),
      result_value<R>(k::strain_at_peak, "", "axial strain at the peak",
                      [](const R& r) { return r.res.strain_at_peak; }),
      result_value<R>(k::n_tension_cracks, "", "broken joint elements in tension at the end",
                      [](const R& r) { return r.res.curve.back().n_tension_cracks; }),
      result_value<R>(k::n_shear_cracks, "", "broken joint elements in shear at the end",
                      [](const R& r) { return r.res.curve.back().n_shear_cracks; }),
      result_value<R>(k::stop_reason, "", "why the test stopped", [](const R& r) { return r.res.stop_reason; }),
      result_value<R>(k::speed_m_per_s, "m/s", "the platens' speed", [](const R& r) { return r.res.speed_m_per_s; }),
      result_number<R>(k::specimen_width_mm, units::kMm, "the specimen's width",
                       [](const R& r) { return r.res.width_m; }),
      result_number<R>(k::gauge_length_mm, units::kMm, "the specimen's height between the platens",
                       [](const R& r) { return r.res.height_m; })};
  return table;
}

const ResultTable<LabTestCheck>& lab_test_check_results() {
  namespace k = lab_test_check_keys;
  using C = LabTestCheck;
  const auto change = [](const C& c) {
    return 100 * (c.slow.peak_stress_Pa - c.res.peak_stress_Pa) / c.res.peak_stress_Pa;
  };
  static const ResultTable<C> table{
      result_value<C>(k::speed_m_per_s, "m/s", "the check's speed (half the test's)",
                      [](const C& c) { return c.speed_m_per_s; }),
      result_number<C>(k::peak_stress_MPa, units::kMPa, "the check's peak stress",
                       [](const C& c) { return c.slow.peak_stress_Pa; }),
      result_value<C>(k::peak_change_percent, "%", "the change of the peak at half the speed", change),
      result_value<C>(k::youngs_modulus_change_percent, "%", "the change of E at half the speed",
                      [](const C& c) {
                        return 100 * (c.slow.youngs_modulus_Pa - c.res.youngs_modulus_Pa) / c.res.youngs_modulus_Pa;
                      }),
      result_value<C>(k::wall_time_s, "s", "the check's wall time", [](const C& c) { return c.slow.wall_time_s; }),
      result_value<C>(k::tolerance_percent, "%", "the largest change of the peak of a quasi-static test",
                      [](const C&) { return kQuasiStaticTolerancePercent; }),
      result_value<C>(k::verdict, "", "`quasi-static` within the tolerance, else `rate-dependent`",
                      [change](const C& c) { return std::string(quasi_static_verdict(change(c))); })};
  return table;
}

std::unique_ptr<SceneKind> make_tension_kind() {
  return std::make_unique<LabTestKind>(LabTest::tension);
}
std::unique_ptr<SceneKind> make_compression_kind() {
  return std::make_unique<LabTestKind>(LabTest::compression);
}

}  // namespace kerf::dem::kinds
