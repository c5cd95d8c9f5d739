// Specimen genesis (physics-dem.md section 2) and the saved specimen format.
#include "kerf/dem/procedures/specimen.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

const EnumNames<Packing>& packing_names() {
  static constexpr std::string_view names[] = {"random", "hexagonal"};
  static const EnumNames<Packing> table{names};
  return table;
}

const FieldTable<SpecimenSpec>& specimen_fields() {
  using namespace units;
  using S = SpecimenSpec;
  static const FieldTable<SpecimenSpec> table{
      number_field("width_mm", kMm, Range::positive(), "specimen width (x)", &S::width_m),
      number_field("height_mm", kMm, Range::positive(), "specimen height (y)", &S::height_m),
      number_field("thickness_mm", kMm, Range::positive(), "out-of-plane thickness: forces and stresses are per it",
                   &S::thickness_m),
      number_field("radius_min_um", kUm, Range::positive(), "smallest disk radius", &S::radius_min_m),
      number_field("radius_max_um", kUm, Range::positive(), "largest disk radius (at most 1/8 of the smaller side)",
                   &S::radius_max_m),
      choice_field("packing", packing_names(), "random packing, or equal disks on a triangular lattice (verification)",
                   &S::packing),
      IntField<S>{"seed", 0, 2147483647, "random packing seed (replicate k uses seed + k)",
                  [](const S& s) { return static_cast<int>(s.seed); },
                  [](S& s, int v) { s.seed = static_cast<std::uint64_t>(v); }},
      number_field("packing_fraction", kNone, Range::closed(0.5, 0.9),
                   "disk area fraction that sets the number of disks (random)", &S::packing_fraction),
      number_field("compaction_pressure_MPa", kMPa, Range::positive(),
                   "isotropic pressure of the frictionless compaction", &S::compaction_pressure_Pa),
      number_field("compaction_modulus_GPa", kGPa, Range::positive(),
                   "E* of the compaction's frictionless reference contact (the same for every material)",
                   &S::compaction_modulus_Pa),
      number_field("installation_gap_um", kUm, Range::non_negative(), "joints at pairs whose surface gap is below this",
                   &S::installation_gap_m),
      int_field("growth_steps", 100, 10000000, "steps of the radius growth and compaction", &S::growth_steps),
      int_field("relax_steps", 0, 10000000, "steps of the relaxation after the walls are removed", &S::relax_steps),
      number_field("fine_radius_min_um", kUm, Range::non_negative(), "smallest disk radius of the fine region",
                   &S::fine_radius_min_m),
      number_field("fine_radius_max_um", kUm, Range::non_negative(),
                   "largest disk radius of the fine region (0: no fine region; at most radius_min_um)",
                   &S::fine_radius_max_m),
      number_field("fine_x_min_mm", kMm, Range::non_negative(), "fine region's left side (x from the specimen's left)",
                   &S::fine_x_min_m),
      number_field("fine_x_max_mm", kMm, Range::non_negative(), "fine region's right side", &S::fine_x_max_m),
      number_field("fine_y_min_mm", kMm, Range::non_negative(),
                   "fine region's lower side (y from the specimen's bottom)", &S::fine_y_min_m),
      number_field("fine_y_max_mm", kMm, Range::non_negative(), "fine region's upper side", &S::fine_y_max_m)};
  return table;
}

