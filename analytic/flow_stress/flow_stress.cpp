#include "kerf/analytic/flow_stress/flow_stress.hpp"

#include <cmath>

#include "kerf/error.hpp"

namespace kerf {

void FlowStressModel::validate(const std::string& path) const {
  if (!johnson_cook && !hall_petch && !dislocation && !hardness) {
    throw InputError(path, "[]", "at least one of 'johnson_cook', 'hall_petch', 'dislocation', or a hardness term");
  }
  if (hardness && (johnson_cook || hall_petch || dislocation)) {
    throw InputError(path, std::string(constraint_model_name(constraint)) + " with other terms",
                     "the hardness term alone (it is a glass's whole flow stress, not an addition to a metal's)");
  }
  if (hardness) hardness->validate("material", constraint);
  if (johnson_cook) johnson_cook->validate(path + ".johnson_cook");
  if (hall_petch) hall_petch->validate(path + ".microstructure");
  if (dislocation) dislocation->validate(path + ".microstructure");
}

FlowStress flow_stress(const FlowStressModel& model, const DeformationState& state, Guards* guards) {
  FlowStress out;
  if (model.hardness) {  // rate- and temperature-independent (hardness_flow.hpp)
    out.hardness_Pa = out.total_Pa = hardness_yield_stress_Pa(*model.hardness, model.constraint);
    out.shear_Pa = out.total_Pa / std::sqrt(3.0);
    return out;
  }
  const JohnsonCookParams* softening_law = model.johnson_cook        ? &*model.johnson_cook
                                           : model.thermal_softening ? &*model.thermal_softening
                                                                     : nullptr;
  const double melt_K = softening_law ? softening_law->melting_temperature_K : model.melting_temperature_K;
  if (melt_K > 0.0 && state.temperature_K >= melt_K) {
    raise(guards, Guard::temperature_at_or_above_melt);
    return out;  // molten: every term is zero
  }
  if (model.johnson_cook) {
    out.johnson_cook_Pa = johnson_cook_stress(*model.johnson_cook, model.policy, state.strain, state.strain_rate_per_s,
                                              state.temperature_K, guards);
  }
  // Shao et al. 2013, Eq. 8 writes K_HP(eps, epsdot, T) but defines K_HP only by Eqs. 10-11, which hold no strain,
  // rate or temperature. kerf's choice: the microstructural terms soften with the Johnson-Cook thermal factor
  // (1 - T*^m) of the same material, so that the whole flow stress, and every force, falls continuously to
  // zero at the melting temperature. At or below room temperature the factor is 1 (Eqs. 4-11 as printed).
  double softening = 1.0;
  if (softening_law && state.temperature_K > softening_law->room_temperature_K) {
    softening = johnson_cook_thermal_factor(*softening_law, model.policy, state.temperature_K, nullptr);
  }
  if (model.hall_petch) out.hall_petch_Pa = softening * hall_petch_stress(*model.hall_petch, guards);
  if (model.dislocation) out.dislocation_Pa = softening * dislocation_stress(*model.dislocation, guards);
  out.total_Pa = out.johnson_cook_Pa + out.hall_petch_Pa + out.dislocation_Pa;
  out.shear_Pa = out.total_Pa / std::sqrt(3.0);
  return out;
}

}  // namespace kerf
