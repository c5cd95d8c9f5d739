#include "kerf/analytic/trepanning_scene.hpp"

#include "kerf/analytic/scene.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf {

TrepanningScene parse_trepanning_scene(const Json& document, MaterialCache* cache) {
  refuse_dem_scene(document);
  ObjectReader root(document, "");
  root.ignore("description");
  TrepanningScene scene;
  // A sweep's or a fit's points share one record: the file is read once.
  scene.material = cache ? cache->get(root.get("material"), "material") : load_material(root.get("material"), "material");

  ObjectReader tool = root.get_object("tool");
  scene.tool.outer_diameter_m = tool.get_si("outer_diameter_mm", Range::positive(), "mm", units::mm_to_m);
  scene.tool.inner_diameter_m = tool.get_si("inner_diameter_mm", Range::non_negative(), "mm", units::mm_to_m);
  tool.finish();
  scene.tool.validate("tool");

  ObjectReader cut = root.get_object("cut");
  scene.cut = TrepanningCut::from_user_units(cut.get_number("feed_rate_um_per_s", Range::positive(), "um/s"),
                                             cut.get_number("spindle_speed_rpm", Range::positive(), "rev/min"));
  cut.finish();
  scene.cut.validate("cut");
  check_feed_plausible(scene.tool, scene.cut);

  ObjectReader models = root.get_object("models");
  models.get_choice("force", {"trepanning"});
  ObjectReader params = models.get_object("trepanning");
  if (auto grits = params.find_object("grits")) {
    TrepanningGritParams g;
    g.grit_density_per_m2 = 1e6 * grits->get_number("grit_density_per_mm2", Range::positive(), "1/mm^2");
    g.shape_coefficient = grits->get_number_or("shape_coefficient", 1.0, Range{0.0, 1.0, true, false}, "");
    g.grit_width_m = grits->get_si("grit_width_um", Range::positive(), "um", units::um_to_m);
    grits->finish();
    g.validate("models.trepanning.grits");
    scene.grits = g;
  }
  const bool has_groups = params.has("axial_group_MPa") || params.has("torque_group_MPa");
  if (has_groups) {
    scene.groups.axial_group_Pa = params.get_si("axial_group_MPa", Range::positive(), "MPa", units::mpa_to_pa);
    scene.groups.torque_group_Pa = params.get_si("torque_group_MPa", Range::positive(), "MPa", units::mpa_to_pa);
    scene.groups_origin = "models.trepanning.axial_group_MPa and torque_group_MPa";
    params.ignore("origin");
    params.finish();
  } else {
    TrepanningMaterial m;
    if (auto h = params.get_optional_number("hardness_GPa", Range::positive(), "GPa")) {
      m.hardness_Pa = units::gpa_to_pa(*h);
    } else {
      const Json& brittle = scene.material.require_group("brittle", "material", "the trepanning model's hardness");
      if (!brittle.contains("hardness_GPa")) {
        throw InputError("models.trepanning.hardness_GPa", "(missing, and not in the material)",
                         "a hardness in GPa here or in the material's brittle.hardness_GPa");
      }
      m.hardness_Pa = units::gpa_to_pa(brittle.at("hardness_GPa").get<double>());
    }
    m.half_angle_rad = units::deg_to_rad(params.get_number("half_angle_deg", Range::open(0.0, 90.0), "deg"));
    m.friction_coefficient = params.get_number("friction_coefficient", Range::non_negative(), "");
    params.ignore("origin");
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
