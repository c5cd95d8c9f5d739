#include "kerf/analytic/kinds/material_models.hpp"

#include <fmt/format.h>

#include <optional>

#include "kerf/error.hpp"
#include "kerf/field_table.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

const FieldUnit kPerS = units::kSi("1/s");
const FieldUnit kKelvin = units::kSi("K");
const FieldUnit kNm{"nm", units::nm_to_m, units::m_to_nm};

/// A number field whose SI value is reached through `at` (a member of a member): `[](auto& s) -> auto& {...}`.
template <class S, class At>
NumberField<S> number_at(std::string_view key, FieldUnit unit, Range range, std::string_view doc, At at,
                         bool required = false) {
  return {key,      unit, range, doc, [at](const S& s) { return at(s); }, [at](S& s, double v) { at(s) = v; },
          required, {},   {}};
}

const FieldTable<ElasticProperties>& elastic_fields() {
  static const FieldTable<ElasticProperties> table{
      required_number_field("youngs_modulus_GPa", units::kGPa, Range::positive(), "Young's modulus E",
                            &ElasticProperties::youngs_modulus_Pa),
      required_number_field("poissons_ratio", units::kNone, Range{-1.0, 0.5, true, true}, "Poisson's ratio nu",
                            &ElasticProperties::poissons_ratio),
      NumberField<ElasticProperties>{"shear_modulus_GPa", units::kGPa, Range::positive(), "shear modulus G",
                                     [](const ElasticProperties& e) { return e.shear_modulus_Pa; },
                                     [](ElasticProperties& e, double v) { e.shear_modulus_Pa = v; }, false,
                                     [](const ElasticProperties& e) { return e.shear_modulus_Pa > 0.0; },
                                     "E / (2 (1 + nu))"}};
  return table;
}

const FieldTable<JohnsonCookParams>& johnson_cook_fields() {
  static const FieldTable<JohnsonCookParams> table{
      required_number_field("A_MPa", units::kMPa, Range::any(), "yield stress A", &JohnsonCookParams::A_Pa),
      required_number_field("B_MPa", units::kMPa, Range::any(), "hardening modulus B", &JohnsonCookParams::B_Pa),
      required_number_field("n", units::kNone, Range::any(), "hardening exponent", &JohnsonCookParams::n),
      required_number_field("C", units::kNone, Range::any(), "strain-rate sensitivity", &JohnsonCookParams::C),
      required_number_field("m", units::kNone, Range::any(), "thermal-softening exponent", &JohnsonCookParams::m),
      required_number_field("reference_strain_rate_per_s", kPerS, Range::any(), "reference strain rate",
                            &JohnsonCookParams::reference_strain_rate_per_s),
      required_number_field("room_temperature_K", kKelvin, Range::any(), "room (reference) temperature",
                            &JohnsonCookParams::room_temperature_K),
      required_number_field("melting_temperature_K", kKelvin, Range::any(), "melting temperature",
                            &JohnsonCookParams::melting_temperature_K)};
  return table;
}

/// The thermal group's keys: conductivity and specific heat are linear in T about one reference temperature.
struct ThermalKeys {
  double density_kg_per_m3 = 0.0;
  double reference_K = 293.15;
  double conductivity = 0.0, conductivity_slope = 0.0;
  double specific_heat = 0.0, specific_heat_slope = 0.0;
};

const FieldTable<ThermalKeys>& thermal_fields() {
  static const FieldTable<ThermalKeys> table{
      required_number_field("density_kg_per_m3", units::kSi("kg/m^3"), Range::positive(), "density",
                            &ThermalKeys::density_kg_per_m3),
      number_field("property_reference_temperature_K", kKelvin, Range::positive(),
                   "the temperature about which conductivity and specific heat are linear", &ThermalKeys::reference_K),
      required_number_field("conductivity_W_per_m_K", units::kSi("W/(m K)"), Range::positive(),
                            "thermal conductivity at the reference temperature", &ThermalKeys::conductivity),
      number_field("conductivity_slope_W_per_m_K2", units::kSi("W/(m K^2)"), Range::any(), "its change per kelvin",
                   &ThermalKeys::conductivity_slope),
      required_number_field("specific_heat_J_per_kg_K", units::kSi("J/(kg K)"), Range::positive(),
                            "specific heat at the reference temperature", &ThermalKeys::specific_heat),
      number_field("specific_heat_slope_J_per_kg_K2", units::kSi("J/(kg K^2)"), Range::any(), "its change per kelvin",
                   &ThermalKeys::specific_heat_slope)};
  return table;
}

