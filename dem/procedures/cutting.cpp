// Orthogonal cutting (seed 000, Section 4; physics-dem.md section 4).
#include "kerf/dem/procedures/cutting.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <type_traits>

#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/time_series.hpp"
#include "kerf/units.hpp"
#include "../engine/serial.hpp"

namespace kerf::dem {

namespace {
constexpr double kPi = std::numbers::pi;

void require(bool ok, const std::string& key, double value, const std::string& expected) {
  if (!ok) throw InputError(key, format_value(value), expected);
}

/// Wedge angle between the rake and clearance faces [rad]: 90 deg - rake - clearance.
double wedge_angle_rad(const CutParams& p) { return units::deg_to_rad(90.0 - p.rake_deg - p.clearance_deg); }

/// Face lengths [m]: the rake face reaches tool.rake_face_height_mm above the tip (default 3 depths of cut,
/// room for the chip), the clearance face is 2 depths of cut long.
double rake_face_length_m(const CutParams& p) {
  const double height = p.rake_face_height_m > 0 ? p.rake_face_height_m : 3 * p.depth_of_cut_m;
  return height / std::cos(units::deg_to_rad(p.rake_deg));
}
double clearance_face_length_m(const CutParams& p) {
  return 2 * p.depth_of_cut_m;
}
}  // namespace

const EnumNames<GrooveShape>& groove_shape_names() {
  static constexpr std::string_view names[] = {"none", "rectangular", "trapezoidal"};
  static const EnumNames<GrooveShape> table{names};
  return table;
}

const FieldTable<CutParams>& cut_fields() {
  using namespace units;
  using P = CutParams;
  static const FieldTable<CutParams> table{
      required_number_field("depth_of_cut_mm", kMm, Range::positive(), "depth of cut below the top surface",
                            &P::depth_of_cut_m),
      number_field("speed_m_per_s", kSi("m/s"), Range::positive(), "cutting speed (scaled up from the seed's)",
                   &P::speed_m_per_s),
      required_number_field("length_mm", kMm, Range::positive(), "tool travel", &P::length_m),
      number_field("entry_fraction", kNone, Range{0.0, 1.0, false, true},
                   "part of the travel left out of the mean forces (the entry)", &P::entry_fraction),
      int_field("sample_every_steps", 1, 1000000, "steps per force sample", &P::sample_every_steps),
      number_field("window_mm", kMm, Range::positive(),
                   "travel per window of results.travel_windows (at least 1/1000 of length_mm)", &P::window_m),
      number_field("held_absorbing_depths", kNone, Range::non_negative(),
                   "absorbing layer along the workpiece's held left side and bottom rows, in depths of cut (0: none; "
                   "the held rows are rigid and reflect the waves an undamped cut sends out; attenuation: "
                   "active_window.absorbing_attenuation)",
                   &P::held_absorbing_depths)};
  return table;
}

const FieldTable<CutParams>& tool_fields() {
  using namespace units;
  using P = CutParams;
  static const FieldTable<CutParams> table{
      number_field("rake_deg", kSi("deg"), Range::open(-90.0, 90.0), "rake angle", &P::rake_deg),
      number_field("clearance_deg", kSi("deg"), Range{0.0, 90.0, false, true},
                   "clearance angle (rake + clearance below 89 deg)", &P::clearance_deg),
      number_field("edge_radius_um", kUm, Range::non_negative(), "cutting-edge radius; 0: sharp", &P::edge_radius_m),
      int_field("edge_segments", 1, 64, "wall segments of a rounded edge", &P::edge_segments),
      number_field("friction_coefficient", kNone, Range::non_negative(),
                   "tool-workpiece Coulomb friction; absent (-1): the material's particle friction",
                   &P::tool_friction_coefficient),
      number_field("rake_face_height_mm", kMm, Range::non_negative(),
                   "rake-face top above the tip; 0: 3 depths of cut", &P::rake_face_height_m)};
  return table;
}

const FieldTable<CutParams>& groove_fields() {
  using namespace units;
  using P = CutParams;
  static const FieldTable<CutParams> table{
      choice_field("shape", groove_shape_names(), "micro-grooves across the cut path", &P::groove_shape),
      number_field("depth_mm", kMm, Range::positive(), "groove depth (default: the depth of cut)", &P::groove_depth_m),
      number_field("pitch_mm", kMm, Range::positive(), "distance between groove centres", &P::groove_pitch_m),
      number_field("width_mm", kMm, Range::positive(), "groove width at the surface (below the pitch)",
                   &P::groove_width_m),
      number_field("bottom_width_mm", kMm, Range::non_negative(),
                   "trapezoidal: width at the groove bottom (default: half the width)", &P::groove_bottom_width_m),
      number_field("damage_depth_um", kUm, Range::non_negative(),
                   "laser-affected layer: joints within this distance of a groove's walls and bottom are pre-broken "
                   "(0: pristine glass up to the groove)",
                   &P::groove_damage_depth_m),
      number_field("damage_broken_fraction", kNone, Range::closed(0, 1),
                   "share of the layer's joints pre-broken (chosen by a hash of the joint: reproducible per packing)",
                   &P::groove_damage_broken_fraction)};
  return table;
}

const FieldTable<CutParams>& active_window_fields() {
  using namespace units;
  using P = CutParams;
  static const FieldTable<CutParams> table{
      bool_field("enabled", "integrate only the disks around the tool (a steady-state cut of a long workpiece)",
                 &P::active_window),
      number_field("ahead_depths", kNone, Range::positive(), "window ahead of the cutting edge, in depths of cut",
                   &P::window_ahead_depths),
      number_field("behind_depths", kNone, Range::positive(), "window behind the cutting edge, in depths of cut",
                   &P::window_behind_depths),
      number_field("below_depths", kNone, Range::positive(), "window below the cut line, in depths of cut",
                   &P::window_below_depths),
      number_field("above_depths", kNone, Range::positive(),
                   "window above the uncut surface (the chip's room; a chip leaving it is removed), in depths of cut",
                   &P::window_above_depths),
      number_field("shift_depths", kNone, Range::positive(),
                   "tool travel between rebuilds of the window, in depths of cut (below ahead_depths)",
                   &P::window_shift_depths),
      number_field("absorbing_depths", kNone, Range::non_negative(),
                   "absorbing layer inside the window's ahead, behind and lower edges, in depths of cut (0: none; the "
                   "held frame is rigid and reflects the waves an undamped cut sends out)",
                   &P::window_absorbing_depths),
      number_field("absorbing_attenuation", kNone, Range::positive(),
                   "e-folds by which the absorbing layer (and cut.held_absorbing_depths') attenuates a p-wave's amplitude "
                   "through it and back",
                   &P::window_absorbing_attenuation),
      bool_field("remove_loose_fragments",
                 "a bound, not a model of glass: at each rebuild remove every disk above the cut line that no intact "
                 "joint path ties to the held rows (every loose fragment gone at once)",
                 &P::window_remove_loose_fragments),
      number_field("grain_strength_MPa", kMPa, Range::non_negative(),
                   "debris grains crush: a disk of a loose fragment pressed by the tool with more than its splitting "
                   "load pi sigma r t is removed (0: disks never break)",
                   &P::window_grain_strength_pa),
      number_field("tied_grain_strength_MPa", kMPa, Range::non_negative(),
                   "the workpiece's own disks crush: a disk still tied to the workpiece pressed by the tool with more "
                   "than pi sigma r t is removed, its joints with it (0: it breaks only by its joints)",
                   &P::window_tied_grain_strength_pa)};
  return table;
}

const FieldTable<CutParams>& edge_zone_fields() {
  using namespace units;
  using P = CutParams;
  // A force the scene may give; absent (negative in the struct) until the cut kind computes it from the material.
  const auto given_force = [](std::string_view key, std::string_view doc, double P::*member) {
    NumberField<P> f = number_field(key, kNPerMm, Range::non_negative(), doc, member);
    f.has = [member](const P& p) { return p.*member >= 0; };
    f.absent = "kerf-forces' edge model of the material";
    return f;
  };
  static const FieldTable<CutParams> table{
      bool_field("enabled",
                 "the tool's edge as a sub-grid model: the ductile layer's force from the analytic side while the edge "
                 "meets intact glass, the disks it reaches removed as its chip (windowed cuts)",
                 &P::edge_zone),
      number_field("radius_um", kUm, Range::non_negative(),
                   "reach of the zone around the tool's tip (0: the workpiece's largest disk diameter)",
                   &P::edge_zone_radius_m),
      number_field("layer_factor", kNone, Range::positive(),
                   "ductile layer l = layer_factor x d_c (Bifano's critical depth of the material)", &P::edge_layer_factor),
      number_field("friction_coefficient", kNone, Range::non_negative(),
                   "tool-glass friction of the layer's cut (0.15-0.4: docs/physics-glass-edge.md)",
                   &P::edge_friction_coefficient),
      given_force("cutting_force_N_per_mm", "the layer's cutting force per unit width (with thrust_force_N_per_mm)",
                  &P::edge_cutting_force_n_per_m),
      given_force("thrust_force_N_per_mm", "the layer's thrust force per unit width (with cutting_force_N_per_mm)",
                  &P::edge_thrust_force_n_per_m)};
  return table;
}

namespace {
/// The relations between fields (each field's own range is its table's); errors name section.key.
void check_cut_relations(const CutParams& p) {
  require(p.window_m >= 1e-3 * p.length_m, "cut.window_mm", units::m_to_mm(p.window_m),
          "a positive window of at least 1/1000 of cut.length_mm");
  require(p.window_grain_strength_pa == 0 || p.active_window, "active_window.grain_strength_MPa",
          units::pa_to_mpa(p.window_grain_strength_pa), "0 unless active_window.enabled (only a window removes disks)");
  require(p.window_tied_grain_strength_pa == 0 || p.active_window, "active_window.tied_grain_strength_MPa",
          units::pa_to_mpa(p.window_tied_grain_strength_pa),
          "0 unless active_window.enabled (only a window removes disks)");
  // The wedge between the two faces must be a real wedge: rake + clearance < 90 deg.
  require(p.rake_deg + p.clearance_deg < 89, "tool.clearance_deg", p.clearance_deg,
          "rake_deg + clearance_deg below 89 deg (a tool wedge angle of at least 1 deg)");
  // The rake face must rise above the uncut surface, or the chip would meet the tool's back face.
  require(p.rake_face_height_m == 0 || p.rake_face_height_m > p.depth_of_cut_m, "tool.rake_face_height_mm",
          units::m_to_mm(p.rake_face_height_m),
          "a height above the depth of cut (" + format_value(units::m_to_mm(p.depth_of_cut_m)) +
              " mm), or 0 for 3 depths of cut");
  // The rounded edge must fit on the faces (see tool_outline).
  const double tangent = p.edge_radius_m / std::tan(0.5 * wedge_angle_rad(p));
  require(tangent < std::min(rake_face_length_m(p), clearance_face_length_m(p)), "tool.edge_radius_um",
          units::m_to_um(p.edge_radius_m), "an edge radius whose rounding fits on both tool faces");
  require(!p.edge_zone || p.active_window, "edge_zone.enabled", 1.0,
          "false unless active_window.enabled (the zone removes disks through the window)");
  require((p.edge_cutting_force_n_per_m < 0) == (p.edge_thrust_force_n_per_m < 0), "edge_zone.thrust_force_N_per_mm",
          units::n_per_m_to_n_per_mm(p.edge_thrust_force_n_per_m),
          "given together with edge_zone.cutting_force_N_per_mm, or both absent (the material's edge model)");
  if (p.active_window)
    require(p.window_shift_depths < p.window_ahead_depths, "active_window.shift_depths", p.window_shift_depths,
            "a shift below active_window.ahead_depths (" + format_value(p.window_ahead_depths) +
                "): the tool must not leave the window between two rebuilds");
  if (p.active_window)
    require(p.window_absorbing_depths <
                std::min({p.window_ahead_depths, p.window_behind_depths, p.window_below_depths}),
            "active_window.absorbing_depths", p.window_absorbing_depths,
            "a layer thinner than the window's ahead, behind and below depths");
  if (p.groove_shape == GrooveShape::none) return;
  require(p.groove_width_m < p.groove_pitch_m, "grooves.width_mm", units::m_to_mm(p.groove_width_m),
          "a positive width below grooves.pitch_mm (" + format_value(units::m_to_mm(p.groove_pitch_m)) + " mm)");
  if (p.groove_shape == GrooveShape::trapezoidal)
    require(p.groove_bottom_width_m < p.groove_width_m, "grooves.bottom_width_mm",
            units::m_to_mm(p.groove_bottom_width_m),
            "a value in [0, grooves.width_mm) (an inverted trapezoid is narrower at the bottom)");
}
}  // namespace

void validate_cut_params(const CutParams& p) {
  with_path("cut", [&] { check_fields(cut_fields(), p); });
  CutParams tool = p;
  if (tool.tool_friction_coefficient < 0) tool.tool_friction_coefficient = 0;  // negative: the material's
  with_path("tool", [&] { check_fields(tool_fields(), tool); });
  if (p.groove_shape != GrooveShape::none) with_path("grooves", [&] { check_fields(groove_fields(), p); });
  if (p.active_window) with_path("active_window", [&] { check_fields(active_window_fields(), p); });
  if (p.edge_zone) with_path("edge_zone", [&] { check_fields(edge_zone_fields(), p); });
  check_cut_relations(p);
}

CutParams read_cut_params(ObjectReader& root) {
  CutParams p;
  ObjectReader cut = root.get_object("cut");
  p = read_fields(cut, cut_fields(), p);
  cut.finish();
  if (auto tool = root.find_object("tool")) {
    p = read_fields(*tool, tool_fields(), p);
    tool->finish();
  }
  if (auto grooves = root.find_object("grooves")) {
    // Seed 000 Section 4: groove depth = depth of cut (as the depth in mm read back), pitch 0.2 mm, width 0.06 mm.
    p.groove_depth_m = units::mm_to_m(units::m_to_mm(p.depth_of_cut_m));
    p = read_fields(*grooves, groove_fields(), p);
    if (!grooves->has("bottom_width_mm"))
      p.groove_bottom_width_m = units::mm_to_m(units::m_to_mm(0.5 * p.groove_width_m));
    grooves->finish();
  }
  if (auto window = root.find_object("active_window")) {
    p = read_fields(*window, active_window_fields(), p);
    window->finish();
  }
  if (auto zone = root.find_object("edge_zone")) {
    p = read_fields(*zone, edge_zone_fields(), p);
    zone->finish();
  }
  check_cut_relations(p);
  return p;
}

Json cut_params_to_json(const CutParams& p) {
  Json j{{"cut", fields_to_json(cut_fields(), p)},
         {"tool", fields_to_json(tool_fields(), p)},
         {"grooves", fields_to_json(groove_fields(), p)}};
  // Only when given: scenes without them keep their replicate_inputs (and so their reusable replicates).
  if (p.tool_friction_coefficient < 0) j["tool"].erase("friction_coefficient");
  if (p.rake_face_height_m <= 0) j["tool"].erase("rake_face_height_mm");
  if (p.groove_shape == GrooveShape::none) j["grooves"] = Json{{"shape", "none"}};
  if (p.groove_shape != GrooveShape::trapezoidal) j["grooves"].erase("bottom_width_mm");
  if (p.groove_damage_depth_m <= 0) {  // pristine: the summaries of scenes without a damaged layer unchanged
    j["grooves"].erase("damage_depth_um");
    j["grooves"].erase("damage_broken_fraction");
  }
  if (p.active_window) j["active_window"] = fields_to_json(active_window_fields(), p);
  if (p.edge_zone) j["edge_zone"] = fields_to_json(edge_zone_fields(), p);  // only when on: other summaries unchanged
  return j;
}

bool inside_groove_outline(const CutParams& p, double dx_m, double depth_m) {
  if (p.groove_shape == GrooveShape::none || depth_m < 0 || depth_m > p.groove_depth_m) return false;
  double width = p.groove_width_m;
  // The laser grooves are inverted trapezoids (seed 000 Section 4, discussion of Figure 18): the width
  // falls linearly from the top width at the surface to the bottom width at the groove depth.
  if (p.groove_shape == GrooveShape::trapezoidal)
    width += (p.groove_bottom_width_m - p.groove_width_m) * depth_m / p.groove_depth_m;
  return std::abs(dx_m) <= 0.5 * width;
}

double distance_to_groove_outline(const CutParams& p, double dx_m, double depth_m) {
  if (inside_groove_outline(p, dx_m, depth_m)) return 0;
  const double top = 0.5 * p.groove_width_m, depth = p.groove_depth_m;
  const double bottom = p.groove_shape == GrooveShape::trapezoidal ? 0.5 * p.groove_bottom_width_m : top;
  // The nearest of the two walls (by symmetry, the one on the point's side) and the bottom.
  const double x = std::abs(dx_m);
  const auto to_segment = [&](double ax, double ay, double bx, double by) {
    const double ux = bx - ax, uy = by - ay;
    const double s = std::clamp(((x - ax) * ux + (depth_m - ay) * uy) / (ux * ux + uy * uy), 0.0, 1.0);
    return std::hypot(x - (ax + s * ux), depth_m - (ay + s * uy));
  };
  return std::min(to_segment(top, 0, bottom, depth), to_segment(0, depth, bottom, depth));
}

std::array<std::size_t, 2> apply_groove_damage(Simulation& workpiece, const CutParams& p,
                                               const std::array<double, 4>& box_m) {
  std::array<std::size_t, 2> count{};
  if (p.groove_shape == GrooveShape::none || p.groove_damage_depth_m <= 0) return count;
  const auto& q = workpiece.particles();
  auto& b = workpiece.bonds();
  const double y_top_m = box_m[3];
  const auto centres = groove_centres(p, box_m[0], box_m[1]);
  const auto stride = static_cast<std::size_t>(b.stride);
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!b.active[k]) continue;
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    const double x = 0.5 * (q.x[i] + q.x[j]), depth = y_top_m - 0.5 * (q.y[i] + q.y[j]);
    bool in_layer = false;
    for (double c : centres)
      in_layer = in_layer || distance_to_groove_outline(p, x - c, depth) <= p.groove_damage_depth_m;
    if (!in_layer) continue;
    ++count[0];
    // SplitMix64's finaliser of the joint's index: a uniform draw in [0, 1) that needs no generator state.
    std::uint64_t z = (static_cast<std::uint64_t>(k) + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    if (static_cast<double>(z >> 11) * 0x1.0p-53 >= p.groove_damage_broken_fraction) continue;
    ++count[1];
    for (std::size_t e = 0; e < stride; ++e) {
      b.bonded[k * stride + e] = 0;
      b.shear_force_n[k * stride + e] = 0;
    }
  }
  return count;
}

