#include "kerf/analytic/guards.hpp"

namespace kerf {

namespace {
struct GuardInfo {
  Guard guard;
  std::string_view name, policy;
};

constexpr GuardInfo kGuards[kGuardCount] = {
    {Guard::temperature_at_or_above_melt, "temperature_at_or_above_melt",
     "T >= T_melt: the material is molten, flow stress set to zero (all terms)"},
    {Guard::temperature_below_room, "temperature_below_room",
     "T < T_room: policy 'clamp' uses T* = 0 (no thermal softening), 'error' refuses"},
    {Guard::strain_rate_below_reference, "strain_rate_below_reference",
     "strain rate below the Johnson-Cook reference rate: policy 'clamp' uses no rate effect, 'power_law' "
     "uses (1 + rate/rate0)^C"},
    {Guard::zero_strain, "zero_strain", "zero plastic strain: stress is A; the hardening slope is infinite for n < 1"},
    {Guard::grain_below_critical_size, "grain_below_critical_size",
     "grain size below the critical size (inverse Hall-Petch range): Hall-Petch term capped at its value there"},
    {Guard::boundary_spacing_below_critical, "boundary_spacing_below_critical",
     "boundary spacing below the critical size: dislocation term capped at its value there"},
    {Guard::heat_partition_clamped, "heat_partition_clamped",
     "Oxley: heat partition beta outside [0, 1] (R_T tan(phi) outside the fitted range): clamped"},
    {Guard::no_chip_on_edge, "no_chip_on_edge",
     "Liu-Li: the whole cut on the edge lies below the lower limit: ploughed, no chip force; the ploughing "
     "model (models.ploughing) gives its force, zero with 'none'"},
    {Guard::lower_limit_above_pole, "lower_limit_above_pole",
     "Liu-Li: constant friction angle puts a pole on the edge; integration starts above it"},
    {Guard::solver_at_bound, "solver_at_bound",
     "Oxley: the solution lies on a bound of the search range (phi, C0 or delta)"},
    {Guard::turning_depth_below_feed, "turning_depth_below_feed",
     "turning: the chip is thinner along the edge than the feed suggests (depth of cut small against feed)"},
    {Guard::no_chip_on_rake_face, "no_chip_on_rake_face",
     "the nominal rake lies below the lower limit (stagnation point or pole): the rake face forms no chip either; "
     "the whole cut is ploughed, its chip force is zero (the ploughing model gives the force under the edge)"},
    {Guard::contact_length_not_applicable, "contact_length_not_applicable",
     "a contact-length model is outside its domain here (its shear angle or length is not positive): its column "
     "is empty, the warning names the reason, the rest of the prediction stands"},
    {Guard::ploughing_field_capped, "ploughing_field_capped",
     "wave ploughing model: the chord of the engaged arc is steeper than eta = acos(f)/2, where the slip-line field "
     "does not exist; its attack angle is capped at eta (the chord's length is kept)"},
};
}  // namespace

std::string_view guard_name(Guard guard) {
  for (const auto& info : kGuards)
    if (info.guard == guard) return info.name;
  return "unknown_guard";
}

std::string_view guard_policy(Guard guard) {
  for (const auto& info : kGuards)
    if (info.guard == guard) return info.policy;
  return "";
}

std::vector<Guard> Guards::fired() const {
  std::vector<Guard> out;
  for (const auto& info : kGuards)
    if (has(info.guard)) out.push_back(info.guard);
  return out;
}

std::string Guards::names() const {
  std::string out;
  for (Guard guard : fired()) {
    if (!out.empty()) out += ';';
    out += guard_name(guard);
  }
  return out;
}

}  // namespace kerf
