#pragma once
// Bonded-particle specimen genesis (physics-dem.md section 2) and its saved form.
//
// Random packing, in two parts. The compaction does not depend on the material: disks with radii uniform in
// [R_min, R_max] placed at random in a walled vessel at half size, grown to their full size through a
// frictionless reference linear contact (E* = compaction_modulus), then servo-controlled (a common radius
// scale) to a low isotropic pressure; floaters (< 3 contacts) are enlarged a little. The finish is the
// material's: joints of its law at every pair closer than the installation gap, the walls removed, the
// specimen relaxed with the material's contact law, friction and damping. One spec and seed give one
// packing whatever the material, so a calibration can evaluate each candidate on exactly the specimen a scene
// with that material builds (SpecimenSource).
// Hexagonal packing: equal disks of radius (R_min + R_max) / 2 on a triangular lattice, every touching
// pair jointed (closed-form elastic constants, for verification).
//
//   SpecimenSpec spec = read_specimen_spec(specimen_reader);  // the scene's "specimen" object
//   SpecimenReport report;
//   Simulation sim = make_specimen(material, spec, report);  // = finish_specimen(compact_packing(spec), ...)
//   save_specimen("out/specimen.json", sim, spec, report);
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/field_table.hpp"
#include "kerf/json_reader.hpp"

namespace kerf::dem {

enum class Packing { random, hexagonal };
/// "random", "hexagonal".
const EnumNames<Packing>& packing_names();

struct SpecimenSpec {
  double width_m = 1e-3, height_m = 2e-3, thickness_m = 1e-3;
  double radius_min_m = 7.5e-6, radius_max_m = 10e-6;
  Packing packing = Packing::random;
  std::uint64_t seed = 1;
  double packing_fraction = 0.85;       ///< area fraction used to choose the number of disks (random)
  double compaction_pressure_Pa = 3e6;  ///< isotropic pressure of the frictionless compaction
  /// E* of the compaction's reference contact (frictionless linear, kappa* kCompactionStiffnessRatio): a
  /// glass-like stiffness, the same for every material, so that the packing is the spec's alone.
  double compaction_modulus_Pa = 90e9;
  double installation_gap_m = 0.5e-6;  ///< joints at pairs whose surface gap is below this
  int growth_steps = 6000, relax_steps = 2000;
  /// A region of finer disks (random packing), radii uniform in [fine_radius_min, fine_radius_max], in the box
  /// [fine_x_min, fine_x_max] x [fine_y_min, fine_y_max] of the specimen (origin at its lower left corner); the
  /// rest keeps [radius_min, radius_max]. Off while fine_radius_max_m is 0. The reference of a sub-grid model at
  /// the disks' scale: e.g. a band of fine disks along a cut line (docs/dem.md, "Specimens").
  double fine_radius_min_m = 0, fine_radius_max_m = 0;
  double fine_x_min_m = 0, fine_x_max_m = 0, fine_y_min_m = 0, fine_y_max_m = 0;
  bool has_fine_region() const { return fine_radius_max_m > 0; }
};

/// The "specimen" section's keys (kerf/field_table.hpp): width_mm, height_mm, thickness_mm, radius_min_um,
/// radius_max_um, packing, seed, packing_fraction, compaction_pressure_MPa, compaction_modulus_GPa,
/// installation_gap_um, growth_steps, relax_steps, fine_radius_min_um, fine_radius_max_um, fine_x_min_mm,
/// fine_x_max_mm, fine_y_min_mm, fine_y_max_mm.
const FieldTable<SpecimenSpec>& specimen_fields();
/// Every field's range and the relations between them (radius_max >= radius_min, at most 1/8 of the smaller
/// side, at most 5 million disks; a fine region's radii at most radius_min, its box inside the specimen and at
/// least four fine diameters on each side, random packing only); InputError names the key ("radius_max_um").
void check_specimen_spec(const SpecimenSpec& spec);
/// Reads the "specimen" object (the table's ranges, then the relations; errors name the dotted path).
SpecimenSpec read_specimen_spec(ObjectReader& reader);
Json specimen_spec_to_json(const SpecimenSpec& spec);

/// A scene's "engine" object: settings applied to a specimen once it is built (the genesis runs with its own).
/// Defaults are the engine's (SimulationOptions).
struct EngineSettings {
  double time_step_safety = SimulationOptions{}.time_step_safety;
  std::int64_t min_parallel_items = SimulationOptions{}.min_parallel_items;
  bool adaptive_threads = true;  ///< the steps choose between all threads and one by measured rate
  /// Sets them on `sim`; the time step is recomputed with the safety factor.
  void apply_to(Simulation& sim) const;
};

/// The "engine" section's keys: time_step_safety, min_parallel_items, adaptive_threads.
const FieldTable<EngineSettings>& engine_fields();
/// Reads the optional "engine" object of a scene and rejects other keys.
EngineSettings read_engine_settings(ObjectReader& scene_root);

struct SpecimenReport {
  int n_particles = 0, n_bonds = 0, n_floaters_enlarged = 0, n_floaters_left = 0;
  double packing_fraction = 0, coordination_number = 0, radius_scale = 1;
  double residual_stress_xx_Pa = 0, residual_stress_yy_Pa = 0, residual_stress_xy_Pa = 0;
  std::int64_t genesis_steps = 0;
};
Json specimen_report_to_json(const SpecimenReport& r);

/// kappa* of the compaction's reference contact. The compaction is frictionless, so only the time step sees it.
inline constexpr double kCompactionStiffnessRatio = 2.5;

/// The disks of a specimen before any joint: the genesis's first part, which depends on the spec alone.
struct CompactedPacking {
  Simulation disks;       ///< unjointed; random: in the walled vessel, at the compaction pressure
  SpecimenReport report;  ///< radius_scale, floaters and the compaction's steps
};

/// `progress(done, total)` is called now and then with steps done (the total includes the finish's relax).
using GenesisProgress = std::function<void(std::int64_t, std::int64_t)>;

/// The genesis's first part (see the top of this header).
CompactedPacking compact_packing(const SpecimenSpec& spec, const GenesisProgress& progress = {});

/// The genesis's second part: `material`'s joints within the installation gap, walls removed, relaxed with
/// the material's laws and damping (random; hexagonal: every touching pair jointed). The specimen at rest,
/// time zero, no crack history; `report` complete.
Simulation finish_specimen(const CompactedPacking& packing, const Material& material, const SpecimenSpec& spec,
                           SpecimenReport& report, const GenesisProgress& progress = {});

/// Builds a jointed specimen: finish_specimen(compact_packing(spec), material, spec, report).
Simulation make_specimen(const Material& material, const SpecimenSpec& spec, SpecimenReport& report,
                         const GenesisProgress& progress = {});

/// What a calibration builds each candidate's specimen from. From a genesis: the compacted packing, finished
/// with the candidate, to the bit the specimen a scene with the same spec and that material builds. From a
/// saved specimen: its packing and joint states with the candidate's micro-parameters (with_material).
/// The engine settings are applied to every specimen it gives.
class SpecimenSource {
 public:
  static SpecimenSource genesis(CompactedPacking packing, const SpecimenSpec& spec, const EngineSettings& engine);
  static SpecimenSource saved(Simulation specimen, const EngineSettings& engine);
  Simulation for_material(const Material& material) const;
  /// The compacted packing's disks, or the saved specimen (for checkpoints and counts).
  const Simulation& disks() const { return packing_.disks; }

