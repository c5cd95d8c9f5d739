#include "kerf/analytic/material_models.hpp"

#include "kerf/units.hpp"

namespace kerf {

ElasticProperties elastic_from_material(const MaterialRecord& material, const std::string& path) {
  ObjectReader reader(material.require_group("elastic", path, "the elastic constants"), path + ".elastic");
  ElasticProperties e;
  e.youngs_modulus_Pa = units::gpa_to_pa(reader.get_number("youngs_modulus_GPa", Range::positive(), "GPa"));
  e.poissons_ratio = reader.get_number("poissons_ratio", Range{-1.0, 0.5, true, true}, "");
  const auto shear = reader.get_optional_number("shear_modulus_GPa", Range::positive(), "GPa");
  e.shear_modulus_Pa = shear ? units::gpa_to_pa(*shear) : e.youngs_modulus_Pa / (2.0 * (1.0 + e.poissons_ratio));
  reader.finish();
  return e;
}

JohnsonCookParams johnson_cook_from_material(const MaterialRecord& material, const std::string& path) {
  const std::string group_path = path + ".johnson_cook";
  ObjectReader reader(material.require_group("johnson_cook", path, "the johnson_cook flow-stress term"), group_path);
  JohnsonCookParams jc;
  jc.A_Pa = units::mpa_to_pa(reader.get_number("A_MPa", Range::any(), "MPa"));
  jc.B_Pa = units::mpa_to_pa(reader.get_number("B_MPa", Range::any(), "MPa"));
  jc.n = reader.get_number("n", Range::any(), "");
  jc.C = reader.get_number("C", Range::any(), "");
  jc.m = reader.get_number("m", Range::any(), "");
  jc.reference_strain_rate_per_s = reader.get_number("reference_strain_rate_per_s", Range::any(), "1/s");
  jc.room_temperature_K = reader.get_number("room_temperature_K", Range::any(), "K");
  jc.melting_temperature_K = reader.get_number("melting_temperature_K", Range::any(), "K");
  reader.finish();
  jc.validate(group_path);
  return jc;
}

ThermalProperties thermal_from_material(const MaterialRecord& material, const std::string& path) {
  const std::string group_path = path + ".thermal";
  ObjectReader reader(material.require_group("thermal", path, "the temperature model"), group_path);
  ThermalProperties t;
  t.density_kg_per_m3 = reader.get_number("density_kg_per_m3", Range::positive(), "kg/m^3");
  const double reference_K = reader.get_number_or("property_reference_temperature_K", 293.15, Range::positive(), "K");
  t.conductivity_W_per_m_K = {reader.get_number("conductivity_W_per_m_K", Range::positive(), "W/(m K)"),
                              reader.get_number_or("conductivity_slope_W_per_m_K2", 0.0, Range::any(), "W/(m K^2)"),
                              reference_K};
  t.specific_heat_J_per_kg_K = {reader.get_number("specific_heat_J_per_kg_K", Range::positive(), "J/(kg K)"),
                                reader.get_number_or("specific_heat_slope_J_per_kg_K2", 0.0, Range::any(), "J/(kg K^2)"),
                                reference_K};
  reader.finish();
  return t;
}

MicrostructureModels microstructure_from_material(const MaterialRecord& material, const std::string& path) {
  const std::string group_path = path + ".microstructure";
  ObjectReader reader(material.require_group("microstructure", path, "the hall_petch and dislocation terms"),
                      group_path);
  const ElasticProperties elastic = elastic_from_material(material, path);
  MicrostructureModels m;
  auto& hp = m.hall_petch;
  auto& d = m.dislocation;
  hp.shear_modulus_Pa = d.shear_modulus_Pa = elastic.shear_modulus_Pa;
  hp.poissons_ratio = elastic.poissons_ratio;
  hp.taylor_factor = d.taylor_factor = reader.get_number_or("taylor_factor", 3.06, Range::positive(), "");
  hp.burgers_vector_m = d.burgers_vector_m =
      units::nm_to_m(reader.get_number("burgers_vector_nm", Range::positive(), "nm"));
  hp.grain_size_m = units::um_to_m(reader.get_number("grain_size_um", Range::positive(), "um"));
  hp.critical_grain_size_m = d.critical_spacing_m =
      units::nm_to_m(reader.get_number_or("critical_grain_size_nm", 20.0, Range::non_negative(), "nm"));
  hp.grain_boundary_stress_ratio = reader.get_number_or("grain_boundary_stress_ratio", 0.057, Range::positive(), "");
  if (auto k_hp = reader.get_optional_number("hall_petch_coefficient_MPa_sqrt_m", Range::non_negative(), "MPa m^0.5")) {
    hp.coefficient_Pa_sqrt_m = units::mpa_to_pa(*k_hp);
  }
  d.alpha = reader.get_number_or("alpha", 0.24, Range::positive(), "");
  d.boundary_constant_k = reader.get_number_or("boundary_constant_k", 3.0, Range::positive(), "");
  d.misorientation_rad = units::deg_to_rad(reader.get_number("misorientation_deg", Range::closed(0.0, 90.0), "deg"));
  d.boundary_spacing_m = units::um_to_m(
      reader.get_number_or("boundary_spacing_um", units::m_to_um(hp.grain_size_m), Range::positive(), "um"));
  d.interior_density_per_m2 =
      reader.get_number_or("interior_dislocation_density_per_m2", 0.0, Range::non_negative(), "1/m^2");
  reader.finish();
  hp.validate(group_path);
  d.validate(group_path);
  return m;
}

OxleyHeatFactors oxley_factors_from_material(const MaterialRecord& material, const std::string& path) {
  OxleyHeatFactors f;
  const Json* group = material.group("oxley");
  if (!group) return f;
  ObjectReader reader(*group, path + ".oxley");
  f.eta = reader.get_number_or("eta", f.eta, Range::closed(0.0, 1.0), "");
  f.psi = reader.get_number_or("psi", f.psi, Range::closed(0.0, 1.0), "");
  reader.finish();
  return f;
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
