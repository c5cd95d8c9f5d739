#pragma once
// Orthogonal cutting of a bonded-particle workpiece (Yang et al. 2018, Section 4; physics-dem.md section 4).
//
// The workpiece is a specimen whose left and bottom boundary disks are held (a prescribed-zero-velocity
// group, as the tension grips use) and whose top is free. The tool is rigid: wall segments (rake face,
// optional edge rounding, clearance face, a closing back face) whose lowest point lies `depth_of_cut`
// below the top surface. It starts with its leading edge just right of the workpiece and moves in -x at
// the cutting speed over `length`, so the chip flows up its rake face and the material is pushed towards the held left
// side. Micro-grooves across the cut path are made as in the paper, by deleting the disks whose centres lie inside each
// groove's outline (rectangular, or the inverted trapezoid of the real laser grooves).
//
// Sign convention (tested): main force = force the tool exerts on the workpiece along the cutting
// direction (-x), thrust force = force the tool exerts on the workpiece into it (-y). A tool pushing into
// material has positive main and thrust forces.
//
//   CutParams params = read_cut_params(root);        // the "cut", "tool" and "grooves" objects
//   CutRun run(specimen, params);
//   while (run.advance()) {}
//   CutResult res = run.result();
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/procedures/cut_window.hpp"
#include "kerf/field_table.hpp"
#include "kerf/json_reader.hpp"

