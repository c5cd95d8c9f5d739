#pragma once
// Builds the analytic models' parameter structs from a material record, validating each group once and
// rejecting unknown keys (errors name the path, e.g. "material.johnson_cook.A_MPa"). Each group is read through
// a field table (analytic/kinds/material_models.cpp), whose key reference is material_key_sections().
//
//   auto record = kerf::load_material(kerf::Json("aisi_1045"), "material");
//   kerf::JohnsonCookParams jc = kerf::johnson_cook_from_material(record, "material");
#include <optional>
#include <string>
#include <vector>

#include "kerf/analytic/flow_stress/dislocation.hpp"
#include "kerf/analytic/flow_stress/hall_petch.hpp"
#include "kerf/analytic/flow_stress/hardness_flow.hpp"
#include "kerf/analytic/flow_stress/johnson_cook.hpp"
#include "kerf/analytic/flow_stress/thermal.hpp"
#include "kerf/analytic/forces/oxley.hpp"
#include "kerf/analytic/kinds/key_sections.hpp"
#include "kerf/material.hpp"

namespace kerf {

struct ElasticProperties {
  double youngs_modulus_Pa = 0.0;
  double poissons_ratio = 0.0;
  double shear_modulus_Pa = 0.0;  ///< given, or E / (2 (1 + nu))
};

struct MicrostructureModels {
  HallPetchParams hall_petch;
  DislocationParams dislocation;
};

struct OxleyHeatFactors {
  double eta = 0.9;
  double psi = 0.9;
};

/// The brittle group's keys (each absent when the material leaves it out): the regime check's hardness and
/// toughness, the trepanning model's default hardness, the hardness flow stress's constraint factor; the strengths
/// are recorded (no analytic model reads them).
struct BrittleGroup {
  std::optional<double> hardness_Pa, fracture_toughness_Pa_sqrt_m, tensile_strength_Pa, compressive_strength_Pa;
  std::optional<double> constraint_factor;  ///< H / Y (models.flow_stress = hardness)
};

/// The hardness flow stress's inputs (hardness_flow.hpp) from the brittle and elastic groups; InputError names a
/// missing key and the term that needs it.
HardnessFlowParams hardness_flow_from_material(const MaterialRecord& material, const std::string& path);

ElasticProperties elastic_from_material(const MaterialRecord& material, const std::string& path);
/// The brittle group read through its field table (all keys absent when the material has no such group).
BrittleGroup brittle_group_from_material(const MaterialRecord& material, const std::string& path);
JohnsonCookParams johnson_cook_from_material(const MaterialRecord& material, const std::string& path);
ThermalProperties thermal_from_material(const MaterialRecord& material, const std::string& path);
MicrostructureModels microstructure_from_material(const MaterialRecord& material, const std::string& path);
OxleyHeatFactors oxley_factors_from_material(const MaterialRecord& material, const std::string& path);
/// The key tables of the groups read above ("material.elastic", ...), for `kerf-forces keys` and docs/scenes.md.
const std::vector<SceneKeySection>& material_key_sections();

/// The extended-Oxley material side: Johnson-Cook, thermal properties and eta/psi, validated.
OxleyParams oxley_params_from_material(const MaterialRecord& material, const std::string& path,
                                       const JohnsonCookPolicy& policy = {});

}  // namespace kerf
