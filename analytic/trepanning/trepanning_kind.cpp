// The trepanning scene kind (models.force = trepanning, Yu et al. 2023): trepanning_scene.hpp parses it,
// trepanning.hpp predicts it; this file puts it behind the AnalyticCase interface (evaluate.hpp) with its CSV
// row and report.
#include <fmt/format.h>

#include <optional>
#include <utility>

#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/trepanning/trepanning.hpp"
#include "kerf/analytic/trepanning/trepanning_scene.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

/// Each grit's depth against the ductile-brittle critical depth (Bifano): {critical depth, regime} when the
/// material has the data.
std::optional<std::pair<double, CuttingRegime>> grit_regime(const TrepanningScene& scene, double grit_depth_m) {
  const Json* brittle = scene.material.group("brittle");
  if (!brittle || !brittle->contains("fracture_toughness_MPa_sqrt_m")) return std::nullopt;
  const double critical = critical_depth_m(brittle_properties(scene.material, "material"));
  return std::pair{critical, classify_regime(grit_depth_m, critical)};
}

void write_trepanning_cells(const TrepanningScene& scene, const TrepanningForces& forces, CellWriter& w) {
  w.text("force_model", "trepanning");
  w.number("outer_diameter_mm", units::m_to_mm(scene.tool.outer_diameter_m));
  w.number("inner_diameter_mm", units::m_to_mm(scene.tool.inner_diameter_m));
  w.number("feed_rate_um_per_s", units::m_to_um(scene.cut.feed_rate_m_per_s));
  w.number("spindle_speed_rpm", scene.cut.spindle_speed_rev_per_s * 60.0);
  w.number("feed_per_rev_um", units::m_to_um(forces.feed_per_rev_m));
  w.number("axial_force_N", forces.axial_force_N);
  w.number("torque_N_m", forces.torque_N_m);
  w.number("axial_group_MPa", units::pa_to_mpa(scene.groups.axial_group_Pa));
  w.number("torque_group_MPa", units::pa_to_mpa(scene.groups.torque_group_Pa));
  if (!scene.grits) return;
  // Column names need no prediction: diagnostics only when the forces were computed (feed per rev > 0).
  const bool computed = forces.feed_per_rev_m > 0.0;
  const auto d = computed ? trepanning_grit_diagnostics(scene.tool, scene.cut, scene.groups, *scene.grits)
                          : TrepanningGritDiagnostics{};
  w.optional_number("grit_count", computed, d.grit_count);
  w.optional_number("cutting_edges", computed, d.cutting_edges);
  w.optional_number("feed_per_edge_um", computed, units::m_to_um(d.feed_per_edge_m));
  w.optional_number("grit_depth_um", computed, units::m_to_um(d.grit_depth_m));
  w.optional_number("grit_normal_force_N", computed, d.grit_normal_force_N);
  w.optional_number("grit_tangential_force_N", computed, d.grit_tangential_force_N);
  const auto regime = computed ? grit_regime(scene, d.grit_depth_m) : std::nullopt;
  w.optional_number("critical_depth_nm", regime.has_value(), regime ? units::m_to_nm(regime->first) : 0.0);
  w.text("grit_regime", regime ? cutting_regime_name(regime->second) : std::string_view());
}

class TrepanningCase final : public AnalyticCase {
 public:
  TrepanningCase(const Json& document, MaterialCache* cache) : scene_(parse_trepanning_scene(document, cache)) {}

  void predict() override { forces_ = trepanning_forces(scene_.tool, scene_.cut, scene_.groups); }

  void write_cells(CellWriter& out) const override {
    write_trepanning_cells(scene_, forces_.value_or(TrepanningForces{}), out);
  }

  void print(std::FILE* text, const std::string& scene_path) const override {
    const TrepanningForces& forces = forces_.value();
    fmt::print(text, "scene             {}\n", scene_path);
    fmt::print(text, "material          {} ({})\n", scene_.material.name, scene_.material.title);
    fmt::print(text, "force model       trepanning (Yu et al. 2023, Eqs. 21-22, brittle regime)\n");
    fmt::print(text, "tool              outer diameter {:.6g} mm, inner diameter {:.6g} mm\n",
               units::m_to_mm(scene_.tool.outer_diameter_m), units::m_to_mm(scene_.tool.inner_diameter_m));
    fmt::print(text, "cut               feed rate {:.6g} um/s, spindle speed {:.6g} rpm ({:.6g} um/rev)\n",
               units::m_to_um(scene_.cut.feed_rate_m_per_s), scene_.cut.spindle_speed_rev_per_s * 60.0,
               units::m_to_um(forces.feed_per_rev_m));
    fmt::print(text, "axial force       {:.6g} N\n", forces.axial_force_N);
    fmt::print(text, "torque            {:.6g} N m\n", forces.torque_N_m);
    fmt::print(text,
               "lumped groups     K_F = H tan(phi) = {:.6g} MPa, K_M = H (1 + pi tan(phi) mu / 2) = {:.6g} MPa ({})\n",
               units::pa_to_mpa(scene_.groups.axial_group_Pa), units::pa_to_mpa(scene_.groups.torque_group_Pa),
               scene_.groups_origin);
    if (!scene_.grits) return;
    const auto d = trepanning_grit_diagnostics(scene_.tool, scene_.cut, scene_.groups, *scene_.grits);
    fmt::print(text,
               "per grit          {:.4g} grits, {:.4g} cutting edges, depth {:.4g} nm, normal {:.4g} mN, tangential "
               "{:.4g} mN (Eqs. 1-20)\n",
               d.grit_count, d.cutting_edges, units::m_to_nm(d.grit_depth_m), 1e3 * d.grit_normal_force_N,
               1e3 * d.grit_tangential_force_N);
    if (const auto regime = grit_regime(scene_, d.grit_depth_m))
      fmt::print(text, "grit regime       {} (each grit's depth against d_c)\n", cutting_regime_name(regime->second));
  }

  std::string_view comparison_title() const override { return "Trepanning model"; }
  bool fits_lumped_groups() const override { return true; }

  void print_regime(std::FILE* text, const std::string& scene_path) const override {
    fmt::print(text,
               "{}: the trepanning model is a brittle-regime model (Yu et al. 2023); the depth each grit cuts "
               "depends on the grit density, which the scene does not give\n",
               scene_path);
  }

 private:
  TrepanningScene scene_;
  std::optional<TrepanningForces> forces_;
};

}  // namespace

std::unique_ptr<AnalyticCase> build_trepanning_scene(const Json& document, MaterialCache* cache) {
  return std::make_unique<TrepanningCase>(document, cache);
}

}  // namespace kerf
