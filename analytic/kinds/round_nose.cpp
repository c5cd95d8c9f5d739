#include "kerf/analytic/kinds/round_nose.hpp"

#include <algorithm>
#include <cmath>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

void RoundNoseTurning::validate(const std::string& path) const {
  check_number(units::m_to_um(feed_m_per_rev), path + ".feed_um_per_rev", Range::positive(), "um/rev");
  check_number(units::m_to_mm(nose_radius_m), path + ".nose_radius_mm", Range::positive(), "mm");
  check_number(units::m_to_um(depth_of_cut_m), path + ".depth_of_cut_um",
               Range{0.0, units::m_to_um(nose_radius_m), true, false}, "um (up to the nose radius)");
  check_number(units::m_to_um(feed_m_per_rev), path + ".feed_um_per_rev",
               Range{0.0, units::m_to_um(2.0 * nose_radius_m), true, true}, "um/rev (below twice the nose radius)");
}

TurningChip round_nose_chip(const RoundNoseTurning& t, Guards* guards) {
  const double R = t.nose_radius_m, f = t.feed_m_per_rev, a = t.depth_of_cut_m;
  TurningChip chip;
  chip.area_m2 = f * a;
  chip.engaged_edge_length_m = R * (std::acos(1.0 - a / R) + std::asin(f / (2.0 * R)));
  const double half_chord = std::sqrt(std::max(0.0, 2.0 * R * a - a * a));  // half-width of the arc at depth a
  if (f <= half_chord) {
    const double inner = R * R + f * f - 2.0 * f * half_chord;
    chip.maximum_thickness_m = std::min(a, R - std::sqrt(std::max(0.0, inner)));
  } else {
    raise(guards, Guard::turning_depth_below_feed);
    chip.maximum_thickness_m = a;
  }
  chip.equivalent_thickness_m = chip.area_m2 / chip.engaged_edge_length_m;
  return chip;
}

}  // namespace kerf