/// The microstructure group's keys, shared by the Hall-Petch and the dislocation terms (each set in both;
/// the defaults are those of HallPetchParams and DislocationParams).
struct MicrostructureKeys {
  MicrostructureModels models;
  std::optional<double> boundary_spacing_m;  ///< default: the grain size
};

/// A key that sets the same quantity in both terms (the table prints the Hall-Petch one).
NumberField<MicrostructureKeys> both_terms_field(std::string_view key, FieldUnit unit, Range range,
                                                 std::string_view doc, double HallPetchParams::*hall_petch,
                                                 double DislocationParams::*dislocation, bool required = false) {
  return {key,
          unit,
          range,
          doc,
          [hall_petch](const MicrostructureKeys& k) { return k.models.hall_petch.*hall_petch; },
          [hall_petch, dislocation](MicrostructureKeys& k, double v) {
            k.models.hall_petch.*hall_petch = k.models.dislocation.*dislocation = v;
          },
          required,
          {},
          {}};
}

template <class At>
NumberField<MicrostructureKeys> micro_field(std::string_view key, FieldUnit unit, Range range, std::string_view doc,
                                            At at, bool required = false) {
  return number_at<MicrostructureKeys>(key, unit, range, doc, at, required);
}

const FieldTable<MicrostructureKeys>& microstructure_fields() {
  static const FieldTable<MicrostructureKeys> table{
      both_terms_field("taylor_factor", units::kNone, Range::positive(), "Taylor factor M",
                       &HallPetchParams::taylor_factor, &DislocationParams::taylor_factor),
      both_terms_field("burgers_vector_nm", kNm, Range::positive(), "Burgers vector b",
                       &HallPetchParams::burgers_vector_m, &DislocationParams::burgers_vector_m, true),
      micro_field(
          "grain_size_um", units::kUm, Range::positive(), "grain size D",
          [](auto& k) -> auto& { return k.models.hall_petch.grain_size_m; }, true),
      both_terms_field("critical_grain_size_nm", kNm, Range::non_negative(),
                       "grain size (and boundary spacing) below which the terms are capped",
                       &HallPetchParams::critical_grain_size_m, &DislocationParams::critical_spacing_m),
      micro_field(
          "grain_boundary_stress_ratio", units::kNone, Range::positive(), "tau_b / G (Shao et al. 2013, Eq. 11)",
          [](auto& k) -> auto& { return k.models.hall_petch.grain_boundary_stress_ratio; }),
      NumberField<MicrostructureKeys>{
          "hall_petch_coefficient_MPa_sqrt_m", FieldUnit{"MPa m^0.5", units::mpa_to_pa, units::pa_to_mpa},
          Range::non_negative(), "a measured Hall-Petch coefficient, which replaces Eqs. 10-11",
          [](const MicrostructureKeys& k) { return k.models.hall_petch.coefficient_Pa_sqrt_m.value_or(0.0); },
          [](MicrostructureKeys& k, double v) { k.models.hall_petch.coefficient_Pa_sqrt_m = v; }, false,
          [](const MicrostructureKeys& k) { return k.models.hall_petch.coefficient_Pa_sqrt_m.has_value(); },
          "none: Eqs. 10-11"},
      micro_field(
          "alpha", units::kNone, Range::positive(), "dislocation interaction constant",
          [](auto& k) -> auto& { return k.models.dislocation.alpha; }),
      micro_field(
          "boundary_constant_k", units::kNone, Range::positive(), "boundary constant k",
          [](auto& k) -> auto& { return k.models.dislocation.boundary_constant_k; }),
      micro_field(
          "misorientation_deg", units::kDeg, Range::closed(0.0, 90.0), "mean boundary misorientation",
          [](auto& k) -> auto& { return k.models.dislocation.misorientation_rad; }, true),
      optional_number_field("boundary_spacing_um", units::kUm, Range::positive(), "mean boundary spacing D_avg",
                            &MicrostructureKeys::boundary_spacing_m, "the grain size"),
      micro_field(
          "interior_dislocation_density_per_m2", units::kSi("1/m^2"), Range::non_negative(),
          "dislocation density inside the grains rho_0",
          [](auto& k) -> auto& { return k.models.dislocation.interior_density_per_m2; })};
  return table;
}

