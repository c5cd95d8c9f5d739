// The DEM engine's setup: particles, joints and walls added, the absorbing rates, the stable time step and the
// first neighbour search and force evaluation (initialise). The step is in simulation.cpp.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

int BondStore::n_bonded_elements(std::size_t b) const {
  int n = 0;
  for (int e = 0; e < stride; ++e) n += bonded[b * static_cast<std::size_t>(stride) + e];
  return n;
}

void BondStore::copy_elements(std::size_t to, const BondStore& from, std::size_t k) {
  if (!from.strength_factor.empty()) set_strength_factor(to, from.strength_factor[k]);
  const auto n = static_cast<std::size_t>(stride);
  for (std::size_t e = 0; e < n; ++e) {
    bonded[to * n + e] = from.bonded[k * n + e];
    shear_force_N[to * n + e] = from.shear_force_N[k * n + e];
  }
  if (state_size > 0 && from.state_size == state_size) {  // the law's state: copied, not read
    const std::size_t m = n * static_cast<std::size_t>(state_size);
    std::copy_n(from.element_state.begin() + static_cast<std::ptrdiff_t>(k * m), m,
                element_state.begin() + static_cast<std::ptrdiff_t>(to * m));
  }
}

Simulation::Simulation(const Material& material, const SimulationOptions& options)
    : material_(material), opt_(options), types_{ParticleType{material.density_kg_per_m3}} {
  if (!(options.thickness_m > 0))
    throw InputError("specimen.thickness_mm", format_value(options.thickness_m * 1e3), "a positive value in mm");
  if (!(options.time_step_safety > 0 && options.time_step_safety <= 1))
    throw InputError("engine.time_step_safety", format_value(options.time_step_safety), "a value in (0, 1]");
  b_.stride = std::visit([](const auto& law) { return bond_elements(law); }, material.joint);
  b_.state_size =
      std::visit([](const auto& law) { return bond_state_size<std::decay_t<decltype(law)>>(); }, material.joint);
  b_.state_names =
      std::visit([](const auto& law) { return bond_state_names<std::decay_t<decltype(law)>>(); }, material.joint);
  speed_limit_ = options.speed_limit_m_per_s > 0 ? options.speed_limit_m_per_s : p_wave_speed_m_per_s(material);
}

double p_wave_speed_m_per_s(const Material& material) {
  const double contact_modulus_Pa =
      std::visit([](const auto& law) { return law.effective_modulus_Pa; }, material.contact);
  return std::sqrt(contact_modulus_Pa / material.density_kg_per_m3);
}

void refuse_small_time_step_safety(double steps, double time_step_s, double safety) {
  const double default_safety = SimulationOptions{}.time_step_safety;
  // dt is proportional to the safety: at the default the run would take steps * safety / default steps.
  if (!(steps > kMaxRunSteps) || safety >= default_safety || !(steps * safety / default_safety <= kMaxRunSteps)) return;
  throw InputError("engine.time_step_safety", format_value(safety),
                   fmt::format("at least {}: smaller, the run takes {:.3g} time steps of {} ns, more than {}",
                               format_value(safety * steps / kMaxRunSteps), steps, format_value(time_step_s * 1e9),
                               format_value(kMaxRunSteps)));
}

void Simulation::set_time_step_safety(double f) {
  if (!(f > 0 && f <= 1)) throw InputError("engine.time_step_safety", format_value(f), "a value in (0, 1]");
  opt_.time_step_safety = f;
  if (initialised_) refresh_time_step();
}

double Simulation::mass_of(double radius_m, std::uint8_t type) const {
  return types_.at(type).density_kg_per_m3 * std::numbers::pi * radius_m * radius_m * opt_.thickness_m;
}

int Simulation::add_particle(double x_m, double y_m, double radius_m, std::uint8_t type) {
  const double m = mass_of(radius_m, type);
  p_.x.push_back(x_m);
  p_.y.push_back(y_m);
  for (auto* v : {&p_.vx, &p_.vy, &p_.theta, &p_.omega, &p_.fx, &p_.fy, &p_.torque}) v->push_back(0.0);
  p_.radius.push_back(radius_m);
  p_.inv_mass.push_back(1.0 / m);
  p_.inv_inertia.push_back(2.0 / (m * radius_m * radius_m));  // disk: I = m r^2 / 2
  p_.type.push_back(type);
  p_.group.push_back(0);
  if (!absorbing_rate_.empty()) absorbing_rate_.push_back(0.0);
  // Added to a running simulation: the next step's drift measures its move from where it starts (the neighbour
  // lists are rebuilt after that drift).
  if (initialised_) x_ref_.push_back(x_m), y_ref_.push_back(y_m);
  need_rebuild_ = true;
  return static_cast<int>(p_.size() - 1);
}

void Simulation::set_absorbing_rates(std::vector<double> rates_per_s) {
  if (!rates_per_s.empty() && rates_per_s.size() != p_.size())
    throw std::logic_error("Simulation::set_absorbing_rates: one rate per disk");
  for (double r : rates_per_s)
    if (!(r >= 0 && std::isfinite(r)))
      throw std::logic_error("Simulation::set_absorbing_rates: a rate not finite and >= 0");
  absorbing_rate_ = std::move(rates_per_s);
  absorbing_decay_.clear();
  absorbing_dt_ = 0;
}

void Simulation::set_radius(std::size_t i, double radius_m) {
  const double m = mass_of(radius_m, p_.type[i]);
  p_.radius[i] = radius_m;
  p_.inv_mass[i] = 1.0 / m;
  p_.inv_inertia[i] = 2.0 / (m * radius_m * radius_m);
}

