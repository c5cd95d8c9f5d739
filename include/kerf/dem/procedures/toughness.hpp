#pragma once
// The fracture-toughness test (issue 37; docs/dem.md, "Fracture toughness"): a single-edge-notched beam (SENB) in
// three-point bending, span S = 4W (ASTM E399), loaded quasi-statically to fracture by a rigid roller at
// mid-span while two rigid rollers support it; the notch is a slot one disk wide (disks removed) from the
// tension face, depth a. The rollers are walls: arcs of short segments (rigid cylinders of radius r).
//
// Two independent measures of the toughness:
//   K_IC = P_max S / (B W^1.5) f(a/W)                         (Srawley 1976, Eq. 2; ASTM E399 A3.5.3)
//   G_c  = (W_ext - dU - dK) / (B (W - a))                   (energy books: the work the load roller did,
//                                                             less the change of what is stored and moving,
//                                                             per unit of new crack area, from the start to
//                                                             the sample the crack has crossed the ligament:
//                                                             a crack within 0.1 W or two disk diameters of
//                                                             the loaded face; later work goes into the hinge
//                                                             of the broken halves)
// and the work of fracture W_ext / (B (W - a)) (the load-deflection curve alone, all stored energy taken as
// released). Irwin's relation compares them: G = K^2 / E' (E' = E of the 2D model's in-plane response).
//
//   ToughnessSpec spec;                         // toughness_fields(): the scene's "toughness" section
//   ToughnessResult r = run_toughness_test(specimen_sim, spec);
//   r.fracture_toughness_Pa_sqrt_m, r.fracture_energy_J_per_m2
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/field_table.hpp"