std::vector<double> groove_centres(const CutParams& p, double x_left_m, double x_right_m) {
  std::vector<double> out;
  if (p.groove_shape == GrooveShape::none) return out;
  const double half = 0.5 * p.groove_width_m;
  // The laser treats the whole top surface, not only the tool's path: a groove ahead of the tool's end
  // still stops a crack, and the workpiece does not change with the travel (seed 000 Section 4: grooves on
  // the top surface).
  for (double c = x_right_m - 0.5 * p.groove_pitch_m; c - half > x_left_m; c -= p.groove_pitch_m)
    out.push_back(c);
  return out;
}

bool inside_any_groove(const CutParams& p, const std::vector<double>& centres, double y_top_m, double x_m, double y_m) {
  for (double c : centres)
    if (inside_groove_outline(p, x_m - c, y_top_m - y_m)) return true;
  return false;
}

std::vector<std::array<double, 2>> tool_outline(const CutParams& p, double x_front_m, double y_tip_m) {
  // Built with the sharp tip at the origin, then moved. The tool moves in -x, so "back" is +x.
  // Rake face (from the tip upwards): rotated from the vertical towards the back by the rake angle; a
  // negative rake leans it forwards, over the chip. Clearance face (from the tip backwards): rises from
  // the machined surface by the clearance angle.
  const double g = units::deg_to_rad(p.rake_deg), a = units::deg_to_rad(p.clearance_deg);
  const std::array<double, 2> r{std::sin(g), std::cos(g)}, c{std::cos(a), std::sin(a)};
  // A back face closes the outline so that no disk can get inside the tool.
  const double lr = rake_face_length_m(p), lc = clearance_face_length_m(p);
  std::vector<std::array<double, 2>> v;
  v.push_back({lr * r[0], lr * r[1]});
  if (p.edge_radius_m > 0) {
    const double beta = wedge_angle_rad(p), rho = p.edge_radius_m;
    const double t = rho / std::tan(0.5 * beta), h = rho / std::sin(0.5 * beta);
    const double bx = r[0] + c[0], by = r[1] + c[1], bn = std::hypot(bx, by);
    const double cx = h * bx / bn, cy = h * by / bn;  // arc centre on the bisector
    const double a0 = std::atan2(t * r[1] - cy, t * r[0] - cx);
    double sweep = std::atan2(t * c[1] - cy, t * c[0] - cx) - a0;
    while (sweep > kPi) sweep -= 2 * kPi;
    while (sweep <= -kPi) sweep += 2 * kPi;
    for (int k = 0; k <= p.edge_segments; ++k) {
      const double phi = a0 + sweep * k / p.edge_segments;
      v.push_back({cx + rho * std::cos(phi), cy + rho * std::sin(phi)});
    }
  } else {
    v.push_back({0, 0});
  }
  v.push_back({lc * c[0], lc * c[1]});
  double x_min = 1e300, y_min = 1e300;
  for (const auto& q : v) x_min = std::min(x_min, q[0]), y_min = std::min(y_min, q[1]);
  for (auto& q : v) q = {q[0] - x_min + x_front_m, q[1] - y_min + y_tip_m};
  return v;
}