namespace {
/// The fine region's area (0 without one).
double fine_region_area(const SpecimenSpec& s) {
  return s.has_fine_region() ? (s.fine_x_max_m - s.fine_x_min_m) * (s.fine_y_max_m - s.fine_y_min_m) : 0.0;
}

/// Mean of r^2 for r uniform in [a, b].
double mean_square_radius(double a, double b) {
  return (a * a + a * b + b * b) / 3;
}

/// How many disks a random genesis draws: the packing fraction of each region's area with its nominal radii.
struct DiskCounts {
  double coarse = 0, fine = 0;
  double total() const { return coarse + fine; }
};
DiskCounts disk_counts(const SpecimenSpec& s) {
  const double fine_area = fine_region_area(s);
  DiskCounts n;
  n.coarse = s.packing_fraction * (s.width_m * s.height_m - fine_area) /
             (std::numbers::pi * mean_square_radius(s.radius_min_m, s.radius_max_m));
  if (s.has_fine_region())
    n.fine = s.packing_fraction * fine_area /
             (std::numbers::pi * mean_square_radius(s.fine_radius_min_m, s.fine_radius_max_m));
  return n;
}

/// A fine region: radii 0 < min <= max <= radius_min, random packing, a box inside the specimen at least four fine
/// diameters on each side.
void check_fine_region(const SpecimenSpec& s) {
  using namespace units;
  const auto um = [](double m) { return format_value(m_to_um(m)); };
  const auto mm = [](double m) { return format_value(m_to_mm(m)); };
  if (s.packing != Packing::random)
    throw InputError("fine_radius_max_um", um(s.fine_radius_max_m), "0 (no fine region) with packing hexagonal");
  if (s.fine_radius_max_m > s.radius_min_m)
    throw InputError("fine_radius_max_um", um(s.fine_radius_max_m),
                     "a value <= radius_min_um = " + um(s.radius_min_m) + " um (the fine region's disks are finer)");
  if (!(s.fine_radius_min_m > 0) || s.fine_radius_min_m > s.fine_radius_max_m)
    throw InputError("fine_radius_min_um", um(s.fine_radius_min_m),
                     "a positive value <= fine_radius_max_um = " + um(s.fine_radius_max_m) + " um");
  const double min_side = 8 * s.fine_radius_max_m;
  if (s.fine_x_max_m > s.width_m)
    throw InputError("fine_x_max_mm", mm(s.fine_x_max_m), "a value <= width_mm = " + mm(s.width_m) + " mm");
  if (s.fine_x_max_m - s.fine_x_min_m < min_side)
    throw InputError("fine_x_max_mm", mm(s.fine_x_max_m),
                     "a value >= fine_x_min_mm + 4 fine diameters = " + mm(s.fine_x_min_m + min_side) + " mm");
  if (s.fine_y_max_m > s.height_m)
    throw InputError("fine_y_max_mm", mm(s.fine_y_max_m), "a value <= height_mm = " + mm(s.height_m) + " mm");
  if (s.fine_y_max_m - s.fine_y_min_m < min_side)
    throw InputError("fine_y_max_mm", mm(s.fine_y_max_m),
                     "a value >= fine_y_min_mm + 4 fine diameters = " + mm(s.fine_y_min_m + min_side) + " mm");
  // Between the region and a side of the specimen: none, or room for a coarse disk's centre.
  const double room = 2 * s.radius_max_m;
  struct Side {
    const char* key;
    double value_m, margin_m;
  };
  const Side sides[] = {{"fine_x_min_mm", s.fine_x_min_m, s.fine_x_min_m},
                        {"fine_x_max_mm", s.fine_x_max_m, s.width_m - s.fine_x_max_m},
                        {"fine_y_min_mm", s.fine_y_min_m, s.fine_y_min_m},
                        {"fine_y_max_mm", s.fine_y_max_m, s.height_m - s.fine_y_max_m}};
  for (const Side& side : sides)
    if (side.margin_m > 0 && side.margin_m < room)
      throw InputError(
          side.key, mm(side.value_m),
          "a region that reaches the specimen's side or leaves a largest coarse diameter to it (" + mm(room) + " mm)");
}

/// The relations between the fields (each field's own range is the table's).
void check_specimen_relations(const SpecimenSpec& s) {
  using namespace units;
  if (s.radius_max_m < s.radius_min_m)
    throw InputError("radius_max_um", format_value(m_to_um(s.radius_max_m)),
                     "a value >= radius_min_um = " + format_value(m_to_um(s.radius_min_m)) + " um")
        .or_from(InputError("radius_min_um", format_value(m_to_um(s.radius_min_m)),
                            "a value <= radius_max_um = " + format_value(m_to_um(s.radius_max_m)) + " um"));
  if (2 * s.radius_max_m * 4 > std::min(s.width_m, s.height_m))
    throw InputError("radius_max_um", format_value(m_to_um(s.radius_max_m)),
                     "at most 1/8 of the specimen's smaller side in um");
  if (s.has_fine_region()) check_fine_region(s);
  if (disk_counts(s).total() > 5e6)
    throw InputError(s.has_fine_region() ? "fine_radius_min_um" : "radius_min_um",
                     format_value(m_to_um(s.has_fine_region() ? s.fine_radius_min_m : s.radius_min_m)),
                     "radii large enough for at most 5 million disks in the specimen, in um");
}
}  // namespace

