#include "kerf/analytic/forces/transition_model.hpp"

#include <fmt/format.h>

#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/forces/transition.hpp"
#include "kerf/analytic/kinds/cells.hpp"
#include "kerf/analytic/kinds/model_fields.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/kinds/scene_keys.hpp"
#include "kerf/error.hpp"
#include "kerf/field_table.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

// The deepest cut the transition model was held against: Yang et al. 2018's Table 6 (0.1 and 0.2 mm).
constexpr double kTransitionValidatedDepth_m = 0.2e-3;

constexpr FieldUnit kMPaSqrtM{"MPa m^0.5", units::mpa_to_pa, units::pa_to_mpa};

// fracture_force_per_width's own fields and the scene's keys that set them.
constexpr SceneKeyOf kSceneKeys[] = {
    {"params.ductile_layer_factor", "models.transition.ductile_layer_factor"},
    {"params.fracture_coefficient", "models.transition.fracture_coefficient"},
    {"fracture_toughness_Pa_sqrt_m", "material.brittle.fracture_toughness_MPa_sqrt_m", kMPaSqrtM, "Pa m^0.5"},
    {"depth_m", "cut.uncut_chip_thickness_um", units::kUm, "m"},
    {"friction_angle_rad", "cut.friction_angle_deg", units::kDeg, ""}};

constexpr char kFracture[] = "fracture";

/// Above l the shear angle, chip, state and edge details are the layer's.
void predict_transition_forces(const AnalyticScene& scene, const OxleyResult* oxley, Prediction& p) {
  if (!scene.critical_depth_m) {
    throw InputError("material.brittle",
                     fmt::format("(no hardness and toughness in material '{}')", scene.material->name),
                     "a brittle material with elastic.youngs_modulus_GPa, brittle.hardness_GPa and "
                     "brittle.fracture_toughness_MPa_sqrt_m: models.force = transition needs its critical depth");
  }
  const TransitionParams& params = scene.params<TransitionParams>();
  const double layer = ductile_layer_m(params, *scene.critical_depth_m);
  const double depth = scene.uncut_chip_thickness_m;
  const bool sharp = scene.edge_radius_m == 0.0;
  TransitionDetails details;
  details.ductile_layer_m = layer;
  if (depth <= layer) {
    predict_chip_forces(scene, oxley, sharp, p);
  } else {
    AnalyticScene layer_scene = scene;
    layer_scene.uncut_chip_thickness_m = layer;
    predict_chip_forces(layer_scene, oxley, sharp, p);
  }
  details.layer = {p.cutting_force_N / scene.width_m, p.thrust_force_N / scene.width_m};
  const BrittleProperties brittle = brittle_properties(*scene.material, "material");
  details.fracture = naming_scene_keys(kSceneKeys, [&] {
    return fracture_force_per_width(params, brittle.fracture_toughness_Pa_sqrt_m, depth, layer, scene.rake_rad,
                                    p.friction_angle_rad);
  });
  if (details.fracture.cutting_N_per_m > details.layer.cutting_N_per_m) {
    p.warnings.push_back(
        "the fracture part (zeta K_c sqrt(h) scaling) carries most of the force: on Yang et al. "
        "2018's soda-lime cuts at 0.1-0.2 mm it is 15-20 times the measured force "
        "(validation/glass_transition/README.md); models.fracture = none gives the edge's layer "
        "alone, a lower bound");
  }
  p.cutting_force_N += details.fracture.cutting_N_per_m * scene.width_m;
  p.thrust_force_N += details.fracture.thrust_N_per_m * scene.width_m;
  p.details = details;
}

void print_transition(std::FILE* text, const AnalyticScene& scene, const Prediction& p) {
  namespace k = transition_keys;
  if (!transition_details(p)) return;
  // The numbers as the CSV row holds them (transition_results).
  const PredictionReport report{scene, p};
  const auto value = [&report](std::string_view key) { return result_of(transition_results(), report, key); };
  fmt::print(text,
             "ductile layer     l = {:.4g} um ({} x d_c); the ductile model's part {:.6g} N cutting, {:.6g} N "
             "thrust\n",
             value(k::ductile_layer_um).get<double>(), scene.params<TransitionParams>().layer_factor,
             value(k::layer_cutting_force_N).get<double>(), value(k::layer_thrust_force_N).get<double>());
  fmt::print(text, "fracture part     {:.6g} N cutting, {:.6g} N thrust ({})\n",
             value(k::fracture_cutting_force_N).get<double>(), value(k::fracture_thrust_force_N).get<double>(),
             value(k::fracture_model).get<std::string>());
}

void read_transition(ObjectReader& object, AnalyticScene& scene) {
  read_fields_into(object, transition_fields(), scene.params<TransitionParams>(), SiCheck::on);
}

constexpr ModelParamsObject kObjects[] = {{"models.transition",
                                           "optional: models.force = transition's ductile layer and fracture part",
                                           &read_transition, [] { return fields_markdown(transition_fields()); }}};

}  // namespace

const FieldTable<TransitionParams>& transition_model_fields() {
  static const FieldTable<TransitionParams> table{model_choice<TransitionParams, FractureModel, kFracture>(
      "the fracture part of models.force = transition above the ductile layer: the LEFM scratch scaling "
      "zeta K_c sqrt(h) (Huang & Detournay 2008, Akono & Ulm 2011), or none (the edge's ductile layer alone)",
      [](auto& s) -> auto& { return s.fracture; })};
  return table;
}

const ModelParams transition_model_params{.fields = [] { return scene_params_fields(transition_model_fields()); },
                                          .objects = kObjects};

const OrthogonalForceModel transition_force_model{.predict = &predict_transition_forces,
                                                  .edge_columns = true,
                                                  .validated_depth_m = kTransitionValidatedDepth_m,
                                                  .results = &transition_results,
                                                  .print = &print_transition};

const TransitionDetails* transition_details(const Prediction& p) {
  return std::any_cast<TransitionDetails>(&p.details);
}

const ResultTable<PredictionReport>& transition_results() {
  namespace k = transition_keys;
  using R = PredictionReport;
  // Its details, zero before a prediction (the column names) and for another model's.
  const auto own = [](const R& r) {
    const TransitionDetails* t = transition_details(r.p);
    return t ? *t : TransitionDetails{};
  };
  static const ResultTable<R> table{
      result_value<R>(
          k::fracture_model, "", "the fracture part's model (models.fracture)",
          [](const R& r) { return std::string(fracture_model_name(r.scene.params<TransitionParams>().fracture)); }),
      result_number<R>(k::ductile_layer_um, units::kUm, "the ductile layer l = lambda d_c",
                       [own](const R& r) { return own(r).ductile_layer_m; }),
      result_value<R>(k::layer_cutting_force_N, "N", "the ductile model's part at min(h, l), cutting",
                      [own](const R& r) { return own(r).layer.cutting_N_per_m * r.p.width_m; }),
      result_value<R>(k::layer_thrust_force_N, "N", "the ductile model's part at min(h, l), thrust",
                      [own](const R& r) { return own(r).layer.thrust_N_per_m * r.p.width_m; }),
      result_value<R>(k::fracture_cutting_force_N, "N", "the fracture part above l, cutting (zero at and below l)",
                      [own](const R& r) { return own(r).fracture.cutting_N_per_m * r.p.width_m; }),
      result_value<R>(k::fracture_thrust_force_N, "N", "the fracture part above l, thrust (zero at and below l)",
                      [own](const R& r) { return own(r).fracture.thrust_N_per_m * r.p.width_m; })};
  return table;
}

}  // namespace kerf
