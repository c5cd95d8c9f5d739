#pragma once
// A random specimen spec with a short genesis (2000 growth and 500 relaxation steps), for tests that need a
// small bonded specimen in well under a second. Default radii of SpecimenSpec unless the test sets them.
#include <cstdint>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/dem/procedures/specimen.hpp"

namespace kerf::dem::testing {

inline SpecimenSpec quick_random_spec(double width_m, double height_m, std::uint64_t seed) {
  SpecimenSpec spec;
  spec.width_m = width_m;
  spec.height_m = height_m;
  spec.growth_steps = 2000;
  spec.relax_steps = 500;
  spec.seed = seed;
  return spec;
}

/// The default material with nothing to dissipate energy: frictionless disks, walls and joint elements, joints too
/// strong to break, no damping (for tests of the energy books: the work done on it is what it stores).
inline Material conservative_material() {
  Material m;
  m.local_damping = 0;
  std::get<LinearContactParams>(m.contact).friction_coefficient = 0;
  auto& joint = std::get<FlatJointParams>(m.joint);
  joint.residual_friction_coefficient = 0;
  joint.bond.tensile_strength_Pa = joint.bond.cohesion_Pa = 1e15;
  return m;
}

/// A small random specimen with the Yang et al. 2018 workpiece's disk radii (10-13 um), default material.
inline Simulation quick_workpiece_specimen(double width_m, double height_m, std::uint64_t seed) {
  SpecimenSpec spec = quick_random_spec(width_m, height_m, seed);
  spec.radius_min_m = 10e-6;
  spec.radius_max_m = 13e-6;
  SpecimenReport report;
  return make_specimen(Material{}, spec, report);
}

/// A 0.05 mm deep, 0.1 mm long cut at 2 m/s through an active window of these extents (depths of cut),
/// rebuilt every 0.2 depths: the windowed cut of the window tests.
inline CutParams windowed(double ahead, double behind, double below, double above) {
  CutParams p;
  p.cut.depth_of_cut_m = 0.05e-3;
  p.cut.speed_m_per_s = 2;
  p.cut.length_m = 0.1e-3;
  p.window.enabled = true;
  p.window.ahead_depths = ahead, p.window.behind_depths = behind, p.window.below_depths = below;
  p.window.above_depths = above;
  p.window.shift_depths = 0.2;
  return p;
}

}  // namespace kerf::dem::testing
