#pragma once
// The 2D bonded-particle DEM engine: disks (structure of arrays), bonds (a separate store with element states
// at the bond law's stride), unbonded contacts, rigid walls with prescribed motion, velocity-Verlet
// integration with Cundall local damping, and an O(N) cell-grid neighbour search with a skin. The contact
// laws are the material's (kerf/dem/laws/contact_laws.hpp): each loop is instantiated once per law and chosen once
// per step, so a law's update inlines into its loop.
//
//   Simulation sim(material, {.thickness_m = 1e-3});
//   int a = sim.add_particle(0, 0, 10e-6), b = sim.add_particle(20e-6, 0, 10e-6);
//   sim.install_bond(a, b);
//   sim.initialise();          // neighbour lists and the stable time step
//   sim.run(1000);             // ModelError if the run goes unstable
//
// Determinism: every contact force is computed into its own slot and summed per particle in a fixed order,
// so a run is bit-identical for the same input whatever the number of OpenMP threads.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kerf/dem/engine/neighbor_grid.hpp"
#include "kerf/dem/engine/team_governor.hpp"
#include "kerf/dem/laws/contact_laws.hpp"
#include "kerf/dem/laws/material.hpp"

namespace kerf::dem {

/// Per-type parameter table entry (all particles of one type share these).
struct ParticleType {
  double density_kg_per_m3 = 2400;
};

/// Particle data, one array per property.
struct Particles {
  std::vector<double> x, y, vx, vy, theta, omega;  ///< position [m], velocity [m/s], rotation [rad], spin [rad/s]
  std::vector<double> fx, fy, torque;              ///< force [N] and torque [N m] of the last evaluation
  std::vector<double> radius, inv_mass, inv_inertia;
  std::vector<std::uint8_t> type;   ///< index into the type table
  std::vector<std::uint8_t> group;  ///< 0: free; > 0: velocity prescribed, forces summed per group
  std::size_t size() const { return x.size(); }
};

/// Bonds; the element states of bond b are at [b * stride, (b + 1) * stride).
struct BondStore {
  int stride = 2;  ///< elements per bond (the bond law's bond_elements: N_r for the flat joint)
  std::vector<std::int32_t> i, j;
  std::vector<double> ref_distance_m;    ///< centre distance at installation (zero gap there)
  std::vector<double> ref_rotation_rad;  ///< theta_j - theta_i at installation
  std::vector<BondInterface> geometry;
  /// Per bond, its strength factor w (Weibull joint strengths: draw_joint_strengths); empty when every factor is 1
  /// (a material without a Weibull modulus), which the joint loop then does not read.
  std::vector<double> strength_factor;
  /// Sets bond b's strength factor, making the factors of the other bonds 1 where the store had none.
  void set_strength_factor(std::size_t b, double w) {
    if (strength_factor.empty()) strength_factor.assign(size(), 1.0);
    strength_factor[b] = w;
  }
  /// What bond b's law functions take: its interface and its strength factor.
  BondGeometry joint_geometry(std::size_t b) const {
    return {geometry[b], strength_factor.empty() ? 1.0 : strength_factor[b]};
  }
  std::vector<std::uint8_t> active;        ///< 0 once retired (broken, per the law): the unbonded contact rules
  std::vector<double> shear_force_N;       ///< per element
  std::vector<std::uint8_t> bonded;        ///< per element
  std::vector<BreakMode> pending;          ///< per element, breaks found in this step's force loop
  std::vector<std::array<double, 4>> out;  ///< per bond: force on j (x, y), torque on i, torque on j
  /// Doubles of the bond law's own state per element (BondLawWithState; 0 for a law without) and their names (the law's
  /// kElementState: specimen files' element_<name> keys); set from the law by the Simulation.
  int state_size = 0;
  std::span<const std::string_view> state_names;
  /// The law's state, state_size doubles per element (element k's at [k * state_size, (k + 1) * state_size)): zero
  /// at installation, advanced by the law's update and bond_element_broken. The engine resizes, copies,
  /// checkpoints and saves it and never reads what it means.
  std::vector<double> element_state;
  std::size_t size() const { return i.size(); }
  int n_bonded_elements(std::size_t b) const;
  /// Copies bond k's strength factor and element states (bonded flags, shear forces, the law's state where both
  /// stores keep the same amount) from `from` into bond `to` of this store, both of the same stride (a specimen copied,
  /// a cut's window rebuilt).
  void copy_elements(std::size_t to, const BondStore& from, std::size_t k);
};

/// A rigid wall: a line segment moving at a prescribed velocity. Disks touch it from either side.
struct Wall {
  double x0, y0, x1, y1;  ///< end points [m]
  double vx = 0, vy = 0;  ///< prescribed velocity [m/s]
  double fx = 0, fy = 0;  ///< force the disks exert on the wall [N], last evaluation
  bool enabled = true;
  /// Coulomb friction of the disk-wall contacts (a tool face's own friction); negative: the material's mu.
  double friction_coefficient = -1;
};

/// One bond-element break (docs/physics-dem.md section 1: every break is a crack event).
struct CrackEvent {
  double time_s, x_m, y_m;
  double orientation_rad;  ///< direction of the interface (the crack line), angle of s from the x axis
  double length_m;         ///< l_e
  BreakMode mode;
  std::int32_t bond, element;
};

/// A run (cut or lab test) that would take more time steps than this is an input error: days of computing
/// on a paper-size workpiece (6x the paper's own 4.23 mm/s over the validation's 0.6 mm of travel), refused
/// rather than started as if it could finish.
inline constexpr double kMaxRunSteps = 1e9;

/// A run that needs `steps` time steps of `time_step_s` at engine.time_step_safety `safety`: when it needs
/// more than kMaxRunSteps but would fit at the default safety (SimulationOptions), the lowered safety is the
/// cause and the InputError names engine.time_step_safety with the smallest value that fits; otherwise
/// nothing (the caller names its speed).
void refuse_small_time_step_safety(double steps, double time_step_s, double safety);

struct SimulationOptions {
  double thickness_m = 1e-3;       ///< out-of-plane thickness t
  double skin_m = 0;               ///< neighbour skin; 0: 0.3 R_min
  double time_step_safety = 0.8;   ///< f_safety in dt = f min(sqrt(m/k), sqrt(I/k_rot))
  double speed_limit_m_per_s = 0;  ///< runaway detection; 0: the p-wave speed sqrt(E*/rho)
  int check_every = 50;            ///< steps between instability checks
  /// Systems with fewer particles and fewer joints than this run on one thread (a team costs more than it
  /// saves on small systems). Results do not depend on it: every sum is taken in a fixed order.
  std::int64_t min_parallel_items = 1024;
  /// Leave unjointed contacts between two prescribed-velocity disks out of the contact lists (their forces
  /// move nothing): the held frame of a windowed cut. Off by default: a lab test sums its grips' forces.
  bool skip_held_pairs = false;
};

/// The shear springs of the unjointed contacts (disk pairs, disk-wall), by particle index: carried from one
/// simulation into another that holds the same disks under other indices (the windowed cut rebuilds its
/// window so). Pairs sorted by (i, j) with i < j; wall contacts by (wall, particle).
struct ContactSprings {
  std::vector<CandidatePair> pairs;
  std::vector<double> pair_shear_N;
  std::vector<std::array<std::int32_t, 2>> wall_contacts;
  std::vector<double> wall_shear_N;
};

/// The p-wave speed sqrt(E* / rho) of the material's unbonded contact law [m/s]: the engine's runaway limit by
/// default, and the wave speed a windowed cut's absorbing layer is tuned to.
double p_wave_speed_m_per_s(const Material& material);

class Simulation {
 public:
  Simulation(const Material& material, const SimulationOptions& options);

