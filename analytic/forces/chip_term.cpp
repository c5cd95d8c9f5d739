#include "kerf/analytic/forces/chip_term.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/forces/shear_angle.hpp"
#include "kerf/analytic/kinds/cells.hpp"
#include "kerf/analytic/kinds/model_fields.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/kinds/scene_keys.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

// Oxley's strain-rate constant C0 lies in 2-10 (Oxley 1989); its middle is used to estimate the primary-zone
// strain rate when the scene neither gives one nor asks for an Oxley solve.
constexpr double kTypicalStrainRateConstant = 5.0;

// The physics' own fields (liu_li_force_per_width's thickness, the ploughing term's edge radius) and the scene's
// keys that set them.
constexpr SceneKeyOf kSceneKeys[] = {{"uncut_chip_thickness_m", "cut.uncut_chip_thickness_um", units::kUm, "m"},
                                     {"edge_radius_m", "tool.edge_radius_um", units::kUm, "m"}};

constexpr char kClosure[] = "friction_closure", kLowerLimit[] = "lower_limit", kPloughing[] = "ploughing";

std::optional<QuadratureRule> quadrature_rule(std::string_view name) {
  return quadrature_rule_from_name(name);
}

std::span<const std::string_view> quadrature_names() {
  static const std::vector<std::string_view> names(quadrature_rule_names().begin(), quadrature_rule_names().end());
  return names;
}

/// Shear-plane strain and Oxley's strain-rate estimate for a sharp tool (physics-analytic.md §3).
DeformationState shear_plane_state(const AnalyticScene& scene, double shear_angle_rad) {
  const double a = scene.rake_rad, phi = shear_angle_rad;
  const double shear_strain = std::cos(a) / (std::sin(phi) * std::cos(phi - a));
  DeformationState state;
  state.strain = shear_strain / std::sqrt(3.0);
  if (scene.given_strain_rate_per_s) {
    state.strain_rate_per_s = *scene.given_strain_rate_per_s;
  } else {
    const double shear_velocity = scene.speed_m_per_s * std::cos(a) / std::cos(phi - a);
    const double shear_plane_length = scene.uncut_chip_thickness_m / std::sin(phi);
    state.strain_rate_per_s = kTypicalStrainRateConstant * shear_velocity / shear_plane_length / std::sqrt(3.0);
  }
  state.temperature_K = scene.workpiece_temperature_K;
  return state;
}

void check_shear_angle(double phi, const AnalyticScene& scene) {
  if (phi > 0.0 && phi < std::numbers::pi / 2.0) return;
  const char* model = scene.shear_angle == ShearAngleSource::merchant      ? "merchant"
                      : scene.shear_angle == ShearAngleSource::lee_shaffer ? "lee_shaffer"
                                                                           : "chip_ratio";
  throw InputError("models.shear_angle", model,
                   fmt::format("a model giving a shear angle in (0, 90) deg; it gives {:.3g} deg for rake {:.3g} deg "
                               "and friction angle {:.3g} deg (friction minus rake too large: lower the friction or "
                               "give a measured cut.chip_ratio)",
                               units::rad_to_deg(phi), units::rad_to_deg(scene.rake_rad),
                               units::rad_to_deg(scene.friction_angle_rad.value_or(0.0))));
}