void check_specimen_spec(const SpecimenSpec& s) {
  check_fields(specimen_fields(), s);
  check_specimen_relations(s);
}

SpecimenSpec read_specimen_spec(ObjectReader& r) {
  const SpecimenSpec s = read_fields(r, specimen_fields(), SpecimenSpec{});
  // The ranges are the reader's; the relations between fields are checked here, once.
  with_path(r.path(), [&] { check_specimen_relations(s); });
  return s;
}

void EngineSettings::apply_to(Simulation& sim) const {
  sim.set_time_step_safety(time_step_safety);
  sim.set_min_parallel_items(min_parallel_items);
  sim.set_adaptive_team(adaptive_threads);
}

const FieldTable<EngineSettings>& engine_fields() {
  using E = EngineSettings;
  static const FieldTable<EngineSettings> table{
      number_field("time_step_safety", units::kNone, Range{0.0, 1.0, true, false},
                   "fraction of the critical time step used", &E::time_step_safety),
      IntField<E>{"min_parallel_items", 0, 1 << 30, "loops shorter than this run on one thread",
                  [](const E& e) { return static_cast<int>(e.min_parallel_items); },
                  [](E& e, int v) { e.min_parallel_items = v; }},
      bool_field("adaptive_threads",
                 "choose between all threads and one by measured speed, again every few seconds: one thread when a "
                 "core is shared with another process (docs/performance.md); results do not depend on it",
                 &E::adaptive_threads)};
  return table;
}

EngineSettings read_engine_settings(ObjectReader& scene_root) {
  EngineSettings e;
  if (auto engine = scene_root.find_object("engine")) {
    e = read_fields(*engine, engine_fields(), e);
    engine->finish();
  }
  return e;
}

Json specimen_spec_to_json(const SpecimenSpec& s) {
  return fields_to_json(specimen_fields(), s);
}

Json specimen_report_to_json(const SpecimenReport& r) {
  return Json{{"n_particles", r.n_particles},
              {"n_bonds", r.n_bonds},
              {"packing_fraction", r.packing_fraction},
              {"coordination_number", r.coordination_number},
              {"radius_scale", r.radius_scale},
              {"n_floaters_enlarged", r.n_floaters_enlarged},
              {"n_floaters_left", r.n_floaters_left},
              {"residual_stress_xx_MPa", units::pa_to_mpa(r.residual_stress_xx_Pa)},
              {"residual_stress_yy_MPa", units::pa_to_mpa(r.residual_stress_yy_Pa)},
              {"residual_stress_xy_MPa", units::pa_to_mpa(r.residual_stress_xy_Pa)},
              {"genesis_steps", r.genesis_steps}};
}