 private:
  SpecimenSource(CompactedPacking packing, const SpecimenSpec& spec, const EngineSettings& engine, bool genesis)
      : packing_(std::move(packing)), spec_(spec), engine_(engine), genesis_(genesis) {}
  CompactedPacking packing_;  ///< saved: the jointed specimen and no report
  SpecimenSpec spec_;
  EngineSettings engine_;
  bool genesis_;
};

/// The same packing and joint states with another material (stiffnesses follow the new micro-parameters;
/// the element count must be the same). Walls and groups are not copied.
Simulation with_material(const Simulation& specimen, const Material& material);

/// A new simulation with `material` holding the disks of `source` whose `keep` flag is set (every disk when
/// `keep` is empty), in order, with their positions, rotations, velocities and groups, and the active joints
/// between kept disks with their element states; the disk types (densities) are the source's when
/// `source_types`, else `material`'s. Walls, cracks and contacts are not copied. The element count of
/// `material`'s joint must be the source's.
Simulation copy_disks_and_joints(const Simulation& source, const Material& material, bool source_types,
                                 const std::vector<std::uint8_t>& keep = {});

/// A seeded flaw: a straight crack from (x0, y0) to (x1, y1).
struct Flaw {
  double x0_m, y0_m, x1_m, y1_m;
};

/// Seeds `material`'s flaws (flaw_length_m, flaw_density_per_m2) into a jointed specimen (docs/physics-dem.md
/// section 6): density x area straight cracks, centres uniform in the disks' centre box widened by half a flaw
/// on each side, orientations uniform, drawn from `seed` (a stream apart from the packing's); every element of
/// each active joint whose centre line crosses a flaw starts broken, with no shear force (a closed crack). The
/// genesis (finish_specimen) calls it with the specimen's seed, before the relaxation; a saved specimen keeps the
/// joint states it was saved with (its flaws, if any) and load_specimen seeds none. Returns the flaws drawn (none
/// when the material has none).
std::vector<Flaw> seed_flaws(Simulation& sim, const Material& material, std::uint64_t seed);

/// Draws every joint's strength factor (BondGeometry::strength_factor) from the material's Weibull modulus
/// (weibull_strength_factor; nothing when the modulus is 0), a stream of `seed` apart from the packing's and the
/// flaws'. The genesis (finish_specimen) calls it with the specimen's seed once the joints are installed; a copy of
/// the specimen (a cut's window, with_material) carries the factors; a saved specimen stores them.
void draw_joint_strengths(Simulation& sim, std::uint64_t seed);

/// Saves particles, joints with their element states, the spec and the report as JSON
/// (format "kerf-dem-specimen", version 1; documented in docs/dem.md).
void save_specimen(const std::string& file_path, const Simulation& sim, const SpecimenSpec& spec,
                   const SpecimenReport& report);

/// Loads a specimen for `material` (joint stiffnesses follow the material; the geometry and the element
/// states come from the file). Returns the spec and report stored with it.
Simulation load_specimen(const std::string& file_path, const Material& material, SpecimenSpec& spec,
                         SpecimenReport& report);

}  // namespace kerf::dem