namespace kerf::dem {

enum class GrooveShape { none, rectangular, trapezoidal };
/// "none", "rectangular", "trapezoidal" (the inverted trapezoid of the real laser grooves).
const EnumNames<GrooveShape>& groove_shape_names();

/// How a cut represents the grooves' laser-affected layer (CutParams::Grooves::damage_model).
enum class GrooveDamageModel { broken_joints, edge_zone };
/// "broken_joints" (the joints within the layer pre-broken), "edge_zone" (a layer below the disks' scale).
const EnumNames<GrooveDamageModel>& groove_damage_model_names();

/// Where the edge zone's lateral crack runs (CutParams::EdgeZone::lateral_crack).
enum class LateralCrack { none, whole_cut_line, ahead_of_edge };
/// "none", "whole_cut_line" (every joint across the cut line broken before the cut: the bound), "ahead_of_edge" (the
/// joints across the cut line within lateral_crack_length_m ahead of the tip broken as the tool advances).
const EnumNames<LateralCrack>& lateral_crack_names();

/// The cut's parameters, one struct per scene section (its keys in that section's field table: cut_fields(),
/// tool_fields(), ...), in SI.
struct CutParams {
  /// Section "cut": the tool's motion and the force samples.
  struct Cut {
    double depth_of_cut_m = 0.1e-3;
    double speed_m_per_s = 1.0;  ///< the paper's 4.23 mm/s is scaled up (physics-dem.md section 4)
    double length_m = 0.5e-3;    ///< tool travel
    /// Part of the travel excluded from the mean forces (the entry), as a fraction of the travel.
    double entry_fraction = 0.25;
    int sample_every_steps = 50;
    /// Report only: CutResult::travel_windows, mean forces per stretch of travel of this length (steadiness).
    double window_m = 0.1e-3;
    /// An absorbing layer along the workpiece's held rows (its left side and bottom, as rigid as the window's
    /// frame), with or without a window: its thickness in depths of cut (0: none), the attenuation
    /// ActiveWindow::absorbing_attenuation.
    double held_absorbing_depths = 0;
  };
  /// Section "tool".
  struct Tool {
    double rake_deg = -15, clearance_deg = 15;  ///< Yang et al. 2018, Section 4
    double edge_radius_m = 0;                   ///< 0: sharp edge
    int edge_segments = 4;                      ///< wall segments approximating a rounded edge
    /// Tool-workpiece Coulomb friction on every tool face; negative (the default): the workpiece material's
    /// particle friction mu, as for any disk-wall contact (PFC's default). Not given by Yang et al. 2018.
    double friction_coefficient = -1;
    /// Height of the rake face's top above the tool tip; 0 (the default): 3 depths of cut, room for the chip.
    /// Yang et al. 2018 does not give its tool's size: a fixed height is one tool for every depth of cut.
    double rake_face_height_m = 0;
  };
  /// Section "grooves".
  struct Grooves {
    GrooveShape shape = GrooveShape::none;
    double depth_m = 0.1e-3, pitch_m = 0.2e-3, width_m = 0.06e-3;
    double bottom_width_m = 0.03e-3;  ///< trapezoidal only: width at the groove bottom
    /// The laser-affected layer along each groove's walls and bottom: its depth (0, the default: pristine glass up
    /// to the groove, as Yang et al. 2018's DEM) and how the cut represents it (damage_model). broken_joints (the
    /// default): joints whose midpoint lies within this distance of the groove's outline are pre-broken, each with
    /// probability damage_broken_fraction (apply_groove_damage). edge_zone, for a layer thinner than the disks
    /// (docs/physics-glass-edge.md section 4: a few um): the joints are kept, and the edge zone's force is off
    /// while the cut line at the tool's tip lies within the layer (in_groove_layer): the edge meets laser-damaged
    /// glass there, not an intact layer to cut (a bound: no force at all on that glass).
    double damage_depth_m = 0;
    double damage_broken_fraction = 1;
    GrooveDamageModel damage_model = GrooveDamageModel::broken_joints;
  };
  /// Section "active_window": the active window of a steady-state cut (kerf/dem/procedures/cut_window.hpp): off,
  /// every disk of the workpiece is integrated. Extents in depths of cut around the cutting edge.
  struct ActiveWindow {
    bool enabled = false;
    /// Defaults: the smallest window whose steady forces agreed with the whole workpiece's within their standard
    /// errors with local damping 0.7 (one packing); undamped they do not (80 % more main force on four packings):
    /// docs/dem.md, "Steady-state cuts".
    double ahead_depths = 7, behind_depths = 3, below_depths = 4, above_depths = 4;
    double shift_depths = 0.25;  ///< tool travel between two rebuilds of the window
    /// The absorbing layer inside the window's ahead, behind and lower edges (kerf/dem/procedures/cut_window.hpp),
    /// its thickness L in depths of cut (0: none), and the e-folds by which it attenuates a p-wave's amplitude on
    /// its way through the layer and back: the peak rate 3 a c / L, with c = sqrt(E* / rho) of the contact law.
    double absorbing_depths = 0, absorbing_attenuation = 2;
    /// A bound, not a model of glass (issue 41 item 4): at each rebuild of the window, remove every disk above the
    /// cut line that no intact joint path ties to the workpiece's held rows (CutWindow::set_remove_loose_fragments),
    /// as if every loose fragment left the plane at once and the tool met none of them again.
    bool remove_loose_fragments = false;
    /// Debris grains that crush (issue 41 item 4; 0, the default: a disk never breaks). A disk of a loose fragment
    /// (no intact joint path to the held rows) pressed by a tool face with a normal force above its splitting load,
    /// F = pi sigma r t (a cylinder of radius r and length t under two opposite line loads splits when
    /// 2 F / (pi 2r t) reaches sigma: the Brazilian test), is crushed: removed at once, its energy leaves with it.
    /// Without it a single loose disk wedged under the tool's tip carries up to ~100 N per mm of width
    /// (docs/notes/2026-11-29-jams.md). Checked at each force sample; windowed cuts only.
    double grain_strength_Pa = 0;
    /// The workpiece's own disks that crush (issue 41 item 4; 0, the default: a disk tied to the workpiece breaks
    /// only by its joints). The same law for a disk still tied to the held rows: pressed by a tool face above
    /// pi sigma r t, it is removed at once, its intact joints with it. A flat joint never fails in compression, so a
    /// disk of the cut line pressed by the tool's tip carries what the lattice behind it does (jams of 50-130 N per
    /// mm of width at every disk size measured: docs/notes/2026-11-29-jams.md); glass under a sharp tip is crushed
    /// at the scale below a disk. Checked at each force sample; windowed cuts only.
    double tied_grain_strength_Pa = 0;
  };
  /// Section "edge_zone" (issue 54 item 4; windowed cuts only; off by default): the tool's edge as a sub-grid
  /// model. Glass at the cut line meets the edge through a ductile layer about d_c thick, 100-300 times below the
  /// disks (docs/physics-glass-edge.md), whose force per unit width comes from the analytic side
  /// (kerf::edge_force_per_width: the layer lambda d_c cut at the tool's rake with friction mu). Within `radius_m`
  /// of the tip (0: the workpiece's largest disk diameter): while a disk tied to the workpiece straddles the cut
  /// line there (the intact glass the edge meets), the tool carries the layer's force and those disks its
  /// reaction; a disk reaching below the cut line that the tool touches there leaves the model as the layer's chip
  /// and powder (tied or loose alike: a rigid 20 um grain at the edge is the jams' artefact).
  struct EdgeZone {
    bool enabled = false;
    double radius_m = 0;                ///< the cut resolves 0 to the largest diameter when it starts
    double layer_factor = 1;            ///< lambda = l / d_c (physics-glass-edge.md section 4: d_c)
    double friction_coefficient = 0.3;  ///< tool on glass at the edge (section 4: 0.15-0.4)
    /// The layer's force per unit width [N/m], cutting and thrust; negative (the default): the cut kind computes
    /// them from the material and the tool (kerf::edge_force_per_width) before the run starts.
    double cutting_force_N_per_m = -1, thrust_force_N_per_m = -1;
    /// The lateral crack under the edge (issue 54 item 3, design 2: docs/notes/2026-12-07-edge-zone-steady-stage-1.md).
    /// In glass the lateral cracks start at the base of the plastic zone under a sharp contact, a few um below it
    /// (Marshall, Lawn & Evans 1982), and run parallel to the surface: at the disks' scale, along the cut line. Their
    /// length per unit line load has no source here, so it is a parameter: ahead_of_edge breaks, at each force
    /// sample, the joints across the cut line between the tip and lateral_crack_length_m ahead of it
    /// (break_cut_line_ahead), a crack that runs that far ahead of the edge; whole_cut_line breaks every joint across
    /// the cut line before the cut (separate_cut_line), the bound of a crack without end. none (the default): the
    /// cracks start where the lattice starts them.
    LateralCrack lateral_crack = LateralCrack::none;
    double lateral_crack_length_m = 0;
  };