double leading_x_in_band(const std::vector<std::array<double, 2>>& v, double y0, double y1) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < v.size(); ++k) {
    auto a = v[k], b = v[(k + 1) % v.size()];
    if (a[1] > b[1]) std::swap(a, b);
    if (b[1] < y0 || a[1] > y1) continue;
    // Clip the edge to the band; x is linear in y along it (a horizontal edge keeps both ends).
    for (double y : {std::max(a[1], y0), std::min(b[1], y1)}) {
      const double x = b[1] > a[1] ? a[0] + (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) : std::min(a[0], b[0]);
      best = std::min(best, x);
    }
  }
  return best;
}

CutCrackCounts count_cut_cracks(const std::vector<CrackEvent>& cracks, double y_cut_m,
                                std::array<double, 2> steady_x_m) {
  CutCrackCounts n;
  std::vector<double> steady_depths_m;
  for (const auto& c : cracks) {
    (c.mode == BreakMode::tension ? n.tensile : n.shear)++;
    if (is_chip_crack(c.y_m, y_cut_m)) {
      ++n.chip;
      continue;
    }
    ++n.subsurface;
    n.subsurface_damage_depth_m = std::max(n.subsurface_damage_depth_m, y_cut_m - c.y_m);
    if (c.x_m >= steady_x_m[0] && c.x_m <= steady_x_m[1]) {
      ++n.subsurface_steady;
      n.subsurface_steady_damage_depth_m = std::max(n.subsurface_steady_damage_depth_m, y_cut_m - c.y_m);
      steady_depths_m.push_back(y_cut_m - c.y_m);
    }
  }
  if (!steady_depths_m.empty()) {  // nearest rank: the ceil(0.95 n)-th smallest depth
    const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(steady_depths_m.size())));
    const auto at = steady_depths_m.begin() + static_cast<std::ptrdiff_t>(rank - 1);
    std::nth_element(steady_depths_m.begin(), at, steady_depths_m.end());
    n.subsurface_steady_damage_depth_p95_m = *at;
  }
  return n;
}

