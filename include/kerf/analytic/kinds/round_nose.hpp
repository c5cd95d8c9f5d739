#pragma once
// Undeformed chip of a round-nose turning tool (Shao et al. 2013's experiments: nose radius R = 0.5 mm, feed
// f = 0.25 um/rev, depth of cut a_p = 0.5-300 um), so a turning scene can be predicted directly.
//
// With a_p <= R the chip section is the crescent between two successive passes of the nose arc:
//   area            A = f a_p
//   engaged edge    L = R (acos(1 - a_p / R) + asin(f / (2 R)))
//   maximum         t_max = R - sqrt(R^2 + f^2 - 2 f sqrt(2 R a_p - a_p^2))   (thickness along the radius at
//                   the top of the cut, valid while f <= sqrt(2 R a_p - a_p^2); otherwise t_max = a_p)
//   equivalent      h_eq = A / L                                             (Tonshoff's equivalent thickness)
// An orthogonal model then cuts thickness t0 over width A / t0 (so t0 times width is the chip area).
//
//   kerf::RoundNoseTurning turn{.feed_m_per_rev = 0.25e-6, .nose_radius_m = 0.5e-3, .depth_of_cut_m = 10e-6};
//   auto chip = kerf::round_nose_chip(turn, nullptr);   // chip.maximum_thickness_m ~ 25 nm
#include <string>

#include "kerf/analytic/guards.hpp"

namespace kerf {

struct RoundNoseTurning {
  double feed_m_per_rev = 0.0;
  double nose_radius_m = 0.0;
  double depth_of_cut_m = 0.0;

  /// Positive values; a_p <= R (the straight side edge is not modelled); f < 2R.
  void validate(const std::string& path) const;
};

struct TurningChip {
  double area_m2 = 0.0;
  double engaged_edge_length_m = 0.0;
  double maximum_thickness_m = 0.0;
  double equivalent_thickness_m = 0.0;
};

TurningChip round_nose_chip(const RoundNoseTurning& turning, Guards* guards);

}  // namespace kerf
