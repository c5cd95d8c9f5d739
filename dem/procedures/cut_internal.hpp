#pragma once
// What the cut's files (cutting.cpp, cut_params.cpp, cut_geometry.cpp) share, internal to the library: the check of a
// parameter and the tool's wedge and face lengths. In an unnamed namespace, as when they were one file's: each file
// has its own copy, which inlines as it did.
#include <cmath>
#include <string>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {
namespace {

inline void require(bool ok, const std::string& key, double value, const std::string& expected) {
  if (!ok) throw InputError(key, format_value(value), expected);
}

/// Wedge angle between the rake and clearance faces [rad]: 90 deg - rake - clearance.
inline double wedge_angle_rad(const CutParams& p) {
  return units::deg_to_rad(90.0 - p.tool.rake_deg - p.tool.clearance_deg);
}

/// Face lengths [m]: the rake face reaches tool.rake_face_height_mm above the tip (default 3 depths of cut,
/// room for the chip), the clearance face is 2 depths of cut long.
inline double rake_face_length_m(const CutParams& p) {
  const double height = p.tool.rake_face_height_m > 0 ? p.tool.rake_face_height_m : 3 * p.cut.depth_of_cut_m;
  return height / std::cos(units::deg_to_rad(p.tool.rake_deg));
}
inline double clearance_face_length_m(const CutParams& p) {
  return 2 * p.cut.depth_of_cut_m;
}

}  // namespace
}  // namespace kerf::dem