namespace {

void finish_report(const Simulation& sim, const SpecimenSpec& spec, SpecimenReport& report) {
  const auto& p = sim.particles();
  double disk_area = 0;
  for (double r : p.radius) disk_area += std::numbers::pi * r * r;
  report.n_particles = static_cast<int>(p.size());
  report.n_bonds = 0;
  for (auto a : sim.bonds().active) report.n_bonds += a;
  report.packing_fraction = disk_area / (spec.width_m * spec.height_m);
  report.coordination_number = sim.coordination_number();
  const auto s = sim.average_stress(spec.width_m * spec.height_m);
  report.residual_stress_xx_Pa = s[0];
  report.residual_stress_yy_Pa = s[1];
  report.residual_stress_xy_Pa = s[2];
}

/// Equal disks on a triangular lattice, unjointed.
CompactedPacking hexagonal_lattice(const SpecimenSpec& spec) {
  Simulation sim(Material{}, {.thickness_m = spec.thickness_m});
  const double r = 0.5 * (spec.radius_min_m + spec.radius_max_m);
  const double row = std::sqrt(3.0) * r;
  for (int k = 0; r + k * row <= spec.height_m - r; ++k) {
    const double x0 = r + (k % 2) * r;
    for (int c = 0; x0 + 2 * r * c <= spec.width_m - r; ++c) sim.add_particle(x0 + 2 * r * c, r + k * row, r);
  }
  return {std::move(sim), {}};
}

/// Mean normal stress on the four vessel walls (compression positive) [Pa].
double wall_pressure(const Simulation& sim, const SpecimenSpec& spec) {
  const auto& w = sim.walls();
  const double t = spec.thickness_m;
  const double syy = 0.5 * (std::abs(w[0].fy) + std::abs(w[2].fy)) / (spec.width_m * t);
  const double sxx = 0.5 * (std::abs(w[1].fx) + std::abs(w[3].fx)) / (spec.height_m * t);
  return 0.5 * (sxx + syy);
}

constexpr int kServoChunk = 100, kServoMax = 80, kFloaterRounds = 6;

/// Steps of the whole random genesis, an upper bound (the servo may stop early), for progress.
std::int64_t random_genesis_steps(const SpecimenSpec& spec) {
  return spec.growth_steps + kServoMax * kServoChunk + kFloaterRounds * 200 + spec.relax_steps;
}

// Long (~90 lines) for a reason: the genesis in order (the draw, the rows, the compaction and its servo) on one
// packing's arrays, each stage reading what the one before left (physics-dem.md section 2).
CompactedPacking compact_random(const SpecimenSpec& spec, const GenesisProgress& progress) {
  const double W = spec.width_m, H = spec.height_m, b = spec.radius_max_m;
  const DiskCounts counts = disk_counts(spec);
  const auto n_coarse = static_cast<std::size_t>(std::lround(counts.coarse));
  const auto n = n_coarse + static_cast<std::size_t>(std::lround(counts.fine));
  std::mt19937_64 rng(spec.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> r(n), x(n), y(n);
  // The coarse disks' centres outside the fine region (drawn again when inside; without one, every first draw
  // stands), then the fine disks' inside it.
  const auto in_fine_region = [&](double px, double py) {
    return spec.has_fine_region() && px >= spec.fine_x_min_m && px <= spec.fine_x_max_m && py >= spec.fine_y_min_m &&
           py <= spec.fine_y_max_m;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const bool fine = k >= n_coarse;
    const double a_k = fine ? spec.fine_radius_min_m : spec.radius_min_m;
    const double b_k = fine ? spec.fine_radius_max_m : spec.radius_max_m;
    r[k] = a_k + (b_k - a_k) * uniform(rng);
    if (fine) {
      x[k] = spec.fine_x_min_m + (spec.fine_x_max_m - spec.fine_x_min_m) * uniform(rng);
      y[k] = spec.fine_y_min_m + (spec.fine_y_max_m - spec.fine_y_min_m) * uniform(rng);
      x[k] = std::clamp(x[k], r[k], W - r[k]), y[k] = std::clamp(y[k], r[k], H - r[k]);
      continue;
    }
    do {
      x[k] = r[k] + (W - 2 * r[k]) * uniform(rng);
      y[k] = r[k] + (H - 2 * r[k]) * uniform(rng);
    } while (in_fine_region(x[k], y[k]));
  }
  // Store the disks in rows (of height 2 R_max) for memory locality of neighbours.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto row_of = [&](std::size_t k) { return static_cast<long>(y[k] / (2 * b)); };
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return row_of(i) != row_of(j) ? row_of(i) < row_of(j) : x[i] < x[j]; });