  Cut cut;
  Tool tool;
  Grooves grooves;
  ActiveWindow window;
  EdgeZone edge_zone;
};

/// The keys of the scene's "cut", "tool", "grooves", "active_window" and "edge_zone" sections
/// (kerf/field_table.hpp), each of its section's struct.
const FieldTable<CutParams::Cut>& cut_fields();
const FieldTable<CutParams::Tool>& tool_fields();
const FieldTable<CutParams::Grooves>& groove_fields();
const FieldTable<CutParams::ActiveWindow>& active_window_fields();
const FieldTable<CutParams::EdgeZone>& edge_zone_fields();

/// Checks every field's range and the cross-field constraints (groove narrower than its pitch, trapezoid bottom
/// narrower than its top, the tool's wedge angle positive ...); InputError names the dotted key, value and expectation.
void validate_cut_params(const CutParams& params);
/// The active window's box and the absorbing layers' thicknesses in metres (each extent in depths of cut times
/// the depth of cut): the one place they are converted. The layers' rates need the material's wave speed and
/// the held rows the workpiece: CutRun sets those.
CutWindowBox window_box_m(const CutParams& params);

/// Reads the "cut" object (depth_of_cut_mm, speed_m_per_s, length_mm, entry_fraction,
/// sample_every_steps, window_mm), the optional "tool" (rake_deg, clearance_deg, edge_radius_um, edge_segments,
/// friction_coefficient, rake_face_height_mm)
/// and "grooves" (shape, depth_mm, pitch_mm, width_mm, bottom_width_mm) objects of a scene, then validates.
CutParams read_cut_params(ObjectReader& root);
Json cut_params_to_json(const CutParams& params);

// --- pure geometry ---

/// Whether a point `dx` from a groove's centre line and `depth` below the top surface lies inside the
/// groove's outline (depth in [0, groove depth]; half-width linear in depth for a trapezoid).
bool inside_groove_outline(const CutParams& params, double dx_m, double depth_m);
/// Centres of the grooves across the top surface: the first half a pitch left of the right edge, then every
/// pitch, as long as the groove lies right of `x_left_m` (whatever the tool's travel).
std::vector<double> groove_centres(const CutParams& params, double x_left_m, double x_right_m);
/// Whether (x, y) lies inside any groove of a workpiece with top surface at `y_top_m`.
bool inside_any_groove(const CutParams& params, const std::vector<double>& centres, double y_top_m, double x_m,
                       double y_m);
/// Whether (x, y) lies within params.grooves.damage_depth_m of any groove's walls or bottom (its laser-affected
/// layer; inside the groove included); false without a layer.
bool in_groove_layer(const CutParams& params, const std::vector<double>& centres, double y_top_m, double x_m,
                     double y_m);

/// The tool outline, a closed polygon: rake-face top, the edge (the sharp tip, or the arc points of a
/// rounded edge), the clearance-face end; segment k joins vertex k to vertex k + 1 (mod n), so the last
/// one is the back face. Placed with its lowest point at height `y_tip_m` and its front-most (smallest x)
/// point at `x_front_m`.
std::vector<std::array<double, 2>> tool_outline(const CutParams& params, double x_front_m, double y_tip_m);

/// The left-most x of the outline's edges within the band y0 <= y <= y1 (the part of the tool that meets
/// the workpiece first when the band spans the cut line to the top surface); +inf if none.
double leading_x_in_band(const std::vector<std::array<double, 2>>& outline, double y0_m, double y1_m);

// --- running ---

struct CutSample {
  double travel_m, time_s, main_force_N, thrust_force_N;  ///< forces averaged over the sample interval
};

struct CutCrackCounts {
  int tensile = 0, shear = 0, chip = 0, subsurface = 0;
  double subsurface_damage_depth_m = 0;  ///< deepest subsurface crack below the cut line
  /// Subsurface cracks under the surface machined during the steady part of the cut (CutResult::
  /// steady_machined_x_m), and the deepest of them: the damage the steady cut leaves in the part. The
  /// whole workpiece's depth above is often a breakout of its free corner at the entry (docs/dem.md).
  int subsurface_steady = 0;
  double subsurface_steady_damage_depth_m = 0;
  /// The depth above which 95 % of those steady subsurface cracks lie (nearest rank; 0 without any): unlike the
  /// deepest one, not set by a sparse tail that reaches the active window's floor (docs/dem.md).
  double subsurface_steady_damage_depth_p95_m = 0;
};

/// What a windowed cut integrated and removed (all zero without an active window).
struct CutWindowReport {
  std::size_t rebuilds = 0, largest_window_particles = 0;
  ChipAccount chips;
};

/// "chip" above the cut line (y > surface - depth of cut), else "subsurface".
inline bool is_chip_crack(double y_m, double y_cut_m) {
  return y_m > y_cut_m;
}
inline const char* crack_place(double y_m, double y_cut_m) {
  return is_chip_crack(y_m, y_cut_m) ? "chip" : "subsurface";
}
/// Counts by mode and place; `steady_x_m` = {from, to} is the span of x machined during the steady part.
CutCrackCounts count_cut_cracks(const std::vector<CrackEvent>& cracks, double y_cut_m,
                                std::array<double, 2> steady_x_m);

/// The mean forces over one stretch of the tool's travel, [from, to).
struct TravelWindow {
  double from_m = 0, to_m = 0;
  double main_force_N = 0, thrust_force_N = 0;
  int n_samples = 0;
};

/// What the tool's edge meets (issue 54 item 2), observed once per kEdgeObserveTravelM of the tool's travel over the
/// steady part (the travel of the mean forces). "Tied": a disk that a path of joints with a bonded element ties to
/// the workpiece's held rows (its fixed left side and bottom), through the whole workpiece (WorkpieceNow); "loose":
/// any other disk still in the workpiece (a fragment, however large, that no intact joint holds to the base).
inline constexpr double kEdgeObserveTravelM = 5e-6;
/// The edge: the tool's boundary within this distance of its tip (the front-most lowest point).
inline constexpr double kEdgeZoneM = 25e-6;
/// The stretches of the cut line where the tied share is read: this far ahead of the tip (-x, towards the uncut
/// glass) and as far behind it (the machined surface), [from, to).
inline constexpr std::array<double, 2> kTiedStretchM{0.05e-3, 0.3e-3};
/// The depth bands below the cut line of the tied share (disk centres), [from, to): 0-25, 25-50, 50-100 um.
inline constexpr std::array<double, 4> kTiedBandDepthM{0, 25e-6, 50e-6, 100e-6};

/// The tool's cutting edge: the front-most (smallest x) of the lowest end points of the walls [first_tool_wall,
/// + n_tool_walls) of `sim` (a flat clearance face has two lowest points) {x, y}.
std::array<double, 2> tool_edge(const Simulation& sim, std::int32_t first_tool_wall, std::int32_t n_tool_walls);

/// The disks touching one of the tool's walls [first_tool_wall, + n_tool_walls) at a contact point (the wall's
/// closest point to the disk's centre) within `reach_m` of the tip, in the order of the wall contacts (a disk
/// touching two walls there, twice).
std::vector<std::size_t> tool_contacts_near(const Simulation& sim, std::int32_t first_tool_wall,
                                            std::int32_t n_tool_walls, std::array<double, 2> tip_m, double reach_m);

/// What the edge touches at one moment: a tied disk if any, else a loose one if any, else nothing.
enum class EdgeMeets { nothing, loose, tied };
/// The disks whose contact with one of the tool's walls [first_tool_wall, + n_tool_walls) lies within kEdgeZoneM
/// of the tip (the closest point of the wall to the disk's centre, the contact's point), touching (positive
/// overlap); `tied` one flag per disk of `sim`.
EdgeMeets edge_meets(const Simulation& sim, std::int32_t first_tool_wall, std::int32_t n_tool_walls,
                     std::array<double, 2> tip_m, const std::vector<std::uint8_t>& tied);

/// Disk counts per stretch (0 ahead, 1 behind) and depth band (kTiedBandDepthM), and how many of them are tied.
struct TiedProfile {
  std::array<std::array<std::int64_t, 3>, 2> disks{}, tied{};
};
/// Adds the present disks of `now` whose centres lie in the stretches ahead of and behind the tip `tip_m`
/// (kTiedStretchM along x, the tool moving in -x) and in the bands below the cut line `y_cut_m`.
void add_tied_profile(const WorkpieceNow& now, std::array<double, 2> tip_m, double y_cut_m, TiedProfile& into);

/// The edge zone's disks at one moment (CutParams::edge_zone; indices of `sim`): those the edge has reached (a disk
/// with a contact with one of the tool's walls within `reach_m` of the tip, free, reaching below the cut line:
/// y - r < y_cut), tied or loose, and the footprint of the layer's reaction (free tied disks not reached that
/// straddle the cut line, |y - y_cut| < r, with part of the disk ahead of the tip, x - r < x_tip, and their centre
/// within reach_m + r of it). Sorted. "Tied" here is local: joined through intact joints to a held disk or to a disk
/// more than `bulk_depth_m` below the cut line (the whole workpiece's test, CutWindow::now, costs a sample's steps).
struct EdgeZoneSets {
  std::vector<std::size_t> reached_tied, reached_loose, footprint;
};
EdgeZoneSets edge_zone_sets(const Simulation& sim, std::int32_t first_tool_wall, std::int32_t n_tool_walls,
                            std::array<double, 2> tip_m, double y_cut_m, double reach_m, double bulk_depth_m);
/// The edge zone's bulk: glass joined to a disk this many zone reaches below the cut line is tied.
inline constexpr double kEdgeZoneBulkReaches = 5;

/// The steady part's observations of the edge (a plain record of counts: stored in the cut's checkpoints).
struct CutEdgeRecord {
  std::int64_t observations = 0, touches_tied = 0, touches_loose = 0;  ///< the rest touched nothing
  TiedProfile profile;
};

/// The edge zone over the steady part (CutParams::edge_zone; a plain record, stored in the cut's checkpoints): the
/// samples, those in which the edge met intact glass (and carried the layer's force), and the energy over the
/// energy books' steady part: the tool's work on the layer, and the reaction's work on the disks (what the DEM
/// received; the rest, the layer's own, is dissipated in it, and counted in CutEnergy::dissipated_J).
struct CutEdgeZoneRecord {
  std::int64_t samples = 0, intact_samples = 0;
  double tool_work_J = 0, reaction_work_J = 0;
};

/// Where the tool's work goes, booked as a cut runs (issue 41 item 4). The integrated disks (the whole workpiece,
/// or the active window) gain the tool's work and lose it three ways: dissipated among them (Coulomb friction,
/// the energy each broken joint element held, the absorbing layers, the integrator's error), and, in a windowed
/// cut, the kinetic and the strain energy of the disks that leave the integration when the window moves on
/// (removed chips, disks frozen into the frame or the reservoir), less what joining disks bring. Running totals
/// and the integrated disks' energies at one moment (Simulation::kinetic_energy; strain:
/// Simulation::stored_elastic_energy, the tool's contacts included).
struct CutEnergyBooks {
  double tool_work_J = 0, left_kinetic_J = 0, left_strain_J = 0;
  double kinetic_J = 0, strain_J = 0;
};

/// The books over the steady part (the same travel as the mean forces): what each took, and the balance
/// dissipated = tool work - left kinetic - left strain - (kinetic + strain at the end - at the steady start).
struct CutEnergy {
  double tool_work_J = 0, dissipated_J = 0, left_kinetic_J = 0, left_strain_J = 0, stored_change_J = 0;
};

struct CutResult {
  std::vector<CutSample> samples;
  double main_force_N = 0, thrust_force_N = 0, main_force_std_N = 0, thrust_force_std_N = 0;  ///< steady part
  /// Standard errors of the steady means (kerf/time_series.hpp): batch means when the steady part holds
  /// kMinBatches batches of 5 g samples, else from the autocorrelation (methods named); the statistical
  /// inefficiency g (samples) and the batch length of each.
  double main_force_sem_N = 0, thrust_force_sem_N = 0;
  const char *main_force_sem_method = "none", *thrust_force_sem_method = "none";
  double main_force_inefficiency = 1, thrust_force_inefficiency = 1;
  std::size_t main_force_batch_samples = 1, thrust_force_batch_samples = 1;
  int n_steady_samples = 0;
  /// Share of the steady samples with the tool in contact (main force > 0): an intermittent cut's duty cycle.
  double contact_share = 0;
  /// The travel the means cover, from the end of the entry (entry_fraction x length) to the last sample.
  double steady_from_travel_m = 0, steady_to_travel_m = 0;
  /// Whether the means are those of a steady cut (steady_statistics): they start after kEntryTravelM and both
  /// have a standard error; if not, why (one line for the log and summary.json).
  bool steady = false;
  std::string not_steady_reason;
  std::vector<TravelWindow> travel_windows;  ///< mean forces per params.cut.window_m of travel (once finished)
  CutCrackCounts cracks;
  double y_top_m = 0, y_cut_m = 0, width_m = 0;  ///< width = out-of-plane thickness
  std::array<double, 4> workpiece_box_m{};       ///< x_min, x_max, y_min, y_max before the cut
  /// x span {from, to} of the surface the tool's cutting edge (its front-most lowest point) machined
  /// during the steady part, from its position at the end of the entry to its final one (once finished).
  std::array<double, 2> steady_machined_x_m{};
  std::size_t n_particles = 0, n_removed_by_grooves = 0;  ///< the workpiece's
  /// Joints within the grooves' laser-affected layer, and those of them broken before the cut (known at the
  /// start only: a checkpoint holds the joints themselves, not these counts).
  std::array<std::size_t, 2> groove_damage_joints{};
  /// Joints across the cut line broken before the cut (separate_cut_line; known at the start only, as above).
  std::size_t cut_line_joints_broken = 0;
  std::int64_t steps = 0;
  /// Disks integrated times steps, over the cut (a windowed cut integrates its window only).
  double particle_steps = 0;
  CutWindowReport window;
  double time_step_s = 0, wall_time_s = 0;
  /// The energy books over the steady part (once finished): booked only by a cut that ran from its start
  /// under a kerf that keeps them (a cut resumed from an older checkpoint has none).
  bool energy_booked = false;
  CutEnergy energy;
  /// What the edge met over the steady part (once finished): recorded only by a cut that ran from its start under
  /// a kerf that records it (a cut resumed from an older checkpoint has none).
  bool edge_recorded = false;
  CutEdgeRecord edge;
  /// The edge zone's steady record (CutParams::edge_zone; zero when off).
  CutEdgeZoneRecord edge_zone;
};

/// {main, thrust} from the force the disks exert on the tool (cutting direction -x): main = F_x, thrust = F_y.
inline std::array<double, 2> tool_force_components(double fx_on_tool_N, double fy_on_tool_N) {
  return {fx_on_tool_N, fy_on_tool_N};
}

/// The travel before a cut's forces are steady: the entry at the free edge. Measured on the Yang et al. 2018 workpiece
/// (1 mm x 1 mm, cuts 0.1 mm deep: the main force over the first 0.3 mm of travel is half that over the next
/// 0.3 mm, in each packing; docs/dem.md, "How long a cut must be"); means that start earlier hold the entry.
inline constexpr double kEntryTravelM = 0.3e-3;

/// Mean and (population) standard deviation of main and thrust forces over samples with travel >= from, the
/// standard errors of the means by batch means, the travel they cover, and whether they are steady: not when
/// they start before kEntryTravelM, hold no sample, or a standard error cannot be computed (too few samples).
void steady_statistics(CutResult& result, double from_travel_m);

/// The travel [0, length] cut into consecutive windows of `window_m` (the last one shorter when the length
/// is not a multiple of it, and holding every sample at or beyond `length`), with the mean forces in each.
/// Windows whose means differ beyond the scatter show a cut that is not steady: the entry at the free
/// edge, or a tool that has come near the held side.
std::vector<TravelWindow> travel_window_means(const std::vector<CutSample>& samples, double length_m, double window_m);

/// Distance from a point `dx` from a groove's centre line and `depth` below the top surface to the groove's
/// walls and bottom (0 inside the outline; the top surface is not part of it).
double distance_to_groove_outline(const CutParams& params, double dx_m, double depth_m);

/// The laser-affected layer of a grooved workpiece cut from a specimen of box {x_min, x_max, y_min, y_max}
/// (the grooves' places: groove_centres, below y_max): breaks every element of
/// the joints whose midpoint lies within params.grooves.damage_depth_m of a groove's walls or bottom, each
/// joint with probability params.grooves.damage_broken_fraction (a hash of the joint's index: the same joints
/// for the same packing). A broken element carries compression and friction (a closed micro-crack), no
/// tension (ultrashort laser pulses leave micro-cracks around what they modify in glass: Werr et al. 2022,
/// docs/references.md). Returns {joints in the layer, joints broken}.
std::array<std::size_t, 2> apply_groove_damage(Simulation& workpiece, const CutParams& params,
                                               const std::array<double, 4>& box_m);

/// The bound of the edge zone's lateral crack (CutParams::EdgeZone::lateral_crack whole_cut_line): breaks every
/// element of the joints that cross the cut line y = y_cut_m (their disks' centres on either side of it), so that the
/// glass above the cut line is joined to the glass below by no joint. A broken element carries compression and
/// friction, no tension, as the grooves' layer (apply_groove_damage). Returns the joints broken.
std::size_t separate_cut_line(Simulation& workpiece, double y_cut_m);
/// The edge zone's lateral crack ahead of the edge (CutParams::EdgeZone::lateral_crack ahead_of_edge): breaks, through
/// the engine's break (Simulation::break_bond: a crack event per element, in tension), the joints across the cut line
/// y = y_cut_m whose crossing (the line between their disks' centres) lies within length_m ahead of the tip at
/// tip_x_m (the tool moves in -x: from tip_x_m - length_m to tip_x_m). Returns the joints broken.
std::size_t break_cut_line_ahead(Simulation& sim, double y_cut_m, double tip_x_m, double length_m);

/// The workpiece: the specimen without the groove disks, left and bottom boundary disks held (group 1).
/// CutRun then breaks the grooves' laser-affected layer (apply_groove_damage).
Simulation make_workpiece(const Simulation& specimen, const CutParams& params, std::size_t& n_removed);

/// A cut in progress, advanced one sample at a time.
class CutRun {
 public:
  CutRun(const Simulation& specimen, const CutParams& params);
  /// Runs one sample interval; returns false once the tool has travelled `length`.
  bool advance();
  bool finished() const { return finished_; }
  /// The simulation that runs: the whole workpiece, or the active window of a windowed cut.
  const Simulation& simulation() const { return sim_; }
  /// The whole workpiece (a windowed cut's as of its last rebuild, and whole once finished, its removed
  /// chips left out), for pictures.
  Simulation workpiece() const { return window_ ? window_->machined_workpiece() : sim_; }
  /// The active window (null without one).
  const CutWindow* window() const { return window_ ? &*window_ : nullptr; }
  /// Every crack of the cut (a windowed cut's as of its last rebuild, and all once finished).
  const std::vector<CrackEvent>& cracks() const { return window_ ? window_->cracks() : sim_.cracks(); }
  /// Cracks so far, the running window's included.
  std::size_t n_cracks() const;
  const CutParams& params() const { return params_; }
  /// The result so far (steady statistics and crack counts filled in once finished).
  const CutResult& result() const { return res_; }
  /// The complete state (checkpoints): restoring it and running on equals the uninterrupted run.
  std::string serialize() const;
  static CutRun deserialize(std::string_view bytes);