/// The friction angle of a Merchant or Liu-Li prediction: the friction closure's beta at the nominal rake and
/// shear angle (the scene's beta for the constant closure; with the matching shear-angle rule the closures give
/// it back). A closure that implies beta < 0 (friction pulling the chip down the rake face: a chip ratio or
/// shear-angle rule the closure cannot match) is refused, naming what set the shear angle.
double prediction_friction_angle(const AnalyticScene& scene, double shear_angle_rad) {
  const ChipTermParams& chip = scene.params<ChipTermParams>();
  const double given = scene.friction_angle_rad.value_or(0.0);
  const double beta = local_friction_angle(chip.liu_li.closure, given, scene.rake_rad, shear_angle_rad);
  if (chip.liu_li.closure == FrictionClosure::constant) return beta;
  const std::string closure(friction_closure_name(chip.liu_li.closure));
  if (beta < 0.0) {
    const bool measured = scene.shear_angle == ShearAngleSource::chip_ratio;
    throw InputError(measured ? "cut.chip_ratio" : "models.friction_closure",
                     measured ? format_value(*scene.chip_ratio) : closure,
                     fmt::format("a shear angle and friction closure giving a friction angle >= 0: shear angle {:.4g} "
                                 "deg with the {} closure at rake {:.4g} deg gives beta = {:.4g} deg (the friction "
                                 "would pull the chip down the rake face)",
                                 units::rad_to_deg(shear_angle_rad), closure, units::rad_to_deg(scene.rake_rad),
                                 units::rad_to_deg(beta)));
  }
  return beta;
}

/// The ploughing model's friction factor: the scene's cut.friction_factor, else sin(2 beta) from the prediction's
/// one friction angle (Lee & Shaffer 1951; 0 for beta <= 0, 1, sticking, for beta >= 45 deg).
double ploughing_friction_factor(const AnalyticScene& scene, double friction_angle_rad) {
  return scene.friction_factor ? *scene.friction_factor : friction_factor_from_friction_angle(friction_angle_rad);
}

/// The nominal shear angle and chip ratio of a Merchant or Liu-Li prediction (from the chip ratio, or the
/// scene's shear-angle rule), checked, with the chip thickness.
void nominal_shear_angle(const AnalyticScene& scene, Prediction& p) {
  if (scene.shear_angle == ShearAngleSource::chip_ratio) {
    p.chip_ratio = *scene.chip_ratio;
    p.shear_angle_rad = shear_angle_from_chip_ratio(p.chip_ratio, scene.rake_rad);
  } else {
    const auto model =
        scene.shear_angle == ShearAngleSource::merchant ? ShearAngleModel::merchant : ShearAngleModel::lee_shaffer;
    p.shear_angle_rad = shear_angle(model, scene.rake_rad, scene.friction_angle_rad.value_or(0.0));
    p.chip_ratio = chip_ratio_from_shear_angle(p.shear_angle_rad, scene.rake_rad);
  }
  check_shear_angle(p.shear_angle_rad, scene);
  p.chip_thickness_m = scene.uncut_chip_thickness_m / p.chip_ratio;
}

/// The deformation state the flow stress is evaluated at, by models.deformation.
DeformationState deformation_state(const AnalyticScene& scene, const OxleyResult* oxley, double shear_angle_rad) {
  switch (scene.deformation) {
    case DeformationModel::given:
      return *scene.given_state;
    case DeformationModel::room_temperature:
      return shear_plane_state(scene, shear_angle_rad);
    case DeformationModel::oxley:
      return shear_plane_state_of(*oxley);
  }
  return {};
}

void predict_merchant_forces(const AnalyticScene& scene, const OxleyResult* oxley, Prediction& p) {
  predict_chip_forces(scene, oxley, true, p);
}

void predict_liu_li_forces(const AnalyticScene& scene, const OxleyResult* oxley, Prediction& p) {
  predict_chip_forces(scene, oxley, false, p);
}

void read_quadrature(ObjectReader& object, AnalyticScene& scene) {
  read_fields_into(object, quadrature_fields(), scene.params<ChipTermParams>().liu_li.quadrature, SiCheck::on);
}

constexpr ModelParamsObject kObjects[] = {{"models.quadrature", "optional: the Liu-Li integration", &read_quadrature,
                                           [] { return fields_markdown(quadrature_fields()); }}};

}  // namespace

