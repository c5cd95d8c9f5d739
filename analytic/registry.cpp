#include "kerf/analytic/registry.hpp"

#include <algorithm>
#include <deque>
#include <map>

// The one file that sees every model: its lines name their entry points and enum values.
#include "kerf/analytic/forces/auto_model.hpp"
#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/forces/transition_model.hpp"
#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/kinds/scene.hpp"

namespace kerf {

namespace {
template <class Enum>
constexpr int id(Enum value) {
  return static_cast<int>(value);
}
}  // namespace

namespace {
// Long (~95 lines) for a reason: the registry is its list, one line per model (adding a model is one line here).
std::vector<AnalyticModelInfo>& registry() {
  static std::vector<AnalyticModelInfo> models = {
      // kind, name, summary, needs, the enum value the name constructs (none: handled by name); force lines:
      // the scene kind that runs the model and, for the orthogonal kind, the force model it runs; the parameter
      // block the model owns (the `models` section lists the blocks in the order of their first line here)
      {"force", "auto",
       "the cheapest valid force model: oxley without friction data, merchant for a sharp edge "
       "(r < 5 % of t0), else liu_li",
       "as the chosen model", -1, &build_orthogonal_scene, &auto_force_model},
      {"force", "merchant", "sharp-tool Merchant force circle", "flow stress, friction, shear angle", -1,
       &build_orthogonal_scene, &merchant_force_model, &chip_term_params},
      {"force", "liu_li", "Liu-Li edge-radius model, Shao et al. 2013, Eqs. 1-3",
       "flow stress, friction, shear angle or chip ratio", -1, &build_orthogonal_scene, &liu_li_force_model,
       &chip_term_params},
      {"force", "oxley", "extended Oxley theory with Johnson-Cook (Lalwani et al. 2009), sharp tool",
       "material johnson_cook, thermal and oxley groups", -1, &build_orthogonal_scene, &oxley_force_model},
      {"force", "transition",
       "brittle materials across the ductile-brittle transition: the ductile model (liu_li, or "
       "merchant for a sharp edge) up to a layer of about d_c, then that layer at the edge "
       "plus a fracture part (models.fracture; docs/models.md); from 0.01 um to 0.2 mm",
       "material E, hardness, toughness; friction; a flow stress (hardness for glasses)", -1, &build_orthogonal_scene,
       &transition_force_model, &transition_model_params},
      {"force", "trepanning",
       "fixed-abrasive trepanning drill, axial force and torque (Yu et al. 2023, Eqs. 21-22; brittle "
       "regime)",
       "tool outer/inner diameter, cut feed rate and spindle speed, the two lumped "
       "groups or hardness, half angle and friction",
       -1, &build_trepanning_scene},
      {"flow_stress", "johnson_cook", "Johnson-Cook, Shao et al. 2013, Eq. 9",
       "material johnson_cook group; a deformation state"},
      {"flow_stress", "hall_petch", "Hall-Petch with K_HP from Shao et al. 2013's Eqs. 10-11",
       "material microstructure and elastic groups"},
      {"flow_stress", "dislocation", "incidental-boundary strengthening, Shao et al. 2013, Eqs. 4-6",
       "material microstructure and elastic groups"},
      {"flow_stress", "hardness",
       "glasses and ceramics: Y = H / C with the material's constraint factor C (Marsh 1964: "
       "1.5-2 for glasses); alone, rate- and temperature-independent",
       "material brittle.hardness_GPa and brittle.constraint_factor, elastic group", id(ConstraintModel::given)},
      {"flow_stress", "hardness_marsh", "glasses and ceramics: Y from H / Y = 0.07 + 0.6 ln(E / Y) (Marsh 1964)",
       "material brittle.hardness_GPa, elastic group; H / E below 0.212", id(ConstraintModel::marsh)},
      {"flow_stress", "hardness_johnson",
       "glasses and ceramics: Y from Johnson's expanding cavity, H / Y = (2/3)(1 + "
       "ln(E* tan 19.7 deg / 3 Y)) (Johnson 1970)",
       "material brittle.hardness_GPa, elastic group; H / E* below 0.0724 (not soda-lime glass)",
       id(ConstraintModel::johnson_cavity)},
      {"deformation", "room_temperature",
       "T = workpiece temperature, shear-plane strain of the shear angle, "
       "Oxley's strain-rate estimate with C0 = 5 unless cut.strain_rate_per_s is given",
       "", id(DeformationModel::room_temperature)},
      {"deformation", "given", "cut.strain, cut.strain_rate_per_s and cut.temperature_K as given", "those keys",
       id(DeformationModel::given)},
      // The Oxley solve's block (models.oxley_tolerance) is carried here, not by the force line `oxley`: the solve
      // serves force oxley and deformation oxley alike, and its key follows the transition model's in `models`.
      {"deformation", "oxley", "zone AB strain, strain rate and temperature of an extended Oxley solve",
       "material johnson_cook, thermal and oxley groups", id(DeformationModel::oxley), nullptr, nullptr,
       &oxley_model_params},
      {"shear_angle", "merchant", "minimum energy (MEP), Berezvai et al. 2019, Eq. 4", "friction",
       id(ShearAngleSource::merchant)},
      {"shear_angle", "lee_shaffer", "maximum shear stress (MSSP), Berezvai et al. 2019, Eq. 4", "friction",
       id(ShearAngleSource::lee_shaffer)},
      {"shear_angle", "chip_ratio", "from a measured chip ratio, Shao et al. 2013, Eq. 3", "cut.chip_ratio",
       id(ShearAngleSource::chip_ratio)},
      {"friction_closure", "constant", "beta_k = beta along the edge (has a pole: ploughing below it)", "friction",
       id(FrictionClosure::constant)},
      {"friction_closure", "merchant", "2 phi_k + beta_k - gamma_k = pi/2 along the edge", "",
       id(FrictionClosure::merchant)},
      {"friction_closure", "lee_shaffer", "phi_k + beta_k - gamma_k = pi/4 along the edge", "",
       id(FrictionClosure::lee_shaffer)},
      {"lower_limit", "stagnation", "integrate from the stagnation point -(pi/4 + beta/2) (Son, Lim & Ahn 2005)",
       "friction", id(LowerLimitRule::stagnation)},
      {"lower_limit", "pole", "integrate from just above the pole (or -pi/2)", "models.lower_limit_margin_deg",
       id(LowerLimitRule::pole)},
      {"ploughing", "wave",
       "Challen-Oxley wave model (Wear 53, 1979) on the chord of the engaged arc below the "
       "stagnation point, as Waldorf, DeVor & Kapoor (1998) use it under a rounded edge",
       "an edge radius; cut.friction_factor or a friction angle in [0, 45) deg", id(PloughingModel::wave)},
      {"ploughing", "none", "no force under the edge below the stagnation point (the ploughed layer is reported)", "",
       id(PloughingModel::none)},
      {"fracture", "lefm_scratch",
       "F / w = zeta K_c (sqrt(h) - sqrt(l)) above the ductile layer l (Huang & "
       "Detournay 2008; zeta = sqrt(2), Akono & Ulm 2011), thrust along the rake face's "
       "friction",
       "material toughness", id(FractureModel::lefm_scratch)},
      {"fracture", "none", "no fracture part: the edge's ductile layer alone above l", "", id(FractureModel::none)},
      {"contact_length", "altintas",
       "Altintas, Berezvai et al. 2019, Eq. 1 (suffix _mep or _mssp picks the shear angle)", "friction",
       id(ContactLengthModel::altintas)},
      {"contact_length", "vinogradov", "Vinogradov, Berezvai et al. 2019, Eq. 2 (suffix _mep or _mssp)", "friction",
       id(ContactLengthModel::vinogradov)},
      {"contact_length", "lee_shaffer", "Lee and Shaffer, Berezvai et al. 2019, Eq. 3 (suffix _mep or _mssp)",
       "friction", id(ContactLengthModel::lee_shaffer)},
  };
  return models;
}

/// The names by kind, and the orthogonal force names, in registry order: built at the first call, kept in step by
/// register_analytic_model. A list is never changed once handed out: a registration appends to a copy, and the
/// old list stays (in `lists`, whose elements never move) for the spans that field tables hold.
struct Names {
  std::deque<std::vector<std::string_view>> lists;
  std::map<std::string, const std::vector<std::string_view>*, std::less<>> by_kind;
  const std::vector<std::string_view>* orthogonal = nullptr;