void steady_statistics(CutResult& res, double from_travel_m) {
  double sm = 0, st = 0, sm2 = 0, st2 = 0;
  int n = 0, touching = 0;
  for (const auto& s : res.samples) {
    if (s.travel_m < from_travel_m) continue;
    sm += s.main_force_n, st += s.thrust_force_n;
    sm2 += s.main_force_n * s.main_force_n, st2 += s.thrust_force_n * s.thrust_force_n;
    touching += s.main_force_n > 0 ? 1 : 0;
    ++n;
  }
  res.n_steady_samples = n;
  res.steady_from_travel_m = from_travel_m;
  res.steady_to_travel_m = res.samples.empty() ? from_travel_m : res.samples.back().travel_m;
  if (n == 0) {
    res.main_force_n = res.thrust_force_n = res.main_force_std_n = res.thrust_force_std_n = 0;
    res.contact_share = 0;
    res.main_force_sem_n = res.thrust_force_sem_n = std::nan("");
    res.main_force_sem_method = res.thrust_force_sem_method = "none";
    res.steady = false;
    res.not_steady_reason =
        fmt::format("no sample at or beyond {:.4g} mm of travel, where the means start", units::m_to_mm(from_travel_m));
    return;
  }
  res.contact_share = static_cast<double>(touching) / n;
  res.main_force_n = sm / n;
  res.thrust_force_n = st / n;
  res.main_force_std_n = std::sqrt(std::max(0.0, sm2 / n - res.main_force_n * res.main_force_n));
  res.thrust_force_std_n = std::sqrt(std::max(0.0, st2 / n - res.thrust_force_n * res.thrust_force_n));
  std::vector<double> main, thrust;
  for (const auto& s : res.samples)
    if (s.travel_m >= from_travel_m) main.push_back(s.main_force_n), thrust.push_back(s.thrust_force_n);
  const BatchMeans bm = batch_means(main), bt = batch_means(thrust);
  res.main_force_sem_n = bm.best_standard_error(&res.main_force_sem_method);
  res.thrust_force_sem_n = bt.best_standard_error(&res.thrust_force_sem_method);
  res.main_force_inefficiency = bm.statistical_inefficiency, res.thrust_force_inefficiency = bt.statistical_inefficiency;
  res.main_force_batch_samples = bm.batch_length, res.thrust_force_batch_samples = bt.batch_length;
  // Steady: the means start after the entry (to 1e-4 of it: a scene's entry_fraction x length rounds) and each
  // has a standard error.
  std::vector<std::string> why;
  const double entry_mm = units::m_to_mm(kEntryTravelM);
  if (res.steady_to_travel_m <= kEntryTravelM)
    why.push_back(
        fmt::format("the cut travels {:.4g} mm, within the entry (the first {:g} mm; docs/dem.md, \"How "
                    "long a cut must be\"): cut further (cut.length_mm)",
                    units::m_to_mm(res.steady_to_travel_m), entry_mm));
  else if (from_travel_m < kEntryTravelM * (1 - 1e-4))
    why.push_back(
        fmt::format("the means start at {:.4g} mm of travel, within the entry (the first {:g} mm; "
                    "docs/dem.md, \"How long a cut must be\"): start them later (cut.entry_fraction)",
                    units::m_to_mm(from_travel_m), entry_mm));
  if (!std::isfinite(res.main_force_sem_n) || !std::isfinite(res.thrust_force_sem_n))
    why.push_back(fmt::format(
        "the standard error of the {} cannot be computed from {} samples (too few for batch "
        "means or the autocorrelation): cut further",
        !std::isfinite(res.main_force_sem_n) && !std::isfinite(res.thrust_force_sem_n) ? "main and thrust means"
        : !std::isfinite(res.main_force_sem_n)                                         ? "main mean"
                                                                                       : "thrust mean",
        n));
  res.steady = why.empty();
  res.not_steady_reason = fmt::format("{}", fmt::join(why, "; "));
}

std::vector<TravelWindow> travel_window_means(const std::vector<CutSample>& samples, double length_m, double window_m) {
  // Whole windows, not one more for the rounding of length / window (0.6 / 0.1 is 6.000000000000001).
  const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(length_m / window_m * (1 - 1e-12))));
  std::vector<TravelWindow> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    out[k].from_m = static_cast<double>(k) * window_m;
    out[k].to_m = std::min(length_m, static_cast<double>(k + 1) * window_m);
  }
  for (const auto& s : samples) {
    const auto k = std::min(n - 1, static_cast<std::size_t>(std::max(0.0, s.travel_m / window_m)));
    out[k].main_force_n += s.main_force_n;
    out[k].thrust_force_n += s.thrust_force_n;
    ++out[k].n_samples;
  }
  for (auto& w : out)
    if (w.n_samples > 0) w.main_force_n /= w.n_samples, w.thrust_force_n /= w.n_samples;
  return out;
}