const FieldTable<ChipTermParams>& chip_term_fields() {
  static const FieldTable<ChipTermParams> table{
      model_choice<ChipTermParams, FrictionClosure, kClosure>(
          "beta_k along the edge (Liu-Li); its value at the nominal rake is the prediction's one friction angle "
          "(Merchant and Liu-Li: forces, stagnation angle, contact lengths, printed value); `constant` keeps the "
          "scene's. With the chip ratio and a closure other than `constant`, no friction input is needed",
          [](auto& s) -> auto& { return s.liu_li.closure; }),
      model_choice<ChipTermParams, LowerLimitRule, kLowerLimit>(
          "start of the edge integral (Liu-Li): the stagnation point -(pi/4 + beta/2), kept a margin above any "
          "pole; or just above the pole (or -pi/2)",
          [](auto& s) -> auto& { return s.liu_li.lower_limit; }),
      model_choice<ChipTermParams, PloughingModel, kPloughing>(
          "the force under the edge below the stagnation point (Liu-Li with an edge radius): the Challen-Oxley wave "
          "model on the chord of the engaged arc, added to the chip term; `none`: no such force (0 N inside the "
          "ploughed layer)",
          [](auto& s) -> auto& { return s.ploughing; }),
      number_at<ChipTermParams>(
          "lower_limit_margin_deg", units::kDeg, Range::open(0.0, 45.0),
          "margin above the pole (and above -pi/2 for the Merchant closure, whose thrust diverges "
          "there)",
          [](auto& s) -> auto& { return s.liu_li.lower_limit_margin_rad; })};
  return table;
}

const FieldTable<QuadratureSettings>& quadrature_fields() {
  static const FieldTable<QuadratureSettings> table{
      mapped_choice<QuadratureSettings, QuadratureRule>(
          "rule", quadrature_names(), "the rule (docs/performance.md: the cost and error of each)",
          [](auto& q) -> auto& { return q.rule; }, &quadrature_rule),
      number_field("tolerance", units::kSi("(relative)"), Range::open(0.0, 1.0), "relative tolerance",
                   &QuadratureSettings::relative_tolerance),
      int_field("max_depth", 1, 20, "adaptive bisection depth (Boost) or 2^max_depth intervals (GSL)",
                &QuadratureSettings::max_depth)};
  return table;
}

const ModelParams chip_term_params{.fields = [] { return scene_params_fields(chip_term_fields()); },
                                   .objects = kObjects};