 private:
  CutRun() : sim_(Material{}, SimulationOptions{}) {}
  Simulation sim_;
  std::optional<CutWindow> window_;
  CutParams params_;
  CutResult res_;
  std::int32_t first_tool_wall_ = 0, n_tool_walls_ = 0;
  /// Crushes the disks the tool presses beyond their splitting load: loose ones at CutParams::
  /// window_grain_strength_Pa, those tied to the workpiece at window_tied_grain_strength_Pa (each 0: never).
  void crush_grains();
  /// Runs `next` (a window built from the running one) in its place, booking what leaves with the disks it drops.
  void take_window(Simulation next);
  double t0_ = 0;
  bool finished_ = false;
  /// The energy books: running (tool work, left), and at the steady part's start (its first sample).
  bool books_kept_ = true, steady_booked_ = false;
  CutEnergyBooks books_, books_steady_start_;
  /// The running books with the integrated disks' energies now.
  CutEnergyBooks books_now() const;
  void finish();
  /// The cutting edge: the front-most of the tool's lowest points (a flat clearance face has two) {x, y}.
  std::array<double, 2> edge() const;
  /// The checkpoint's fields before the engine state, in order: io(field...) writes or reads them.
  template <class Self, class Io>
  static void state_fields(Self& run, Io& io);
  /// The energy books' fields, after the engine state (KERFCUT9), then the edge's record (KERFCUTA).
  template <class Self, class Io>
  static void book_fields(Self& run, Io& io);
  template <class Self, class Io>
  static void edge_fields(Self& run, Io& io);
  /// The edge's record: kept from the start (else none), the last observation's travel in kEdgeObserveTravelM.
  bool edge_kept_ = true;
  std::int64_t edge_last_step_ = -1;
  /// Observes what the edge meets now and the tied profile around it (res_.edge).
  void observe_edge();
  /// Per disk of the running simulation: tied to the workpiece's held rows through the whole workpiece.
  std::vector<std::uint8_t> tied_of(const WorkpieceNow& now) const;
  /// The edge zone at a sample's start: removes the disks the edge has reached, then finds the intact glass it
  /// meets and loads it with the layer's reaction (Simulation::set_disk_loads); returns whether it met any.
  bool edge_zone_begin_sample();
  /// The reaction's work over a sample on the loaded disks that were at `start_m` when it began.
  double edge_zone_reaction_work_J(const std::vector<std::array<double, 2>>& start_m) const;
  template <class Self, class Io>
  static void zone_record_fields(Self& run, Io& io);
};

/// A cut's forces.csv: "tool_travel_mm,time_s,cutting_force_N,thrust_force_N,cutting_force_N_per_mm,
/// thrust_force_N_per_mm,main_force_N", one row per sample; the forces over the cut's width (the specimen's
/// thickness), the _per_mm ones divided by it; main_force_N, the cutting force's old name, is deprecated (removed in
/// 0.3.0). The header and one row, as cut_forces_csv writes them (a running cut's file grows by whole rows).
std::string cut_forces_csv(const CutResult& result);
std::string cut_forces_csv_header();
std::string cut_forces_csv_row(const CutSample& sample, double width_m);

}  // namespace kerf::dem
