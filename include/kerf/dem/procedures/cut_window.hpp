#pragma once
// The active window of a steady-state cut (issue 20; docs/dem.md, "Steady-state cuts"): on a long
// workpiece only the disks around the tool are integrated. The whole workpiece is a reservoir that is never
// stepped; the simulation that runs holds
//   - the free disks: centres inside the window box, from `ahead` depths of cut ahead of the cutting edge to
//     `behind` depths behind it, from `below` depths under the cut line up to `above` depths over the
//     uncut surface (the chip's room); the workpiece's held boundary disks stay held;
//   - the held frame: the disks within two largest diameters outside the box, at rest (they hold the free
//     disks' joints and contacts); joints and contacts between two held disks are not computed;
//   - optionally an absorbing layer along the box's ahead, behind and lower edges (CutWindowBox::absorbing_m):
//     the held frame is rigid, and undamped elastic waves would reflect from it into the process zone; and
//     one along the workpiece's own held rows (CutWindowBox::held_absorbing_m), which are as rigid.
// Every `shift` of tool travel the window is rebuilt around the edge: the running simulation's disks,
// joints, cracks and contact springs go back to the reservoir, and a new simulation is built from it, the
// shear springs of the unjointed contacts carried over. A disk the window leaves behind is frozen where it
// is (velocity zero): the machined workpiece. A free disk that leaves the box more than a largest radius
// above the cut line is chip or debris (the tool has passed there): removed from the simulation and counted
// (disks, mass, and the cracks of the joints it carried).
// Disks ahead of the window have never moved. So the cost per step is that of the window, whatever the
// workpiece's length.
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"

namespace kerf::dem {

/// The sponge's profile (Cerjan et al. 1985): the rate at distance `d_m` from the layer's outer edge, a
/// quadratic ramp from `peak_rate_per_s` at the edge (d <= 0) to 0 at its inner side (d >= thickness_m).
inline double sponge_rate_per_s(double d_m, double thickness_m, double peak_rate_per_s) {
  if (!(d_m < thickness_m)) return 0.0;
  const double ramp = 1 - std::max(d_m, 0.0) / thickness_m;
  return peak_rate_per_s * ramp * ramp;
}

/// The held rows of a cut's workpiece (Yang et al. 2018, Section 4: the disks whose centres lie within two largest
/// radii of the left side or of the bottom are fixed): their inner lines, x = x_m and y = y_m.
struct HeldRows {
  double x_m = 0, y_m = 0;
  /// A free disk's distance from the held rows (the nearer of the two lines).
  double distance_m(double x, double y) const { return std::min(x - x_m, y - y_m); }
};

/// The sponge along the held rows, `thickness_m` thick with `peak_rate_per_s` at their lines: raises each free
/// disk's rate in `rates_per_s` (one per disk of `p`) to the layer's where that is higher.
void add_held_rows_layer(const Particles& p, const HeldRows& held, double thickness_m, double peak_rate_per_s,
                         std::vector<double>& rates_per_s);

/// The window's extent around the cutting edge [m] (the cut's depths times the scene's window keys).
struct CutWindowBox {
  double ahead_m = 0, behind_m = 0, below_m = 0, above_m = 0;
  double shift_m = 0;  ///< tool travel between rebuilds
  /// The absorbing layer inside the box's ahead, behind and lower edges (0: none): a free disk at distance
  /// d < absorbing_m from the nearest of them has its velocity decay at absorbing_rate_per_s (1 - d / L)^2
  /// (Simulation::set_absorbing_rates), set when the window is built. The top is the free surface.
  double absorbing_m = 0, absorbing_rate_per_s = 0;
  /// The absorbing layer along the workpiece's own held rows (the left side and the bottom: CutParams::Cut::
  /// held_absorbing_depths; 0: none): a free disk at distance d < held_absorbing_m from them (HeldRows) has
  /// its velocity decay at held_absorbing_rate_per_s (1 - d / L)^2; where the two layers meet, the larger rate.
  double held_absorbing_m = 0, held_absorbing_rate_per_s = 0;
  HeldRows held_rows{};  ///< where the held rows are (when held_absorbing_m > 0)
};

/// The whole workpiece at one moment (issue 54 item 2: what the tool's edge meets): per workpiece disk its place,
/// whether it is still in the workpiece, and whether it is tied to it.
struct WorkpieceNow {
  std::vector<double> x_m, y_m;
  /// 1: still in the workpiece (not removed as a chip or crushed).
  std::vector<std::uint8_t> present;
  /// 1: a path of joints with a bonded element ties it to a held disk of the workpiece (its held left side and
  /// bottom, seed 000's fixed base), through any disk still present (Simulation::tied_to_held's rule over the
  /// whole workpiece). A disk of a loose fragment, however large, is not tied.
  std::vector<std::uint8_t> tied;
};

/// The workpiece of a cut without a window: the simulation's disks, every one present, tied by its held disks.
WorkpieceNow workpiece_now(const Simulation& sim);

/// What the windowed cut removed as chips.
struct ChipAccount {
  std::size_t particles = 0;
  double mass_kg = 0;
  int cracks = 0;                  ///< crack events of joints with a removed disk at either end
  std::size_t crushed_grains = 0;  ///< of the particles, those crushed (CutWindow::crush), with their mass
  double crushed_mass_kg = 0;
  std::size_t crushed_tied_disks = 0;  ///< of the particles, those crushed while tied to the workpiece
  double crushed_tied_mass_kg = 0;
  /// Of the particles, those the edge zone removed (CutWindow::remove_at_edge) as the ductile layer's chip and
  /// powder: tied to the workpiece when reached, or loose, with their masses.
  std::size_t edge_tied_disks = 0, edge_loose_disks = 0;
  double edge_tied_mass_kg = 0, edge_loose_mass_kg = 0;
};

class CutWindow {
 public:
  CutWindow() = default;
  /// `workpiece`: the whole workpiece (make_workpiece) with its tool walls and its time step set;
  /// `y_top_m`, `y_cut_m`: the uncut surface and the cut line.
  CutWindow(Simulation workpiece, const CutWindowBox& box, double y_top_m, double y_cut_m);