void predict_chip_forces(const AnalyticScene& scene, const OxleyResult* oxley, bool sharp, Prediction& p) {
  const double t0 = scene.uncut_chip_thickness_m;
  nominal_shear_angle(scene, p);

  // One friction angle for the whole prediction: the closure's value at the nominal rake (the scene's beta for
  // the constant closure). It sets the rake-face force, the stagnation angle, the contact lengths and the
  // printed value, for Merchant and Liu-Li alike, so that Liu-Li's r -> 0 limit is Merchant on the same scene.
  const double beta = prediction_friction_angle(scene, p.shear_angle_rad);
  p.friction_angle_rad = beta;
  p.has_friction = true;

  p.state = deformation_state(scene, oxley, p.shear_angle_rad);
  p.flow = flow_stress(scene.flow_stress, p.state, &p.guards);
  const double k_s = p.flow.shear_Pa;

  const ChipTermParams& chip = scene.params<ChipTermParams>();
  LiuLiParams params = chip.liu_li;
  params.rake_rad = scene.rake_rad;
  params.edge_radius_m = sharp ? 0.0 : scene.edge_radius_m;  // Merchant: r = 0
  params.chip_ratio = p.chip_ratio;
  params.friction_angle_rad = beta;
  const LiuLiResult liu_li =
      naming_scene_keys(kSceneKeys, [&] { return liu_li_force_per_width(params, k_s, t0, &p.guards); });
  if (sharp) {
    warn_if_edge_ignored(scene, "the sharp-tool model ignores it (use models.force = liu_li)", p);
  } else {
    p.chip_term.liu_li = liu_li;
  }
  if (liu_li.rake_face_ploughs) {
    p.warnings.push_back(
        fmt::format("rake {:.4g} deg lies below the {} cut-off {:.4g} deg: no chip forms, the whole "
                    "cut is ploughed (chip force zero)",
                    units::rad_to_deg(scene.rake_rad), lower_limit_rule_name(chip.liu_li.lower_limit),
                    units::rad_to_deg(liu_li.cut_off_rad)));
  }
  // The ploughing term under the edge: the wave model on the chord of the arc below h_p = min(t0, h_s).
  ForcePerWidth ploughing;
  if (p.chip_term.liu_li && chip.ploughing == PloughingModel::wave && params.edge_radius_m > 0.0) {
    p.chip_term.friction_factor = ploughing_friction_factor(scene, beta);
    const EdgePloughingParams plough{.edge_radius_m = params.edge_radius_m,
                                     .friction_factor = p.chip_term.friction_factor};
    p.chip_term.ploughing = naming_scene_keys(kSceneKeys, [&] {
      return edge_ploughing_force_per_width(plough, k_s, liu_li.ploughed_thickness_m, &p.guards);
    });
    ploughing = p.chip_term.ploughing->force;
  }
  p.cutting_force_N = (liu_li.total.cutting_N_per_m + ploughing.cutting_N_per_m) * scene.width_m;
  p.thrust_force_N = (liu_li.total.thrust_N_per_m + ploughing.thrust_N_per_m) * scene.width_m;

  if (scene.friction_angle_rad && std::fabs(beta - *scene.friction_angle_rad) > kSameAngle_rad) {
    p.warnings.push_back(fmt::format(
        "the {} friction closure at the nominal rake gives beta = {:.4g} deg with this shear angle ({}); it is used "
        "for the forces, the stagnation angle and the contact lengths, not the scene's {:.4g} deg ({})",
        friction_closure_name(chip.liu_li.closure), units::rad_to_deg(beta),
        scene.shear_angle == ShearAngleSource::chip_ratio ? "from cut.chip_ratio" : "from models.shear_angle",
        units::rad_to_deg(*scene.friction_angle_rad), scene.friction_origin));
  }
  add_contact_lengths(scene, beta, p);
}

// Their registry lines (analytic/registry.cpp) carry them.
const OrthogonalForceModel merchant_force_model{.predict = &predict_merchant_forces};
const OrthogonalForceModel liu_li_force_model{.predict = &predict_liu_li_forces, .edge_columns = true};

namespace {
using R = PredictionReport;
bool has_edge(const R& r) {
  return r.p.chip_term.liu_li.has_value();
}
const LiuLiResult& edge(const R& r) {
  return *r.p.chip_term.liu_li;
}
bool ploughs(const R& r) {
  return r.p.chip_term.ploughing.has_value();
}
}  // namespace