  // docs/physics-dem.md section 2: frictionless compaction, here through a reference contact of the spec's,
  // so that the packing does not depend on the material (the density only scales time: not a choice).
  Material reference;
  reference.name = "compaction reference";
  reference.contact = LinearContactParams{spec.compaction_modulus_Pa, kCompactionStiffnessRatio, 0.0};
  reference.local_damping = 0.7;
  CompactedPacking out{Simulation(reference, {.thickness_m = spec.thickness_m}), {}};
  Simulation& sim = out.disks;
  SpecimenReport& report = out.report;
  double scale = 0.5;
  for (std::size_t k : order) sim.add_particle(x[k], y[k], scale * r[k]);
  sim.add_wall({0, 0, W, 0});
  sim.add_wall({W, 0, W, H});
  sim.add_wall({W, H, 0, H});
  sim.add_wall({0, H, 0, 0});
  std::vector<double> r_sorted(n);
  for (std::size_t k = 0; k < n; ++k) r_sorted[k] = r[order[k]];
  const auto set_scale = [&](double s) {
    scale = s;
    for (std::size_t k = 0; k < n; ++k) sim.set_radius(k, s * r_sorted[k]);
    sim.invalidate_neighbours();
    sim.refresh_time_step();
  };
  sim.initialise();
  const std::int64_t total = random_genesis_steps(spec);
  const auto report_progress = [&] {
    if (progress) progress(sim.step_count(), total);
  };
  // 1. Grow from half size to full size.
  const int n_growth = std::max(1, spec.growth_steps / kServoChunk);
  for (int k = 1; k <= n_growth; ++k) {
    set_scale(0.5 + 0.5 * k / n_growth);
    sim.run(kServoChunk);
    report_progress();
  }
  // 2. Servo the common radius scale to the compaction pressure (areal strain ~ 2 dscale / scale).
  const double target = spec.compaction_pressure_Pa, modulus = spec.compaction_modulus_Pa;
  for (int k = 0; k < kServoMax; ++k) {
    sim.run(kServoChunk);
    report_progress();
    const double p = wall_pressure(sim, spec);
    if (k >= 5 && std::abs(p - target) < 0.2 * target) break;
    const double change = std::clamp(-(p - target) / modulus, -2e-3, 1e-3);
    set_scale(scale * (1 + change));
  }
  report.radius_scale = scale;
  // 3. Floaters (fewer than 3 contacts): enlarge by 1 % per round, at most kFloaterRounds rounds.
  report.n_floaters_enlarged = 0;
  for (int round = 0; round < kFloaterRounds; ++round) {
    sim.evaluate_forces();
    int floaters = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (sim.n_contacts_of(k) >= 3) continue;
      sim.set_radius(k, sim.particles().radius[k] * 1.01);
      ++floaters;
      if (round == 0) ++report.n_floaters_enlarged;
    }
    if (floaters == 0) break;
    sim.invalidate_neighbours();
    sim.refresh_time_step();
    sim.run(200);
    report_progress();
  }
  sim.evaluate_forces();
  report.n_floaters_left = 0;
  for (std::size_t k = 0; k < n; ++k) report.n_floaters_left += sim.n_contacts_of(k) < 3;
  report.genesis_steps = sim.step_count();
  return out;
}

/// A specimen's joints carry the strength factors drawn for its material's Weibull modulus and reference
/// half-length (draw_joint_strengths): another material takes them only with the same two (its strengths may
/// differ, the factors being relative); InputError names the key otherwise.
void check_same_strength_draw(const BondStiffnessStrength& drawn, const BondStiffnessStrength& wanted,
                              const std::string& whose) {
  if (wanted.strength_weibull_modulus != drawn.strength_weibull_modulus)
    throw InputError("material.strength_weibull_modulus", format_value(wanted.strength_weibull_modulus),
                     whose + " " + format_value(drawn.strength_weibull_modulus) +
                         " (its joints' strengths were drawn with it; build the specimen again)");
  if (drawn.strength_weibull_modulus != 0 &&
      wanted.strength_reference_half_length_m != drawn.strength_reference_half_length_m)
    throw InputError("material.strength_reference_half_length_um",
                     format_value(units::m_to_um(wanted.strength_reference_half_length_m)),
                     whose + " " + format_value(units::m_to_um(drawn.strength_reference_half_length_m)) +
                         " (its joints' strengths were drawn with it; build the specimen again)");
}