  // --- building ---
  int add_particle(double x_m, double y_m, double radius_m, std::uint8_t type = 0);
  /// Changes a radius (and mass); used by specimen genesis.
  void set_radius(std::size_t i, double radius_m);
  int add_wall(const Wall& wall);
  /// Installs a stress-free bond between i and j (docs/physics-dem.md section 1: zero gap at installation).
  int install_bond(int i, int j);
  /// Installs a joint whose zero-gap state is at the given centre distance and relative rotation (loading).
  int install_bond(int i, int j, double ref_distance_m, double ref_rotation_rad);
  /// Recomputes the time step for the current radii and contacts (genesis changes radii).
  void refresh_time_step() {
    if (!dt_fixed_) dt_ = stable_time_step();
  }
  /// Installs joints at every pair whose surface gap is below `gap_m` (overlaps included).
  int install_bonds_within_gap(double gap_m);
  /// Builds the neighbour lists; computes the time step unless set_time_step was called.
  void initialise();
  void set_time_step(double dt_s) {
    dt_ = dt_s;
    dt_fixed_ = true;
  }
  /// Changes f_safety (validated as engine.time_step_safety) and recomputes the step.
  void set_time_step_safety(double f);
  void set_min_parallel_items(std::int64_t n) { opt_.min_parallel_items = n; }
  /// Whether the steps choose between all threads and one by measured rate (kerf/dem/engine/team_governor.hpp; on
  /// by default; results do not depend on it). Not part of the saved state: a restored run has it on.
  void set_adaptive_team(bool on) { adaptive_team_ = on; }
  bool adaptive_team() const { return adaptive_team_; }
  /// The governor of the team size (a test sets one that switches often).
  void set_team_governor(const TeamGovernor& governor) { governor_ = governor; }
  const TeamGovernor& team_governor() const { return governor_; }
  /// f_safety min over disks of sqrt(m / k_tran), sqrt(I / k_rot), k summed over bonds and candidate contacts.
  double stable_time_step() const;