const FieldTable<OxleyHeatFactors>& oxley_fields() {
  static const FieldTable<OxleyHeatFactors> table{
      number_field("eta", units::kNone, Range::closed(0.0, 1.0),
                   "Oxley's eta: T_AB = T_w + eta dT_SZ (the mean shear-plane temperature)", &OxleyHeatFactors::eta),
      number_field("psi", units::kNone, Range::closed(0.0, 1.0),
                   "Oxley's psi: T_int = T_w + dT_SZ + psi dT_M (mean over the contact)", &OxleyHeatFactors::psi)};
  return table;
}

const FieldUnit kMPaSqrtM{"MPa m^0.5", units::mpa_to_pa, units::pa_to_mpa};

const FieldTable<BrittleGroup>& brittle_fields() {
  static const FieldTable<BrittleGroup> table{
      optional_number_field("hardness_GPa", units::kGPa, Range::positive(), "hardness H", &BrittleGroup::hardness_Pa,
                            "none"),
      optional_number_field("fracture_toughness_MPa_sqrt_m", kMPaSqrtM, Range::positive(), "fracture toughness K_c",
                            &BrittleGroup::fracture_toughness_Pa_sqrt_m, "none"),
      optional_number_field("constraint_factor", units::kNone, Range::at_least(1.0),
                            "constraint factor C = H / Y of the hardness flow stress (models.flow_stress = hardness)",
                            &BrittleGroup::constraint_factor, "none"),
      optional_number_field("tensile_strength_MPa", units::kMPa, Range::positive(),
                            "tensile strength (recorded: no analytic model reads it)",
                            &BrittleGroup::tensile_strength_Pa, "none"),
      optional_number_field("compressive_strength_MPa", units::kMPa, Range::positive(),
                            "unconfined compressive strength (recorded: no analytic model reads it)",
                            &BrittleGroup::compressive_strength_Pa, "none")};
  return table;
}

}  // namespace

const std::vector<SceneKeySection>& material_key_sections() {
  static const std::vector<SceneKeySection> list{
      {"material.elastic", "used by hall_petch, dislocation and the regime check",
       [] { return fields_markdown(elastic_fields()); }},
      {"material.johnson_cook", "used by johnson_cook and oxley",
       [] { return fields_markdown(johnson_cook_fields()); }},
      {"material.thermal", "used by oxley", [] { return fields_markdown(thermal_fields()); }},
      {"material.microstructure", "used by hall_petch and dislocation (with the elastic group)",
       [] { return fields_markdown(microstructure_fields()); }},
      {"material.oxley", "optional, used by oxley: the heat partition factors",
       [] { return fields_markdown(oxley_fields()); }},
      {"material.brittle",
       "optional: hardness and toughness give the regime check's critical depth (with "
       "elastic.youngs_modulus_GPa) and the transition model's fracture part; the hardness is the "
       "trepanning model's default and, with the constraint factor, the hardness flow stress",
       [] { return fields_markdown(brittle_fields()); }}};
  return list;
}

ElasticProperties elastic_from_material(const MaterialRecord& material, const std::string& path) {
  ObjectReader reader(material.require_group("elastic", path, "the elastic constants"), path + ".elastic");
  ElasticProperties e = read_fields(reader, elastic_fields(), ElasticProperties{});
  if (!reader.has("shear_modulus_GPa")) e.shear_modulus_Pa = e.youngs_modulus_Pa / (2.0 * (1.0 + e.poissons_ratio));
  reader.finish();
  return e;
}

