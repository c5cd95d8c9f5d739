// The trepanning scene kind (models.force = trepanning, Yu et al. 2023): trepanning_scene.hpp parses it,
// trepanning.hpp predicts it; this file puts it behind the AnalyticCase interface (evaluate.hpp) with its CSV
// row and report.
#include <fmt/format.h>

#include <optional>
#include <utility>

#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/kinds/cells.hpp"
#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/trepanning/trepanning.hpp"
#include "kerf/analytic/trepanning/trepanning_results.hpp"
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

}  // namespace

TrepanningRow::TrepanningRow(const TrepanningScene& s, const TrepanningForces& f)
    : scene(s), forces(f), computed(f.feed_per_rev_m > 0.0) {
  // Column names need no prediction: diagnostics only when the forces were computed (feed per rev > 0).
  if (!scene.grits || !computed) return;
  grits = trepanning_grit_diagnostics(scene.tool, scene.cut, scene.groups, *scene.grits);
  regime = grit_regime(scene, grits.grit_depth_m);
}

const ResultTable<TrepanningRow>& trepanning_results() {
  using R = TrepanningRow;
  namespace k = trepanning_keys;
  const auto with_grits = [](const R& r) { return r.scene.grits.has_value(); };
  // A grit column: present with the scene's grits, empty until the forces are computed.
  const auto grit_number = [with_grits](std::string_view key, std::string_view unit, std::string_view doc,
                                        double (*get)(const R&)) {
    return result_if(result_value<R>(key, unit, doc, [get](const R& r) { return r.computed ? Json(get(r)) : Json(); }),
                     with_grits);
  };
  static const ResultTable<R> table{
      result_value<R>(k::force_model, "", "the force model (trepanning)",
                      [](const R&) { return std::string("trepanning"); }),
      result_value<R>(k::outer_diameter_mm, "mm", "the tool's outer diameter",
                      [](const R& r) { return units::m_to_mm(r.scene.tool.outer_diameter_m); }),
      result_value<R>(k::inner_diameter_mm, "mm", "the tool's inner diameter",
                      [](const R& r) { return units::m_to_mm(r.scene.tool.inner_diameter_m); }),
      result_value<R>(k::feed_rate_um_per_s, "um/s", "feed rate",
                      [](const R& r) { return units::m_to_um(r.scene.cut.feed_rate_m_per_s); }),
      result_value<R>(k::spindle_speed_rpm, "rpm", "spindle speed",
                      [](const R& r) { return r.scene.cut.spindle_speed_rev_per_s * 60.0; }),
      result_value<R>(k::feed_per_rev_um, "um", "feed per revolution",
                      [](const R& r) { return units::m_to_um(r.forces.feed_per_rev_m); }),
      result_value<R>(k::axial_force_N, "N", "axial force (Yu et al. 2023, Eq. 21)",
                      [](const R& r) { return r.forces.axial_force_N; }),
      result_value<R>(k::torque_N_m, "N m", "torque (Eq. 22)", [](const R& r) { return r.forces.torque_N_m; }),
      result_value<R>(k::axial_group_MPa, "MPa", "the lumped axial group K_F = H tan(phi)",
                      [](const R& r) { return units::pa_to_mpa(r.scene.groups.axial_group_Pa); }),
      result_value<R>(k::torque_group_MPa, "MPa", "the lumped torque group K_M = H (1 + pi tan(phi) mu / 2)",
                      [](const R& r) { return units::pa_to_mpa(r.scene.groups.torque_group_Pa); }),
      grit_number(k::grit_count, "", "grits on the end face, N_c = S C (Eq. 2; models.trepanning.grits)",
                  [](const R& r) { return r.grits.grit_count; }),
      grit_number(k::cutting_edges, "", "cutting edges Z = N_c / N_0 (Eqs. 1, 5)",
                  [](const R& r) { return r.grits.cutting_edges; }),
      grit_number(k::feed_per_edge_um, "um", "feed per cutting edge a_f = f / Z (Eqs. 6, 8)",
                  [](const R& r) { return units::m_to_um(r.grits.feed_per_edge_m); }),
      grit_number(k::grit_depth_um, "um", "each grit's depth of cut g = a_f (Eq. 14)",
                  [](const R& r) { return units::m_to_um(r.grits.grit_depth_m); }),
      grit_number(k::grit_normal_force_N, "N", "each grit's normal force F_an (Eqs. 11, 15, 17, 19)",
                  [](const R& r) { return r.grits.grit_normal_force_N; }),
      grit_number(k::grit_tangential_force_N, "N", "each grit's tangential force F_at (Eqs. 12, 16, 18, 20)",
                  [](const R& r) { return r.grits.grit_tangential_force_N; }),
      result_if(result_value<R>(k::critical_depth_nm, "nm", "the ductile-brittle critical depth d_c (Bifano)",
                                [](const R& r) { return r.regime ? Json(units::m_to_nm(r.regime->first)) : Json(); }),
                with_grits),
      result_if(result_value<R>(
                    k::grit_regime, "", "each grit's depth against d_c: ductile, transition, brittle",
                    [](const R& r) { return std::string(r.regime ? cutting_regime_name(r.regime->second) : ""); }),
                with_grits)};
  return table;
}

namespace {

class TrepanningCase final : public AnalyticCase {
 public:
  TrepanningCase(const Json& document, MaterialCache* cache) : scene_(parse_trepanning_scene(document, cache)) {}

  void predict() override { forces_ = trepanning_forces(scene_.tool, scene_.cut, scene_.groups); }

  void write_cells(CellWriter& out) const override {
    const TrepanningForces forces = forces_.value_or(TrepanningForces{});
    write_result_cells(trepanning_results(), TrepanningRow{scene_, forces}, out);
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
    const TrepanningRow row{scene_, forces};  // its grits' diagnostics and regime, as the CSV row has them
    const TrepanningGritDiagnostics& d = row.grits;
    fmt::print(text,
               "per grit          {:.4g} grits, {:.4g} cutting edges, depth {:.4g} nm, normal {:.4g} mN, tangential "
               "{:.4g} mN (Eqs. 1-20)\n",
               d.grit_count, d.cutting_edges, units::m_to_nm(d.grit_depth_m), 1e3 * d.grit_normal_force_N,
               1e3 * d.grit_tangential_force_N);
    if (row.regime)
      fmt::print(text, "grit regime       {} (each grit's depth against d_c)\n",
                 cutting_regime_name(row.regime->second));
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
