#pragma once
// The composite flow stress of Shao et al. 2013 (Eq. 8) and the shear flow stress (Eq. 12):
//
//   sigma = sigma_JC(eps, epsdot, T) + K_HP / sqrt(D) + M alpha G b sqrt(k theta_av / (D_avg b))
//   k_s   = sigma / sqrt(3)
//
// Each term is optional: a scene names the terms it wants. Eq. 8 writes K_HP(eps, epsdot, T) but Eqs. 10-11
// define no dependence; kerf's choice: the microstructural terms soften with the material's Johnson-Cook
// thermal factor (1 - T*^m) above room temperature, so the flow stress falls continuously to zero at T_melt.
// At T >= T_melt every term is zero (a melt has no grains) and Guard::temperature_at_or_above_melt is raised.
// Glasses and ceramics take the hardness term instead (hardness_flow.hpp): Y = H / C, independent of strain,
// rate and temperature, alone (it is a whole flow stress, not an addition to the metals' terms).
//
//   kerf::FlowStressModel model;
//   model.johnson_cook = jc;  model.hall_petch = hp;         // dislocation term left out
//   auto s = kerf::flow_stress(model, {.strain = 1.0, .strain_rate_per_s = 1e5, .temperature_K = 600.0}, nullptr);
//   double k_s_Pa = s.shear_Pa;
#include <optional>
#include <string>

#include "kerf/analytic/flow_stress/dislocation.hpp"
#include "kerf/analytic/flow_stress/hall_petch.hpp"
#include "kerf/analytic/flow_stress/hardness_flow.hpp"
#include "kerf/analytic/flow_stress/johnson_cook.hpp"
#include "kerf/analytic/guards.hpp"

namespace kerf {

/// Strain, strain rate and temperature at which a flow stress is evaluated.
struct DeformationState {
  double strain = 0.0;
  double strain_rate_per_s = 0.0;
  double temperature_K = 293.15;
};

struct FlowStressModel {
  std::optional<JohnsonCookParams> johnson_cook;
  JohnsonCookPolicy policy;
  std::optional<HallPetchParams> hall_petch;
  std::optional<DislocationParams> dislocation;
  /// A glass's or ceramic's yield stress from its hardness (models.flow_stress hardness, hardness_marsh or
  /// hardness_johnson), the only term when present.
  std::optional<HardnessFlowParams> hardness;
  ConstraintModel constraint = ConstraintModel::given;
  /// The material's Johnson-Cook law when the Johnson-Cook term is not used: its thermal factor softens the
  /// microstructural terms (when the term is used, its own law does).
  std::optional<JohnsonCookParams> thermal_softening;
  /// The melt policy for the microstructural terms when neither law is known (0: none).
  double melting_temperature_K = 0.0;

  /// At least one term, the hardness term alone; each term validated under `path`.
  void validate(const std::string& path) const;
};

struct FlowStress {
  double johnson_cook_Pa = 0.0;
  double hall_petch_Pa = 0.0;
  double dislocation_Pa = 0.0;
  double hardness_Pa = 0.0;  ///< Y = H / C (hardness_flow.hpp)
  double total_Pa = 0.0;     ///< sigma (Eq. 8)
  double shear_Pa = 0.0;     ///< k_s = sigma / sqrt(3) (Eq. 12)
};

FlowStress flow_stress(const FlowStressModel& model, const DeformationState& state, Guards* guards);

}  // namespace kerf
