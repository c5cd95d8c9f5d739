// The orthogonal-cutting scene kind (models.force merchant, liu_li, oxley, transition or auto): scene.hpp parses it,
// predict.hpp predicts it; this file puts it behind the AnalyticCase interface (evaluate.hpp) with its report.
#include <fmt/format.h>

#include <cmath>

#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

void print_prediction(std::FILE* text, const std::string& scene_path, const AnalyticScene& scene, const Prediction& p) {
  namespace k = prediction_keys;
  // The numbers as the CSV row holds them (prediction_results: each converted once, there).
  const PredictionReport report{scene, p};
  const auto value = [&report](std::string_view key) {
    return result_of(prediction_results(), report, key).get<double>();
  };
  fmt::print(text, "scene             {}\n", scene_path);
  fmt::print(text, "material          {} ({})\n", scene.material->name, scene.material->title);
  fmt::print(text, "force model       {}{}\n", p.force_model,
             scene.force_choice_reason.empty() ? "" : " (auto: " + scene.force_choice_reason + ")");
  fmt::print(text, "cut               t0 = {:.6g} um, width = {:.6g} mm, speed = {:.6g} m/min\n",
             value(k::uncut_chip_thickness_um), value(k::width_mm), value(k::speed_m_per_min));
  fmt::print(text, "tool              rake = {:.6g} deg, edge radius = {:.6g} um\n", value(k::rake_deg),
             value(k::edge_radius_um));
  fmt::print(text, "cutting force     {:.6g} N  ({:.6g} N/mm)\n", value(k::cutting_force_N),
             value(k::cutting_force_N_per_mm));
  fmt::print(text, "thrust force      {:.6g} N  ({:.6g} N/mm)\n", value(k::thrust_force_N),
             value(k::thrust_force_N_per_mm));
  fmt::print(text, "shear angle       {:.4g} deg\n", value(k::shear_angle_deg));
  if (p.has_friction) {
    const bool own_friction = scene.force_model().solves_oxley;
    const bool from_scene = scene.friction_angle_rad && !own_friction &&
                            std::fabs(*scene.friction_angle_rad - p.friction_angle_rad) <= kSameAngle_rad;
    fmt::print(text, "friction angle    {:.4g} deg (from {})\n", value(k::friction_angle_deg),
               own_friction ? "the extended-Oxley solution"
               : from_scene ? scene.friction_origin
                            : fmt::format("the {} friction closure at the nominal rake",
                                          friction_closure_name(scene.params<ChipTermParams>().liu_li.closure)));
  }
  fmt::print(text, "chip ratio        {:.4g} (chip thickness {:.6g} um)\n", value(k::chip_ratio),
             value(k::chip_thickness_um));
  if (scene.flow_stress.hardness) {
    fmt::print(text,
               "flow stress       {:.6g} MPa (hardness {:.6g} MPa / constraint factor {:.4g}, {}); k_s = {:.6g} MPa\n",
               value(k::flow_stress_MPa), units::pa_to_mpa(scene.flow_stress.hardness->hardness_Pa),
               scene.flow_stress.hardness->hardness_Pa / p.flow.total_Pa,
               constraint_model_name(scene.flow_stress.constraint), value(k::shear_flow_stress_MPa));
  } else {
    fmt::print(text,
               "flow stress       {:.6g} MPa (JC {:.6g} + Hall-Petch {:.6g} + dislocation {:.6g}); k_s = {:.6g} MPa\n",
               value(k::flow_stress_MPa), value(k::johnson_cook_stress_MPa), value(k::hall_petch_stress_MPa),
               value(k::dislocation_stress_MPa), value(k::shear_flow_stress_MPa));
  }
  fmt::print(text, "at                strain {:.4g}, strain rate {:.4g} 1/s, temperature {:.5g} K\n", value(k::strain),
             value(k::strain_rate_per_s), value(k::temperature_K));
  if (scene.critical_depth_m) {
    fmt::print(text, "regime            {} (critical depth d_c = {:.3g} nm)\n", p.regime,
               result_of(prediction_verdict_results(), report, k::critical_depth_nm).get<double>());
  }
  for (const auto& [column, length_m] : p.contact_lengths_m) {
    const std::string name = column.substr(0, column.size() - 3);
    if (length_m) fmt::print(text, "{:<17} {:.6g} mm\n", name, units::m_to_mm(*length_m));
    if (!length_m) fmt::print(text, "{:<17} not applicable (see the warnings)\n", name);
  }
  print_edge_details(text, scene, p);                                        // chip_term.hpp
  if (scene.force_model().print) scene.force_model().print(text, scene, p);  // the model's own lines
  print_oxley_details(text, scene, p);                                       // oxley_model.hpp
  const auto fired = p.guards.fired();
  if (fired.empty()) fmt::print(text, "guards            none fired\n");
  for (auto guard : fired) fmt::print(text, "guard             {}: {}\n", guard_name(guard), guard_policy(guard));
  for (const auto& w : p.warnings) fmt::print(text, "warning           {}\n", w);
}