/// The disks and joints of `source` with `material`'s laws and densities, at rest and in no group: the
/// packing only (finish_specimen, with_material).
Simulation copy_at_rest(const Simulation& source, const Material& material) {
  Simulation sim = copy_disks_and_joints(source, material, false);
  auto& p = sim.particles();
  std::fill(p.vx.begin(), p.vx.end(), 0.0), std::fill(p.vy.begin(), p.vy.end(), 0.0);
  std::fill(p.omega.begin(), p.omega.end(), 0.0), std::fill(p.group.begin(), p.group.end(), std::uint8_t{0});
  return sim;
}

/// A specimen file's key for one double of the bond law's state per element: "element_" and the law's name for it
/// (the softening flat joint's damage: "element_damage").
std::string element_state_key(std::string_view name) {
  return "element_" + std::string(name);
}

}  // namespace

CompactedPacking compact_packing(const SpecimenSpec& spec, const GenesisProgress& progress) {
  return spec.packing == Packing::hexagonal ? hexagonal_lattice(spec) : compact_random(spec, progress);
}

Simulation finish_specimen(const CompactedPacking& packing, const Material& material, const SpecimenSpec& spec,
                           SpecimenReport& report, const GenesisProgress& progress) {
  report = packing.report;
  Simulation sim = copy_at_rest(packing.disks, material);  // no joints yet, no walls
  if (spec.packing == Packing::hexagonal) {
    sim.install_bonds_within_gap(1e-6 * 0.5 * (spec.radius_min_m + spec.radius_max_m));
    draw_joint_strengths(sim, spec.seed);
    seed_flaws(sim, material, spec.seed);
    sim.initialise();
  } else {
    // 4. Joints, stress free, within the installation gap; 5. the walls are not copied; 6. relax with the
    // material's contact law (friction on) and damping.
    sim.install_bonds_within_gap(spec.installation_gap_m);
    draw_joint_strengths(sim, spec.seed);
    seed_flaws(sim, material, spec.seed);
    sim.initialise();
    sim.run(spec.relax_steps);
    if (progress) progress(report.genesis_steps + sim.step_count(), random_genesis_steps(spec));
    report.genesis_steps += sim.step_count();
    sim.evaluate_forces();
  }
  finish_report(sim, spec, report);
  // The specimen starts a test at rest, at time zero, with no crack history.
  sim.set_clock(0, 0);
  sim.cracks().clear();
  return sim;
}

Simulation make_specimen(const Material& material, const SpecimenSpec& spec, SpecimenReport& report,
                         const GenesisProgress& progress) {
  return finish_specimen(compact_packing(spec, progress), material, spec, report, progress);
}

SpecimenSource SpecimenSource::genesis(CompactedPacking packing, const SpecimenSpec& spec,
                                       const EngineSettings& engine) {
  if (packing.disks.bonds().size() != 0)
    throw ModelError("specimen", "a compacted packing has no joints (a checkpoint of an older kerf-dem?)");
  return {std::move(packing), spec, engine, true};
}

SpecimenSource SpecimenSource::saved(Simulation specimen, const EngineSettings& engine) {
  return {{std::move(specimen), {}}, {}, engine, false};
}

Simulation SpecimenSource::for_material(const Material& material) const {
  SpecimenReport report;
  Simulation sim =
      genesis_ ? finish_specimen(packing_, material, spec_, report) : with_material(packing_.disks, material);
  engine_.apply_to(sim);
  return sim;
}

Simulation with_material(const Simulation& specimen, const Material& material) {
  const int elements = std::visit([](const auto& law) { return bond_elements(law); }, material.joint);
  if (elements != specimen.bonds().stride)
    throw InputError("material.n_elements", std::to_string(elements),
                     "the specimen's element count " + std::to_string(specimen.bonds().stride));
  check_same_strength_draw(joint_bond(specimen.material()), joint_bond(material), "the specimen's");
  Simulation sim = copy_at_rest(specimen, material);
  sim.initialise();
  return sim;
}