  /// Whether the edge has travelled a shift since the window was built.
  bool due(double x_edge_m) const { return x_built_m_ - x_edge_m >= box_.shift_m; }
  /// The simulation of the window around the cutting edge at `x_edge_m`; `current` (the one running, or
  /// null for the first) goes back to the reservoir first.
  Simulation build(const Simulation* current, double x_edge_m);
  /// Writes the running window back into the reservoir (positions, joints, cracks): workpiece() and
  /// cracks() are then up to date.
  void sync(const Simulation& current);

  /// The whole workpiece as of the last sync.
  const Simulation& workpiece() const { return full_; }
  /// The workpiece's index of the running window's disk `u` (the window built last).
  std::int32_t workpiece_index(std::size_t u) const { return global_of_[u]; }
  /// Every crack of the cut so far (joint indices of the whole workpiece), as of the last sync.
  const std::vector<CrackEvent>& cracks() const { return full_.cracks(); }
  /// The workpiece as the cut left it, without the removed chips (for pictures).
  Simulation machined_workpiece() const;
  /// The chips removed so far (from the removal flags), with the cracks they carried.
  ChipAccount chips() const;
  std::size_t rebuilds() const { return rebuilds_; }
  /// From the next build on, also remove (as chips) every disk above the cut line that no path of joints with a
  /// bonded element ties to a held disk of the workpiece (CutParams::ActiveWindow::remove_loose_fragments; not stored:
  /// the cut sets it again from its parameters when restored).
  void set_remove_loose_fragments(bool on) { remove_loose_ = on; }
  /// Removes the running window's disks `grains` (indices in `current`) as crushed grains, and `tied_disks` as
  /// disks crushed while tied to the workpiece, and rebuilds the window around the same edge (a rebuild: counted
  /// in rebuilds()).
  Simulation crush(const Simulation& current, const std::vector<std::size_t>& grains,
                   const std::vector<std::size_t>& tied_disks = {});
  /// Removes the running window's disks that the edge zone reached (indices in `current`): `tied` ones tied to the
  /// workpiece, `loose` ones not, and rebuilds the window around the same edge (a rebuild: counted in rebuilds()).
  Simulation remove_at_edge(const Simulation& current, const std::vector<std::size_t>& tied,
                            const std::vector<std::size_t>& loose);
  std::size_t largest_window() const { return largest_window_; }
  /// The whole workpiece now, without changing anything: the running window's disks and joints as `current` (the
  /// window built last) has them, the others as the reservoir holds them. The window's held frame counts for
  /// nothing here: a disk is tied through the workpiece's own held rows (WorkpieceNow::tied).
  WorkpieceNow now(const Simulation& current) const;

  std::string serialize() const;
  static CutWindow deserialize(std::string_view bytes);

 private:
  /// The derived members below from the reservoir (and the window's disks).
  void index_reservoir();
  Simulation full_{Material{}, SimulationOptions{}};
  CutWindowBox box_;
  double y_top_m_ = 0, y_cut_m_ = 0;
  double x_built_m_ = 0;               ///< the edge's x when the window was last built
  double max_displacement_m_ = 0;      ///< largest |x - x0| of a disk written back (widens the reservoir search)
  std::vector<double> x0_;             ///< each disk's x in the uncut workpiece
  std::vector<std::uint8_t> removed_;  ///< per disk: removed as a chip (1), crushed (2), crushed tied (3),
                                       ///< by the edge zone tied (4) or loose (5)
  std::vector<std::int32_t> global_of_, bond_global_of_;  ///< the window's disks and joints in the workpiece
  ContactSprings springs_;                                ///< of the last sync, by workpiece index
  std::size_t rebuilds_ = 0, largest_window_ = 0;
  std::size_t cracks_synced_ = 0;  ///< the running window's cracks already moved to the workpiece's
  bool remove_loose_ = false;
  /// Marks removed every disk above the cut line not tied by bonded joints to a held disk.
  void remove_loose_fragments();
  // Derived from the above (not stored): the frame's width, the window's skin and the largest radius, disks
  // by x0, joints per disk.
  double frame_m_ = 0, skin_m_ = 0, r_max_m_ = 0;
  std::vector<std::int32_t> by_x0_, bond_start_, bond_list_;
  std::vector<std::int32_t> local_of_;  ///< per workpiece disk: its index in the window, or -1
};

}  // namespace kerf::dem
