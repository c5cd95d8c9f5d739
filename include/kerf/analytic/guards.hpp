#pragma once
// Domain guards: every place where a model leaves the range its equations hold in, and the documented
// policy kerf applies there. A guard that fires is recorded and reported with the result; results never
// carry a silent NaN. The bit set costs nothing in the hot loops of a sweep.
//
//   kerf::Guards guards;
//   double s = kerf::johnson_cook_stress(jc, policy, 0.5, 1e3, 2000.0, &guards);
//   if (guards.has(kerf::Guard::temperature_at_or_above_melt)) ...
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kerf {

enum class Guard : std::uint32_t {
  temperature_at_or_above_melt = 1u << 0,
  temperature_below_room = 1u << 1,
  strain_rate_below_reference = 1u << 2,
  zero_strain = 1u << 3,
  grain_below_critical_size = 1u << 4,
  boundary_spacing_below_critical = 1u << 5,
  heat_partition_clamped = 1u << 6,
  no_chip_on_edge = 1u << 7,
  lower_limit_above_pole = 1u << 8,
  solver_at_bound = 1u << 9,
  turning_depth_below_feed = 1u << 10,
  no_chip_on_rake_face = 1u << 11,
  contact_length_not_applicable = 1u << 12,
  ploughing_field_capped = 1u << 13,
};

inline constexpr int kGuardCount = 14;

/// Name (snake_case, for CSV and JSON) of a guard.
std::string_view guard_name(Guard guard);
/// One sentence: what happened and which policy kerf applied.
std::string_view guard_policy(Guard guard);

class Guards {
 public:
  void raise(Guard guard) { bits_ |= static_cast<std::uint32_t>(guard); }
  bool has(Guard guard) const { return (bits_ & static_cast<std::uint32_t>(guard)) != 0; }
  bool any() const { return bits_ != 0; }
  void merge(const Guards& other) { bits_ |= other.bits_; }
  std::uint32_t bits() const { return bits_; }
  std::vector<Guard> fired() const;
  /// Names joined by ';' ("temperature_below_room;zero_strain"), empty when none fired.
  std::string names() const;

 private:
  std::uint32_t bits_ = 0;
};

/// Records into `guards` when it is not null (the models take an optional Guards*).
inline void raise(Guards* guards, Guard guard) {
  if (guards) guards->raise(guard);
}

}  // namespace kerf
