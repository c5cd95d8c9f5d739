#pragma once
// The columns of a trepanning prediction (its CSV row, kerf.predict's dict, the compare's prediction columns),
// declared once in a result table (kerf/result_table.hpp), as the orthogonal prediction's are (kinds/predict.hpp).
//
//   const TrepanningRow row{scene, forces};
//   write_result_cells(trepanning_results(), row, writer);   // kinds/cells.hpp
#include <optional>
#include <string>
#include <utility>

#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/trepanning/trepanning_scene.hpp"
#include "kerf/result_table.hpp"

namespace kerf {

/// The keys of a trepanning prediction's row, one constant each (the identifier is the key).
namespace trepanning_keys {
KERF_RESULT_KEY(force_model)
KERF_RESULT_KEY(outer_diameter_mm)
KERF_RESULT_KEY(inner_diameter_mm)
KERF_RESULT_KEY(feed_rate_um_per_s)
KERF_RESULT_KEY(spindle_speed_rpm)
KERF_RESULT_KEY(feed_per_rev_um)
KERF_RESULT_KEY(axial_force_N)
KERF_RESULT_KEY(torque_N_m)
KERF_RESULT_KEY(axial_group_MPa)
KERF_RESULT_KEY(torque_group_MPa)
KERF_RESULT_KEY(grit_count)
KERF_RESULT_KEY(cutting_edges)
KERF_RESULT_KEY(feed_per_edge_um)
KERF_RESULT_KEY(grit_depth_um)
KERF_RESULT_KEY(grit_normal_force_N)
KERF_RESULT_KEY(grit_tangential_force_N)
KERF_RESULT_KEY(critical_depth_nm)
KERF_RESULT_KEY(grit_regime)
}  // namespace trepanning_keys

/// A trepanning prediction as its row is written: the scene, its forces (feed_per_rev_m 0: not computed, the column
/// names only), and with the scene's grits their diagnostics and each grit's regime against d_c.
struct TrepanningRow {
  const TrepanningScene& scene;
  const TrepanningForces& forces;
  bool computed = false;                                   ///< the forces were computed (feed per rev > 0)
  TrepanningGritDiagnostics grits;                         ///< when the scene has grits and the forces were computed
  std::optional<std::pair<double, CuttingRegime>> regime;  ///< {critical depth, regime} when the material has them

  TrepanningRow(const TrepanningScene& scene, const TrepanningForces& forces);
};

/// The table of a trepanning row's columns, in the row's order (the grit columns present with the scene's grits).
const ResultTable<TrepanningRow>& trepanning_results();

}  // namespace kerf