  // --- running ---
  void step();
  void run(std::int64_t n_steps);
  /// Breaks every bonded element of bond b now, in `mode`, as the engine breaks an element its law finds failed: a
  /// crack event each, the law's state of a broken element, the bond retired where the law retires it (a model that
  /// decides a break the lattice cannot resolve: the edge zone's lateral crack). Between steps only.
  void break_bond(std::size_t b, BreakMode mode);

  // --- access ---
  Particles& particles() { return p_; }
  const Particles& particles() const { return p_; }
  BondStore& bonds() { return b_; }
  const BondStore& bonds() const { return b_; }
  std::vector<Wall>& walls() { return walls_; }
  const std::vector<Wall>& walls() const { return walls_; }
  std::vector<ParticleType>& types() { return types_; }
  const std::vector<ParticleType>& types() const { return types_; }
  const std::vector<CrackEvent>& cracks() const { return cracks_; }
  std::vector<CrackEvent>& cracks() { return cracks_; }
  const Material& material() const { return material_; }
  /// Replaces the unbonded contact law (e.g. frictionless compaction during genesis).
  void set_contact_law(const ContactLaw& c) { material_.contact = c; }
  void set_local_damping(double alpha) { material_.local_damping = alpha; }
  /// An absorbing layer (a sponge: Cerjan et al. 1985): each free disk's velocity and spin decay at its own rate
  /// gamma [1/s] (dv/dt = -gamma v, applied after each step's second half kick as v exp(-gamma dt)), so the
  /// elastic waves that reach the edge of a windowed cut's held frame are absorbed there instead of reflected.
  /// One rate per disk (0: none; finite, >= 0), or empty: no layer (the default; the step then does what it did
  /// before, to the bit). A disk added later gets rate 0.
  void set_absorbing_rates(std::vector<double> rates_per_s);
  const std::vector<double>& absorbing_rates() const { return absorbing_rate_; }
  /// A force on one disk from outside the model [N] (a cut's edge zone: the reaction of the tool's edge on the
  /// glass it meets), added to its contact and joint forces at every step until the loads are set again.
  struct DiskLoad {
    std::size_t disk = 0;
    double fx_N = 0, fy_N = 0;
  };
  /// The loads of the next steps (replacing any before; finite; a held disk's is ignored, as its other forces are);
  /// empty, the default: none, and the step does what it did before, to the bit. Not saved with the state: its
  /// owner sets them again (a disk added or removed changes the indices).
  void set_disk_loads(std::vector<DiskLoad> loads);
  const std::vector<DiskLoad>& disk_loads() const { return disk_loads_; }
  const SimulationOptions& options() const { return opt_; }
  double time_step() const { return dt_; }
  double time() const { return time_; }
  std::int64_t step_count() const { return steps_; }
  void set_clock(double time_s, std::int64_t steps) {
    time_ = time_s;
    steps_ = steps;
  }

