#include "kerf/analytic/forces/critical_depth.hpp"

#include <fmt/format.h>

#include "kerf/analytic/kinds/material_models.hpp"
#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

void BrittleProperties::validate(const std::string& path) const {
  check_number(units::pa_to_gpa(youngs_modulus_Pa), path + ".elastic.youngs_modulus_GPa", Range::positive(), "GPa");
  check_number(units::pa_to_gpa(hardness_Pa), path + ".brittle.hardness_GPa", Range::positive(), "GPa");
  check_number(units::pa_to_mpa(fracture_toughness_Pa_sqrt_m), path + ".brittle.fracture_toughness_MPa_sqrt_m",
               Range::positive(), "MPa m^0.5");
}

namespace {
/// A key the critical depth needs: InputError naming it and the material when it is absent.
double required(const std::optional<double>& value, const MaterialRecord& material, const std::string& key_path) {
  if (!value) {
    throw InputError(key_path, fmt::format("(missing in material '{}')", material.name),
                     "a number: the ductile-brittle critical depth needs it");
  }
  return *value;
}
}  // namespace

BrittleProperties brittle_properties(const MaterialRecord& material, const std::string& path) {
  const std::string purpose = "the ductile-brittle critical depth";
  BrittleProperties p;
  // E is the elastic group's one key the regime check reads (the elastic table also requires Poisson's ratio).
  const Json& elastic = material.require_group("elastic", path, purpose);
  const auto e = elastic.find("youngs_modulus_GPa");
  if (e == elastic.end() || !e->is_number()) {
    throw InputError(
        path + ".elastic.youngs_modulus_GPa",
        e == elastic.end() ? fmt::format("(missing in material '{}')", material.name) : json_value_text(*e),
        "a number: " + purpose + " needs it");
  }
  p.youngs_modulus_Pa = units::gpa_to_pa(e->get<double>());
  material.require_group("brittle", path, purpose);
  const BrittleGroup brittle = brittle_group_from_material(material, path);
  p.hardness_Pa = required(brittle.hardness_Pa, material, path + ".brittle.hardness_GPa");
  p.fracture_toughness_Pa_sqrt_m =
      required(brittle.fracture_toughness_Pa_sqrt_m, material, path + ".brittle.fracture_toughness_MPa_sqrt_m");
  p.validate(path);
  return p;
}

double critical_depth_m(const BrittleProperties& p) {
  p.validate("material");
  const double toughness_over_hardness = p.fracture_toughness_Pa_sqrt_m / p.hardness_Pa;  // m^0.5
  return 0.15 * (p.youngs_modulus_Pa / p.hardness_Pa) * toughness_over_hardness * toughness_over_hardness;
}

std::string_view cutting_regime_name(CuttingRegime regime) {
  switch (regime) {
    case CuttingRegime::ductile:
      return "ductile";
    case CuttingRegime::transition:
      return "transition";
    case CuttingRegime::brittle:
      return "brittle";
  }
  return "brittle";
}

void RegimeBand::validate(const std::string& path) const {
  check_number(brittle_factor, path + ".brittle_factor", Range::at_least(1.0), "(times the critical depth)");
}

CuttingRegime classify_regime(double depth_m, double critical_depth, const RegimeBand& band) {
  band.validate("regime");
  check_number(depth_m, "depth_m", Range::non_negative(), "m");
  check_number(critical_depth, "critical_depth_m", Range::positive(), "m");
  if (depth_m < critical_depth) return CuttingRegime::ductile;
  if (depth_m < band.brittle_factor * critical_depth) return CuttingRegime::transition;
  return CuttingRegime::brittle;
}

}  // namespace kerf