  void add(const AnalyticModelInfo& m) {
    append(by_kind[std::string(m.kind)], m.name);
    if (m.kind == "force" && m.orthogonal) append(orthogonal, m.name);
  }
  void append(const std::vector<std::string_view>*& list, std::string_view name) {
    std::vector<std::string_view> longer = list ? *list : std::vector<std::string_view>{};
    longer.push_back(name);
    list = &lists.emplace_back(std::move(longer));
  }
};

Names& names() {
  static Names all = [] {
    Names n;
    n.orthogonal = &n.lists.emplace_back();
    for (const auto& m : registry()) n.add(m);
    return n;
  }();
  return all;
}
}  // namespace

const std::vector<AnalyticModelInfo>& analytic_models() {
  return registry();
}

bool register_analytic_model(const AnalyticModelInfo& line) {
  if (registered_line(registry(), line.kind, line.name)) {
    throw std::logic_error("analytic registry: " + std::string(line.kind) + " '" + std::string(line.name) +
                           "' registered twice");
  }
  auto& lists = names();  // built from the lines before this one
  registry().push_back(line);
  lists.add(line);
  return true;
}

std::vector<const ModelParams*> analytic_model_params() {
  std::vector<const ModelParams*> blocks;
  for (const auto& m : registry())
    if (m.params && std::find(blocks.begin(), blocks.end(), m.params) == blocks.end()) blocks.push_back(m.params);
  return blocks;
}

std::span<const std::string_view> analytic_model_names(std::string_view kind) {
  const auto& by_kind = names().by_kind;
  const auto it = by_kind.find(kind);
  return it == by_kind.end() ? std::span<const std::string_view>{} : *it->second;
}

std::span<const std::string_view> orthogonal_force_names() {
  return *names().orthogonal;
}

const AnalyticModelInfo* registered_line(const std::vector<AnalyticModelInfo>& registry, std::string_view kind,
                                         std::string_view name) {
  for (const auto& m : registry) {
    if (m.kind == kind && m.name == name) return &m;
  }
  return nullptr;
}

std::optional<int> registered_id(const std::vector<AnalyticModelInfo>& registry, std::string_view kind,
                                 std::string_view name) {
  const AnalyticModelInfo* m = registered_line(registry, kind, name);
  return m && m->id >= 0 ? std::optional<int>(m->id) : std::nullopt;
}

}  // namespace kerf
