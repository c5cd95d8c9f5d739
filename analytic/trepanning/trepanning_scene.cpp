#include "kerf/analytic/trepanning/trepanning_scene.hpp"

#include "kerf/analytic/kinds/material_models.hpp"
#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/error.hpp"
#include "kerf/field_table.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

const FieldUnit kUmPerS{"um/s", units::um_to_m, units::m_to_um};
const FieldUnit kRpm{"rev/min", units::rpm_to_rev_per_s, units::rev_per_s_to_rpm};
constexpr double per_mm2_to_per_m2(double n) {
  return 1e6 * n;
}
constexpr double per_m2_to_per_mm2(double n) {
  return 1e-6 * n;
}
const FieldUnit kPerMm2{"1/mm^2", per_mm2_to_per_m2, per_m2_to_per_mm2};

const FieldTable<TrepanningTool>& tool_fields() {
  static const FieldTable<TrepanningTool> table{
      required_number_field("outer_diameter_mm", units::kMm, Range::positive(), "cutter outer diameter D",
                            &TrepanningTool::outer_diameter_m),
      required_number_field("inner_diameter_mm", units::kMm, Range::non_negative(),
                            "cutter inner diameter d, D > d (0: a solid core drill)",
                            &TrepanningTool::inner_diameter_m)};
  return table;
}

const FieldTable<TrepanningCut>& cut_fields() {
  static const FieldTable<TrepanningCut> table{
      required_number_field("feed_rate_um_per_s", kUmPerS, Range::positive(), "feed rate v_f",
                            &TrepanningCut::feed_rate_m_per_s),
      required_number_field("spindle_speed_rpm", kRpm, Range::positive(), "spindle speed n_0",
                            &TrepanningCut::spindle_speed_rev_per_s)};
  return table;
}

/// models.force of a trepanning scene: the one model (required: it is what makes the scene a trepanning one).
enum class TrepanningForce { trepanning };
struct TrepanningModels {
  TrepanningForce force = TrepanningForce::trepanning;
};
constexpr std::string_view kForceNamesText[] = {"trepanning"};
constexpr EnumNames<TrepanningForce> kForceNames{kForceNamesText};

const FieldTable<TrepanningModels>& models_fields() {
  static const FieldTable<TrepanningModels> table{
      choice_field("force", kForceNames, "the model: a trepanning scene must name it (it makes the scene one)",
                   &TrepanningModels::force)};
  return table;
}

const FieldTable<TrepanningGroups>& groups_fields() {
  static const FieldTable<TrepanningGroups> table{
      required_number_field("axial_group_MPa", units::kMPa, Range::positive(),
                            "K_F = H tan(phi) (what `compare --fit` fits)", &TrepanningGroups::axial_group_Pa),
      required_number_field("torque_group_MPa", units::kMPa, Range::positive(), "K_M = H (1 + pi tan(phi) mu / 2)",
                            &TrepanningGroups::torque_group_Pa)};
  return table;
}

const FieldTable<TrepanningMaterial>& material_fields() {
  static const FieldTable<TrepanningMaterial> table{
      NumberField<TrepanningMaterial>{"hardness_GPa", units::kGPa, Range::positive(), "hardness H",
                                      [](const TrepanningMaterial& m) { return m.hardness_Pa; },
                                      [](TrepanningMaterial& m, double v) { m.hardness_Pa = v; }, false,
                                      [](const TrepanningMaterial& m) { return m.hardness_Pa > 0.0; },
                                      "the material's `brittle.hardness_GPa`"},
      required_number_field("half_angle_deg", units::kDeg, Range::open(0.0, 90.0), "abrasive grit half angle phi",
                            &TrepanningMaterial::half_angle_rad),
      required_number_field("friction_coefficient", units::kNone, Range::non_negative(), "friction coefficient mu",
                            &TrepanningMaterial::friction_coefficient)};
  return table;
}

