#pragma once
// What a cut reports in summary.json, as result tables (kerf/result_table.hpp): the keys of "results" (one run),
// of each of its "travel_windows", of "active_window", and of a replicated cut's means. The tables write the
// summary and the key reference (kerf-dem results, docs/dem-keys.md); readers name a key by its constant here
// (C++) or in kerf.result_keys (Python, generated from these tables), never by a literal.
#include <string>
#include <string_view>
#include <vector>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/result_table.hpp"

namespace kerf::dem {

/// The keys of a cut's "results" (cut_results(), cut_edge_results(), replicate_spread_key), one constant each.
namespace cut_keys {
KERF_RESULT_KEY(main_force_N)
KERF_RESULT_KEY(thrust_force_N)
KERF_RESULT_KEY(main_force_std_N)
KERF_RESULT_KEY(thrust_force_std_N)
KERF_RESULT_KEY(main_force_sem_N)
KERF_RESULT_KEY(thrust_force_sem_N)
KERF_RESULT_KEY(main_force_sem_method)
KERF_RESULT_KEY(thrust_force_sem_method)
KERF_RESULT_KEY(main_force_inefficiency_samples)
KERF_RESULT_KEY(thrust_force_inefficiency_samples)
KERF_RESULT_KEY(main_force_batch_samples)
KERF_RESULT_KEY(thrust_force_batch_samples)
KERF_RESULT_KEY(steady_from_travel_mm)
KERF_RESULT_KEY(steady_to_travel_mm)
KERF_RESULT_KEY(steady_samples)
KERF_RESULT_KEY(contact_share_steady)
KERF_RESULT_KEY(steady)
KERF_RESULT_KEY(not_steady_reason)
KERF_RESULT_KEY(width_mm)
KERF_RESULT_KEY(cracks_tensile)
KERF_RESULT_KEY(cracks_shear)
KERF_RESULT_KEY(cracks_chip)
KERF_RESULT_KEY(cracks_subsurface)
KERF_RESULT_KEY(subsurface_damage_depth_um)
KERF_RESULT_KEY(steady_machined_from_x_mm)
KERF_RESULT_KEY(steady_machined_to_x_mm)
KERF_RESULT_KEY(cracks_subsurface_steady)
KERF_RESULT_KEY(subsurface_damage_depth_steady_um)
KERF_RESULT_KEY(subsurface_damage_depth_steady_p95_um)
KERF_RESULT_KEY(surface_y_mm)
KERF_RESULT_KEY(cut_line_y_mm)
KERF_RESULT_KEY(particles_removed_by_grooves)
KERF_RESULT_KEY(travel_windows)
KERF_RESULT_KEY(grains_crushed)
KERF_RESULT_KEY(grains_crushed_mass_kg)
KERF_RESULT_KEY(tied_disks_crushed)
KERF_RESULT_KEY(tied_disks_crushed_mass_kg)
KERF_RESULT_KEY(energy_tool_work_steady_J)
KERF_RESULT_KEY(energy_dissipated_steady_J)
KERF_RESULT_KEY(energy_left_kinetic_steady_J)
KERF_RESULT_KEY(energy_left_strain_steady_J)
KERF_RESULT_KEY(energy_stored_change_steady_J)
KERF_RESULT_KEY(edge_observations_steady)
KERF_RESULT_KEY(edge_touches_tied_share_steady)
KERF_RESULT_KEY(edge_touches_loose_share_steady)
KERF_RESULT_KEY(edge_touches_nothing_share_steady)
KERF_RESULT_KEY(edge_zone_samples_steady)
KERF_RESULT_KEY(edge_zone_intact_share_steady)
KERF_RESULT_KEY(edge_zone_cutting_force_N_per_mm)
KERF_RESULT_KEY(edge_zone_thrust_force_N_per_mm)
KERF_RESULT_KEY(edge_zone_removed_tied_disks)
KERF_RESULT_KEY(edge_zone_removed_loose_disks)
KERF_RESULT_KEY(edge_zone_removed_mass_kg)
KERF_RESULT_KEY(energy_edge_zone_tool_work_steady_J)
KERF_RESULT_KEY(energy_edge_zone_reaction_work_steady_J)
KERF_RESULT_KEY(energy_edge_layer_steady_J)
// The cut's forces under their current names (name_cut_forces: each main_force_* also as cutting_force_*, and
// per mm of width).
KERF_RESULT_KEY(cutting_force_N)
KERF_RESULT_KEY(cutting_force_N_per_mm)
KERF_RESULT_KEY(thrust_force_N_per_mm)
// A replicated cut's (run_cut_replicates): the error of the mean from the cuts' own signals.
KERF_RESULT_KEY(main_force_sem_within_cuts_N)
KERF_RESULT_KEY(thrust_force_sem_within_cuts_N)
}  // namespace cut_keys

/// The keys of one of a cut's "travel_windows".
namespace travel_window_keys {
KERF_RESULT_KEY(from_travel_mm)
KERF_RESULT_KEY(to_travel_mm)
KERF_RESULT_KEY(main_force_N)
KERF_RESULT_KEY(thrust_force_N)
KERF_RESULT_KEY(samples)
}  // namespace travel_window_keys

/// The keys of a windowed cut's "active_window".
namespace active_window_keys {
KERF_RESULT_KEY(rebuilds)
KERF_RESULT_KEY(largest_window_particles)
KERF_RESULT_KEY(mean_window_particles)
KERF_RESULT_KEY(chip_particles_removed)
KERF_RESULT_KEY(chip_mass_removed_kg)
KERF_RESULT_KEY(chip_cracks_removed)
KERF_RESULT_KEY(damage_depth_limit_um)
}  // namespace active_window_keys

/// The columns of a cut's forces.csv.
namespace forces_csv_keys {
KERF_RESULT_KEY(tool_travel_mm)
KERF_RESULT_KEY(time_s)
KERF_RESULT_KEY(cutting_force_N)
KERF_RESULT_KEY(thrust_force_N)
KERF_RESULT_KEY(cutting_force_N_per_mm)
KERF_RESULT_KEY(thrust_force_N_per_mm)
KERF_RESULT_KEY(main_force_N)
}  // namespace forces_csv_keys

/// A finished cut as its results see it: its parameters (the run's own, CutRun::params) and its result.
struct CutReport {
  const CutParams& cut;
  const CutResult& res;
};

/// One sample as a row of forces.csv: the sample and the cut's width in mm.
struct CutForcesRow {
  const CutSample& s;
  double width_mm;
};
/// forces.csv's columns, in order (cut_forces_csv_header, cut_forces_csv_row).
const ResultTable<CutForcesRow>& cut_forces_columns();

/// summary.json's "results" of one cut (before name_cut_forces adds the forces' current names), with the results
/// of the options that write them (the energy books, the edge's record, the edge zone, crushing grains) marked so.
const ResultTable<CutReport>& cut_results();
/// Each of "results"'s "travel_windows".
const ResultTable<TravelWindow>& travel_window_results();
/// summary.json's "active_window" of a windowed cut.
const ResultTable<CutReport>& active_window_results();

/// The results a replicated cut (kerf-dem run --replicates) gives as the mean over its replicates with their
/// spread (replicate_spread_key), in that order.
const std::vector<std::string_view>& cut_replicated_results();
/// The key of a replicated result's spread over the replicates: "_replicate_std" before the key's unit suffix
/// (main_force_N -> main_force_replicate_std_N); `key` one of cut_results().
std::string replicate_spread_key(std::string_view key);

/// A force result's current name (name_cut_forces): main_force_* as cutting_force_*; empty for another key.
std::string cutting_force_name(std::string_view key);
/// The names a cut's "results" derive from its table's (no getter: name_cut_forces and run_cut_replicates write
/// them): a replicated cut's spreads and errors, the forces per mm of width, each main_force_* under its current name.
const ResultTable<CutReport>& cut_derived_results();
/// Every key a cut's "results" may hold: cut_results()'s and cut_derived_results()'s (kerf.result_keys).
std::vector<std::string> cut_result_names();

/// The results each replicate's row of a replicated cut copies from its own run, beside the replicated ones.
const std::vector<std::string_view>& cut_replicate_row_results();

}  // namespace kerf::dem
