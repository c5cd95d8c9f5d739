#include "kerf/analytic/scene.hpp"

#include <fmt/format.h>

#include <cmath>

#include "kerf/analytic/critical_depth.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf {

std::string_view force_model_name(ForceModel model) {
  switch (model) {
    case ForceModel::merchant: return "merchant";
    case ForceModel::liu_li: return "liu_li";
    case ForceModel::oxley: return "oxley";
  }
  return "";
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

std::vector<std::string> read_name_list(ObjectReader& reader, const std::string& key,
                                        const std::vector<std::string>& valid, std::vector<std::string> fallback) {
  const Json* value = reader.find(key);
  if (!value) return fallback;
  const std::string path = reader.key_path(key);
  if (value->is_string()) return {value->get<std::string>()};
  if (!value->is_array()) throw InputError(path, json_value_text(*value), "a list of names");
  std::vector<std::string> names;
  for (const auto& item : *value) {
    const std::string text = item.is_string() ? item.get<std::string>() : json_value_text(item);
    if (!item.is_string()) throw InputError(path, text, describe_choices(text, valid));
    names.push_back(text);
  }
  return names;
}

std::vector<ContactLengthRequest> parse_contact_lengths(ObjectReader& models) {
  const auto base = analytic_model_names("contact_length");
  std::vector<std::string> valid;
  for (const auto& b : base) {
    valid.push_back(b);
    valid.push_back(b + "_mep");
    valid.push_back(b + "_mssp");
  }
  const std::string default_angle = models.get_choice_or("contact_shear_angle", "mep", {"mep", "mssp"});
  std::vector<ContactLengthRequest> out;
  for (const auto& name : read_name_list(models, "contact_length", valid, {})) {
    if (std::find(valid.begin(), valid.end(), name) == valid.end()) {
      throw InputError(models.key_path("contact_length"), name, describe_choices(name, valid));
    }
    ContactLengthRequest request;
    std::string model_name = name, angle = default_angle;
    for (const char* suffix : {"_mep", "_mssp"}) {
      const std::string s = suffix;
      if (name.size() > s.size() && name.ends_with(s)) {
        model_name = name.substr(0, name.size() - s.size());
        angle = s.substr(1);
      }
    }
    request.model = registered_model<ContactLengthModel>("contact_length", model_name);
    request.shear_angle = angle == "mep" ? ShearAngleModel::merchant : ShearAngleModel::lee_shaffer;
    request.column = fmt::format("contact_length_{}_mm", name);
    for (const auto& existing : out) {
      if (existing.column == request.column) {
        throw InputError(models.key_path("contact_length"), name, "each contact-length model named once");
      }
    }
    out.push_back(request);
  }
  return out;
}

void parse_friction(ObjectReader& cut, ObjectReader& root, AnalyticScene& scene) {
  const auto angle = cut.get_optional_number("friction_angle_deg", Range::open(-90.0, 90.0), "deg");
  const auto coefficient = cut.get_optional_number("friction_coefficient", Range::non_negative(), "");
  auto measured = root.find_object("measured");
  if (angle && coefficient) {
    throw InputError(cut.key_path("friction_coefficient"), format_value(*coefficient),
                     "either cut.friction_angle_deg or cut.friction_coefficient, not both");
  }
  if (angle) {
    scene.friction_angle_rad = units::deg_to_rad(*angle);
    scene.friction_origin = "cut.friction_angle_deg";
  } else if (coefficient) {
    scene.friction_angle_rad = std::atan(*coefficient);
    scene.friction_origin = "cut.friction_coefficient";
  }
  if (measured) {
    const double fc = measured->get_number("cutting_force_N", Range::positive(), "N");
    const double ft = measured->get_number("thrust_force_N", Range::any(), "N");
    measured->finish();
    if (scene.friction_angle_rad) {
      throw InputError("measured", "(given)", "measured forces or a friction value in cut, not both");
    }
    // seed 003, Section 2: beta = atan(F_z / F_x) + rake
    scene.friction_angle_rad = std::atan2(ft, fc) + scene.rake_rad;
    scene.friction_origin = "measured forces";
  }
}

}  // namespace