const FieldTable<TrepanningGritParams>& grit_fields() {
  static const FieldTable<TrepanningGritParams> table{
      required_number_field("grit_density_per_mm2", kPerMm2, Range::positive(), "grits per unit area of the end face C",
                            &TrepanningGritParams::grit_density_per_m2),
      number_field("shape_coefficient", units::kNone, Range{0.0, 1.0, true, false},
                   "G: the fraction of the end face that carries grits", &TrepanningGritParams::shape_coefficient),
      required_number_field("grit_width_um", units::kUm, Range::positive(), "cutting width of one grit a",
                            &TrepanningGritParams::grit_width_m)};
  return table;
}

}  // namespace

const std::vector<SceneKeySection>& trepanning_key_sections() {
  static const std::vector<SceneKeySection> list{
      {"tool", "trepanning scenes: the drill", [] { return fields_markdown(tool_fields()); }},
      {"cut", "trepanning scenes", [] { return fields_markdown(cut_fields()); }},
      {"models", "trepanning scenes: besides `force`, the object `trepanning`",
       [] { return fields_markdown(models_fields()); }},
      {"models.trepanning",
       "the two lumped groups; or the three keys of the next table (each way may carry a free-text `origin`)",
       [] { return fields_markdown(groups_fields()); }},
      {"models.trepanning", "or: hardness, half angle and friction, from which the groups follow",
       [] { return fields_markdown(material_fields()); }},
      {"models.trepanning.grits", "optional: the per-grit diagnostics of Eqs. 1-20 (the totals do not depend on them)",
       [] { return fields_markdown(grit_fields()); }}};
  return list;
}

TrepanningScene parse_trepanning_scene(const Json& document, MaterialCache* cache) {
  refuse_dem_scene(document);
  ObjectReader root(document, "");
  root.ignore("description");
  TrepanningScene scene;
  // A sweep's or a fit's points share one record: the file is read once.
  scene.material =
      cache ? cache->get(root.get("material"), "material") : load_material(root.get("material"), "material");

  ObjectReader tool = root.get_object("tool");
  read_fields_into(tool, tool_fields(), scene.tool, SiCheck::on);
  tool.finish();
  scene.tool.validate("tool");

  ObjectReader cut = root.get_object("cut");
  read_fields_into(cut, cut_fields(), scene.cut, SiCheck::on);
  cut.finish();
  scene.cut.validate("cut");
  with_path("cut", [&] { check_feed_plausible(scene.tool, scene.cut); });

  ObjectReader models = root.get_object("models");
  models.get("force");  // required (an error naming it when missing); read with its table
  read_fields(models, models_fields(), TrepanningModels{}, SiCheck::on);
  ObjectReader params = models.get_object("trepanning");
  if (auto grits = params.find_object("grits")) {
    TrepanningGritParams g = read_fields(*grits, grit_fields(), TrepanningGritParams{}, SiCheck::on);
    grits->finish();
    g.validate("models.trepanning.grits");
    scene.grits = g;
  }
  params.ignore("origin");
  if (params.has("axial_group_MPa") || params.has("torque_group_MPa")) {
    read_fields_into(params, groups_fields(), scene.groups, SiCheck::on);
    scene.groups_origin = "models.trepanning.axial_group_MPa and torque_group_MPa";
    params.finish();
  } else {
    TrepanningMaterial m = read_fields(params, material_fields(), TrepanningMaterial{}, SiCheck::on);
    if (!params.has("hardness_GPa")) {
      scene.material.require_group("brittle", "material", "the trepanning model's hardness");
      const auto hardness_Pa = brittle_group_from_material(scene.material, "material").hardness_Pa;
      if (!hardness_Pa) {
        throw InputError("models.trepanning.hardness_GPa", "(missing, and not in the material)",
                         "a hardness in GPa here or in the material's brittle.hardness_GPa");
      }
      m.hardness_Pa = *hardness_Pa;
    }
    params.finish({"axial_group_MPa", "torque_group_MPa"});
    m.validate("models.trepanning");
    scene.material_params = m;
    scene.groups = TrepanningGroups::from_material(m);
    scene.groups_origin = "hardness, half angle and friction coefficient";
  }
  models.finish();
  root.finish();
  return scene;
}

}  // namespace kerf
