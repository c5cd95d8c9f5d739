// The orthogonal cut's parameters (cutting.hpp's CutParams): the scene sections' field tables (one per section's
// struct), the relations between fields, validation, reading and JSON.
#include <algorithm>
#include <cmath>
#include <string>

#include "cut_internal.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

const EnumNames<GrooveShape>& groove_shape_names() {
  static constexpr std::string_view names[] = {"none", "rectangular", "trapezoidal"};
  static const EnumNames<GrooveShape> table{names};
  return table;
}

const EnumNames<GrooveDamageModel>& groove_damage_model_names() {
  static constexpr std::string_view names[] = {"broken_joints", "edge_zone"};
  static const EnumNames<GrooveDamageModel> table{names};
  return table;
}

const EnumNames<LateralCrack>& lateral_crack_names() {
  static constexpr std::string_view names[] = {"none", "whole_cut_line", "ahead_of_edge"};
  static const EnumNames<LateralCrack> table{names};
  return table;
}

const FieldTable<CutParams::Cut>& cut_fields() {
  using namespace units;
  using P = CutParams::Cut;
  static const FieldTable<P> table{
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

const FieldTable<CutParams::Tool>& tool_fields() {
  using namespace units;
  using P = CutParams::Tool;
  static const FieldTable<P> table{
      number_field("rake_deg", kSi("deg"), Range::open(-90.0, 90.0), "rake angle", &P::rake_deg),
      number_field("clearance_deg", kSi("deg"), Range{0.0, 90.0, false, true},
                   "clearance angle (rake + clearance below 89 deg)", &P::clearance_deg),
      number_field("edge_radius_um", kUm, Range::non_negative(), "cutting-edge radius; 0: sharp", &P::edge_radius_m),
      int_field("edge_segments", 1, 64, "wall segments of a rounded edge", &P::edge_segments),
      number_field("friction_coefficient", kNone, Range::non_negative(),
                   "tool-workpiece Coulomb friction; absent (-1): the material's particle friction",
                   &P::friction_coefficient),
      number_field("rake_face_height_mm", kMm, Range::non_negative(), "rake-face top above the tip; 0: 3 depths of cut",
                   &P::rake_face_height_m)};
  return table;
}

const FieldTable<CutParams::Grooves>& groove_fields() {
  using namespace units;
  using P = CutParams::Grooves;
  static const FieldTable<P> table{
      choice_field("shape", groove_shape_names(), "micro-grooves across the cut path", &P::shape),
      number_field("depth_mm", kMm, Range::positive(), "groove depth (default: the depth of cut)", &P::depth_m),
      number_field("pitch_mm", kMm, Range::positive(), "distance between groove centres", &P::pitch_m),
      number_field("width_mm", kMm, Range::positive(), "groove width at the surface (below the pitch)", &P::width_m),
      number_field("bottom_width_mm", kMm, Range::non_negative(),
                   "trapezoidal: width at the groove bottom (default: half the width)", &P::bottom_width_m),
      number_field("damage_depth_um", kUm, Range::non_negative(),
                   "laser-affected layer along a groove's walls and bottom, its depth (0: pristine glass up to the "
                   "groove)",
                   &P::damage_depth_m),
      number_field("damage_broken_fraction", kNone, Range::closed(0, 1),
                   "broken_joints: share of the layer's joints pre-broken (chosen by a hash of the joint: reproducible "
                   "per packing)",
                   &P::damage_broken_fraction),
      choice_field("damage_model", groove_damage_model_names(),
                   "the layer as broken_joints (its joints pre-broken) or edge_zone (below the disks' scale: joints "
                   "kept, the edge zone's force off while the cut line at the tip lies in the layer)",
                   &P::damage_model)};
  return table;
}

const FieldTable<CutParams::ActiveWindow>& active_window_fields() {
  using namespace units;
  using P = CutParams::ActiveWindow;
  static const FieldTable<P> table{
      bool_field("enabled", "integrate only the disks around the tool (a steady-state cut of a long workpiece)",
                 &P::enabled),
      number_field("ahead_depths", kNone, Range::positive(), "window ahead of the cutting edge, in depths of cut",
                   &P::ahead_depths),
      number_field("behind_depths", kNone, Range::positive(), "window behind the cutting edge, in depths of cut",
                   &P::behind_depths),
      number_field("below_depths", kNone, Range::positive(), "window below the cut line, in depths of cut",
                   &P::below_depths),
      number_field("above_depths", kNone, Range::positive(),
                   "window above the uncut surface (the chip's room; a chip leaving it is removed), in depths of cut",
                   &P::above_depths),
      number_field("shift_depths", kNone, Range::positive(),
                   "tool travel between rebuilds of the window, in depths of cut (below ahead_depths)",
                   &P::shift_depths),
      number_field("absorbing_depths", kNone, Range::non_negative(),
                   "absorbing layer inside the window's ahead, behind and lower edges, in depths of cut (0: none; the "
                   "held frame is rigid and reflects the waves an undamped cut sends out)",
                   &P::absorbing_depths),
      number_field(
          "absorbing_attenuation", kNone, Range::positive(),
          "e-folds by which the absorbing layer (and cut.held_absorbing_depths') attenuates a p-wave's amplitude "
          "through it and back",
          &P::absorbing_attenuation),
      bool_field("remove_loose_fragments",
                 "a bound, not a model of glass: at each rebuild remove every disk above the cut line that no intact "
                 "joint path ties to the held rows (every loose fragment gone at once)",
                 &P::remove_loose_fragments),
      number_field("grain_strength_MPa", kMPa, Range::non_negative(),
                   "debris grains crush: a disk of a loose fragment pressed by the tool with more than its splitting "
                   "load pi sigma r t is removed (0: disks never break)",
                   &P::grain_strength_Pa),
      number_field("tied_grain_strength_MPa", kMPa, Range::non_negative(),
                   "the workpiece's own disks crush: a disk still tied to the workpiece pressed by the tool with more "
                   "than pi sigma r t is removed, its joints with it (0: it breaks only by its joints)",
                   &P::tied_grain_strength_Pa)};
  return table;
}

const FieldTable<CutParams::EdgeZone>& edge_zone_fields() {
  using namespace units;
  using P = CutParams::EdgeZone;
  // A force the scene may give; absent (negative in the struct) until the cut kind computes it from the material.
  const auto given_force = [](std::string_view key, std::string_view doc, double P::*member) {
    NumberField<P> f = number_field(key, kNPerMm, Range::non_negative(), doc, member);
    f.has = [member](const P& p) { return p.*member >= 0; };
    f.absent = "kerf-forces' edge model of the material";
    return f;
  };
  static const FieldTable<P> table{
      bool_field("enabled",
                 "the tool's edge as a sub-grid model: the ductile layer's force from the analytic side while the edge "
                 "meets intact glass, the disks it reaches removed as its chip (windowed cuts)",
                 &P::enabled),
      number_field("radius_um", kUm, Range::non_negative(),
                   "reach of the zone around the tool's tip (0: the workpiece's largest disk diameter)", &P::radius_m),
      number_field("layer_factor", kNone, Range::positive(),
                   "ductile layer l = layer_factor x d_c (Bifano's critical depth of the material)", &P::layer_factor),
      number_field("friction_coefficient", kNone, Range::non_negative(),
                   "tool-glass friction of the layer's cut (0.15-0.4: docs/physics-glass-edge.md)",
                   &P::friction_coefficient),
      given_force("cutting_force_N_per_mm", "the layer's cutting force per unit width (with thrust_force_N_per_mm)",
                  &P::cutting_force_N_per_m),
      given_force("thrust_force_N_per_mm", "the layer's thrust force per unit width (with cutting_force_N_per_mm)",
                  &P::thrust_force_N_per_m),
      choice_field("lateral_crack", lateral_crack_names(),
                   "the lateral crack under the edge: none (where the lattice starts it), ahead_of_edge (the joints "
                   "across the cut line within lateral_crack_length_um ahead of the tip broken as the tool advances) "
                   "or whole_cut_line (every joint across the cut line broken before the cut: the bound)",
                   &P::lateral_crack),
      number_field("lateral_crack_length_um", kUm, Range::non_negative(),
                   "ahead_of_edge: how far ahead of the tip the lateral crack runs", &P::lateral_crack_length_m)};
  return table;
}

namespace {
/// The relations between fields (each field's own range is its table's); errors name section.key.
void check_cut_relations(const CutParams& p) {
  require(p.cut.window_m >= 1e-3 * p.cut.length_m, "cut.window_mm", units::m_to_mm(p.cut.window_m),
          "a positive window of at least 1/1000 of cut.length_mm");
  require(p.window.grain_strength_Pa == 0 || p.window.enabled, "active_window.grain_strength_MPa",
          units::pa_to_mpa(p.window.grain_strength_Pa), "0 unless active_window.enabled (only a window removes disks)");
  require(p.window.tied_grain_strength_Pa == 0 || p.window.enabled, "active_window.tied_grain_strength_MPa",
          units::pa_to_mpa(p.window.tied_grain_strength_Pa),
          "0 unless active_window.enabled (only a window removes disks)");
  // The wedge between the two faces must be a real wedge: rake + clearance < 90 deg.
  require(p.tool.rake_deg + p.tool.clearance_deg < 89, "tool.clearance_deg", p.tool.clearance_deg,
          "rake_deg + clearance_deg below 89 deg (a tool wedge angle of at least 1 deg)");
  // The rake face must rise above the uncut surface, or the chip would meet the tool's back face.
  require(p.tool.rake_face_height_m == 0 || p.tool.rake_face_height_m > p.cut.depth_of_cut_m,
          "tool.rake_face_height_mm", units::m_to_mm(p.tool.rake_face_height_m),
          "a height above the depth of cut (" + format_value(units::m_to_mm(p.cut.depth_of_cut_m)) +
              " mm), or 0 for 3 depths of cut");
  // The rounded edge must fit on the faces (see tool_outline).
  const double tangent = p.tool.edge_radius_m / std::tan(0.5 * wedge_angle_rad(p));
  require(tangent < std::min(rake_face_length_m(p), clearance_face_length_m(p)), "tool.edge_radius_um",
          units::m_to_um(p.tool.edge_radius_m), "an edge radius whose rounding fits on both tool faces");
  require(!p.edge_zone.enabled || p.window.enabled, "edge_zone.enabled", 1.0,
          "false unless active_window.enabled (the zone removes disks through the window)");
  require(p.edge_zone.lateral_crack != LateralCrack::ahead_of_edge || p.edge_zone.lateral_crack_length_m > 0,
          "edge_zone.lateral_crack_length_um", units::m_to_um(p.edge_zone.lateral_crack_length_m),
          "a positive length with edge_zone.lateral_crack = ahead_of_edge");
  if (p.edge_zone.lateral_crack != LateralCrack::none && !p.edge_zone.enabled)
    throw InputError("edge_zone.lateral_crack", lateral_crack_names().name(p.edge_zone.lateral_crack),
                     "none unless edge_zone.enabled (the crack runs under the zone's edge)");
  require((p.edge_zone.cutting_force_N_per_m < 0) == (p.edge_zone.thrust_force_N_per_m < 0),
          "edge_zone.thrust_force_N_per_mm", units::n_per_m_to_n_per_mm(p.edge_zone.thrust_force_N_per_m),
          "given together with edge_zone.cutting_force_N_per_mm, or both absent (the material's edge model)");
  if (p.window.enabled)
    require(p.window.shift_depths < p.window.ahead_depths, "active_window.shift_depths", p.window.shift_depths,
            "a shift below active_window.ahead_depths (" + format_value(p.window.ahead_depths) +
                "): the tool must not leave the window between two rebuilds");
  if (p.window.enabled)
    require(
        p.window.absorbing_depths < std::min({p.window.ahead_depths, p.window.behind_depths, p.window.below_depths}),
        "active_window.absorbing_depths", p.window.absorbing_depths,
        "a layer thinner than the window's ahead, behind and below depths");
  if (p.grooves.shape == GrooveShape::none) return;
  if (p.grooves.damage_model == GrooveDamageModel::edge_zone && !(p.edge_zone.enabled && p.grooves.damage_depth_m > 0))
    throw InputError(
        "grooves.damage_model", "edge_zone",
        "broken_joints unless edge_zone.enabled and grooves.damage_depth_um > 0 (the zone reads the layer)");
  require(p.grooves.width_m < p.grooves.pitch_m, "grooves.width_mm", units::m_to_mm(p.grooves.width_m),
          "a positive width below grooves.pitch_mm (" + format_value(units::m_to_mm(p.grooves.pitch_m)) + " mm)");
  if (p.grooves.shape == GrooveShape::trapezoidal)
    require(p.grooves.bottom_width_m < p.grooves.width_m, "grooves.bottom_width_mm",
            units::m_to_mm(p.grooves.bottom_width_m),
            "a value in [0, grooves.width_mm) (an inverted trapezoid is narrower at the bottom)");
}
}  // namespace

void validate_cut_params(const CutParams& p) {
  with_path("cut", [&] { check_fields(cut_fields(), p.cut); });
  CutParams::Tool tool = p.tool;
  if (tool.friction_coefficient < 0) tool.friction_coefficient = 0;  // negative: the material's
  with_path("tool", [&] { check_fields(tool_fields(), tool); });
  if (p.grooves.shape != GrooveShape::none) with_path("grooves", [&] { check_fields(groove_fields(), p.grooves); });
  if (p.window.enabled) with_path("active_window", [&] { check_fields(active_window_fields(), p.window); });
  if (p.edge_zone.enabled) with_path("edge_zone", [&] { check_fields(edge_zone_fields(), p.edge_zone); });
  check_cut_relations(p);
}

CutParams read_cut_params(ObjectReader& root) {
  CutParams p;
  ObjectReader cut = root.get_object("cut");
  read_fields_into(cut, cut_fields(), p.cut);
  cut.finish();
  if (auto tool = root.find_object("tool")) {
    read_fields_into(*tool, tool_fields(), p.tool);
    tool->finish();
  }
  if (auto grooves = root.find_object("grooves")) {
    // Seed 000 Section 4: groove depth = depth of cut (as the depth in mm read back), pitch 0.2 mm, width 0.06 mm.
    p.grooves.depth_m = units::mm_to_m(units::m_to_mm(p.cut.depth_of_cut_m));
    read_fields_into(*grooves, groove_fields(), p.grooves);
    if (!grooves->has("bottom_width_mm"))
      p.grooves.bottom_width_m = units::mm_to_m(units::m_to_mm(0.5 * p.grooves.width_m));
    grooves->finish();
  }
  if (auto window = root.find_object("active_window")) {
    read_fields_into(*window, active_window_fields(), p.window);
    window->finish();
  }
  if (auto zone = root.find_object("edge_zone")) {
    read_fields_into(*zone, edge_zone_fields(), p.edge_zone);
    zone->finish();
  }
  check_cut_relations(p);
  return p;
}

Json cut_params_to_json(const CutParams& p) {
  Json j{{"cut", fields_to_json(cut_fields(), p.cut)},
         {"tool", fields_to_json(tool_fields(), p.tool)},
         {"grooves", fields_to_json(groove_fields(), p.grooves)}};
  // Only when given: scenes without them keep their replicate_inputs (and so their reusable replicates).
  if (p.tool.friction_coefficient < 0) j["tool"].erase("friction_coefficient");
  if (p.tool.rake_face_height_m <= 0) j["tool"].erase("rake_face_height_mm");
  if (p.grooves.shape == GrooveShape::none) j["grooves"] = Json{{"shape", "none"}};
  if (p.grooves.shape != GrooveShape::trapezoidal) j["grooves"].erase("bottom_width_mm");
  if (p.grooves.damage_depth_m <= 0) {  // pristine: the summaries of scenes without a damaged layer unchanged
    j["grooves"].erase("damage_depth_um");
    j["grooves"].erase("damage_broken_fraction");
  }
  if (p.grooves.damage_depth_m <= 0 || p.grooves.damage_model == GrooveDamageModel::broken_joints)
    j["grooves"].erase("damage_model");  // the layers recorded before the choice keep their summaries
  if (p.window.enabled) j["active_window"] = fields_to_json(active_window_fields(), p.window);
  if (p.edge_zone.enabled) {
    j["edge_zone"] = fields_to_json(edge_zone_fields(), p.edge_zone);  // only when on: other summaries unchanged
    if (p.edge_zone.lateral_crack == LateralCrack::none)
      j["edge_zone"].erase("lateral_crack");  // the zones recorded before the choice keep their summaries
    if (p.edge_zone.lateral_crack != LateralCrack::ahead_of_edge) j["edge_zone"].erase("lateral_crack_length_um");
  }
  return j;
}

}  // namespace kerf::dem