JohnsonCookParams johnson_cook_from_material(const MaterialRecord& material, const std::string& path) {
  const std::string group_path = path + ".johnson_cook";
  ObjectReader reader(material.require_group("johnson_cook", path, "the johnson_cook flow-stress term"), group_path);
  const JohnsonCookParams jc = read_fields(reader, johnson_cook_fields(), JohnsonCookParams{});
  reader.finish();
  jc.validate(group_path);
  return jc;
}

ThermalProperties thermal_from_material(const MaterialRecord& material, const std::string& path) {
  const std::string group_path = path + ".thermal";
  ObjectReader reader(material.require_group("thermal", path, "the temperature model"), group_path);
  const ThermalKeys k = read_fields(reader, thermal_fields(), ThermalKeys{});
  reader.finish();
  ThermalProperties t;
  t.density_kg_per_m3 = k.density_kg_per_m3;
  t.conductivity_W_per_m_K = {k.conductivity, k.conductivity_slope, k.reference_K};
  t.specific_heat_J_per_kg_K = {k.specific_heat, k.specific_heat_slope, k.reference_K};
  return t;
}

MicrostructureModels microstructure_from_material(const MaterialRecord& material, const std::string& path) {
  const std::string group_path = path + ".microstructure";
  ObjectReader reader(material.require_group("microstructure", path, "the hall_petch and dislocation terms"),
                      group_path);
  const ElasticProperties elastic = elastic_from_material(material, path);
  MicrostructureKeys k = read_fields(reader, microstructure_fields(), MicrostructureKeys{});
  reader.finish();
  MicrostructureModels m = k.models;
  auto& hp = m.hall_petch;
  auto& d = m.dislocation;
  hp.shear_modulus_Pa = d.shear_modulus_Pa = elastic.shear_modulus_Pa;
  hp.poissons_ratio = elastic.poissons_ratio;
  // Default: the grain size, through its key's unit (um) as when it was read by hand, to the bit.
  d.boundary_spacing_m = k.boundary_spacing_m.value_or(units::um_to_m(units::m_to_um(hp.grain_size_m)));
  hp.validate(group_path);
  d.validate(group_path);
  return m;
}

namespace {
/// A group the material may leave out, read through its table: T's defaults without it.
template <class T>
T optional_group(const MaterialRecord& material, const std::string& path, const std::string& group_name,
                 const FieldTable<T>& table) {
  const Json* group = material.group(group_name);
  if (!group) return T{};
  ObjectReader reader(*group, path + "." + group_name);
  const T values = read_fields(reader, table, T{});
  reader.finish();
  return values;
}
}  // namespace

BrittleGroup brittle_group_from_material(const MaterialRecord& material, const std::string& path) {
  return optional_group(material, path, "brittle", brittle_fields());
}

HardnessFlowParams hardness_flow_from_material(const MaterialRecord& material, const std::string& path) {
  const std::string purpose = "the hardness flow stress (models.flow_stress = hardness)";
  material.require_group("brittle", path, purpose);
  const BrittleGroup brittle = brittle_group_from_material(material, path);
  if (!brittle.hardness_Pa) {
    throw InputError(path + ".brittle.hardness_GPa", fmt::format("(missing in material '{}')", material.name),
                     "a number: " + purpose + " needs it");
  }
  material.require_group("elastic", path, purpose);
  const ElasticProperties elastic = elastic_from_material(material, path);
  return {.hardness_Pa = *brittle.hardness_Pa,
          .youngs_modulus_Pa = elastic.youngs_modulus_Pa,
          .poissons_ratio = elastic.poissons_ratio,
          .constraint_factor = brittle.constraint_factor};
}

OxleyHeatFactors oxley_factors_from_material(const MaterialRecord& material, const std::string& path) {
  return optional_group(material, path, "oxley", oxley_fields());
}

OxleyParams oxley_params_from_material(const MaterialRecord& material, const std::string& path,
                                       const JohnsonCookPolicy& policy) {
  OxleyParams oxley;
  oxley.johnson_cook = johnson_cook_from_material(material, path);
  oxley.policy = policy;
  oxley.thermal = thermal_from_material(material, path);
  const auto factors = oxley_factors_from_material(material, path);
  oxley.eta = factors.eta;
  oxley.psi = factors.psi;
  oxley.validate(path);
  return oxley;
}

}  // namespace kerf