namespace {
struct Bounds {
  double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300, r_min = 1e300, r_max = 0;
};
Bounds bounds_of(const Particles& p) {
  Bounds b;
  for (std::size_t i = 0; i < p.size(); ++i) {
    b.x_min = std::min(b.x_min, p.x[i] - p.radius[i]);
    b.x_max = std::max(b.x_max, p.x[i] + p.radius[i]);
    b.y_min = std::min(b.y_min, p.y[i] - p.radius[i]);
    b.y_max = std::max(b.y_max, p.y[i] + p.radius[i]);
    b.r_min = std::min(b.r_min, p.radius[i]);
    b.r_max = std::max(b.r_max, p.radius[i]);
  }
  return b;
}

/// The tool may advance at most this fraction of the smallest disk radius per time step: a contact then
/// builds up over 100 steps or more, and no disk can pass through a tool face between two steps.
constexpr double kMaxToolAdvancePerRadius = 0.01;

/// The cut must be one the disks resolve and the workpiece holds: deeper than the smallest disk radius
/// (a shallower tool passes over the disks' tops and measures nothing); neither the tool nor a groove
/// reaching the held bottom rows (a groove that deep would cut the workpiece into loose columns); and
/// short enough that the tool's leading edge (it starts half a largest radius right of the workpiece)
/// stays off the held left disks (centres within 2 largest radii of the left side, as the bottom rows).
void check_cut_fits_workpiece(const CutParams& p, const Bounds& b) {
  const double held_top_depth_m = b.y_max - b.y_min - 2 * b.r_max;
  const auto above_held_rows = [&](const char* key, double depth_m, const char* what) {
    require(depth_m < held_top_depth_m, key, units::m_to_mm(depth_m),
            std::string(what) + " above the held bottom row (workpiece height " +
                format_value(units::m_to_mm(b.y_max - b.y_min)) + " mm)");
  };
  above_held_rows("cut.depth_of_cut_mm", p.depth_of_cut_m, "a depth of cut");
  if (p.groove_shape != GrooveShape::none) above_held_rows("grooves.depth_mm", p.groove_depth_m, "a groove depth");
  require(p.depth_of_cut_m >= b.r_min, "cut.depth_of_cut_mm", units::m_to_mm(p.depth_of_cut_m),
          "a depth of cut of at least the smallest disk radius (" + format_value(units::m_to_um(b.r_min)) +
              " um): a shallower tool passes over the disks' tops; use smaller disks (specimen.radius_min_um, "
              "specimen.radius_max_um)");
  // The layer along the held rows (held_absorbing_depths) must stay below the cut line and off the tool's path.
  const double layer_m = window_box_m(p).held_absorbing_m;
  if (layer_m > 0)
    require(layer_m < held_top_depth_m - p.depth_of_cut_m, "cut.held_absorbing_depths", p.held_absorbing_depths,
            "a layer below the cut line: thinner than " +
                format_value((held_top_depth_m - p.depth_of_cut_m) / p.depth_of_cut_m) + " depths of cut (" +
                format_value(units::m_to_mm(held_top_depth_m - p.depth_of_cut_m)) +
                " mm, the distance from the held bottom rows to the cut line)");
  const double width = b.x_max - b.x_min, max_travel = width - 2.5 * b.r_max - layer_m;
  require(p.length_m <= max_travel, "cut.length_mm", units::m_to_mm(p.length_m),
          "a travel of at most " + format_value(units::m_to_mm(max_travel)) + " mm: further on, the tool would reach the held left disks" +
              (layer_m > 0 ? " (or their absorbing layer)" : "") + " of the " + format_value(units::m_to_mm(width)) +
              " mm long workpiece");
}

/// The held rows of the workpiece cut from a specimen of bounds `b` (make_workpiece).
HeldRows held_rows_of(const Bounds& b) { return {b.x_min + 2 * b.r_max, b.y_min + 2 * b.r_max}; }

/// A groove pattern that removes no disk is not a grooved workpiece: either no groove lies on the surface
/// (the pitch) or none is wide enough to hold a disk's centre (the width).
void check_grooves_remove_disks(const CutParams& p, const Bounds& b, std::size_t n_removed) {
  if (p.groove_shape == GrooveShape::none || n_removed > 0) return;
  require(!groove_centres(p, b.x_min, b.x_max).empty(), "grooves.pitch_mm", units::m_to_mm(p.groove_pitch_m),
          "a pitch that puts at least one groove on the " + format_value(units::m_to_mm(b.x_max - b.x_min)) +
              " mm long workpiece");
  throw InputError("grooves.width_mm", format_value(units::m_to_mm(p.groove_width_m)),
                   "a groove wide enough to remove disks (no disk centre lies inside any groove; disk radii " +
                       format_value(units::m_to_um(b.r_min)) + "-" + format_value(units::m_to_um(b.r_max)) + " um)");
}

/// The tool speed against the time step: fast enough to finish within kMaxRunSteps, slow enough to
/// advance at most kMaxToolAdvancePerRadius of the smallest radius per step.
void check_tool_speed(const CutParams& p, double time_step_s, double time_step_safety, double r_min_m) {
  const double fastest = kMaxToolAdvancePerRadius * r_min_m / time_step_s;
  const double slowest = p.length_m / (kMaxRunSteps * time_step_s);
  const std::string step = format_value(time_step_s * 1e9) + " ns";
  require(p.speed_m_per_s <= fastest, "cut.speed_m_per_s", p.speed_m_per_s,
          "a speed of at most " + format_value(fastest) + " m/s: the tool may advance at most " +
              format_value(100 * kMaxToolAdvancePerRadius) + " % of the smallest disk radius (" +
              format_value(units::m_to_um(r_min_m)) + " um) per time step (" + step + ")");
  refuse_small_time_step_safety(p.length_m / (p.speed_m_per_s * time_step_s), time_step_s, time_step_safety);
  require(p.speed_m_per_s >= slowest, "cut.speed_m_per_s", p.speed_m_per_s,
          "a speed of at least " + format_value(slowest) + " m/s: slower, the travel of " +
              format_value(units::m_to_mm(p.length_m)) + " mm takes more than " + format_value(kMaxRunSteps) +
              " time steps of " + step + " (the seed's 4.23 mm/s is scaled up in every DEM cut; docs/dem.md)");
}
}  // namespace

