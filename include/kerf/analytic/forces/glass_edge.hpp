#pragma once
// The force of a tool's edge on intact glass at the cut line, per unit width: the ductile layer l = lambda d_c that
// the edge removes in the ductile mode however deep the cut (docs/models.md, "Glass and ceramics"; the edge part
// of models.force = transition). The DEM's edge model calls it: the physics of the edge lies 100-300 times below
// its disks (docs/physics-glass-edge.md). It runs the analytic scene of that layer, so it is the same
// number `kerf-forces predict` gives for models.force = transition with models.fracture = none.
//
//   kerf::EdgeTool tool{.rake_rad = kerf::units::deg_to_rad(-15.0), .edge_radius_m = 0.0,
//                       .friction_coefficient = 0.3};
//   kerf::EdgeForce f = kerf::edge_force_per_width(kerf::Json("soda_lime_glass"), tool);   // about 0.2 N/mm
#include <string>

#include "kerf/analytic/forces/merchant.hpp"
#include "kerf/json_reader.hpp"

namespace kerf {

struct EdgeTool {
  double rake_rad = 0.0;              ///< in (-pi/2, pi/2)
  double edge_radius_m = 0.0;         ///< >= 0; 0: a sharp edge (Merchant), else Liu-Li with the wave model
  double friction_coefficient = 0.3;  ///< >= 0, tool on glass (0.15-0.4: physics-glass-edge.md section 4)
  double layer_factor = 1.0;          ///< lambda = l / d_c > 0
};

struct EdgeForce {
  ForcePerWidth force;  ///< N/m: cutting along the cut, thrust into the workpiece
  double ductile_layer_m = 0.0;
  double critical_depth_m = 0.0;
  double flow_stress_Pa = 0.0;  ///< the hardness flow stress the layer was cut at
};

/// The edge's force on the ductile layer of `material` (a material as a scene names it: a library name, a path
/// or an inline object). InputError names the tool field or material key at fault (paths "tool.rake_deg",
/// "material.brittle.hardness_GPa", ...).
EdgeForce edge_force_per_width(const Json& material, const EdgeTool& tool);

}  // namespace kerf