const ResultTable<PredictionReport>& edge_results() {
  namespace k = edge_keys;
  using units::m_to_um;
  using units::rad_to_deg;
  static const ResultTable<R> table{
      result_value<R>(k::friction_closure, "", "the friction closure along the edge (models.friction_closure)",
                      [](const R& r) {
                        return std::string(friction_closure_name(r.scene.params<ChipTermParams>().liu_li.closure));
                      }),
      result_value<R>(k::lower_limit_rule, "", "the rule of the edge integral's lower limit (models.lower_limit)",
                      [](const R& r) {
                        return std::string(lower_limit_rule_name(r.scene.params<ChipTermParams>().liu_li.lower_limit));
                      }),
      result_or_null<R>(k::lower_limit_deg, "deg", "the edge integral's lower limit (empty without an edge)", has_edge,
                        [](const R& r) { return rad_to_deg(edge(r).lower_limit_rad); }),
      result_or_null<R>(k::upper_limit_deg, "deg", "the edge integral's upper limit", has_edge,
                        [](const R& r) { return rad_to_deg(edge(r).upper_limit_rad); }),
      result_or_null<R>(k::stagnation_angle_deg, "deg", "the stagnation point's angle on the edge", has_edge,
                        [](const R& r) { return rad_to_deg(edge(r).stagnation_angle_rad); }),
      result_or_null<R>(
          k::pole_deg, "deg", "the friction closure's pole on the edge (empty: none)",
          [](const R& r) { return has_edge(r) && edge(r).pole_rad.has_value(); },
          [](const R& r) { return rad_to_deg(*edge(r).pole_rad); }),
      result_or_null<R>(k::ploughed_thickness_um, "um", "the ploughed layer h_s below the stagnation point", has_edge,
                        [](const R& r) { return m_to_um(edge(r).ploughed_thickness_m); }),
      result_or_null<R>(k::edge_cutting_force_N, "N", "the edge arc's chip force, cutting (part of the chip term)",
                        has_edge, [](const R& r) { return edge(r).edge.cutting_N_per_m * r.p.width_m; }),
      result_or_null<R>(k::edge_thrust_force_N, "N", "the edge arc's chip force, thrust", has_edge,
                        [](const R& r) { return edge(r).edge.thrust_N_per_m * r.p.width_m; }),
      result_value<R>(
          k::ploughing_model, "", "the force under the edge below the stagnation point (models.ploughing)",
          [](const R& r) { return std::string(ploughing_model_name(r.scene.params<ChipTermParams>().ploughing)); }),
      result_or_null<R>(k::friction_factor, "", "the ploughing model's friction factor f (empty without its term)",
                        ploughs, [](const R& r) { return r.p.chip_term.friction_factor; }),
      result_or_null<R>(k::ploughing_attack_angle_deg, "deg",
                        "the wave model's attack angle: the chord's alpha, capped at eta (empty without its term)",
                        ploughs,
                        [](const R& r) { return rad_to_deg(r.p.chip_term.ploughing->factors.attack_angle_rad); })};
  return table;
}

void print_edge_details(std::FILE* text, const AnalyticScene& scene, const Prediction& p) {
  namespace k = edge_keys;
  if (!p.chip_term.liu_li) return;
  // The numbers as the CSV row holds them (edge_results, and the shared ploughing columns: converted once, there).
  const PredictionReport report{scene, p};
  const auto value = [&report](const ResultTable<PredictionReport>& table, std::string_view key) {
    return result_of(table, report, key);
  };
  const auto edge = [&value](std::string_view key) { return value(edge_results(), key).get<double>(); };
  fmt::print(text,
             "edge integral     from {:.4g} deg to {:.4g} deg (stagnation {:.4g} deg{}); ploughed layer {:.6g} um\n",
             edge(k::lower_limit_deg), edge(k::upper_limit_deg), edge(k::stagnation_angle_deg),
             p.chip_term.liu_li->pole_rad ? fmt::format(", pole {:.4g} deg", edge(k::pole_deg)) : "",
             edge(k::ploughed_thickness_um));
  fmt::print(text,
             "edge part         cutting {:.6g} N, thrust {:.6g} N (the thrust depends strongly on the lower limit)\n",
             edge(k::edge_cutting_force_N), edge(k::edge_thrust_force_N));
  if (p.chip_term.ploughing) {
    fmt::print(text,
               "ploughing part    cutting {:.6g} N, thrust {:.6g} N (wave model, f = {:.4g}, chord {:.6g} um at "
               "{:.4g} deg)\n",
               value(prediction_results(), prediction_keys::ploughing_cutting_force_N).get<double>(),
               value(prediction_results(), prediction_keys::ploughing_thrust_force_N).get<double>(),
               edge(k::friction_factor), units::m_to_um(p.chip_term.ploughing->chord_m),
               edge(k::ploughing_attack_angle_deg));
  } else {
    fmt::print(text, "ploughing part    none (models.ploughing = {})\n",
               value(edge_results(), k::ploughing_model).get<std::string>());
  }
}

}  // namespace kerf