Simulation make_workpiece(const Simulation& specimen, const CutParams& params, std::size_t& n_removed) {
  const auto& p = specimen.particles();
  const Bounds b = bounds_of(p);
  const HeldRows held = held_rows_of(b);
  const auto centres = groove_centres(params, b.x_min, b.x_max);
  // Grooves: the paper deletes the disks inside each groove (seed 000 Section 4); a disk goes when its
  // centre lies inside the outline.
  std::vector<std::uint8_t> keep(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) keep[k] = !inside_any_groove(params, centres, b.y_max, p.x[k], p.y[k]);
  Simulation sim = copy_disks_and_joints(specimen, specimen.material(), true, keep);
  n_removed = p.size() - sim.particles().size();
  // Seed 000 Section 4: the particles on the left side and the bottom are fixed (zero prescribed
  // velocity, group 1); the top is free. "On the side" = centre within 2 R_max of the edge, as the grips.
  auto& q = sim.particles();
  for (std::size_t k = 0; k < q.size(); ++k) {
    q.group[k] = 0;  // whatever the specimen held (a test's grips)
    if (q.x[k] < held.x_m || q.y[k] < held.y_m) {
      q.group[k] = 1;
      q.vx[k] = q.vy[k] = q.omega[k] = 0;
    }
  }
  return sim;
}

EdgeMeets edge_meets(const Simulation& sim, std::int32_t first_tool_wall, std::int32_t n_tool_walls,
                     std::array<double, 2> tip_m, const std::vector<std::uint8_t>& tied) {
  const Particles& p = sim.particles();
  bool loose = false;
  for (const auto& c : sim.wall_contact_loads()) {
    if (c.wall < first_tool_wall || c.wall >= first_tool_wall + n_tool_walls) continue;
    const Wall& w = sim.walls()[static_cast<std::size_t>(c.wall)];
    const auto u = static_cast<std::size_t>(c.disk);
    // The contact's point: the wall's closest point to the disk's centre.
    const double ex = w.x1 - w.x0, ey = w.y1 - w.y0, len2 = ex * ex + ey * ey;
    const double s = len2 > 0 ? std::clamp(((p.x[u] - w.x0) * ex + (p.y[u] - w.y0) * ey) / len2, 0.0, 1.0) : 0.0;
    if (std::hypot(w.x0 + s * ex - tip_m[0], w.y0 + s * ey - tip_m[1]) > kEdgeZoneM) continue;
    if (tied[u]) return EdgeMeets::tied;
    loose = true;
  }
  return loose ? EdgeMeets::loose : EdgeMeets::nothing;
}

void add_tied_profile(const WorkpieceNow& now, std::array<double, 2> tip_m, double y_cut_m, TiedProfile& into) {
  for (std::size_t g = 0; g < now.present.size(); ++g) {
    if (!now.present[g]) continue;
    const double depth = y_cut_m - now.y_m[g];
    if (!(depth >= kTiedBandDepthM.front() && depth < kTiedBandDepthM.back())) continue;
    const double dx = now.x_m[g] - tip_m[0];  // the tool moves in -x: ahead is dx < 0
    const double along = std::abs(dx);
    if (!(along >= kTiedStretchM[0] && along < kTiedStretchM[1])) continue;
    const std::size_t side = dx < 0 ? 0 : 1;
    std::size_t band = 0;
    while (depth >= kTiedBandDepthM[band + 1]) ++band;
    ++into.disks[side][band];
    into.tied[side][band] += now.tied[g];
  }
}

CutWindowBox window_box_m(const CutParams& p) {
  const double d = p.depth_of_cut_m;
  CutWindowBox box{p.window_ahead_depths * d, p.window_behind_depths * d, p.window_below_depths * d,
                   p.window_above_depths * d, p.window_shift_depths * d};
  if (p.window_absorbing_depths > 0) box.absorbing_m = p.window_absorbing_depths * d;
  box.held_absorbing_m = p.held_absorbing_depths * d;
  return box;
}

CutRun::CutRun(const Simulation& specimen, const CutParams& params)
    : sim_(specimen.material(), specimen.options()), params_(params) {
  validate_cut_params(params_);
  const Bounds b0 = bounds_of(specimen.particles());
  check_cut_fits_workpiece(params_, b0);
  sim_ = make_workpiece(specimen, params_, res_.n_removed_by_grooves);
  check_grooves_remove_disks(params_, b0, res_.n_removed_by_grooves);
  res_.y_top_m = b0.y_max;
  res_.workpiece_box_m = {b0.x_min, b0.x_max, b0.y_min, b0.y_max};
  res_.groove_damage_joints = apply_groove_damage(sim_, params_, res_.workpiece_box_m);
  res_.y_cut_m = b0.y_max - params_.depth_of_cut_m;
  res_.width_m = sim_.options().thickness_m;
  // The tool starts with the part that meets the workpiece first (its left-most point between the cut
  // line and the top surface: the rake face at the surface for a negative rake) half a largest radius
  // right of the workpiece, so the travel is not spent in the air. It moves in -x.
  auto outline = tool_outline(params_, 0, res_.y_cut_m);
  const double shift = b0.x_max + 0.5 * b0.r_max - leading_x_in_band(outline, res_.y_cut_m, res_.y_top_m);
  for (auto& q : outline) q[0] += shift;
  first_tool_wall_ = static_cast<std::int32_t>(sim_.walls().size());
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const auto& a = outline[k];
    const auto& e = outline[(k + 1) % outline.size()];
    Wall face{a[0], a[1], e[0], e[1], -params_.speed_m_per_s, 0};
    face.friction_coefficient = params_.tool_friction_coefficient;
    sim_.add_wall(face);
  }
  n_tool_walls_ = static_cast<std::int32_t>(outline.size());
  sim_.invalidate_neighbours();
  sim_.initialise();
  check_tool_speed(params_, sim_.time_step(), sim_.options().time_step_safety, b0.r_min);
  if (params_.edge_zone) {
    if (params_.edge_zone_radius_m == 0) params_.edge_zone_radius_m = 2 * b0.r_max;  // stored with the parameters
    require(params_.edge_cutting_force_n_per_m >= 0, "edge_zone.cutting_force_N_per_mm",
            units::n_per_m_to_n_per_mm(params_.edge_cutting_force_n_per_m),
            "the layer's force per unit width, given or computed from the material by the cut kind, >= 0");
  }
  sim_.cracks().clear();  // only the cut's cracks count
  t0_ = sim_.time();
  res_.n_particles = sim_.particles().size();
  res_.time_step_s = sim_.time_step();
  res_.samples.push_back({0, 0, 0, 0});
  // A sponge layer's peak rate for its thickness L: the amplitude decays at gamma / 2 in time, gamma / (2 c)
  // in space; through the quadratic ramp and back, exp(-gamma_max L / (3 c)) = exp(-attenuation).
  const auto peak_rate_per_s = [&](double thickness_m) {
    return 3 * params_.window_absorbing_attenuation * p_wave_speed_m_per_s(sim_.material()) / thickness_m;
  };
  const HeldRows held = held_rows_of(b0);
  CutWindowBox box = window_box_m(params_);
  const double held_layer_m = box.held_absorbing_m;
  if (params_.active_window) {
    // The workpiece becomes the window's reservoir; its time step (of the whole workpiece) is every window's.
    if (box.absorbing_m > 0) box.absorbing_rate_per_s = peak_rate_per_s(box.absorbing_m);
    if (held_layer_m > 0) {
      box.held_absorbing_rate_per_s = peak_rate_per_s(held_layer_m);
      box.held_rows = held;
    }
    const double x_edge = edge()[0];
    window_.emplace(std::move(sim_), box, res_.y_top_m, res_.y_cut_m);
    window_->set_remove_loose_fragments(params_.window_remove_loose_fragments);
    sim_ = window_->build(nullptr, x_edge);
  } else if (held_layer_m > 0) {
    // Every disk active: the layer along the held rows is set once (no disk joins or leaves the cut).
    std::vector<double> rates(sim_.particles().size(), 0.0);
    add_held_rows_layer(sim_.particles(), held, held_layer_m, peak_rate_per_s(held_layer_m), rates);
    sim_.set_absorbing_rates(std::move(rates));
  }
}