void refuse_dem_scene(const Json& document) {
  if (!document.is_object() || !document.contains("kind")) return;
  const Json& kind = document["kind"];
  throw InputError("kind", json_value_text(kind),
                   fmt::format("no kind in a kerf-forces scene: this is a kerf-dem scene (kind: {}); run it with "
                               "kerf-dem run",
                               json_value_text(kind)));
}

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
    scene.rake_rad = units::deg_to_rad(tool.get_number("rake_deg", Range::open(-90.0, 90.0), "deg"));
    scene.edge_radius_m = tool.get_si_or("edge_radius_um", 0.0, Range::non_negative(), "um", units::um_to_m);
    scene.clearance_rad = units::deg_to_rad(tool.get_number_or("clearance_deg", kDefaultClearance_deg, Range::open(0.0, 90.0), "deg"));
    tool.finish();
  }

  // Cut
  auto cut = root.get_object("cut");
  if (auto turning = cut.find_object("turning")) {
    TurningScene t;
    t.geometry.feed_m_per_rev = turning->get_si("feed_um_per_rev", Range::positive(), "um/rev", units::um_to_m);
    t.geometry.nose_radius_m = turning->get_si("nose_radius_mm", Range::positive(), "mm", units::mm_to_m);
    t.geometry.depth_of_cut_m = turning->get_si("depth_of_cut_um", Range::positive(), "um", units::um_to_m);
    t.thickness = turning->get_choice_or("chip_thickness", "equivalent", {"equivalent", "maximum"}) == "maximum"
                      ? TurningThickness::maximum
                      : TurningThickness::equivalent;
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
    scene.uncut_chip_thickness_m =
        cut.get_si("uncut_chip_thickness_um", Range::positive(), "um", units::um_to_m);
    scene.width_m = cut.get_si("width_mm", Range::positive(), "mm", units::mm_to_m);
  }
  scene.speed_m_per_s =
      cut.get_si("speed_m_per_min", Range::positive(), "m/min", units::m_per_min_to_m_per_s);
  scene.chip_ratio = cut.get_optional_number("chip_ratio", Range::positive(), "");
  scene.friction_factor = cut.get_optional_number("friction_factor", Range{0.0, 1.0, false, true}, "(tau/k)");
  parse_friction(cut, root, scene);
  const auto strain = cut.get_optional_number("strain", Range::non_negative(), "");
  const auto strain_rate = cut.get_optional_number("strain_rate_per_s", Range::non_negative(), "1/s");
  const auto temperature = cut.get_optional_number("temperature_K", Range::positive(), "K");
  const auto workpiece_temperature = cut.get_optional_number("workpiece_temperature_K", Range::positive(), "K");

  // Models
  auto models = root.get_object("models");
  const std::string force_name = models.get_choice_or("force", "auto", analytic_model_names("force"));
  if (force_name == "trepanning") {
    throw InputError("models.force", force_name,
                     "an orthogonal-cut model here (trepanning scenes are read by parse_trepanning_scene)");
  }
  const auto terms = read_name_list(models, "flow_stress", analytic_model_names("flow_stress"), {"johnson_cook"});
  const std::string deformation_name =
      models.get_choice_or("deformation", "room_temperature", analytic_model_names("deformation"));
  const std::string shear_name = models.get_choice_or(
      "shear_angle", scene.chip_ratio ? "chip_ratio" : "merchant", analytic_model_names("shear_angle"));
  const std::string closure_name = models.get_choice_or("friction_closure", "merchant", analytic_model_names("friction_closure"));
  const std::string lower_name = models.get_choice_or("lower_limit", "stagnation", analytic_model_names("lower_limit"));
  const std::string ploughing_name = models.get_choice_or("ploughing", "wave", analytic_model_names("ploughing"));
  scene.liu_li.lower_limit_margin_rad =
      units::deg_to_rad(models.get_number_or("lower_limit_margin_deg", 1.0, Range::open(0.0, 45.0), "deg"));
  if (auto quadrature = models.find_object("quadrature")) {
    scene.liu_li.quadrature.rule =
        *quadrature_rule_from_name(quadrature->get_choice_or("rule", "gauss_kronrod", quadrature_rule_names()));
    scene.liu_li.quadrature.relative_tolerance =
        quadrature->get_number_or("tolerance", 1e-8, Range::open(0.0, 1.0), "(relative)");
    scene.liu_li.quadrature.max_depth = quadrature->get_int_or("max_depth", 15, 1, 20);
    quadrature->finish();
  }
  scene.oxley_options.tolerance =
      models.get_number_or("oxley_tolerance", scene.oxley_options.tolerance, Range::closed(1e-15, 1e-2), "(relative)");
  scene.contact_lengths = parse_contact_lengths(models);
  if (auto policy = models.find_object("flow_stress_policy")) {
    scene.flow_stress.policy.strain_rate =
        policy->get_choice_or("strain_rate", "clamp", {"clamp", "power_law"}) == "clamp" ? StrainRatePolicy::clamp
                                                                                          : StrainRatePolicy::power_law;
    scene.flow_stress.policy.cold =
        policy->get_choice_or("cold", "clamp", {"clamp", "error"}) == "clamp" ? ColdPolicy::clamp : ColdPolicy::error;
    policy->finish();
  }
  models.finish();

  scene.shear_angle = registered_model<ShearAngleSource>("shear_angle", shear_name);
  scene.liu_li.closure = registered_model<FrictionClosure>("friction_closure", closure_name);
  scene.liu_li.lower_limit = registered_model<LowerLimitRule>("lower_limit", lower_name);
  scene.ploughing = registered_model<PloughingModel>("ploughing", ploughing_name);
  scene.deformation = registered_model<DeformationModel>("deformation", deformation_name);

  // The round-nose chip gives thickness and width (width = chip area / thickness).
  if (scene.turning) {
    scene.turning->chip = round_nose_chip(scene.turning->geometry, nullptr);
    const auto& chip = scene.turning->chip;
    scene.uncut_chip_thickness_m = scene.turning->thickness == TurningThickness::maximum ? chip.maximum_thickness_m
                                                                                         : chip.equivalent_thickness_m;
    scene.width_m = chip.area_m2 / scene.uncut_chip_thickness_m;
  }

  // models.force = "auto": the cheapest valid model.
  scene.force_auto = force_name == "auto";
  if (scene.force_auto) {
    if (!scene.friction_angle_rad && scene.shear_angle != ShearAngleSource::chip_ratio) {
      scene.force = ForceModel::oxley;
      scene.force_choice_reason = "no friction data: only oxley predicts without it";
    } else if (scene.edge_radius_m < kSharpEdgeRatio * scene.uncut_chip_thickness_m) {
      scene.force = ForceModel::merchant;
      scene.force_choice_reason = "edge radius below 5 % of the uncut chip thickness: sharp-tool model";
    } else {
      scene.force = ForceModel::liu_li;
      scene.force_choice_reason = "edge radius at least 5 % of the uncut chip thickness: edge-radius model";
    }
  } else {
    scene.force = registered_model<ForceModel>("force", force_name);
  }

  // Friction is needed by every model except oxley, unless the chip ratio gives the shear angle and a closure
  // other than the constant one gives beta (which then also sets the stagnation angle and contact lengths).
  const bool needs_friction =
      scene.force != ForceModel::oxley &&
      (scene.shear_angle != ShearAngleSource::chip_ratio || scene.liu_li.closure == FrictionClosure::constant);
  if (needs_friction && !scene.friction_angle_rad) {
    throw InputError("cut.friction_angle_deg", "(missing)",
                     "a friction angle (or cut.friction_coefficient, or measured.cutting_force_N and "
                     "thrust_force_N) for this choice of models");
  }
  if (scene.shear_angle == ShearAngleSource::chip_ratio && !scene.chip_ratio) {
    throw InputError("cut.chip_ratio", "(missing)", "a chip ratio t0/t_chip for models.shear_angle = chip_ratio");
  }
  scene.liu_li.friction_angle_rad = scene.friction_angle_rad.value_or(0.0);

  // Flow stress: only the terms named.
  for (const auto& term : terms) {
    const auto valid = analytic_model_names("flow_stress");
    if (std::find(valid.begin(), valid.end(), term) == valid.end()) {
      throw InputError("models.flow_stress", term, describe_choices(term, valid));
    }
  }
  scene.flow_stress_terms = terms;
  const auto has_term = [&](const char* t) { return std::find(terms.begin(), terms.end(), t) != terms.end(); };
  // Oxley needs the Johnson-Cook law even when the flow stress of the force model does not add it.
  const bool uses_oxley = scene.force == ForceModel::oxley || scene.deformation == DeformationModel::oxley;
  std::optional<JohnsonCookParams> johnson_cook;
  if (has_term("johnson_cook") || uses_oxley) johnson_cook = materials.derived(record, &johnson_cook_from_material);
  if (has_term("johnson_cook") || scene.force == ForceModel::oxley) scene.flow_stress.johnson_cook = johnson_cook;
  if (has_term("hall_petch") || has_term("dislocation")) {
    const auto micro = materials.derived(record, &microstructure_from_material);
    if (has_term("hall_petch")) scene.flow_stress.hall_petch = micro.hall_petch;
    if (has_term("dislocation")) scene.flow_stress.dislocation = micro.dislocation;
  }
  const double room_K =
      johnson_cook ? johnson_cook->room_temperature_K : 293.15;
  scene.workpiece_temperature_K = workpiece_temperature.value_or(room_K);
  if (const Json* jc_group = record.group("johnson_cook"); jc_group && jc_group->contains("melting_temperature_K")) {
    scene.flow_stress.melting_temperature_K = jc_group->at("melting_temperature_K").get<double>();
    // The microstructural terms soften with the material's Johnson-Cook thermal factor (flow_stress.hpp).
    if (!scene.flow_stress.johnson_cook && (has_term("hall_petch") || has_term("dislocation")) && jc_group->contains("m")) {
      scene.flow_stress.thermal_softening = johnson_cook ? *johnson_cook : materials.derived(record, &johnson_cook_from_material);
    }
  }
  scene.flow_stress.validate("models.flow_stress");

  // Deformation state
  if (scene.deformation == DeformationModel::given) {
    if (!strain || !strain_rate || !temperature) {
      throw InputError(!strain ? "cut.strain" : !strain_rate ? "cut.strain_rate_per_s" : "cut.temperature_K",
                       "(missing)", "a value: models.deformation = given needs strain, strain rate and temperature");
    }
    scene.given_state = DeformationState{*strain, *strain_rate, *temperature};
  } else if (strain || temperature) {
    throw InputError(strain ? "cut.strain" : "cut.temperature_K", "(given)",
                     "no value unless models.deformation = given (use cut.workpiece_temperature_K for the workpiece)");
  }
  scene.given_strain_rate_per_s = strain_rate;
  if (scene.force == ForceModel::oxley && (scene.flow_stress.hall_petch || scene.flow_stress.dislocation)) {
    throw InputError("models.flow_stress", "(microstructure terms)",
                     "johnson_cook alone with models.force = oxley (Oxley's solution uses the Johnson-Cook law; "
                     "use force merchant or liu_li with deformation oxley to add microstructure terms)");
  }
  if (uses_oxley) scene.oxley = oxley_params_from_material(record, "material", scene.flow_stress.policy);

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