  /// Sum of contact forces on the particles of prescribed-velocity group g [N].
  std::array<double, 2> group_force(std::uint8_t g) const;
  double kinetic_energy() const;
  /// The elastic energy every spring holds [J]: the joints', the unjointed disk-disk contacts' and the disk-wall
  /// contacts' (normal and shear springs; a wall is a disk of zero radius to its contact law). What every energy
  /// book counts as stored (a cut's, a toughness test's): without the walls' part the springs between the disks
  /// and a pressing tool, platen or roller are booked as dissipated (7.5 % of the work of the tool in
  /// tests/dem/cutting_test.cpp's frictionless cut).
  double stored_elastic_energy() const;
  /// A disk-wall contact's normal force now [N] (compression positive), from its overlap by the contact law.
  struct WallContactLoad {
    std::int32_t wall = 0, disk = 0;
    double normal_force_N = 0;
  };
  /// The disk-wall contacts that touch (positive overlap) with their normal forces.
  std::vector<WallContactLoad> wall_contact_loads() const;
  /// Per disk: 1 if a path of joints with a bonded element ties it to a held disk (group != 0), else 0. Disks with
  /// `excluded[u]` != 0 (when given: one flag per disk) are neither held nor on any path.
  std::vector<std::uint8_t> tied_to_held(std::span<const std::uint8_t> excluded = {}) const;
  /// The joints with a bonded element, per disk (CSR): disk u's partners are other[start[u]] .. other[start[u+1]-1].
  struct JointGraph {
    std::vector<std::size_t> start, other;
  };
  JointGraph intact_joint_graph() const;
  /// Number of active joints and of touching unjointed contacts, per particle (mean coordination number).
  double coordination_number() const;
  int n_contacts_of(std::size_t i) const;
  /// Average (Love) stress of the assembly over `area_m2`: sigma = -(1/V) sum f (x) l, tension positive [Pa].
  std::array<double, 3> average_stress(double area_m2) const;  // xx, yy, xy
  /// Per disk, from the forces of the last evaluation: the 2D Love-Weber average stress over the disk's own volume
  /// (pi r^2 thickness), sigma = (1/V) sum_c f_c (x) (x_c - x_p) symmetrised, over its joints, its touching
  /// contacts and its wall contacts, the contact point on its rim along the centre line (a wall's: the closest
  /// point), tension positive [Pa]; and the sum of those forces' magnitudes [N]: force chains (issue 55 item 6).
  struct DiskStresses {
    std::vector<std::array<double, 3>> stress_Pa;  ///< xx, yy, xy
    std::vector<double> force_sum_N;
  };
  DiskStresses disk_stresses() const;
  /// Joint b's force of the last evaluation: along its centre line, tension positive, and across it (the
  /// component on disk j along the centre line turned +90 degrees) [N].
  std::array<double, 2> joint_force(std::size_t b) const;
  /// Number of touching unjointed disk-disk contacts.
  int n_touching_pairs() const;
  /// The complete state (particles, joints, contact lists with their shear springs, neighbour reference
  /// positions, walls, cracks, clock) as bytes: restoring it and running on gives bit-identical results to
  /// an uninterrupted run. Format: "KERFDEM8", the material with its two laws each as a record by name (the
  /// registry name, then every key of its field table with its SI value), then each field as a length-prefixed
  /// raw array (native endianness, same build), the law's element state (BondStore::element_state) then the
  /// joints' strength factors last. "KERFDEM8" (without the factors), "KERFDEM7" (without the element state either)
  /// and "KERFDEM6" (also the laws as raw variants, kerf 4a34e1f) are still read; another version is a
  /// ModelError naming it.
  std::string serialize() const;
  static Simulation deserialize(std::string_view bytes);
  /// Bytes held by the engine's arrays (particles, joints with their elements, contact lists, incidence).
  std::size_t memory_bytes() const;
  /// The unjointed contacts' shear springs now (those of touching contacts; zero ones left out).
  ContactSprings contact_springs() const;
  /// Installs shear springs before initialise(): its neighbour search keeps those of the contacts it finds.
  void set_contact_springs(ContactSprings springs);
  /// Forces the neighbour lists to be rebuilt before the next force evaluation.
  void invalidate_neighbours() { need_rebuild_ = true; }
  /// Recomputes forces at the current state without moving anything (no shear increments; static checks).
  void evaluate_forces();
  /// Recomputes forces at the current state with the shear increments of one step at the current
  /// velocities, without moving anything (prescribed-motion tests of the contact kinematics).
  void evaluate_forces_with_increment();

