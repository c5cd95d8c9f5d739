#include "kerf/analytic/flow_stress.hpp"

#include <cmath>

#include "kerf/error.hpp"

namespace kerf {

void FlowStressModel::validate(const std::string& path) const {
  if (!johnson_cook && !hall_petch && !dislocation) {
    throw InputError(path + ".terms", "[]", "at least one of 'johnson_cook', 'hall_petch', 'dislocation'");
  }
  if (johnson_cook) johnson_cook->validate(path + ".johnson_cook");
  if (hall_petch) hall_petch->validate(path + ".microstructure");
  if (dislocation) dislocation->validate(path + ".microstructure");
}

FlowStress flow_stress(const FlowStressModel& model, const DeformationState& state, Guards* guards) {
  FlowStress out;
  const double melt_K = model.johnson_cook ? model.johnson_cook->melting_temperature_K : model.melting_temperature_K;
  if (melt_K > 0.0 && state.temperature_K >= melt_K) {
    raise(guards, Guard::temperature_at_or_above_melt);
    return out;  // molten: every term is zero
  }
  if (model.johnson_cook) {
    out.johnson_cook_Pa = johnson_cook_stress(*model.johnson_cook, model.policy, state.strain, state.strain_rate_per_s,
                                              state.temperature_K, guards);
  }
  if (model.hall_petch) out.hall_petch_Pa = hall_petch_stress(*model.hall_petch, guards);
  if (model.dislocation) out.dislocation_Pa = dislocation_stress(*model.dislocation, guards);
  out.total_Pa = out.johnson_cook_Pa + out.hall_petch_Pa + out.dislocation_Pa;
  out.shear_Pa = out.total_Pa / std::sqrt(3.0);
  return out;
}

}  // namespace kerf