std::array<double, 2> CutRun::edge() const {
  const auto& walls = sim_.walls();
  double y_low = std::numeric_limits<double>::infinity(), x_edge = y_low;
  for (std::int32_t w = 0; w < n_tool_walls_; ++w) {
    const Wall& face = walls[static_cast<std::size_t>(first_tool_wall_ + w)];
    for (const auto& [x, y] : {std::pair{face.x0, face.y0}, std::pair{face.x1, face.y1}}) {
      if (y < y_low - 1e-12)
        y_low = y, x_edge = x;
      else if (y < y_low + 1e-12)
        x_edge = std::min(x_edge, x);
    }
  }
  return {x_edge, y_low};
}

std::size_t CutRun::n_cracks() const {
  // A window's cracks are moved to its reservoir when it is rebuilt.
  return window_ ? window_->cracks().size() + sim_.cracks().size() : sim_.cracks().size();
}

namespace {
/// The books between two moments (CutEnergy's balance).
CutEnergy cut_energy_between(const CutEnergyBooks& from, const CutEnergyBooks& to) {
  CutEnergy e;
  e.tool_work_j = to.tool_work_j - from.tool_work_j;
  e.left_kinetic_j = to.left_kinetic_j - from.left_kinetic_j;
  e.left_strain_j = to.left_strain_j - from.left_strain_j;
  e.stored_change_j = (to.kinetic_j + to.strain_j) - (from.kinetic_j + from.strain_j);
  e.dissipated_j = e.tool_work_j - e.left_kinetic_j - e.left_strain_j - e.stored_change_j;
  return e;
}
}  // namespace

CutEnergyBooks CutRun::books_now() const {
  CutEnergyBooks b = books_;
  b.kinetic_j = sim_.kinetic_energy();
  b.strain_j = sim_.stored_elastic_energy();
  return b;
}

