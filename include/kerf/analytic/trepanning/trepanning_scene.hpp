#pragma once
// A trepanning scene: the JSON a user writes for models.force = "trepanning" (Yu et al. 2023), validated into SI.
//
//   {
//     "material": "k9_glass",
//     "tool":   {"outer_diameter_mm": 132, "inner_diameter_mm": 124},
//     "cut":    {"feed_rate_um_per_s": 20, "spindle_speed_rpm": 90.5},
//     "models": {"force": "trepanning",
//                "trepanning": {"axial_group_MPa": 10740, "torque_group_MPa": 6030}}
//   }
//
// models.trepanning holds either the two lumped groups (K_F = H tan(phi), K_M = H (1 + pi tan(phi) mu / 2),
// in MPa) or half_angle_deg and friction_coefficient with an optional hardness_GPa (default: the material's
// brittle.hardness_GPa), and optionally `grits` for the per-grit diagnostics. Unknown keys are rejected with a
// suggestion.
//
//   kerf::TrepanningScene s =
//       kerf::parse_trepanning_scene(kerf::read_json_file("validation/k9_trepanning/scene.json"));
//   kerf::TrepanningForces f = kerf::trepanning_forces(s.tool, s.cut, s.groups);
#include <optional>
#include <string>
#include <vector>

#include "kerf/analytic/kinds/key_sections.hpp"
#include "kerf/analytic/trepanning/trepanning.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/material.hpp"

namespace kerf {

class MaterialCache;  // kerf/analytic/kinds/scene.hpp

struct TrepanningScene {
  MaterialRecord material;
  TrepanningTool tool;
  TrepanningCut cut;
  TrepanningGroups groups;
  std::optional<TrepanningMaterial> material_params;  ///< when the scene gave H, phi, mu instead of the groups
  /// models.trepanning.grits {grit_density_per_mm2, shape_coefficient, grit_width_um}: the per-grit diagnostics
  /// of Eqs. 1-20 (optional; the totals do not depend on them).
  std::optional<TrepanningGritParams> grits;
  std::string
      groups_origin;  ///< "models.trepanning.axial_group_MPa/torque_group_MPa" or "hardness, half angle, friction"
};

/// Validates a scene document; InputError names the first bad field by its dotted path.
TrepanningScene parse_trepanning_scene(const Json& document, MaterialCache* cache = nullptr);

/// The trepanning scene's sections, read through the field tables they print (analytic_scene_keys_markdown).
const std::vector<SceneKeySection>& trepanning_key_sections();

}  // namespace kerf