int Simulation::add_wall(const Wall& wall) {
  walls_.push_back(wall);
  need_rebuild_ = true;
  return static_cast<int>(walls_.size() - 1);
}

int Simulation::install_bond(int i, int j) {
  if (i > j) std::swap(i, j);
  const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
  return install_bond(i, j, std::hypot(p_.x[uj] - p_.x[ui], p_.y[uj] - p_.y[ui]), p_.theta[uj] - p_.theta[ui]);
}

int Simulation::install_bond(int i, int j, double ref_distance_m, double ref_rotation_rad) {
  const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
  b_.i.push_back(i);
  b_.j.push_back(j);
  b_.ref_distance_m.push_back(ref_distance_m);
  b_.ref_rotation_rad.push_back(ref_rotation_rad);
  b_.geometry.push_back(std::visit(
      [&](const auto& law) -> BondInterface {
        return bond_geometry(law, p_.radius[ui], p_.radius[uj], opt_.thickness_m);
      },
      material_.joint));
  if (!b_.strength_factor.empty()) b_.strength_factor.push_back(1.0);
  b_.active.push_back(1);
  for (int e = 0; e < b_.stride; ++e) {
    b_.shear_force_N.push_back(0.0);
    b_.bonded.push_back(1);
    b_.pending.push_back(BreakMode::none);
    for (int s = 0; s < b_.state_size; ++s) b_.element_state.push_back(0.0);
  }
  b_.out.push_back({0, 0, 0, 0});
  need_rebuild_ = true;
  return static_cast<int>(b_.size() - 1);
}

int Simulation::install_bonds_within_gap(double gap_m) {
  std::vector<CandidatePair> candidates;
  find_candidate_pairs(p_.x, p_.y, p_.radius, gap_m, candidates);
  std::vector<CandidatePair> existing;
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b]) existing.push_back({b_.i[b], b_.j[b]});
  std::sort(existing.begin(), existing.end());
  int n = 0;
  for (const auto& c : candidates) {
    if (std::binary_search(existing.begin(), existing.end(), c)) continue;
    install_bond(c.i, c.j);
    ++n;
  }
  return n;
}

double Simulation::stable_time_step() const {
  const std::size_t n = p_.size();
  std::vector<double> kt(n, 0.0), kr(n, 0.0);
  const double t = opt_.thickness_m;
  // A contact's stiffness on disk u: the larger eigenvalue of k_n n n + k_s s s, and the rotational k_b + k_s r^2.
  const auto add = [&](std::size_t u, const TimeStepStiffness& k) {
    kt[u] += std::max(k.normal, k.shear);
    kr[u] += k.bending + k.shear * p_.radius[u] * p_.radius[u];
  };
  std::visit(
      [&](const auto& law) {
        for (std::size_t b = 0; b < b_.size(); ++b) {
          if (!b_.active[b]) continue;
          const TimeStepStiffness k = bond_time_step_stiffness(law, b_.joint_geometry(b));
          for (auto u : {b_.i[b], b_.j[b]}) add(static_cast<std::size_t>(u), k);
        }
      },
      material_.joint);
  return std::visit(
      [&](const auto& law) {
        for (const auto& c : pairs_) {
          const TimeStepStiffness k = contact_time_step_stiffness(law, p_.radius[c.i], p_.radius[c.j], t);
          add(static_cast<std::size_t>(c.i), k);
          add(static_cast<std::size_t>(c.j), k);
        }
        for (const auto& wc : wall_contacts_) {
          const auto u = static_cast<std::size_t>(wc[1]);
          add(u, contact_time_step_stiffness(law, p_.radius[u], 0.0, t));
        }
        double dt = std::numeric_limits<double>::infinity();
        for (std::size_t u = 0; u < n; ++u) {
          // Floor: four contacts with an equal disk, so that contacts formed later (fracture, genesis) stay
          // stable. With f_safety <= 0.8 the step keeps a margin of about sqrt(2) / 0.8 on the Gershgorin bound
          // of the largest eigenfrequency, sqrt(2 sum k / m).
          const TimeStepStiffness self = contact_time_step_stiffness(law, p_.radius[u], p_.radius[u], t);
          const double ktu = std::max(kt[u], 4 * std::max(self.normal, self.shear));
          const double kru = std::max(kr[u], 4 * self.shear * p_.radius[u] * p_.radius[u]);
          dt = std::min({dt, std::sqrt(1.0 / (p_.inv_mass[u] * ktu)), std::sqrt(1.0 / (p_.inv_inertia[u] * kru))});
        }
        dt *= opt_.time_step_safety;
        // A density or stiffness so extreme that the masses or the step leave the doubles (1e308 kg/m^3:
        // dt = inf; 1e-300: the masses underflow) cannot be integrated: say which inputs, before any step.
        if (!(std::isfinite(dt) && dt > 0))
          throw ModelError("dem", fmt::format("the stable time step is {:.4g} s, not a positive finite number: the "
                                              "masses or stiffnesses are beyond double precision "
                                              "(material.density_kg_per_m3 = {:.6g}, specimen.thickness_mm = {:.6g})",
                                              dt, material_.density_kg_per_m3, 1e3 * t));
        return dt;
      },
      material_.contact);
}

void Simulation::initialise() {
  if (p_.size() == 0) throw ModelError("dem", "no particles to simulate");
  skin_ = opt_.skin_m > 0 ? opt_.skin_m : 0.3 * *std::min_element(p_.radius.begin(), p_.radius.end());
  rebuild_neighbours();
  if (!dt_fixed_) dt_ = stable_time_step();
  evaluate_forces();
  initialised_ = true;
}

}  // namespace kerf::dem