void CutRun::crush_grains() {
  // The disks a tool face presses with more than their splitting load F = pi sigma r t, sigma the loose grains'
  // (CutParams::window_grain_strength_pa) or the tied disks' (window_tied_grain_strength_pa); 0 is never.
  const double loose_pa = params_.window_grain_strength_pa, tied_pa = params_.window_tied_grain_strength_pa;
  const double weakest_pa = loose_pa > 0 && tied_pa > 0 ? std::min(loose_pa, tied_pa) : std::max(loose_pa, tied_pa);
  const auto& p = sim_.particles();
  const double t = sim_.options().thickness_m;
  const auto splitting_load_n = [&](std::size_t u, double strength_pa) {
    return std::numbers::pi * strength_pa * p.radius[u] * t;
  };
  std::vector<std::pair<std::size_t, double>> pressed;  // disk, its largest tool load
  for (const auto& c : sim_.wall_contact_loads()) {
    const auto u = static_cast<std::size_t>(c.disk);
    if (c.wall >= first_tool_wall_ && c.wall < first_tool_wall_ + n_tool_walls_ && p.group[u] == 0 &&
        c.normal_force_n > splitting_load_n(u, weakest_pa))
      pressed.emplace_back(u, c.normal_force_n);
  }
  if (pressed.empty()) return;
  // Each against its own strength: a loose fragment's disk as a grain, a disk tied to the workpiece as one.
  const auto tied = sim_.tied_to_held();
  std::vector<std::size_t> grains, tied_disks;
  for (const auto& [u, load_n] : pressed) {
    const double strength_pa = tied[u] ? tied_pa : loose_pa;
    if (strength_pa > 0 && load_n > splitting_load_n(u, strength_pa)) (tied[u] ? tied_disks : grains).push_back(u);
  }
  if (grains.empty() && tied_disks.empty()) return;
  for (auto* list : {&grains, &tied_disks}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  take_window(window_->crush(sim_, grains, tied_disks));  // what the crushed disks held leaves with them
}

void CutRun::take_window(Simulation next) {
  // What the disks leaving the integration take with them (less what joining disks bring): the books. `next` was
  // built from sim_ without changing it.
  const CutEnergyBooks before = books_now();
  sim_ = std::move(next);
  const CutEnergyBooks after = books_now();
  books_.left_kinetic_j += before.kinetic_j - after.kinetic_j;
  books_.left_strain_j += before.strain_j - after.strain_j;
}

bool CutRun::advance() {
  if (finished_) return false;
  const auto start = std::chrono::steady_clock::now();
  if (window_) {
    const double x_edge = edge()[0];
    if (window_->due(x_edge)) take_window(window_->build(&sim_, x_edge));
  }
  // The edge zone: the layer's force on the tool while the edge meets intact glass, its reaction on that glass.
  const bool zone_on = params_.edge_zone && edge_zone_begin_sample();
  const double t = sim_.options().thickness_m;
  const double zone_fx = zone_on ? params_.edge_cutting_force_n_per_m * t : 0.0;
  const double zone_fy = zone_on ? params_.edge_thrust_force_n_per_m * t : 0.0;
  std::vector<std::array<double, 2>> loaded_at;
  for (const auto& l : sim_.disk_loads()) loaded_at.push_back({sim_.particles().x[l.disk], sim_.particles().y[l.disk]});
  res_.particle_steps += static_cast<double>(sim_.particles().size()) * params_.sample_every_steps;
  double fx = 0, fy = 0;
  const auto& walls = sim_.walls();
  for (int s = 0; s < params_.sample_every_steps; ++s) {
    sim_.step();
    for (std::int32_t w = 0; w < n_tool_walls_; ++w) {
      fx += walls[static_cast<std::size_t>(first_tool_wall_ + w)].fx;
      fy += walls[static_cast<std::size_t>(first_tool_wall_ + w)].fy;
    }
    if (zone_on) fx += zone_fx, fy += zone_fy;
  }
  const double reaction_work_j = zone_on ? edge_zone_reaction_work_j(loaded_at) : 0.0;
  if (window_ && (params_.window_grain_strength_pa > 0 || params_.window_tied_grain_strength_pa > 0)) crush_grains();
  const auto f = tool_force_components(fx / params_.sample_every_steps, fy / params_.sample_every_steps);
  const double elapsed = sim_.time() - t0_, travel = params_.speed_m_per_s * elapsed;
  res_.samples.push_back({travel, elapsed, f[0], f[1]});
  // What the edge meets: once per kEdgeObserveTravelM of travel over the steady part (it changes nothing).
  if (edge_kept_ && travel >= params_.entry_fraction * params_.length_m) {
    const auto step = static_cast<std::int64_t>(std::floor(travel / kEdgeObserveTravelM));
    if (step > edge_last_step_) {
      edge_last_step_ = step;
      observe_edge();
    }
  }
  // The tool moves at -speed in x; the disks push it with fx each step: it does fx speed dt of work on them.
  books_.tool_work_j += fx * params_.speed_m_per_s * sim_.time_step();
  if (params_.edge_zone && travel >= params_.entry_fraction * params_.length_m) {
    CutEdgeZoneRecord& z = res_.edge_zone;
    ++z.samples;
    z.intact_samples += zone_on;
    if (steady_booked_) {  // the books' steady part starts after its first sample
      z.tool_work_j += zone_fx * params_.sample_every_steps * params_.speed_m_per_s * sim_.time_step();
      z.reaction_work_j += reaction_work_j;
    }
  }
  if (books_kept_ && !steady_booked_ && travel >= params_.entry_fraction * params_.length_m) {
    books_steady_start_ = books_now();
    steady_booked_ = true;
  }
  res_.steps = sim_.step_count();
  res_.wall_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (travel >= params_.length_m) finish();
  return !finished_;
}

std::vector<std::uint8_t> CutRun::tied_of(const WorkpieceNow& now) const {
  std::vector<std::uint8_t> tied(sim_.particles().size());
  for (std::size_t u = 0; u < tied.size(); ++u)
    tied[u] = now.tied[window_ ? static_cast<std::size_t>(window_->workpiece_index(u)) : u];
  return tied;
}

void CutRun::observe_edge() {
  const auto tip = edge();
  const WorkpieceNow now = window_ ? window_->now(sim_) : workpiece_now(sim_);
  const std::vector<std::uint8_t> tied = tied_of(now);
  CutEdgeRecord& e = res_.edge;
  ++e.observations;
  switch (edge_meets(sim_, first_tool_wall_, n_tool_walls_, tip, tied)) {
    case EdgeMeets::tied: ++e.touches_tied; break;
    case EdgeMeets::loose: ++e.touches_loose; break;
    case EdgeMeets::nothing: break;
  }
  add_tied_profile(now, tip, res_.y_cut_m, e.profile);
}

void CutRun::finish() {
  finished_ = true;
  const double steady_from_m = params_.entry_fraction * params_.length_m;
  steady_statistics(res_, steady_from_m);
  res_.travel_windows = travel_window_means(res_.samples, params_.length_m, params_.window_m);
  const double x_edge = edge()[0];
  // It was (final travel - steady start) further right when the steady part began.
  res_.steady_machined_x_m = {x_edge, x_edge + res_.samples.back().travel_m - steady_from_m};
  if (window_) {
    window_->sync(sim_);
    res_.window = {window_->rebuilds(), window_->largest_window(), window_->chips()};
  }
  res_.cracks = count_cut_cracks(cracks(), res_.y_cut_m, res_.steady_machined_x_m);
  res_.energy_booked = books_kept_ && steady_booked_;
  res_.edge_recorded = edge_kept_;
  if (res_.energy_booked) res_.energy = cut_energy_between(books_steady_start_, books_now());
}

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

/// The cut's parameters by the keys of the scene sections that hold them.
const std::array<serial::SectionFields<CutParams>, 5>& cut_sections() {
  static const std::array<serial::SectionFields<CutParams>, 5> sections{
      {{"cut", cut_fields()},
       {"tool", tool_fields()},
       {"grooves", groove_fields()},
       {"active_window", active_window_fields()},
       {"edge_zone", edge_zone_fields()}}};
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
    io(p.depth_of_cut_m, p.speed_m_per_s, p.length_m, p.rake_deg, p.clearance_deg, p.edge_radius_m, p.groove_depth_m,
       p.groove_pitch_m, p.groove_width_m, p.groove_bottom_width_m, p.entry_fraction, p.window_m,
       p.tool_friction_coefficient, p.rake_face_height_m);
    std::string groove_shape;  // by name, as before the enum
    io(p.edge_segments, p.sample_every_steps, groove_shape, r.samples);
    p.groove_shape = groove_shape_names().parse(groove_shape, "cut checkpoint");
    io(r.y_top_m, r.y_cut_m, r.width_m, r.time_step_s, r.wall_time_s, run.t0_, r.workpiece_box_m);
    io(r.n_particles, r.n_removed_by_grooves, r.steps, run.first_tool_wall_, run.n_tool_walls_, run.finished_);
    io(p.active_window, p.window_ahead_depths, p.window_behind_depths, p.window_below_depths, p.window_above_depths,
       p.window_shift_depths, r.particle_steps, p.window_absorbing_depths, p.window_absorbing_attenuation);
    io(p.held_absorbing_depths);
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
  io(z.samples, z.intact_samples, z.tool_work_j, z.reaction_work_j);
}

template <class Self, class Io>
void CutRun::edge_fields(Self& run, Io& io) {
  io(run.edge_kept_, run.edge_last_step_, run.res_.edge);
}

template <class Self, class Io>
void CutRun::book_fields(Self& run, Io& io) {
  io(run.books_kept_, run.steady_booked_);
  for (auto* b : {&run.books_, &run.books_steady_start_})
    io(b->tool_work_j, b->left_kinetic_j, b->left_strain_j, b->kinetic_j, b->strain_j);
}

CutRun CutRun::deserialize(std::string_view bytes) {
  std::size_t version = 0;
  serial::In io = serial::open_tagged(
      bytes, {kCutMagic, kCutMagicNoZone, kCutMagicNoEdge, kCutMagicNoBooks, kCutMagicListed}, "cut checkpoint", &version);
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
    run.edge_kept_ = false;  // nor the edge's record
  if (version == 0) zone_record_fields(run, io);  // an older one has no edge zone (its parameters are off)
  io.expect_end("cut checkpoint");
  validate_cut_params(run.params_);
  run.sim_ = Simulation::deserialize(state);
  if (run.params_.active_window != !window.empty()) throw ModelError("dem", "corrupt cut checkpoint (the window)");
  if (run.params_.active_window) {
    run.window_ = CutWindow::deserialize(window);
    run.window_->set_remove_loose_fragments(run.params_.window_remove_loose_fragments);  // a parameter, stored by key
  }
  if (run.finished_) run.finish();
  return run;
}

std::string cut_forces_csv_header() {
  return csv_line({"tool_travel_mm", "time_s", "cutting_force_N", "thrust_force_N", "cutting_force_N_per_mm",
                   "thrust_force_N_per_mm", "main_force_N"});
}

std::string cut_forces_csv_row(const CutSample& s, double width_m) {
  const double width_mm = units::m_to_mm(width_m);
  return csv_line({csv_number(units::m_to_mm(s.travel_m)), csv_number(s.time_s), csv_number(s.main_force_n),
                   csv_number(s.thrust_force_n), csv_number(s.main_force_n / width_mm),
                   csv_number(s.thrust_force_n / width_mm), csv_number(s.main_force_n)});
}

std::string cut_forces_csv(const CutResult& res) {
  std::string out = cut_forces_csv_header();
  for (const auto& s : res.samples) out += cut_forces_csv_row(s, res.width_m);
  return out;
}

}  // namespace kerf::dem
