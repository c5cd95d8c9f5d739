// The orthogonal cut's state as bytes (CutRun::serialize, deserialize; checkpoints: KERFCUTB; KERFCUTA to KERFCUT7
// still read).
#include <string>
#include <string_view>
#include <type_traits>

#include "../engine/serial.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

namespace {

constexpr std::string_view kCutMagic = "KERFCUTB";         // 3: tool_friction_coefficient, 4: rake_face_height_m,
                                                           // 5: the active window, 6: its absorbing layer,
                                                           // 7: the held rows' layer, 8: the parameters by key,
                                                           // 9: the energy books, A (10): the edge's record,
                                                           // B (11): the edge zone's record
constexpr std::string_view kCutMagicNoZone = "KERFCUTA";   // still read: no edge zone (its parameters are new too)
constexpr std::string_view kCutMagicNoEdge = "KERFCUT9";   // still read: no edge record (the run keeps none)
constexpr std::string_view kCutMagicNoBooks = "KERFCUT8";  // still read: no energy books (the run keeps none)
constexpr std::string_view kCutMagicListed = "KERFCUT7";   // still read: the parameters listed by hand

/// A KERFCUT7 state's reader: CutRun::state_fields reads that format's order with it (frozen, as the format was).
struct Cut7In {
  serial::In& io;
  template <class... T>
  void operator()(T&... v) {
    io(v...);
  }
};

/// The cut's parameters by the keys of the scene sections that hold them: each section's table, read through its
/// member of CutParams (the records' keys and order as when CutParams was one flat struct).
const std::array<serial::SectionFields<CutParams>, 5>& cut_sections() {
  using P = CutParams;
  static const FieldTable<P> cut = embedded_fields(cut_fields(), &P::cut),
                             tool = embedded_fields(tool_fields(), &P::tool),
                             grooves = embedded_fields(groove_fields(), &P::grooves),
                             window = embedded_fields(active_window_fields(), &P::window),
                             zone = embedded_fields(edge_zone_fields(), &P::edge_zone);
  static const std::array<serial::SectionFields<P>, 5> sections{
      {{"cut", cut}, {"tool", tool}, {"grooves", grooves}, {"active_window", window}, {"edge_zone", zone}}};
  return sections;
}

}  // namespace

// The run's state after its parameters (which serialize() writes by key from their tables). Called with
// Cut7In, the frozen order of a KERFCUT7 state: the parameters by hand among the other fields.
template <class Self, class Io>
void CutRun::state_fields(Self& run, Io& io) {
  auto& r = run.res_;
  if constexpr (std::is_same_v<Io, Cut7In>) {
    auto& p = run.params_;
    io(p.cut.depth_of_cut_m, p.cut.speed_m_per_s, p.cut.length_m, p.tool.rake_deg, p.tool.clearance_deg,
       p.tool.edge_radius_m, p.grooves.depth_m, p.grooves.pitch_m, p.grooves.width_m, p.grooves.bottom_width_m,
       p.cut.entry_fraction, p.cut.window_m, p.tool.friction_coefficient, p.tool.rake_face_height_m);
    std::string groove_shape;  // by name, as before the enum
    io(p.tool.edge_segments, p.cut.sample_every_steps, groove_shape, r.samples);
    p.grooves.shape = groove_shape_names().parse(groove_shape, "cut checkpoint");
    io(r.y_top_m, r.y_cut_m, r.width_m, r.time_step_s, r.wall_time_s, run.t0_, r.workpiece_box_m);
    io(r.n_particles, r.n_removed_by_grooves, r.steps, run.first_tool_wall_, run.n_tool_walls_, run.finished_);
    io(p.window.enabled, p.window.ahead_depths, p.window.behind_depths, p.window.below_depths, p.window.above_depths,
       p.window.shift_depths, r.particle_steps, p.window.absorbing_depths, p.window.absorbing_attenuation);
    io(p.cut.held_absorbing_depths);
  } else {
    io(r.samples, r.y_top_m, r.y_cut_m, r.width_m, r.time_step_s, r.wall_time_s, run.t0_, r.workpiece_box_m);
    io(r.n_particles, r.n_removed_by_grooves, r.steps, run.first_tool_wall_, run.n_tool_walls_, run.finished_,
       r.particle_steps);
  }
}

std::string CutRun::serialize() const {
  std::string out(kCutMagic);
  serial::put_fields(out, cut_sections(), params_);
  serial::Out io{out};
  state_fields(*this, io);
  io(sim_.serialize(), window_ ? window_->serialize() : std::string());
  book_fields(*this, io);
  edge_fields(*this, io);
  zone_record_fields(*this, io);
  return out;
}

template <class Self, class Io>
void CutRun::zone_record_fields(Self& run, Io& io) {
  auto& z = run.res_.edge_zone;
  io(z.samples, z.intact_samples, z.tool_work_J, z.reaction_work_J);
}

template <class Self, class Io>
void CutRun::edge_fields(Self& run, Io& io) {
  io(run.edge_kept_, run.edge_last_step_, run.res_.edge);
}

template <class Self, class Io>
void CutRun::book_fields(Self& run, Io& io) {
  io(run.books_kept_, run.steady_booked_);
  for (auto* b : {&run.books_, &run.books_steady_start_})
    io(b->tool_work_J, b->left_kinetic_J, b->left_strain_J, b->kinetic_J, b->strain_J);
}

CutRun CutRun::deserialize(std::string_view bytes) {
  std::size_t version = 0;
  serial::In io =
      serial::open_tagged(bytes, {kCutMagic, kCutMagicNoZone, kCutMagicNoEdge, kCutMagicNoBooks, kCutMagicListed},
                          "cut checkpoint", &version);
  CutRun run;
  if (version == 4) {
    Cut7In listed{io};
    state_fields(run, listed);
  } else {
    serial::get_fields(io, cut_sections(), run.params_, "cut checkpoint");
    state_fields(run, io);
  }
  std::string state, window;
  io(state, window);
  if (version <= 2)
    book_fields(run, io);
  else
    run.books_kept_ = false;  // an older kerf kept no books: the finished run reports none
  if (version <= 1)
    edge_fields(run, io);
  else
    run.edge_kept_ = false;                       // nor the edge's record
  if (version == 0) zone_record_fields(run, io);  // an older one has no edge zone (its parameters are off)
  io.expect_end("cut checkpoint");
  validate_cut_params(run.params_);
  run.sim_ = Simulation::deserialize(state);
  if (run.params_.window.enabled != !window.empty()) throw ModelError("dem", "corrupt cut checkpoint (the window)");
  if (run.params_.window.enabled) {
    run.window_ = CutWindow::deserialize(window);
    run.window_->set_remove_loose_fragments(run.params_.window.remove_loose_fragments);  // a parameter, stored by key
  }
  if (run.finished_) run.finish();
  return run;
}

}  // namespace kerf::dem