Simulation copy_disks_and_joints(const Simulation& source, const Material& material, bool source_types,
                                 const std::vector<std::uint8_t>& keep) {
  Simulation sim(material, source.options());
  if (source_types) sim.types() = source.types();  // before the disks: their masses follow the types
  const auto& p = source.particles();
  std::vector<std::int32_t> index(p.size(), -1);
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!keep.empty() && !keep[k]) continue;
    index[k] = sim.add_particle(p.x[k], p.y[k], p.radius[k], p.type[k]);
    auto& q = sim.particles();
    const auto u = static_cast<std::size_t>(index[k]);
    q.theta[u] = p.theta[k];
    q.vx[u] = p.vx[k], q.vy[u] = p.vy[k], q.omega[u] = p.omega[k];
    q.group[u] = p.group[k];
  }
  const auto& b = source.bonds();
  for (std::size_t k = 0; k < b.size(); ++k) {
    const auto i = index[static_cast<std::size_t>(b.i[k])], j = index[static_cast<std::size_t>(b.j[k])];
    if (!b.active[k] || i < 0 || j < 0) continue;
    const auto id = static_cast<std::size_t>(sim.install_bond(i, j, b.ref_distance_m[k], b.ref_rotation_rad[k]));
    sim.bonds().copy_elements(id, b, k);
  }
  return sim;
}

void save_specimen(const std::string& file_path, const Simulation& sim, const SpecimenSpec& spec,
                   const SpecimenReport& report) {
  const auto& p = sim.particles();
  const auto& b = sim.bonds();
  Json j;
  j["format"] = "kerf-dem-specimen";
  j["version"] = 1;
  j["spec"] = specimen_spec_to_json(spec);
  j["report"] = specimen_report_to_json(report);
  j["material"] = material_to_json(sim.material());
  j["particles"] = Json{{"x_m", p.x}, {"y_m", p.y}, {"radius_m", p.radius}, {"theta_rad", p.theta}};
  std::vector<int> i, jj, bonded;
  std::vector<double> d0, rot0, shear, factor;
  const auto stride = static_cast<std::size_t>(b.stride);
  const auto m = static_cast<std::size_t>(b.state_size);
  std::vector<std::vector<double>> state(m);  // the law's state per element, one list per name
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!b.active[k]) continue;
    i.push_back(b.i[k]);
    jj.push_back(b.j[k]);
    d0.push_back(b.ref_distance_m[k]);
    rot0.push_back(b.ref_rotation_rad[k]);
    factor.push_back(b.joint_geometry(k).strength_factor);
    for (std::size_t e = 0; e < stride; ++e) {
      bonded.push_back(b.bonded[k * stride + e]);
      shear.push_back(b.shear_force_N[k * stride + e]);
      for (std::size_t s = 0; s < m; ++s) state[s].push_back(b.element_state[(k * stride + e) * m + s]);
    }
  }
  j["bonds"] = Json{{"n_elements", b.stride},
                    {"i", i},
                    {"j", jj},
                    {"ref_distance_m", d0},
                    {"ref_rotation_rad", rot0},
                    {"element_bonded", bonded},
                    {"element_shear_force_N", shear}};
  for (std::size_t s = 0; s < m; ++s)  // a law with a state of its own, each double by the law's name for it
    j["bonds"][element_state_key(b.state_names[s])] = state[s];
  const BondStiffnessStrength& bond = joint_bond(sim.material());
  if (bond.strength_weibull_modulus != 0) {  // Weibull strengths: the factors drawn, and what they were drawn with
    j["bonds"]["strength_factor"] = factor;
    j["bonds"]["strength_weibull_modulus"] = bond.strength_weibull_modulus;
    j["bonds"]["strength_reference_half_length_m"] = bond.strength_reference_half_length_m;  // SI: to the bit
  }
  write_file_atomically(file_path, j.dump());
}

