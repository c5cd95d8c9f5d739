#include "kerf/analytic/kinds/scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <mutex>
#include <span>
#include <tuple>

#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/kinds/model_fields.hpp"
#include "kerf/analytic/kinds/model_params.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/analytic/trepanning/trepanning_scene.hpp"
#include "kerf/error.hpp"
#include "kerf/field_table.hpp"
#include "kerf/units.hpp"

namespace kerf {

const OrthogonalForceModel& AnalyticScene::force_model() const {
  return *force->orthogonal;
}

std::shared_ptr<const MaterialRecord> MaterialCache::share(const Json& spec, const std::string& path) {
  const std::string key = spec.dump();
  {
    std::lock_guard lock(mutex_);
    if (auto it = records_.find(key); it != records_.end()) return it->second;
  }
  auto record = std::make_shared<const MaterialRecord>(load_material(spec, path));
  std::lock_guard lock(mutex_);
  return records_.try_emplace(key, std::move(record)).first->second;
}

namespace {

constexpr char kDeformation[] = "deformation", kShearAngle[] = "shear_angle";

const FieldUnit kUmPerRev{"um/rev", units::um_to_m, units::m_to_um};
const FieldUnit kMPerMin{"m/min", units::m_per_min_to_m_per_s, units::m_per_s_to_m_per_min};

// ---- tool
const FieldTable<AnalyticScene>& tool_fields() {
  static const FieldTable<AnalyticScene> table{
      required_number_field("rake_deg", units::kDeg, Range::open(-90.0, 90.0), "nominal rake angle",
                            &AnalyticScene::rake_rad),
      number_field("edge_radius_um", units::kUm, Range::non_negative(), "cutting-edge radius r (0: sharp)",
                   &AnalyticScene::edge_radius_m),
      number_field("clearance_deg", units::kDeg, Range::open(0.0, 90.0),
                   "clearance (relief) angle; recorded, not used by the ductile models",
                   &AnalyticScene::clearance_rad)};
  return table;
}

// ---- cut: the keys as given (friction, deformation state and workpiece temperature are resolved from them)
struct CutKeys {
  std::optional<double> uncut_chip_thickness_m, width_m;  ///< required without cut.turning
  double speed_m_per_s = 0.0;
  std::optional<double> chip_ratio, friction_factor, friction_angle_rad, friction_coefficient;
  std::optional<double> strain, strain_rate_per_s, temperature_K, workpiece_temperature_K;
};

const FieldTable<CutKeys>& cut_fields() {
  static const FieldTable<CutKeys> table{
      optional_number_field("uncut_chip_thickness_um", units::kUm, Range::positive(),
                            "uncut chip thickness t0 (orthogonal cut)", &CutKeys::uncut_chip_thickness_m,
                            "required without `turning`"),
      optional_number_field("width_mm", units::kMm, Range::positive(), "width of cut; forces are for this width",
                            &CutKeys::width_m, "required without `turning`"),
      required_number_field("speed_m_per_min", kMPerMin, Range::positive(), "cutting speed", &CutKeys::speed_m_per_s),
      optional_number_field("chip_ratio", units::kNone, Range::positive(),
                            "measured chip ratio r_c = t0 / t_chip (for `models.shear_angle = chip_ratio`)",
                            &CutKeys::chip_ratio),
      optional_number_field("friction_factor", units::kSi("(tau/k)"), Range{0.0, 1.0, false, true},
                            "f = tau / k on the edge, for `models.ploughing = wave`", &CutKeys::friction_factor,
                            "sin(2 beta) (docs/models.md)"),
      optional_number_field("friction_angle_deg", units::kDeg, Range::open(-90.0, 90.0),
                            "mean tool-chip friction angle beta", &CutKeys::friction_angle_rad),
      optional_number_field("friction_coefficient", units::kNone, Range::non_negative(),
                            "mu; beta = atan(mu) (give this or the angle, not both)", &CutKeys::friction_coefficient),
      optional_number_field("strain", units::kNone, Range::non_negative(), "for `models.deformation = given`",
                            &CutKeys::strain),
      optional_number_field("strain_rate_per_s", units::kSi("1/s"), Range::non_negative(),
                            "for `models.deformation = given` (alone, it also feeds `room_temperature`)",
                            &CutKeys::strain_rate_per_s),
      optional_number_field("temperature_K", units::kSi("K"), Range::positive(), "for `models.deformation = given`",
                            &CutKeys::temperature_K),
      optional_number_field("workpiece_temperature_K", units::kSi("K"), Range::positive(), "workpiece temperature",
                            &CutKeys::workpiece_temperature_K, "the Johnson-Cook room temperature")};
  return table;
}

constexpr std::string_view kTurningThicknessNamesText[] = {"equivalent", "maximum"};
constexpr EnumNames<TurningThickness> kTurningThicknessNames{kTurningThicknessNamesText};

const FieldTable<TurningScene>& turning_fields() {
  static const FieldTable<TurningScene> table{
      number_at<TurningScene>(
          "feed_um_per_rev", kUmPerRev, Range::positive(), "feed per revolution",
          [](auto& t) -> auto& { return t.geometry.feed_m_per_rev; }, true),
      number_at<TurningScene>(
          "nose_radius_mm", units::kMm, Range::positive(), "tool nose radius",
          [](auto& t) -> auto& { return t.geometry.nose_radius_m; }, true),
      number_at<TurningScene>(
          "depth_of_cut_um", units::kUm, Range::positive(), "depth of cut (up to the nose radius)",
          [](auto& t) -> auto& { return t.geometry.depth_of_cut_m; }, true),
      choice_field("chip_thickness", kTurningThicknessNames,
                   "the chip thickness the models use: area / engaged edge (`equivalent`) or the largest",
                   &TurningScene::thickness)};
  return table;
}

struct MeasuredForces {
  double cutting_force_N = 0.0, thrust_force_N = 0.0;
};

const FieldTable<MeasuredForces>& measured_fields() {
  static const FieldTable<MeasuredForces> table{
      required_number_field("cutting_force_N", units::kSi("N"), Range::positive(), "measured cutting force",
                            &MeasuredForces::cutting_force_N),
      required_number_field("thrust_force_N", units::kSi("N"), Range::any(), "measured thrust force",
                            &MeasuredForces::thrust_force_N)};
  return table;
}

// ---- models
/// models.force: a registered model, or "auto" (the cheapest valid one, chosen once the scene is read).
ChoiceField<AnalyticScene> force_field() {
  const auto names = orthogonal_force_names();
  return {"force", names,
          "the force model; `auto` picks the cheapest valid one: `oxley` without friction data, `merchant` when "
          "r < 5 % of t0, else `liu_li` (the choice and its reason are printed). `trepanning` is not a model of this "
          "scene: it makes the scene a trepanning scene (below)",
          [names](const AnalyticScene& s) {
            for (std::size_t k = 0; k < names.size(); ++k)
              if (s.force_auto ? names[k] == "auto" : s.force && names[k] == s.force->name) return static_cast<int>(k);
            return 0;
          },
          [names](AnalyticScene& s, int k) {
            s.force = registered_line(analytic_models(), "force", names[static_cast<std::size_t>(k)]);
            s.force_auto = s.force->orthogonal->choose != nullptr;
          }};
}

constexpr std::string_view kContactShearAngleNamesText[] = {"mep", "mssp"};
constexpr EnumNames<ShearAngleModel> kContactShearAngleNames{kContactShearAngleNamesText};

/// Each contact-length model, alone or suffixed with the shear angle it uses.
std::span<const std::string_view> contact_length_names() {
  static const auto names = [] {
    std::vector<std::string> text;
    for (const auto& base : analytic_model_names("contact_length"))
      for (const char* suffix : {"", "_mep", "_mssp"}) text.push_back(std::string(base) + suffix);
    return text;
  }();
  static const std::vector<std::string_view> views(names.begin(), names.end());
  return views;
}

NameListField<AnalyticScene> contact_length_field() {
  return {"contact_length", contact_length_names(),
          "contact-length columns `contact_length_<name>_mm` (Berezvai et al. 2019); a name without a suffix uses "
          "`contact_shear_angle`",
          [](const AnalyticScene& s) {
            std::vector<std::string> names;
            for (const auto& r : s.contact_lengths) names.push_back(r.column.substr(15, r.column.size() - 18));
            return names;
          },
          [](AnalyticScene& s, const std::vector<std::string>& names) {
            s.contact_lengths.clear();
            for (const auto& name : names) {
              ContactLengthRequest request;
              std::string model_name = name;
              request.shear_angle = s.contact_shear_angle;
              for (const auto& [suffix, angle] : {std::pair{std::string_view("_mep"), ShearAngleModel::merchant},
                                                  std::pair{std::string_view("_mssp"), ShearAngleModel::lee_shaffer}}) {
                if (name.size() > suffix.size() && name.ends_with(suffix)) {
                  model_name = name.substr(0, name.size() - suffix.size());
                  request.shear_angle = angle;
                }
              }
              request.model = registered_model<ContactLengthModel>("contact_length", model_name);
              request.column = fmt::format("contact_length_{}_mm", name);
              for (const auto& existing : s.contact_lengths)
                if (existing.column == request.column)
                  throw InputError("models.contact_length", name, "each contact-length model named once");
              s.contact_lengths.push_back(request);
            }
          }};
}

/// The models' parameter blocks, as the registry's lines carry them (the chip term's, the transition model's, the
/// Oxley solve's, ...): taken once, with the `models` table.
const std::vector<const ModelParams*>& parameter_blocks() {
  static const std::vector<const ModelParams*> blocks = analytic_model_params();
  return blocks;
}

/// The models section: the scene's own choices, then each parameter block's keys from its unit's table, then the
/// contact lengths (read after contact_shear_angle, which they use).
const FieldTable<AnalyticScene>& models_fields() {
  static const FieldTable<AnalyticScene> table = [] {
    FieldTable<AnalyticScene> out{
        force_field(),
        NameListField<AnalyticScene>{
            "flow_stress", analytic_model_names("flow_stress"),
            "the terms of Shao et al. 2013's Eq. 8 to add, or one "
            "hardness term for a glass or ceramic (the default for a material with a hardness "
            "and no johnson_cook group: hardness with its constraint factor, else hardness_marsh)",
            [](const AnalyticScene& s) { return s.flow_stress_terms; },
            [](AnalyticScene& s, const std::vector<std::string>& terms) { s.flow_stress_terms = terms; }},
        model_choice<AnalyticScene, DeformationModel, kDeformation>(
            "where the flow stress is evaluated: workpiece temperature with the shear-plane strain and Oxley's "
            "strain-rate estimate (C0 = 5); the `cut` values; or zone AB of an extended-Oxley solve",
            [](auto& s) -> auto& { return s.deformation; }),
        model_choice<AnalyticScene, ShearAngleSource, kShearAngle>(
            "nominal shear angle: MEP, MSSP or from `cut.chip_ratio` (the default when it is given); gives the chip "
            "ratio for Liu-Li",
            [](auto& s) -> auto& { return s.shear_angle; })};
    for (const ModelParams* block : parameter_blocks()) {
      const FieldTable<AnalyticScene> fields = block->fields();
      out.insert(out.end(), fields.begin(), fields.end());
    }
    out.push_back(choice_field("contact_shear_angle", kContactShearAngleNames,
                               "shear angle (MEP or MSSP) of the contact-length names without a suffix",
                               &AnalyticScene::contact_shear_angle));
    out.push_back(contact_length_field());
    // Two blocks (or a block and the scene's own choices) declaring one key would read one value into both: a
    // registry's mistake (analytic/registry.cpp's parameter blocks), said at the first use.
    std::vector<std::string_view> objects;
    for (const ModelParams* block : parameter_blocks())
      for (const ModelParamsObject& object : block->objects) objects.push_back(object.key());
    check_unique_keys(out, "models", objects);
    return out;
  }();
  return table;
}

constexpr std::string_view kStrainRatePolicyNamesText[] = {"clamp", "power_law"};
constexpr EnumNames<StrainRatePolicy> kStrainRatePolicyNames{kStrainRatePolicyNamesText};
constexpr std::string_view kColdPolicyNamesText[] = {"clamp", "error"};
constexpr EnumNames<ColdPolicy> kColdPolicyNames{kColdPolicyNamesText};

const FieldTable<JohnsonCookPolicy>& flow_stress_policy_fields() {
  static const FieldTable<JohnsonCookPolicy> table{
      choice_field("strain_rate", kStrainRatePolicyNames,
                   "below the reference strain rate: no rate effect (`clamp`) or (1 + rate/rate0)^C",
                   &JohnsonCookPolicy::strain_rate),
      choice_field("cold", kColdPolicyNames, "below room temperature: T* = 0 (`clamp`) or an error",
                   &JohnsonCookPolicy::cold)};
  return table;
}

void parse_friction(const CutKeys& keys, ObjectReader& cut, ObjectReader& root, AnalyticScene& scene) {
  auto measured = root.find_object("measured");
  if (keys.friction_angle_rad && keys.friction_coefficient) {
    throw InputError(cut.key_path("friction_coefficient"), format_value(*keys.friction_coefficient),
                     "either cut.friction_angle_deg or cut.friction_coefficient, not both");
  }
  if (keys.friction_angle_rad) {
    scene.friction_angle_rad = keys.friction_angle_rad;
    scene.friction_origin = "cut.friction_angle_deg";
  } else if (keys.friction_coefficient) {
    scene.friction_angle_rad = std::atan(*keys.friction_coefficient);
    scene.friction_origin = "cut.friction_coefficient";
  }
  if (measured) {
    const MeasuredForces forces = read_fields(*measured, measured_fields(), MeasuredForces{}, SiCheck::on);
    measured->finish();
    if (scene.friction_angle_rad) {
      throw InputError("measured", "(given)", "measured forces or a friction value in cut, not both");
    }
    // Berezvai et al. 2019, Section 2: beta = atan(F_z / F_x) + rake
    scene.friction_angle_rad = std::atan2(forces.thrust_force_N, forces.cutting_force_N) + scene.rake_rad;
    scene.friction_origin = "measured forces";
  }
}

/// The key reference's line on `models`: the objects under it, the parameter blocks' and the scene's own.
std::string_view models_about() {
  static const std::string about = [] {
    std::vector<std::string_view> objects;
    for (const ModelParams* block : parameter_blocks())
      for (const auto& object : block->objects) objects.push_back(object.key());
    objects.push_back("flow_stress_policy");
    std::string text = "the models to run; besides these, the objects ";
    for (std::size_t k = 0; k < objects.size(); ++k)
      text += fmt::format("{}`{}`", k == 0 ? "" : k + 1 == objects.size() ? " and " : ", ", objects[k]);
    return text;
  }();
  return about;
}

const std::vector<SceneKeySection>& key_sections() {
  static const std::vector<SceneKeySection> list = [] {
    std::vector<SceneKeySection> out = material_key_sections();
    out.insert(
        out.end(),
        {{"tool", "the cutting tool", [] { return fields_markdown(tool_fields()); }},
         {"cut", "an orthogonal cut (`uncut_chip_thickness_um`, `width_mm`) or a turning cut (`turning`)",
          [] { return fields_markdown(cut_fields()); }},
         {"cut.turning",
          "optional, instead of `cut.uncut_chip_thickness_um` and `width_mm`: a round-nose turning cut, whose width "
          "is chip area / thickness",
          [] { return fields_markdown(turning_fields()); }},
         {"measured",
          "optional, top level: the friction angle is then beta = atan(F_thrust / F_cutting) + rake (Berezvai et al. "
          "2019), in place of a friction value in `cut`",
          [] { return fields_markdown(measured_fields()); }},
         {"models", models_about(), [] { return fields_markdown(models_fields()); }}});
    for (const ModelParams* block : parameter_blocks())
      for (const auto& object : block->objects) out.push_back({object.section, object.about, object.markdown});
    out.push_back({"models.flow_stress_policy", "optional: the Johnson-Cook law outside its domain",
                   [] { return fields_markdown(flow_stress_policy_fields()); }});
    for (const auto& s : trepanning_key_sections()) out.push_back(s);
    return out;
  }();
  return list;
}
}  // namespace

std::vector<std::string> analytic_scene_sections() {
  return key_section_names(key_sections());
}

std::string analytic_scene_keys_markdown(const std::string& section) {
  return key_sections_markdown(key_sections(), section);
}

void refuse_dem_scene(const Json& document) {
  if (!document.is_object() || !document.contains("kind")) return;
  const Json& kind = document["kind"];
  throw InputError("kind", json_value_text(kind),
                   fmt::format("no kind in a kerf-forces scene: this is a kerf-dem scene (kind: {}); run it with "
                               "kerf-dem run",
                               json_value_text(kind)));
}

namespace {

/// The cut section (a turning cut gives thickness and width later, from its round-nose chip): the keys as given,
/// with thickness, width, speed, chip ratio and friction set in `scene`.
CutKeys read_cut(ObjectReader& root, ObjectReader& cut, AnalyticScene& scene) {
  if (auto turning = cut.find_object("turning")) {
    TurningScene t;
    read_fields_into(*turning, turning_fields(), t, SiCheck::on);
    turning->finish();
    t.geometry.validate(cut.key_path("turning"));
    for (const char* key : {"uncut_chip_thickness_um", "width_mm"}) {
      if (cut.has(key)) {
        throw InputError(cut.key_path(key), json_value_text(cut.get(key)),
                         "no value: with cut.turning the chip thickness and width follow from feed, nose radius "
                         "and depth of cut");
      }
    }
    scene.turning = t;
  } else {
    for (const char* key : {"uncut_chip_thickness_um", "width_mm"}) cut.get(key);  // required: missing is an error
  }
  const CutKeys keys = read_fields(cut, cut_fields(), CutKeys{}, SiCheck::on);
  if (!scene.turning) {
    scene.uncut_chip_thickness_m = *keys.uncut_chip_thickness_m;
    scene.width_m = *keys.width_m;
  }
  scene.speed_m_per_s = keys.speed_m_per_s;
  scene.chip_ratio = keys.chip_ratio;
  scene.friction_factor = keys.friction_factor;
  parse_friction(keys, cut, root, scene);
  return keys;
}

/// The models section (shear_angle defaults to chip_ratio when the cut gives one).
void read_models(ObjectReader& root, AnalyticScene& scene) {
  if (scene.chip_ratio) scene.shear_angle = ShearAngleSource::chip_ratio;
  auto models = root.get_object("models");
  // models.force names the scene's kind too: an unknown name is refused against every value the key takes
  // (trepanning included), a line of another kind (trepanning) names a scene this parser does not read.
  if (models.has("force") && models.get("force").is_string()) {
    const std::string name = models.get("force").get<std::string>();
    const auto* line = registered_line(analytic_models(), "force", name);
    if (!line) {
      const auto names = analytic_model_names("force");
      throw InputError(models.key_path("force"), name,
                       describe_choices(name, std::vector<std::string>(names.begin(), names.end())));
    }
    if (!line->orthogonal) {
      throw InputError("models.force", name,
                       "an orthogonal-cut model here (" + name + " is a scene kind of its own, read by parse_scene)");
    }
  }
  scene.flow_stress_named = models.has("flow_stress");
  read_fields_into(models, models_fields(), scene, SiCheck::on);
  for (const ModelParams* block : parameter_blocks()) {
    for (const auto& object : block->objects) {
      if (auto reader = models.find_object(object.key())) {
        object.read(*reader, scene);
        reader->finish();
      }
    }
  }
  if (auto policy = models.find_object("flow_stress_policy")) {
    read_fields_into(*policy, flow_stress_policy_fields(), scene.flow_stress.policy, SiCheck::on);
    policy->finish();
  }
  models.finish();
}

/// A turning cut's thickness and width from its round-nose chip; the force model: the named one, or the one
/// `auto` chooses for the scene as read; then the friction and chip ratio the chosen models need.
void resolve_force_model(AnalyticScene& scene) {
  // The round-nose chip gives thickness and width (width = chip area / thickness).
  if (scene.turning) {
    scene.turning->chip = round_nose_chip(scene.turning->geometry, nullptr);
    const auto& chip = scene.turning->chip;
    scene.uncut_chip_thickness_m =
        scene.turning->thickness == TurningThickness::maximum ? chip.maximum_thickness_m : chip.equivalent_thickness_m;
    scene.width_m = chip.area_m2 / scene.uncut_chip_thickness_m;
  }

  // models.force = "auto" (also when the scene names none): its line chooses the model.
  if (scene.force_auto) {
    const AnalyticModelInfo* chooser = scene.force ? scene.force : registered_line(analytic_models(), "force", "auto");
    scene.force =
        registered_line(analytic_models(), "force", chooser->orthogonal->choose(scene, &scene.force_choice_reason));
  }
  const bool solves_oxley = scene.force_model().solves_oxley;

  // Friction is needed by every model except oxley, unless the chip ratio gives the shear angle and a closure
  // other than the constant one gives beta (which then also sets the stagnation angle and contact lengths).
  const bool needs_friction =
      !solves_oxley && (scene.shear_angle != ShearAngleSource::chip_ratio ||
                        scene.params<ChipTermParams>().liu_li.closure == FrictionClosure::constant);
  if (needs_friction && !scene.friction_angle_rad) {
    throw InputError("cut.friction_angle_deg", "(missing)",
                     "a friction angle (or cut.friction_coefficient, or measured.cutting_force_N and "
                     "thrust_force_N) for this choice of models");
  }
  if (scene.shear_angle == ShearAngleSource::chip_ratio && !scene.chip_ratio) {
    throw InputError("cut.chip_ratio", "(missing)", "a chip ratio t0/t_chip for models.shear_angle = chip_ratio");
  }
}

/// The flow-stress terms named (and the Johnson-Cook law Oxley needs), from the material; the workpiece
/// temperature's default.
void resolve_flow_stress(const MaterialRecord& record, MaterialCache& materials, const CutKeys& keys,
                         AnalyticScene& scene) {
  const bool solves_oxley = scene.force_model().solves_oxley;
  // A glass or ceramic (no Johnson-Cook group, a hardness) takes its flow stress from its hardness unless the
  // scene names the terms: with its constraint factor when the material gives one, else Marsh's relation.
  if (!scene.flow_stress_named && !record.group("johnson_cook")) {
    const BrittleGroup brittle = materials.derived(record, &brittle_group_from_material);
    if (brittle.hardness_Pa) scene.flow_stress_terms = {brittle.constraint_factor ? "hardness" : "hardness_marsh"};
  }
  // Flow stress: only the terms named.
  const auto& terms = scene.flow_stress_terms;
  for (const auto& term : terms) {
    const auto* line = registered_line(analytic_models(), "flow_stress", term);
    if (!line || line->id < 0) continue;  // the metals' terms are handled by name below
    if (scene.flow_stress.hardness) {
      throw InputError("models.flow_stress", term,
                       "one hardness term at most (hardness, hardness_marsh or "
                       "hardness_johnson)");
    }
    scene.flow_stress.hardness = materials.derived(record, &hardness_flow_from_material);
    scene.flow_stress.constraint = static_cast<ConstraintModel>(line->id);
  }
  const auto has_term = [&](const char* t) { return std::find(terms.begin(), terms.end(), t) != terms.end(); };
  // Oxley needs the Johnson-Cook law even when the flow stress of the force model does not add it.
  const bool uses_oxley = solves_oxley || scene.deformation == DeformationModel::oxley;
  std::optional<JohnsonCookParams> johnson_cook;
  if (has_term("johnson_cook") || uses_oxley) johnson_cook = materials.derived(record, &johnson_cook_from_material);
  if (has_term("johnson_cook") || solves_oxley) scene.flow_stress.johnson_cook = johnson_cook;
  if (has_term("hall_petch") || has_term("dislocation")) {
    const auto micro = materials.derived(record, &microstructure_from_material);
    if (has_term("hall_petch")) scene.flow_stress.hall_petch = micro.hall_petch;
    if (has_term("dislocation")) scene.flow_stress.dislocation = micro.dislocation;
  }
  // Default: the Johnson-Cook room temperature, else the member's own.
  if (johnson_cook) scene.workpiece_temperature_K = johnson_cook->room_temperature_K;
  if (keys.workpiece_temperature_K) scene.workpiece_temperature_K = *keys.workpiece_temperature_K;
  if (const Json* jc_group = record.group("johnson_cook"); jc_group && jc_group->contains("melting_temperature_K")) {
    scene.flow_stress.melting_temperature_K = jc_group->at("melting_temperature_K").get<double>();
    // The microstructural terms soften with the material's Johnson-Cook thermal factor (flow_stress.hpp).
    if (!scene.flow_stress.johnson_cook && (has_term("hall_petch") || has_term("dislocation")) &&
        jc_group->contains("m")) {
      scene.flow_stress.thermal_softening =
          johnson_cook ? *johnson_cook : materials.derived(record, &johnson_cook_from_material);
    }
  }
  scene.flow_stress.validate("models.flow_stress");
}

/// The deformation state given in the cut (models.deformation = given) and the Oxley parameters.
void resolve_deformation(const MaterialRecord& record, const CutKeys& keys, AnalyticScene& scene) {
  const bool solves_oxley = scene.force_model().solves_oxley;
  const bool uses_oxley = solves_oxley || scene.deformation == DeformationModel::oxley;
  // Deformation state
  const auto& [strain, strain_rate, temperature] = std::tie(keys.strain, keys.strain_rate_per_s, keys.temperature_K);
  if (scene.deformation == DeformationModel::given) {
    if (!strain || !strain_rate || !temperature) {
      throw InputError(!strain        ? "cut.strain"
                       : !strain_rate ? "cut.strain_rate_per_s"
                                      : "cut.temperature_K",
                       "(missing)", "a value: models.deformation = given needs strain, strain rate and temperature");
    }
    scene.given_state = DeformationState{*strain, *strain_rate, *temperature};
  } else if (strain || temperature) {
    throw InputError(strain ? "cut.strain" : "cut.temperature_K", "(given)",
                     "no value unless models.deformation = given (use cut.workpiece_temperature_K for the workpiece)");
  }
  scene.given_strain_rate_per_s = strain_rate;
  if (solves_oxley && (scene.flow_stress.hall_petch || scene.flow_stress.dislocation)) {
    throw InputError("models.flow_stress", "(microstructure terms)",
                     "johnson_cook alone with models.force = oxley (Oxley's solution uses the Johnson-Cook law; "
                     "use force merchant or liu_li with deformation oxley to add microstructure terms)");
  }
  if (uses_oxley)
    scene.params<OxleyModelParams>().material =
        oxley_params_from_material(record, "material", scene.flow_stress.policy);
}

}  // namespace

AnalyticScene parse_analytic_scene(const Json& document, MaterialCache* cache) {
  refuse_dem_scene(document);
  ObjectReader root(document, "");
  root.ignore("description");
  AnalyticScene scene;

  const Json& material_spec = root.get("material");
  MaterialCache local_cache;
  MaterialCache& materials = cache ? *cache : local_cache;
  scene.material = materials.share(material_spec, "material");
  const MaterialRecord& record = *scene.material;

  // Tool
  {
    auto tool = root.get_object("tool");
    read_fields_into(tool, tool_fields(), scene, SiCheck::on);
    tool.finish();
  }
  auto cut = root.get_object("cut");
  const CutKeys keys = read_cut(root, cut, scene);
  read_models(root, scene);
  resolve_force_model(scene);
  resolve_flow_stress(record, materials, keys, scene);
  resolve_deformation(record, keys, scene);

  // The regime check needs E, H and K_c; metals carry no brittle group and get none.
  if (const Json* brittle = record.group("brittle");
      brittle && brittle->contains("hardness_GPa") && brittle->contains("fracture_toughness_MPa_sqrt_m")) {
    scene.critical_depth_m = critical_depth_m(materials.derived(record, &brittle_properties));
  }

  cut.finish();
  root.finish({"measured"});
  return scene;
}

}  // namespace kerf
