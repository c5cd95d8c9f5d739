// The DEM engine's state as bytes (checkpoints: KERFDEM9; KERFDEM8, 7 and 6 still read) and the memory it holds.
#include <string>
#include <string_view>

#include "kerf/dem/engine/simulation.hpp"
#include "serial.hpp"

namespace kerf::dem {

namespace {
template <class... V>
std::size_t bytes_of(const V&... v) {
  return (... + (v.capacity() * sizeof(typename V::value_type)));
}

}  // namespace

std::size_t Simulation::memory_bytes() const {
  return bytes_of(p_.x, p_.y, p_.vx, p_.vy, p_.theta, p_.omega, p_.fx, p_.fy, p_.torque, p_.radius, p_.inv_mass,
                  p_.inv_inertia, p_.type, p_.group) +
         bytes_of(b_.i, b_.j, b_.ref_distance_m, b_.ref_rotation_rad, b_.geometry, b_.strength_factor, b_.active,
                  b_.shear_force_N, b_.bonded, b_.pending, b_.out, b_.element_state) +
         bytes_of(pairs_, pair_shear_, pair_out_, wall_contacts_, wall_shear_, wall_out_, incidence_start_, incidence_,
                  incidence_pair_begin_, incidence_wall_begin_, x_ref_, y_ref_, wall_ref_, fixed_, cracks_);
}

namespace {

constexpr std::string_view kStateMagic = "KERFDEM9";          // 2: Wall::friction_coefficient; 3: the laws as variants;
                                                              // 4: the viscous damping ratio; 5: skip_held_pairs;
                                                              // 6: the absorbing rates; 7: the laws by name;
                                                              // 8: the bonds' element state; 9: the joints'
                                                              // strength factors (BondStore::strength_factor)
constexpr std::string_view kStateMagicNoFactor = "KERFDEM8";  // still read: every joint's strength factor 1
constexpr std::string_view kStateMagicNoState = "KERFDEM7";   // still read: also no element state (no law had one)
constexpr std::string_view kStateMagicRawLaws = "KERFDEM6";   // still read: also the laws as raw variants of 4a34e1f

}  // namespace

template <class Self, class Io>
void Simulation::state_fields(Self& sim, Io& io, int version) {
  auto& p = sim.p_;
  auto& b = sim.b_;
  io(sim.types_);
  for (auto* v :
       {&p.x, &p.y, &p.vx, &p.vy, &p.theta, &p.omega, &p.fx, &p.fy, &p.torque, &p.radius, &p.inv_mass, &p.inv_inertia})
    io(*v);
  io(p.type, p.group);
  io(b.stride, b.i, b.j, b.ref_distance_m, b.ref_rotation_rad, b.geometry, b.active, b.shear_force_N, b.bonded,
     b.pending, b.out);
  io(sim.walls_, sim.cracks_, sim.pairs_, sim.pair_shear_, sim.pair_out_, sim.wall_contacts_, sim.wall_shear_,
     sim.wall_out_, sim.incidence_start_, sim.incidence_, sim.incidence_pair_begin_, sim.incidence_wall_begin_,
     sim.x_ref_, sim.y_ref_, sim.wall_ref_, sim.fixed_, sim.absorbing_rate_);
  io(sim.need_rebuild_, sim.need_breaks_, sim.initialised_, sim.dt_fixed_);
  io(sim.dt_, sim.time_, sim.skin_, sim.speed_limit_, sim.steps_);
  // Last, so that the earlier formats are this one without them.
  if (version == 0 || version == 1) io(b.element_state);
  if (version == 0) io(b.strength_factor);
}

std::string Simulation::serialize() const {
  std::string out(kStateMagic);
  serial::Out io{out};
  io(material_.density_kg_per_m3, material_.contact, material_.joint, material_.local_damping,
     material_.viscous_damping_ratio, material_.name, opt_);
  state_fields(*this, io, 0);
  return out;
}

Simulation Simulation::deserialize(std::string_view bytes) {
  std::size_t version = 0;
  serial::In io = serial::open_tagged(bytes, {kStateMagic, kStateMagicNoFactor, kStateMagicNoState, kStateMagicRawLaws},
                                      "engine state", &version);
  io.raw_laws = version == 3;
  Material m;
  SimulationOptions opt;
  io(m.density_kg_per_m3, m.contact, m.joint, m.local_damping, m.viscous_damping_ratio, m.name, opt);
  Simulation sim(m, opt);
  state_fields(sim, io, static_cast<int>(version));
  io.expect_end("engine state");
  const BondStore& b = sim.b_;
  if (b.element_state.size() != b.bonded.size() * static_cast<std::size_t>(b.state_size))
    throw ModelError("dem", "corrupt checkpoint (the bond law's element state does not match the elements)");
  if (!b.strength_factor.empty() && b.strength_factor.size() != b.size())
    throw ModelError("dem", "corrupt checkpoint (the joints' strength factors do not match the joints)");
  return sim;
}

}  // namespace kerf::dem