class OrthogonalCase final : public AnalyticCase {
 public:
  OrthogonalCase(const Json& document, MaterialCache* cache) : scene_(parse_analytic_scene(document, cache)) {}

  void predict() override { prediction_ = kerf::predict(scene_); }

  void write_cells(CellWriter& out) const override {
    if (prediction_) return write_prediction_cells(scene_, *prediction_, out);
    write_prediction_cells(scene_, Prediction{}, out);
  }

  void print(std::FILE* text, const std::string& scene_path) const override {
    print_prediction(text, scene_path, scene_, prediction_.value());
  }

  void print_regime(std::FILE* text, const std::string&) const override {
    const auto properties = brittle_properties(*scene_.material, "material");
    const double critical = critical_depth_m(properties);
    const double depth = scene_.uncut_chip_thickness_m;
    const auto regime = classify_regime(depth, critical);
    fmt::print(text, "material          {} (E = {:.4g} GPa, H = {:.4g} GPa, K_c = {:.4g} MPa m^0.5)\n",
               scene_.material->name, units::pa_to_gpa(properties.youngs_modulus_Pa),
               units::pa_to_gpa(properties.hardness_Pa), units::pa_to_mpa(properties.fracture_toughness_Pa_sqrt_m));
    fmt::print(text, "critical depth    d_c = 0.15 (E/H) (K_c/H)^2 = {:.4g} nm (Bifano, Dow & Scattergood 1991)\n",
               units::m_to_nm(critical));
    fmt::print(text, "uncut thickness   {:.4g} nm ({:.3g} d_c)\n", units::m_to_nm(depth), depth / critical);
    fmt::print(text, "regime            {}\n", cutting_regime_name(regime));
    switch (regime) {
      case CuttingRegime::ductile:
        fmt::print(text,
                   "model to use      the ductile-regime analytic models (merchant, liu_li, oxley; "
                   "transition reduces to them here)\n");
        break;
      case CuttingRegime::transition:
        fmt::print(text,
                   "model to use      models.force = transition (the ductile layer plus a fracture part); the "
                   "ductile models alone overestimate the chip's integrity\n");
        break;
      case CuttingRegime::brittle:
        fmt::print(text,
                   "model to use      models.force = transition up to about 0.2 mm, the DEM (kerf-dem) for cuts "
                   "of tens of um and more, or the trepanning model for abrasive drilling\n");
        break;
    }
  }

  std::vector<std::string> guard_names() const override {
    std::vector<std::string> names;
    if (prediction_)
      for (auto guard : prediction_->guards.fired()) names.emplace_back(guard_name(guard));
    return names;
  }

  std::string_view comparison_title() const override { return "Analytic force model"; }
  std::optional<double> force_width_m() const override { return scene_.width_m; }

  std::vector<std::string> warnings() const override {
    return prediction_ ? prediction_->warnings : std::vector<std::string>{};
  }

 private:
  AnalyticScene scene_;
  std::optional<Prediction> prediction_;
};

}  // namespace

std::unique_ptr<AnalyticCase> build_orthogonal_scene(const Json& document, MaterialCache* cache) {
  return std::make_unique<OrthogonalCase>(document, cache);
}

}  // namespace kerf