 private:
  void rebuild_neighbours();
  /// The enabled disk-wall contacts that touch: (index in the wall contact list, overlap [m]).
  std::vector<std::pair<std::size_t, double>> wall_overlaps() const;
  /// stored_elastic_energy's parts: the joints' and disk-disk contacts', the disk-wall contacts'.
  double joint_and_contact_energy() const;
  double wall_contact_energy() const;
  /// Breaks found and joints retired by one force evaluation (summed over threads).
  struct ForceCounts {
    int n_breaking = 0, n_retired = 0;
  };
  /// A team is worth starting: more particles or joints than options().min_parallel_items.
  bool parallel_here() const {
    return static_cast<std::int64_t>(std::max(p_.size(), b_.size())) > opt_.min_parallel_items;
  }
  void compute_forces();
  /// The force loops as orphaned worksharing: called by every thread of a team, or by one thread alone.
  void force_loops(ForceCounts& counts);
  /// The bond, pair and wall loops of force_loops, one instantiation per law.
  /// kViscous: with the contact dashpots of Material::viscous_damping_ratio (an instantiation without them
  /// runs when the ratio is 0, so undamped runs are the same to the bit).
  /// `state`: the bonds' element state (BondStore::element_state) for a law that has one (BondLawWithState), else
  /// nothing (the loop then calls the law's update as before there was any). kFactors: the joints have strength
  /// factors (BondStore::strength_factor); without, a loop whose factor is the constant 1 (no memory read, no
  /// multiplication left: the joint loop of the build before Weibull strengths, measured in docs/performance.md).
  template <class Law, bool kViscous, bool kFactors, class... State>
  void bond_loop(const Law& law, ForceCounts& counts, State*... state);
  /// bond_loop with the element state for a law that has one.
  template <bool kViscous, class Law>
  void bond_loop_of(const Law& law, ForceCounts& counts);
  template <class Law, bool kViscous>
  void pair_loop(const Law& law);
  template <class Law, bool kViscous>
  void wall_loop(const Law& law);
  /// 2 beta sqrt(m_eff k) for the pair (i, j): m_eff = 1 / (1/m_i + 1/m_j), a prescribed disk counting as
  /// infinitely heavy (j = -1: a wall); 0 when both are prescribed.
  double dashpot_coefficient(std::size_t i, std::int64_t j, double stiffness) const;
  void finish_forces(const ForceCounts& counts);
  void apply_breaks();
  template <class Law>
  void apply_breaks_of(const Law& law);
  /// Orphaned worksharing loops over the disks (every thread of the step's team calls them): the first half
  /// kick of the free disks and the drift of all, returning this thread's largest squared move since the
  /// last rebuild; the damped second half kick of the free disks.
  double half_kick_and_drift(double dt);
  void damped_half_kick(double dt);
  void check_stability() const;
  double mass_of(double radius_m, std::uint8_t type) const;
  /// The state after the material and options, in checkpoint order: io(field...) writes or reads them.
  /// `version`: the format's index, 0 the newest ("KERFDEM9": the joints' strength factors last, after the element
  /// state), 1 "KERFDEM8" (no factors), 2 and 3 "KERFDEM7" and "KERFDEM6" (no element state either).
  template <class Self, class Io>
  static void state_fields(Self& sim, Io& io, int version);

  Material material_;
  SimulationOptions opt_;
  std::vector<ParticleType> types_;
  Particles p_;
  BondStore b_;
  std::vector<Wall> walls_;
  std::vector<CrackEvent> cracks_;

  // Unjointed disk-disk candidate pairs (within the skin) with their shear state.
  std::vector<CandidatePair> pairs_;
  std::vector<double> pair_shear_;
  std::vector<std::array<double, 4>> pair_out_;
  // Disk-wall candidate contacts.
  std::vector<std::array<std::int32_t, 2>> wall_contacts_;  ///< wall, particle
  std::vector<double> wall_shear_;
  std::vector<std::array<double, 3>> wall_out_;  ///< force on the particle (x, y), torque on it
  // Per-particle incidence (CSR): entry = index << 3 | kind << 1 | role.
  std::vector<std::int32_t> incidence_start_;
  std::vector<std::uint32_t> incidence_;
  // Where each particle's pair entries and wall entries begin (its joint entries begin at incidence_start_).
  std::vector<std::int32_t> incidence_pair_begin_, incidence_wall_begin_;
  // Positions at the last rebuild.
  std::vector<double> x_ref_, y_ref_, wall_ref_;
  std::vector<std::int32_t> fixed_;      ///< indices of prescribed-velocity particles
  std::vector<double> absorbing_rate_;   ///< per disk [1/s], or empty (set_absorbing_rates)
  std::vector<double> absorbing_decay_;  ///< exp(-rate dt) for absorbing_dt_ (derived, not saved)
  double absorbing_dt_ = 0;
  std::vector<DiskLoad> disk_loads_;  ///< set_disk_loads (not saved)
  void absorb_disks();                ///< this thread's share of the decay (in the step's team)
  bool need_rebuild_ = true, need_breaks_ = false, initialised_ = false, dt_fixed_ = false;
  double dt_ = 0, time_ = 0, skin_ = 0, speed_limit_ = 0;
  std::int64_t steps_ = 0;
  bool adaptive_team_ = true;
  TeamGovernor governor_;
  /// The threads of the next step's team: OpenMP's maximum, or the governor's choice out of it.
  int team_threads();
};

}  // namespace kerf::dem
