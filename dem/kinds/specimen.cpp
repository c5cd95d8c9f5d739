// Scene kind "specimen": a genesis (or a loaded specimen), saved for reuse with a VTK frame and a picture.
#include <fmt/format.h>

#include <iostream>

#include "common.hpp"
#include "kerf/dem/output/output.hpp"
#include "kerf/dem/output/png.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf::dem::kinds {

namespace {

class SpecimenKind final : public SceneKind {
 public:
  std::string name() const override { return "specimen"; }
  void read(ObjectReader&, const SceneCommon&) override {}

  void check_options(const RunOptions& options, const SceneCommon& common) const override {
    if (options.checkpoint_every > 0)
      throw InputError("--checkpoint-every", std::to_string(options.checkpoint_every),
                       "checkpoints only for tension, compression, calibrate and cut scenes");
    SceneKind::check_options(options, common);
  }

  SceneOutcome run(const SceneCommon& common, const SceneRun& run) override {
    const fs::path& out = run.options.out;
    StartedRun started = start_from_specimen(common, name(), progress_target(run.options));
    const Simulation& specimen = started.specimen;
    Json& summary = started.summary;
    const SpecimenReport& report = started.report;
    const double genesis_s = summary["specimen"]["genesis_wall_time_s"].get<double>();
    save_specimen((out / "specimen.json").string(), specimen, started.spec, report);
    write_vtp_frame(out / "specimen.vtp", specimen);
    write_specimen_png(out / "specimen.png", specimen, name());
    summary["n_particles"] = report.n_particles;
    summary["steps"] = report.genesis_steps;
    summary["wall_time_s"] = genesis_s;
    summary["particle_steps_per_s"] = report.n_particles * static_cast<double>(report.genesis_steps) / genesis_s;
    write_summary(run.options, run.doc, summary);
    std::cout << fmt::format(
        "specimen: {} disks, {} joints, packing fraction {:.4f}, coordination {:.3f}, residual "
        "stress ({:.3g}, {:.3g}) MPa -> {}\n",
        report.n_particles, report.n_bonds, report.packing_fraction, report.coordination_number,
        units::pa_to_mpa(report.residual_stress_xx_Pa), units::pa_to_mpa(report.residual_stress_yy_Pa),
        (out / "specimen.json").string());
    return {0, summary, {}};
  }
};

}  // namespace

std::unique_ptr<SceneKind> make_specimen_kind() {
  return std::make_unique<SpecimenKind>();
}

}  // namespace kerf::dem::kinds