Simulation load_specimen(const std::string& file_path, const Material& material, SpecimenSpec& spec,
                         SpecimenReport& report) {
  const Json j = read_json_file(file_path);
  if (j.value("format", "") != "kerf-dem-specimen" || j.value("version", 0) != 1)
    throw InputError(file_path, j.value("format", "?"), "a kerf-dem-specimen version 1 file");
  try {
    ObjectReader sr(j.at("spec"), "spec");
    spec = read_specimen_spec(sr);
    const Json& rep = j.at("report");
    report.n_particles = rep.at("n_particles");
    report.n_bonds = rep.at("n_bonds");
    report.packing_fraction = rep.at("packing_fraction");
    report.coordination_number = rep.at("coordination_number");
    report.radius_scale = rep.at("radius_scale");
    report.n_floaters_enlarged = rep.at("n_floaters_enlarged");
    report.n_floaters_left = rep.at("n_floaters_left");
    report.residual_stress_xx_Pa = units::mpa_to_pa(rep.at("residual_stress_xx_MPa").get<double>());
    report.residual_stress_yy_Pa = units::mpa_to_pa(rep.at("residual_stress_yy_MPa").get<double>());
    report.residual_stress_xy_Pa = units::mpa_to_pa(rep.at("residual_stress_xy_MPa").get<double>());
    report.genesis_steps = rep.at("genesis_steps");
    Simulation sim(material, {.thickness_m = spec.thickness_m});
    const Json& p = j.at("particles");
    const auto x = p.at("x_m").get<std::vector<double>>(), y = p.at("y_m").get<std::vector<double>>();
    const auto r = p.at("radius_m").get<std::vector<double>>(), th = p.at("theta_rad").get<std::vector<double>>();
    for (std::size_t k = 0; k < x.size(); ++k) {
      sim.add_particle(x.at(k), y.at(k), r.at(k));
      sim.particles().theta[k] = th.at(k);
    }
    const Json& b = j.at("bonds");
    const auto bi = b.at("i").get<std::vector<int>>(), bj = b.at("j").get<std::vector<int>>();
    const auto d0 = b.at("ref_distance_m").get<std::vector<double>>();
    const auto rot0 = b.at("ref_rotation_rad").get<std::vector<double>>();
    const auto bonded = b.at("element_bonded").get<std::vector<int>>();
    const auto shear = b.at("element_shear_force_N").get<std::vector<double>>();
    std::vector<std::vector<double>> state;  // the law's state per element by its names; absent: zero
    for (const std::string_view name : sim.bonds().state_names)
      state.push_back(b.value(element_state_key(name), std::vector<double>()));
    BondStiffnessStrength drawn;  // absent: uniform strengths (modulus 0)
    drawn.strength_weibull_modulus = b.value("strength_weibull_modulus", 0.0);
    drawn.strength_reference_half_length_m =
        b.value("strength_reference_half_length_m", drawn.strength_reference_half_length_m);
    check_same_strength_draw(drawn, joint_bond(material), file_path + "'s");
    const auto factor = b.value("strength_factor", std::vector<double>());
    const auto stored = static_cast<std::size_t>(b.at("n_elements").get<int>());
    const auto stride = static_cast<std::size_t>(sim.bonds().stride);
    for (std::size_t k = 0; k < bi.size(); ++k) {
      if (bi[k] < 0 || bj[k] < 0 || static_cast<std::size_t>(std::max(bi[k], bj[k])) >= x.size())
        throw InputError(file_path + ": bonds", std::to_string(k), "particle indices within the file");
      const auto id = static_cast<std::size_t>(sim.install_bond(bi[k], bj[k], d0.at(k), rot0.at(k)));
      if (!factor.empty()) sim.bonds().set_strength_factor(id, factor.at(k));
      // Element states carry over only when the element count is the same (else the joint starts intact).
      if (stored != stride) continue;
      for (std::size_t e = 0; e < stride; ++e) {
        sim.bonds().bonded[id * stride + e] = static_cast<std::uint8_t>(bonded.at(k * stride + e));
        sim.bonds().shear_force_N[id * stride + e] = shear.at(k * stride + e);
        for (std::size_t s = 0; s < state.size(); ++s)
          if (!state[s].empty())
            sim.bonds().element_state[(id * stride + e) * state.size() + s] = state[s].at(k * stride + e);
      }
    }
    sim.initialise();
    return sim;
  } catch (const Json::exception& e) {
    throw InputError(file_path, e.what(), "a complete kerf-dem-specimen file");
  }
}

}  // namespace kerf::dem
