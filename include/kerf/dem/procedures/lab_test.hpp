#pragma once
// The calibration tests of Yang et al. 2018, Section 3 (physics-dem.md section 3): direct tension (a row of
// particles at top and bottom as grips, moved apart) and unconfined compression (rigid platens moved
// together), each side at a constant speed, until the stress has fallen to a fraction of its peak.
// Stress = platen (grip) force / (width t); axial strain = relative displacement / initial height;
// lateral strain from the particles on the two sides (middle half of the height). E and nu are secant
// values at 50 % of the peak.
//
//   LoadingSpec load = read_loading_spec(reader, LabTest::compression);
//   LabTestResult res = run_lab_test(specimen_sim, load);
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/field_table.hpp"
#include "kerf/json_reader.hpp"

namespace kerf::dem {

enum class LabTest { tension, compression };
/// "tension", "compression".
const EnumNames<LabTest>& lab_test_names();

struct LoadingSpec {
  LabTest test = LabTest::compression;
  double speed_m_per_s = 0.05;  ///< of each platen (grip)
  double stop_fraction = 0.7;   ///< stop when the stress falls below this fraction of the peak
  double max_strain = 0.02;     ///< stop anyway at this axial strain
  int sample_every_steps = 50;
  bool quasi_static_check = true;  ///< rerun at half the speed and report the change of the peak
};

/// The "loading" section's keys: speed_m_per_s, stop_fraction_of_peak, max_strain, sample_every_steps,
/// quasi_static_check.
const FieldTable<LoadingSpec>& loading_fields();
/// Reads the "loading" object (max_strain defaults to 0.005 in tension).
LoadingSpec read_loading_spec(ObjectReader& reader, LabTest test);

struct CurveSample {
  double time_s, axial_strain, lateral_strain, stress_Pa;  ///< strain and stress positive in the loading sense
  int n_tension_cracks, n_shear_cracks;
};

struct LabTestResult {
  LabTest test = LabTest::compression;
  std::vector<CurveSample> curve;
  double peak_stress_Pa = 0, strain_at_peak = 0;
  double youngs_modulus_Pa = 0, poissons_ratio = 0;  ///< secant at 50 % of the peak
  double width_m = 0, height_m = 0, speed_m_per_s = 0;
  std::int64_t steps = 0;
  double time_step_s = 0, wall_time_s = 0;
  std::size_t n_particles = 0;
  std::string stop_reason;
};

/// A test in progress, advanced one sample at a time; it can be saved and restored (checkpoints) with
/// bit-identical continuation.
class LabTestRun {
 public:
  LabTestRun(const Simulation& specimen, const LoadingSpec& spec);
  /// Runs one sample interval; returns false once the test has stopped.
  bool advance();
  bool finished() const { return finished_; }
  const Simulation& simulation() const { return sim_; }
  Simulation& simulation() { return sim_; }
  const LoadingSpec& spec() const { return spec_; }
  /// The result so far (E and nu filled in once finished).
  const LabTestResult& result() const { return res_; }
  std::string serialize() const;
  static LabTestRun deserialize(std::string_view bytes);

 private:
  LabTestRun() : sim_(Material{}, SimulationOptions{}) {}
  Simulation sim_;
  LoadingSpec spec_;
  LabTestResult res_;
  std::vector<std::int64_t> left_, right_;
  double side0_ = 0, t0_ = 0;
  std::int64_t counted_ = 0;
  int n_tension_ = 0, n_shear_ = 0;
  bool finished_ = false;
  double side_distance() const;
  /// The checkpoint's fields before the engine state, in order: io(field...) writes or reads them.
  template <class Self, class Io>
  static void state_fields(Self& run, Io& io);
};

/// Runs one test on a copy of the specimen. `on_sample(sim, sample)` is called after every sample (for
/// frames and progress); `sim` is the simulation at that moment.
LabTestResult run_lab_test(const Simulation& specimen, const LoadingSpec& spec,
                           const std::function<void(const Simulation&, const CurveSample&)>& on_sample = {},
                           Simulation* final_state = nullptr);

/// Secant modulus and Poisson's ratio at `fraction` of the peak, interpolated on the rising branch.
void secant_properties(LabTestResult& result, double fraction = 0.5);

}  // namespace kerf::dem