namespace kerf::dem {

/// Span over depth of the SENB of ASTM E399 and of Srawley's geometry factor.
inline constexpr double kSenbSpanOverDepth = 4.0;
/// Overhang of the beam beyond each support, over the depth: the specimen is at least (4 + 2 x 0.1) W long
/// (ASTM E399: length at least 4.2 W).
inline constexpr double kSenbOverhangOverDepth = 0.1;

struct ToughnessSpec {
  double notch_depth_m = 0.2e-3;     ///< a, from the tension face
  double roller_radius_m = 0.05e-3;  ///< of the three rigid rollers
  double speed_m_per_s = 0.02;       ///< of the load roller (the supports stand still)
  double stop_fraction = 0.05;  ///< stop once the load has stayed below this fraction of the peak over a peak window
  double max_deflection_m = 20e-6;  ///< stop anyway at this load-point deflection
  /// K_IC from the peak of the load averaged over this much deflection (a centred moving average): the load on
  /// a rigid roller rings in an undamped glass, by tens of per cent of the load in a W = 1 mm beam.
  double peak_window_m = 0.1e-6;
  double youngs_modulus_Pa = 71e9;  ///< E' of the 2D model, for K^2 / E' (the glass's calibrated E)
  int sample_every_steps = 50;
  bool quasi_static_check = true;  ///< rerun at half the speed and report the change of the peak load
};

/// The "toughness" section's keys: notch_depth_mm, roller_radius_mm, speed_m_per_s, stop_fraction_of_peak,
/// max_deflection_um, peak_window_um, youngs_modulus_GPa, sample_every_steps, quasi_static_check.
const FieldTable<ToughnessSpec>& toughness_fields();

/// The keys a message about the test names: its own section's and those that size the beam (the toughness
/// scene's specimen; a calibration's calibration.toughness.beam_depth_mm and beam_length_mm).
struct ToughnessKeys {
  std::string section = "toughness";
  std::string depth = "specimen.height_mm", length = "specimen.width_mm";
};

/// The fields' own ranges and the relations between the test and its specimen: the notch shorter than the
/// depth W (a/W in [0.1, 0.8], with 4 disks of ligament at least), the span 4W longer than the notch and within
/// the beam (its length at least 4.2 W), the rollers smaller than W / 2. InputError names the key as `keys`
/// say ("toughness.notch_depth_mm", "specimen.width_mm").
void check_toughness_spec(const ToughnessSpec& spec, const SpecimenSpec& specimen, const ToughnessKeys& keys = {});

/// Srawley's geometry factor f(a/W) of the three-point-bend SENB with S = 4W (J. E. Srawley 1976, "Wide range
/// stress intensity factor expressions for ASTM E 399 standard fracture toughness specimens", Int. J. Fracture
/// 12, 475-476, Eq. 2; ASTM E399 A3.5.3): f(x) = 3 sqrt(x) [1.99 - x (1 - x)(2.15 - 3.93 x + 2.7 x^2)] /
/// [2 (1 + 2x)(1 - x)^1.5], within 0.5 % of the boundary-collocation values for 0 <= x < 1.
double senb_geometry_factor(double a_over_w);

/// K_I = P S / (B W^1.5) f(a/W) [Pa sqrt(m)] (Srawley 1976; ASTM E399 A3.5.3): load P [N], span S, thickness B,
/// depth W, notch a [m].
double senb_stress_intensity(double load_N, double span_m, double thickness_m, double depth_m, double notch_m);

struct ToughnessSample {
  double time_s, deflection_m, load_N;  ///< load-point deflection (the load roller's travel), load on it
                                        ///< (the mean over the sample's steps)
  double support_load_N;                ///< the two supports' reaction together (= load when quasi-static)
  double external_work_J;               ///< integral of the load over the deflection so far
  double stored_elastic_energy_J;       ///< Simulation::stored_elastic_energy (the rollers' contacts included)
  double kinetic_energy_J;
  int n_cracks;                ///< broken joint elements beyond the notch
  double smoothed_load_N = 0;  ///< the load averaged over peak_window_um about this deflection (at the end)
};

struct ToughnessResult {
  std::vector<ToughnessSample> curve;
  double peak_load_N = 0, deflection_at_peak_m = 0;  ///< of the smoothed load (K_IC's)
  double raw_peak_load_N = 0;                        ///< the largest sample's load, ringing included
  double depth_m = 0, length_m = 0, span_m = 0, thickness_m = 0, notch_m = 0;  ///< W, L, S, B, a (measured W)
  double notch_x_m = 0;                     ///< where the notch (and the load roller) is: mid-length
  double fracture_toughness_Pa_sqrt_m = 0;  ///< K_IC from the peak of the smoothed load
  double raw_peak_toughness_Pa_sqrt_m = 0;  ///< K from the raw peak (ringing included), for comparison
  double external_work_J = 0;               ///< W_ext, the load roller's work to the end
  double fracture_energy_J_per_m2 = 0;      ///< G_c: (W_ext - dU - dK) / (B (W - a)), start to broken through
  double crack_tip_y_m = -1e300;            ///< highest crack within W/2 of the notch's line
  int through_sample = -1;                  ///< the sample at which the crack had crossed the ligament; -1: never
  double work_of_fracture_J_per_m2 = 0;     ///< W_ext / (B (W - a)), to broken through
  double irwin_energy_J_per_m2 = 0;         ///< K_IC^2 / E'
  double speed_m_per_s = 0, time_step_s = 0, wall_time_s = 0;
  std::int64_t steps = 0;
  std::size_t n_particles = 0;
  int n_notch_disks = 0;           ///< disks removed to make the notch (a slot one disk wide)
  int n_notch_joints_retired = 0;  ///< joints still crossing the notch's line, retired
  std::string stop_reason;
};

/// A test in progress, advanced one sample at a time.
class ToughnessRun {
 public:
  /// Sets up the beam on a copy of `specimen` (its lower face the tension face): the notch (disks removed) at
  /// mid-length, the rollers (walls) touching it. InputError (naming "toughness.speed_m_per_s") if the run would take
  /// more than kMaxRunSteps.
  ToughnessRun(const Simulation& specimen, const ToughnessSpec& spec);
  /// Runs one sample interval; returns false once the test has stopped.
  bool advance();
  const Simulation& simulation() const { return sim_; }
  const ToughnessResult& result() const { return res_; }

 private:
  Simulation sim_;
  ToughnessSpec spec_;
  ToughnessResult res_;
  std::vector<int> load_walls_, support_walls_;
  double t0_ = 0, load_prev_ = 0;
  double low_since_m_ = -1;  ///< deflection since which the load has stayed below the stop fraction; -1: not
  double through_y_m_ = 0, crack_band_m_ = 0;  ///< where a crack counts as through the ligament
  std::size_t counted_ = 0;
  int n_cracks_ = 0;
  bool finished_ = false;
  double roller_force(const std::vector<int>& walls) const;
  void finish();
};

/// Runs one test on a copy of the specimen; `on_sample` after every sample.
ToughnessResult run_toughness_test(const Simulation& specimen, const ToughnessSpec& spec,
                                   const std::function<void(const Simulation&, const ToughnessSample&)>& on_sample = {},
                                   Simulation* final_state = nullptr);

}  // namespace kerf::dem
