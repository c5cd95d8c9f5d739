#include "kerf/analytic/kinds/scene.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/kinds/material_models.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using kerf::Json;

namespace {
Json orthogonal_scene() {
  return Json::parse(R"({
    "material": "psic",
    "tool": {"rake_deg": 0, "edge_radius_um": 0.2},
    "cut": {"uncut_chip_thickness_um": 0.1, "width_mm": 1, "speed_m_per_min": 60, "friction_coefficient": 0.35},
    "models": {"force": "liu_li", "flow_stress": ["johnson_cook", "hall_petch", "dislocation"]}
  })");
}
}  // namespace

TEST_CASE("A scene builds only the flow-stress terms it names", "[scene]") {
  auto doc = orthogonal_scene();
  doc["models"]["flow_stress"] = Json::array({"hall_petch"});
  const auto scene = kerf::parse_analytic_scene(doc);
  CHECK_FALSE(scene.flow_stress.johnson_cook.has_value());
  CHECK(scene.flow_stress.hall_petch.has_value());
  CHECK_FALSE(scene.flow_stress.dislocation.has_value());
  const auto p = kerf::predict(scene);
  CHECK(p.flow.johnson_cook_Pa == 0.0);
  CHECK(p.flow.total_Pa == p.flow.hall_petch_Pa);
}

TEST_CASE("Forces scale with the width but per-width columns do not", "[scene]") {
  auto doc = orthogonal_scene();
  const auto narrow = kerf::predict(kerf::parse_analytic_scene(doc));
  doc["cut"]["width_mm"] = 3.0;
  const auto wide = kerf::predict(kerf::parse_analytic_scene(doc));
  CHECK_THAT(wide.cutting_force_N, WithinRel(3.0 * narrow.cutting_force_N, 1e-12));
  CHECK_THAT(wide.thrust_force_N, WithinRel(3.0 * narrow.thrust_force_N, 1e-12));
}

TEST_CASE("models.force = auto picks the cheapest valid model", "[scene][registry]") {
  auto doc = orthogonal_scene();
  doc["models"]["force"] = "auto";
  doc["tool"]["edge_radius_um"] = 0.001;  // 1 % of t0: sharp
  CHECK(kerf::parse_analytic_scene(doc).force->name == "merchant");
  doc["tool"]["edge_radius_um"] = 0.2;
  CHECK(kerf::parse_analytic_scene(doc).force->name == "liu_li");
  doc["cut"].erase("friction_coefficient");
  doc["material"] = "aisi_1045";
  doc["models"]["flow_stress"] = "johnson_cook";
  CHECK(kerf::parse_analytic_scene(doc).force->name == "oxley");
}

TEST_CASE("Merchant and Liu-Li agree for a sharp edge", "[scene]") {
  auto doc = orthogonal_scene();
  doc["tool"]["edge_radius_um"] = 0.0;
  const auto liu_li = kerf::predict(kerf::parse_analytic_scene(doc));
  doc["models"]["force"] = "merchant";
  const auto merchant = kerf::predict(kerf::parse_analytic_scene(doc));
  CHECK_THAT(liu_li.cutting_force_N, WithinRel(merchant.cutting_force_N, 1e-12));
  CHECK_THAT(liu_li.thrust_force_N, WithinRel(merchant.thrust_force_N, 1e-12));
}

TEST_CASE("Friction from measured forces follows Berezvai et al. 2019", "[scene]") {
  auto doc = orthogonal_scene();
  doc["cut"].erase("friction_coefficient");
  doc["tool"]["rake_deg"] = 15.0;
  doc["measured"] = {{"cutting_force_N", 200.0}, {"thrust_force_N", 100.0}};
  const auto scene = kerf::parse_analytic_scene(doc);
  CHECK_THAT(*scene.friction_angle_rad, WithinRel(std::atan(0.5) + kerf::units::deg_to_rad(15.0), 1e-14));
  doc["cut"]["friction_angle_deg"] = 20.0;
  CHECK_THROWS_AS(kerf::parse_analytic_scene(doc), kerf::InputError);
}

TEST_CASE("Scene errors name the field", "[scene]") {
  auto doc = orthogonal_scene();
  doc["cut"]["speed_m_per_min"] = -1.0;
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc), Contains("cut.speed_m_per_min = -1"));
  doc = orthogonal_scene();
  doc["models"]["contact_length"] = Json::array({"lee_shafer"});
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc), Contains("did you mean 'lee_shaffer'?"));
  doc = orthogonal_scene();
  doc["cut"]["turning"] = {{"feed_um_per_rev", 0.25}, {"nose_radius_mm", 0.5}, {"depth_of_cut_um", 10}};
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc), Contains("cut.uncut_chip_thickness_um"));
  doc = orthogonal_scene();
  doc["models"]["shear_angle"] = "chip_ratio";
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc), Contains("cut.chip_ratio"));
}

TEST_CASE("A turning scene cuts the equivalent chip over the engaged edge", "[scene][round_nose]") {
  auto doc = orthogonal_scene();
  doc["cut"].erase("uncut_chip_thickness_um");
  doc["cut"].erase("width_mm");
  doc["cut"]["turning"] = {{"feed_um_per_rev", 0.25}, {"nose_radius_mm", 0.5}, {"depth_of_cut_um", 10}};
  const auto scene = kerf::parse_analytic_scene(doc);
  REQUIRE(scene.turning.has_value());
  CHECK_THAT(scene.width_m, WithinRel(scene.turning->chip.engaged_edge_length_m, 1e-12));
  CHECK_THAT(scene.uncut_chip_thickness_m * scene.width_m, WithinRel(0.25e-6 * 10e-6, 1e-12));
  // Forces rise with depth of cut (Shao et al. 2013, Figs. 4-5). A 5 nm edge keeps the ploughed layer (about 1 nm)
  // below the equivalent chip thickness of the shallowest cut (about 6 nm).
  doc["tool"]["edge_radius_um"] = 0.005;
  double previous = 0.0;
  for (double depth_um : {0.5, 5.0, 50.0, 300.0}) {
    doc["cut"]["turning"]["depth_of_cut_um"] = depth_um;
    const auto p = kerf::predict(kerf::parse_analytic_scene(doc));
    CHECK(p.cutting_force_N > previous);
    previous = p.cutting_force_N;
  }
}

TEST_CASE("Extreme inputs give a finite result or a clean error, never NaN", "[scene][extremes]") {
  // Issue 2: t0 1 nm - 1 mm, r 0 - 100 um, rake -60 - +30 deg, T up to T_melt, grains 1 nm - 1 mm.
  int finite = 0, refused = 0;
  for (const char* force : {"merchant", "liu_li"}) {
    for (double t0_um : {1e-3, 1e-1, 10.0, 1000.0}) {
      for (double radius_um : {0.0, 0.05, 5.0, 100.0}) {
        for (double rake_deg : {-60.0, -20.0, 0.0, 30.0}) {
          for (double temperature_K : {200.0, 293.15, 1500.0, 3003.0}) {
            for (double grain_um : {1e-3, 1.0, 1000.0}) {
              Json doc = orthogonal_scene();
              doc["models"]["force"] = force;
              doc["models"]["deformation"] = "given";
              doc["cut"]["strain"] = 1.0;
              doc["cut"]["strain_rate_per_s"] = 1e6;
              doc["cut"]["temperature_K"] = temperature_K;
              doc["cut"]["uncut_chip_thickness_um"] = t0_um;
              doc["tool"]["edge_radius_um"] = radius_um;
              doc["tool"]["rake_deg"] = rake_deg;
              // An inline copy of p-SiC with the grain size varied.
              try {
                Json material = Json::parse(R"({"name": "psic_variant",
                  "elastic": {"youngs_modulus_GPa": 410, "poissons_ratio": 0.14},
                  "johnson_cook": {"A_MPa": 8000, "B_MPa": 0, "n": 1, "C": 0, "m": 1,
                    "reference_strain_rate_per_s": 1, "room_temperature_K": 293.15, "melting_temperature_K": 3003},
                  "microstructure": {"burgers_vector_nm": 0.308, "misorientation_deg": 2.5}})");
                material["microstructure"]["grain_size_um"] = grain_um;
                doc["material"] = material;
                const auto p = kerf::predict(kerf::parse_analytic_scene(doc));
                CHECK(std::isfinite(p.cutting_force_N));
                CHECK(std::isfinite(p.thrust_force_N));
                CHECK(std::isfinite(p.flow.total_Pa));
                for (const auto& [name, value] : kerf::prediction_columns(kerf::parse_analytic_scene(doc), p)) {
                  INFO(name);
                  CHECK(value.find("nan") == std::string::npos);
                  CHECK(value.find("inf") == std::string::npos);
                }
                ++finite;
              } catch (const kerf::InputError& e) {
                ++refused;
                CHECK(std::string(e.what()).find(" = ") != std::string::npos);  // names a field and its value
              }
            }
          }
        }
      }
    }
  }
  INFO("finite " << finite << ", refused " << refused);
  CHECK(finite > 1000);
}

TEST_CASE("Oxley through a scene: forces, and the zone-AB state feeding Liu-Li", "[scene][oxley]") {
  const Json steel = Json::parse(R"({
    "material": "aisi_1045",
    "tool": {"rake_deg": -7},
    "cut": {"uncut_chip_thickness_um": 150, "width_mm": 1.6, "speed_m_per_min": 200},
    "models": {"force": "oxley"}
  })");
  const auto oxley = kerf::predict(kerf::parse_analytic_scene(steel));
  REQUIRE(oxley.oxley.has_value());
  CHECK(oxley.cutting_force_N > oxley.thrust_force_N);
  CHECK(oxley.oxley->residual < 1e-6);
  CHECK(oxley.state.temperature_K > 298.15);  // shear-zone heating

  // The same cut with a Liu-Li force and the Oxley state: with a sharp edge and Oxley's own friction
  // angle and chip ratio, the Merchant force of the zone-AB stress is not Oxley's force (Oxley's shear plane
  // carries a non-uniform stress), but it is within a factor of two.
  Json chained = steel;
  chained["models"] = {{"force", "liu_li"}, {"deformation", "oxley"}, {"shear_angle", "chip_ratio"}};
  chained["cut"]["chip_ratio"] = oxley.chip_ratio;
  chained["cut"]["friction_angle_deg"] = kerf::units::rad_to_deg(oxley.friction_angle_rad);
  const auto liu_li = kerf::predict(kerf::parse_analytic_scene(chained));
  CHECK_THAT(liu_li.state.temperature_K, WithinRel(oxley.state.temperature_K, 1e-12));
  CHECK_THAT(liu_li.flow.total_Pa, WithinRel(oxley.flow.total_Pa, 1e-12));
  CHECK(liu_li.cutting_force_N > 0.5 * oxley.cutting_force_N);
  CHECK(liu_li.cutting_force_N < 2.0 * oxley.cutting_force_N);
}

TEST_CASE("Oxley refuses microstructure terms it cannot use", "[scene][oxley]") {
  auto doc = orthogonal_scene();
  doc["models"]["force"] = "oxley";
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc), Contains("models.flow_stress"));
}

TEST_CASE("Oxley deformation works when the force model's flow stress leaves Johnson-Cook out", "[scene][oxley]") {
  // AISI 1045 at the reference cut of Pantale et al. (Oxley solves there), with an (illustrative) microstructure
  // group so that the force model can use the Hall-Petch term alone.
  Json doc = Json::parse(R"({
    "tool": {"rake_deg": -7},
    "cut": {"uncut_chip_thickness_um": 150, "width_mm": 1.6, "speed_m_per_min": 200, "friction_coefficient": 0.3},
    "models": {"force": "liu_li", "deformation": "oxley", "flow_stress": ["hall_petch"]}
  })");
  doc["material"] = kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/materials/aisi_1045.json");
  doc["material"]["microstructure"] = {
      {"grain_size_um", 20.0}, {"burgers_vector_nm", 0.248}, {"misorientation_deg", 2.0}};
  const auto scene = kerf::parse_analytic_scene(doc);
  CHECK_FALSE(scene.flow_stress.johnson_cook.has_value());
  REQUIRE(scene.params<kerf::OxleyModelParams>().material.has_value());
  CHECK_THAT(scene.params<kerf::OxleyModelParams>().material->johnson_cook.A_Pa,
             WithinRel(553.1e6, 1e-12));  // AISI 1045's Johnson-Cook A
  const auto p = kerf::predict(scene);
  CHECK(p.flow.johnson_cook_Pa == 0.0);
  CHECK(p.flow.total_Pa == p.flow.hall_petch_Pa);
  CHECK(p.state.temperature_K > 298.15);  // zone AB's temperature, which softens the Hall-Petch term
}

// ---- Issue 22: the analytic models at their edges ---------------------------------------------------------

namespace {
Json a2024_scene() {
  return Json::parse(R"({
    "material": "a2024_t351",
    "tool": {"rake_deg": 15, "edge_radius_um": 0},
    "cut": {"uncut_chip_thickness_um": 3, "width_mm": 2, "speed_m_per_min": 10, "friction_angle_deg": 20,
            "chip_ratio": 0.5},
    "models": {"force": "liu_li", "flow_stress": ["johnson_cook"]}
  })");
}
// Merchant's force circle (Berezvai et al. 2019; physics-analytic.md section 2) at the prediction's own phi and beta.
double merchant_cutting_force(const kerf::Prediction& p, double rake_rad) {
  const double phi = p.shear_angle_rad, beta = p.friction_angle_rad;
  return p.flow.shear_Pa * p.uncut_chip_thickness_m * p.width_m * std::cos(beta - rake_rad) /
         (std::sin(phi) * std::cos(phi + beta - rake_rad));
}
}  // namespace

TEST_CASE("One friction angle: Liu-Li's r -> 0 limit is Merchant on the same scene for every closure and rule",
          "[scene][liu_li][issue22]") {
  const double rake = kerf::units::deg_to_rad(15.0);
  for (const char* closure : {"constant", "merchant", "lee_shaffer"}) {
    for (const char* rule : {"merchant", "lee_shaffer", "chip_ratio"}) {
      for (const char* lower : {"stagnation", "pole"}) {
        CAPTURE(closure, rule, lower);
        Json doc = a2024_scene();
        doc["models"]["friction_closure"] = closure;
        doc["models"]["shear_angle"] = rule;
        doc["models"]["lower_limit"] = lower;
        doc["tool"]["edge_radius_um"] = 1e-8;  // 0.01 pm: the edge part is O(r / t0)
        const auto liu_li = kerf::predict(kerf::parse_analytic_scene(doc));
        doc["models"]["force"] = "merchant";
        doc["tool"]["edge_radius_um"] = 0.0;
        const auto merchant = kerf::predict(kerf::parse_analytic_scene(doc));
        CHECK_THAT(liu_li.friction_angle_rad, WithinRel(merchant.friction_angle_rad, 1e-14));
        CHECK_THAT(liu_li.cutting_force_N, WithinRel(merchant.cutting_force_N, 1e-5));
        CHECK_THAT(liu_li.thrust_force_N, WithinRel(merchant.thrust_force_N, 1e-5));
        CHECK_THAT(merchant.cutting_force_N, WithinRel(merchant_cutting_force(merchant, rake), 1e-12));
        // The thrust/cutting ratio is tan(beta - a) with the printed beta: the forces and the printed value agree.
        CHECK_THAT(merchant.thrust_force_N / merchant.cutting_force_N,
                   WithinRel(std::tan(merchant.friction_angle_rad - rake), 1e-12));
        // The stagnation angle uses the same beta.
        REQUIRE(liu_li.chip_term.liu_li.has_value());
        CHECK_THAT(liu_li.chip_term.liu_li->stagnation_angle_rad,
                   WithinRel(-(std::numbers::pi / 4.0 + liu_li.friction_angle_rad / 2.0), 1e-14));
      }
    }
  }
}

TEST_CASE("Issue 22 reproducer 1: a measured chip ratio with the Merchant closure sets beta everywhere",
          "[scene][issue22]") {
  // r = 0, rake 15 deg, t0 = 3 um, r_c = 0.5, scene beta 20 deg: the closure gives beta = 90 + a - 2 phi.
  Json doc = a2024_scene();
  doc["models"]["shear_angle"] = "chip_ratio";
  doc["models"]["contact_length"] = Json::array({"altintas_mep"});
  const auto p = kerf::predict(kerf::parse_analytic_scene(doc));
  const double phi = std::atan2(0.5 * std::cos(kerf::units::deg_to_rad(15.0)),
                                1.0 - 0.5 * std::sin(kerf::units::deg_to_rad(15.0)));  // Shao et al. 2013, Eq. 3
  const double beta = std::numbers::pi / 2.0 + kerf::units::deg_to_rad(15.0) - 2.0 * phi;
  CHECK_THAT(kerf::units::rad_to_deg(p.friction_angle_rad), WithinAbs(46.96, 0.01));  // the issue's 46.96 deg
  CHECK_THAT(p.friction_angle_rad, WithinRel(beta, 1e-12));
  CHECK_THAT(p.thrust_force_N / p.cutting_force_N, WithinRel(std::tan(beta - kerf::units::deg_to_rad(15.0)), 1e-12));
  // The contact length uses it too: Altintas (Berezvai et al. 2019, Eq. 1) with the MEP shear angle of beta.
  const double a = kerf::units::deg_to_rad(15.0), phi_mep = std::numbers::pi / 4.0 - (beta - a) / 2.0;
  REQUIRE(p.contact_lengths_m.size() == 1);
  CHECK_THAT(*p.contact_lengths_m[0].second,
             WithinRel(3e-6 * std::sin(phi_mep + beta - a) / (std::sin(phi_mep) * std::cos(beta)), 1e-12));
  bool warned = false;
  for (const auto& w : p.warnings) warned = warned || w.find("not the scene's 20 deg") != std::string::npos;
  CHECK(warned);
}

TEST_CASE("The stagnation cut-off holds for the whole tool: a rake face below it ploughs", "[scene][liu_li][issue22]") {
  // Issue 22 reproducer 2: rake -60 deg, below the -55 deg stagnation angle of beta = 20 deg.
  Json doc = a2024_scene();
  doc["cut"].erase("chip_ratio");
  doc["models"]["shear_angle"] = "merchant";
  doc["models"]["friction_closure"] = "constant";
  doc["tool"]["rake_deg"] = -60.0;
  for (double radius_um : {0.0, 35.0}) {
    for (const char* force : {"liu_li", "merchant"}) {
      CAPTURE(radius_um, force);
      doc["tool"]["edge_radius_um"] = radius_um;
      doc["models"]["force"] = force;
      const auto p = kerf::predict(kerf::parse_analytic_scene(doc));
      CHECK(p.guards.has(kerf::Guard::no_chip_on_rake_face));
      // No chip force: with an edge, the force is the ploughing force under it alone (issue 38).
      const double ploughing_N = p.chip_term.ploughing ? p.chip_term.ploughing->force.cutting_N_per_m * p.width_m : 0.0;
      CHECK(p.cutting_force_N == ploughing_N);
      CHECK((ploughing_N > 0.0) == (radius_um > 0.0 && std::string(force) == "liu_li"));
      if (p.chip_term.liu_li) CHECK(p.chip_term.liu_li->ploughed_thickness_m == 3e-6);
      if (p.chip_term.liu_li) CHECK(p.chip_term.liu_li->total.cutting_N_per_m == 0.0);
      if (p.chip_term.liu_li) CHECK(p.chip_term.liu_li->total.thrust_N_per_m == 0.0);
      doc["models"]["ploughing"] = "none";
      const auto none = kerf::predict(kerf::parse_analytic_scene(doc));
      doc["models"].erase("ploughing");
      CHECK(none.cutting_force_N == 0.0);
      CHECK(none.thrust_force_N == 0.0);
    }
  }
  // Across the stagnation angle (-55 deg): the edge part closes continuously (its range [g_s, a] shrinks to
  // nothing); the straight rake face switches off at once, the model's criterion being a switch (docs/models.md).
  doc["models"]["force"] = "liu_li";
  doc["tool"]["edge_radius_um"] = 10.0;
  doc["cut"]["uncut_chip_thickness_um"] = 5.0;
  double previous_edge = -1.0;
  for (double rake_deg = -54.0; rake_deg >= -56.0; rake_deg -= 0.05) {
    CAPTURE(rake_deg);
    doc["tool"]["rake_deg"] = rake_deg;
    const auto p = kerf::predict(kerf::parse_analytic_scene(doc));
    REQUIRE(p.chip_term.liu_li.has_value());
    const double edge = p.chip_term.liu_li->edge.cutting_N_per_m * p.width_m;
    if (previous_edge >= 0.0)
      CHECK(std::fabs(edge - previous_edge) < 0.01 * p.chip_term.liu_li->rake_face.cutting_N_per_m * 2e-3 + 1e-3);
    previous_edge = edge;
    CHECK((p.chip_term.liu_li->rake_face.cutting_N_per_m > 0.0) == (rake_deg > -55.0));
  }
  CHECK(previous_edge == 0.0);
}

TEST_CASE("A contact-length variant outside its domain is not applicable, the rest goes on", "[scene][issue22]") {
  // Issue 22 reproducer 4: a2024_planing at rake -60 deg: the MSSP shear angle is -26.3 deg.
  Json doc = kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/scenes/a2024_planing.json");
  doc["tool"]["rake_deg"] = -60.0;
  const auto scene = kerf::parse_analytic_scene(doc);
  const auto p = kerf::predict(scene);
  CHECK(p.guards.has(kerf::Guard::contact_length_not_applicable));
  std::map<std::string, std::string> row;
  for (const auto& [name, value] : kerf::prediction_columns(scene, p)) row[name] = value;
  CHECK(row["contact_length_altintas_mssp_mm"].empty());
  CHECK(row["contact_length_lee_shaffer_mssp_mm"].empty());
  CHECK_FALSE(row["contact_length_altintas_mep_mm"].empty());
  CHECK_THAT(row["guards"], Contains("contact_length_not_applicable"));
  CHECK_THAT(row["warnings"], Contains("shear angle -26.31 deg outside (0, 90) deg"));
}

TEST_CASE("Plausibility: a closure implying a negative friction angle is refused", "[scene][issue22]") {
  // Issue 22: chip ratio 3 at rake <= 0 gave a negative thrust (beta = 90 + a - 2 phi < 0).
  Json doc = a2024_scene();
  doc["cut"]["chip_ratio"] = 3.0;
  doc["tool"]["rake_deg"] = 0.0;
  doc["models"]["shear_angle"] = "chip_ratio";
  const auto scene = kerf::parse_analytic_scene(doc);
  CHECK_THROWS_WITH(
      kerf::predict(scene),
      Contains("cut.chip_ratio = 3: expected a shear angle and friction closure giving a friction angle >= 0"));
}

TEST_CASE("Plausibility: rake -89.9 deg cuts no chip instead of a 1000-fold thrust", "[scene][issue22]") {
  Json doc = a2024_scene();  // chip ratio 0.5 with the Merchant closure: beta = 0.03 deg at this rake
  doc["models"]["shear_angle"] = "chip_ratio";
  doc["tool"]["rake_deg"] = -89.9;
  for (const char* lower : {"stagnation", "pole"}) {
    doc["models"]["lower_limit"] = lower;
    const auto p = kerf::predict(kerf::parse_analytic_scene(doc));
    CHECK(p.thrust_force_N == 0.0);
    CHECK(p.guards.has(kerf::Guard::no_chip_on_rake_face));
  }
}

TEST_CASE("The A2024 contact-length validity warning fires only for A2024", "[scene][issue22]") {
  Json doc = a2024_scene();
  doc["cut"]["uncut_chip_thickness_um"] = 150.0;
  doc["models"]["contact_length"] = Json::array({"altintas_mep"});
  const auto has_warning = [](const kerf::Prediction& p) {
    for (const auto& w : p.warnings)
      if (w.find("validated up to h = 0.1 mm") != std::string::npos) return true;
    return false;
  };
  CHECK(has_warning(kerf::predict(kerf::parse_analytic_scene(doc))));
  doc["material"] = "aisi_1045";
  CHECK_FALSE(has_warning(kerf::predict(kerf::parse_analytic_scene(doc))));
}

TEST_CASE("The force falls continuously to zero at the melting temperature", "[scene][flow_stress][issue22]") {
  // Issue 22: p-SiC's force jumped from 0.432 N at 3002.9 K to 0 N at 3003 K (microstructural terms unsoftened).
  Json doc = orthogonal_scene();
  doc["models"]["deformation"] = "given";
  doc["cut"]["strain"] = 1.0;
  doc["cut"]["strain_rate_per_s"] = 1e6;
  double previous = std::numeric_limits<double>::infinity();
  const auto force_at = [&](double temperature_K) {
    doc["cut"]["temperature_K"] = temperature_K;
    return kerf::predict(kerf::parse_analytic_scene(doc)).cutting_force_N;
  };
  const double room = force_at(293.15);
  for (double temperature_K : {293.15, 1000.0, 2000.0, 2900.0, 3000.0, 3002.9, 3002.999}) {
    const double f = force_at(temperature_K);
    CHECK(f <= previous);
    previous = f;
  }
  CHECK(force_at(3002.9) < 1e-4 * room);  // continuous with the molten 0 N
  CHECK(force_at(3003.0) == 0.0);
}

TEST_CASE("Oxley mode reports its own friction angle and the contact lengths from it", "[scene][oxley][issue22]") {
  Json doc = kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/scenes/aisi1045_oxley.json");
  doc["cut"]["friction_angle_deg"] = 5.0;  // ignored by Oxley, which predicts lambda
  const auto p = kerf::predict(kerf::parse_analytic_scene(doc));
  REQUIRE(p.oxley.has_value());
  // lambda = theta + a - phi, and F_t / F_c = tan(lambda - a) (Oxley's force circle, O 6).
  const double a = kerf::units::deg_to_rad(-7.0);
  CHECK_THAT(p.thrust_force_N / p.cutting_force_N, WithinRel(std::tan(p.friction_angle_rad - a), 1e-9));
  const double phi_mep = std::numbers::pi / 4.0 - (p.friction_angle_rad - a) / 2.0;  // Berezvai et al. 2019, Eq. 4
  REQUIRE(p.contact_lengths_m.size() == 2);
  CHECK_THAT(*p.contact_lengths_m[1].second, WithinRel(150e-6 * std::sin(phi_mep + p.friction_angle_rad - a) /
                                                           (std::sin(phi_mep) * std::cos(p.friction_angle_rad)),
                                                       1e-12));  // altintas_mep, Berezvai et al. 2019, Eq. 1
}

TEST_CASE("Oxley without a physical solution is a model failure naming why", "[scene][oxley][issue22]") {
  // Issue 22 reproducer 3: AISI 1045 at rake -60 deg (F_t = -0.0035 N, temperature at melting, exit 0).
  Json steel = kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/scenes/aisi1045_oxley.json");
  steel["tool"]["rake_deg"] = -60.0;
  CHECK_THROWS_WITH(kerf::predict(kerf::parse_analytic_scene(steel)), Contains("temperature at melting"));
  // a2024_planing with Oxley, sharp: delta pinned at 0.2 from 200 um, phi at its 5 deg bound at 190 um.
  Json doc = kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/scenes/a2024_planing.json");
  doc["models"]["force"] = "oxley";
  doc["tool"]["edge_radius_um"] = 0.0;
  doc["cut"]["uncut_chip_thickness_um"] = 200.0;
  CHECK_THROWS_AS(kerf::predict(kerf::parse_analytic_scene(doc)), kerf::ModelError);
  CHECK_THROWS_WITH(kerf::predict(kerf::parse_analytic_scene(doc)), Contains("delta at its bound (0.2"));
  doc["cut"]["uncut_chip_thickness_um"] = 190.0;
  CHECK_THROWS_WITH(kerf::predict(kerf::parse_analytic_scene(doc)), Contains("phi at its bound (5 deg"));
  // The reference cut solves, on one branch.
  const auto p = kerf::predict(kerf::parse_analytic_scene(
      kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/scenes/aisi1045_oxley.json")));
  REQUIRE(p.oxley.has_value());
  CHECK(p.oxley->shear_angle_roots == 1);
}

namespace {
/// The psic scene at thickness t0 (um) and edge radius r (um) with a ploughing model.
kerf::Prediction predict_ploughing(double t0_um, double r_um, const char* ploughing = "wave") {
  Json doc = orthogonal_scene();
  doc["cut"]["uncut_chip_thickness_um"] = t0_um;
  doc["tool"]["edge_radius_um"] = r_um;
  doc["models"]["ploughing"] = ploughing;
  return kerf::predict(kerf::parse_analytic_scene(doc));
}
}  // namespace

TEST_CASE("Ploughing: the total force is continuous where the chip starts at the stagnation height",
          "[scene][ploughing]") {
  // h_s = r (1 + sin g_s) does not depend on t0: read it off a thick cut.
  const double r_um = 0.2;
  const auto thick = predict_ploughing(1.0, r_um);
  REQUIRE(thick.chip_term.liu_li.has_value());
  const double h_s_um = kerf::units::m_to_um(thick.chip_term.liu_li->ploughed_thickness_m);
  CHECK_THAT(h_s_um, WithinRel(r_um * (1.0 + std::sin(thick.chip_term.liu_li->stagnation_angle_rad)), 1e-12));
  const auto below = predict_ploughing(h_s_um - 0.5e-9, r_um);
  const auto above = predict_ploughing(h_s_um + 0.5e-9, r_um);
  REQUIRE(below.chip_term.ploughing.has_value());
  REQUIRE(above.chip_term.ploughing.has_value());
  CHECK(below.guards.has(kerf::Guard::no_chip_on_edge));
  CHECK_FALSE(above.guards.has(kerf::Guard::no_chip_on_edge));
  CHECK(below.chip_term.liu_li->total.cutting_N_per_m == 0.0);
  CHECK(below.chip_term.ploughing->force.cutting_N_per_m > 0.0);
  // The note's criterion: no step finer than 1e-6 relative across a 1e-9 um step.
  CHECK_THAT(above.cutting_force_N, WithinRel(below.cutting_force_N, 1e-6));
  CHECK_THAT(above.thrust_force_N, WithinRel(below.thrust_force_N, 1e-6));
  // Inside the layer the ploughed height is t0 itself, above it h_s: the ploughing term stops growing there.
  const auto inside = predict_ploughing(0.5 * h_s_um, r_um);
  CHECK_THAT(inside.chip_term.ploughing->ploughed_height_m, WithinRel(0.5 * h_s_um * 1e-6, 1e-12));
  CHECK(inside.chip_term.ploughing->force.thrust_N_per_m < below.chip_term.ploughing->force.thrust_N_per_m);
  CHECK_THAT(thick.chip_term.ploughing->ploughed_height_m, WithinRel(h_s_um * 1e-6, 1e-12));
}

TEST_CASE("Ploughing: above the layer the chip term is unchanged and the ploughing term stays at h_s",
          "[scene][ploughing]") {
  for (double t0_um : {0.1, 0.3, 1.0, 5.0}) {
    CAPTURE(t0_um);
    const auto wave = predict_ploughing(t0_um, 0.2);
    const auto none = predict_ploughing(t0_um, 0.2, "none");
    REQUIRE(wave.chip_term.ploughing.has_value());
    CHECK_FALSE(none.chip_term.ploughing.has_value());
    CHECK(wave.chip_term.liu_li->total.cutting_N_per_m == none.chip_term.liu_li->total.cutting_N_per_m);
    CHECK(wave.chip_term.liu_li->total.thrust_N_per_m == none.chip_term.liu_li->total.thrust_N_per_m);
    CHECK(none.cutting_force_N == none.chip_term.liu_li->total.cutting_N_per_m * none.width_m);
    CHECK_THAT(wave.cutting_force_N - none.cutting_force_N,
               WithinRel(wave.chip_term.ploughing->force.cutting_N_per_m * wave.width_m, 1e-9));
    CHECK_THAT(wave.thrust_force_N - none.thrust_force_N,
               WithinRel(wave.chip_term.ploughing->force.thrust_N_per_m * wave.width_m, 1e-9));
    CHECK_THAT(wave.chip_term.ploughing->ploughed_height_m,
               WithinRel(wave.chip_term.liu_li->ploughed_thickness_m, 1e-14));
    // The friction factor is the Lee-Shaffer sin(2 beta) of the prediction's one friction angle.
    CHECK_THAT(wave.chip_term.friction_factor, WithinRel(std::sin(2.0 * wave.friction_angle_rad), 1e-14));
  }
}

TEST_CASE("Ploughing: grows with the edge radius at a fixed thickness, vanishes with it", "[scene][ploughing]") {
  for (double t0_um : {0.001, 0.02, 0.1}) {
    CAPTURE(t0_um);
    double previous_cut = 0.0, previous_thrust = 0.0;
    for (double r_um = 0.01; r_um <= 5.0; r_um *= 1.25) {
      CAPTURE(r_um);
      const auto p = predict_ploughing(t0_um, r_um);
      REQUIRE(p.chip_term.ploughing.has_value());
      const double cut = p.chip_term.ploughing->force.cutting_N_per_m,
                   thrust = p.chip_term.ploughing->force.thrust_N_per_m;
      CHECK(cut > previous_cut);
      CHECK(thrust > previous_thrust);
      previous_cut = cut;
      previous_thrust = thrust;
    }
  }
  // r -> 0: the ploughing force goes to zero with r (its layer is a fixed fraction of r).
  const auto small = predict_ploughing(0.1, 1e-6), smaller = predict_ploughing(0.1, 1e-9);
  CHECK_THAT(smaller.chip_term.ploughing->force.thrust_N_per_m,
             WithinRel(1e-3 * small.chip_term.ploughing->force.thrust_N_per_m, 1e-6));
  CHECK(predict_ploughing(0.1, 0.0).cutting_force_N == predict_ploughing(0.1, 0.0, "none").cutting_force_N);
}

TEST_CASE("Ploughing: a friction factor outside 0 <= f < 1 names its key, and a given one is used",
          "[scene][ploughing]") {
  for (double f : {-0.1, 1.0, 1.5}) {
    CAPTURE(f);
    Json doc = orthogonal_scene();
    doc["cut"]["friction_factor"] = f;
    try {
      kerf::parse_analytic_scene(doc);
      FAIL("accepted");
    } catch (const kerf::InputError& e) {
      CHECK_THAT(e.what(), Contains("cut.friction_factor"));
      CHECK_THAT(e.what(), Contains("[0, 1)"));
    }
  }
  Json doc = orthogonal_scene();
  doc["cut"]["friction_factor"] = 0.25;
  const auto p = kerf::predict(kerf::parse_analytic_scene(doc));
  CHECK(p.chip_term.friction_factor == 0.25);
  auto row = kerf::prediction_columns(kerf::parse_analytic_scene(doc), p);
  std::map<std::string, std::string> cells(row.begin(), row.end());
  CHECK(cells[std::string(kerf::edge_keys::friction_factor)] == "0.25");
  CHECK(std::stod(cells[std::string(kerf::prediction_keys::ploughing_thrust_force_N)]) > 0.0);
  CHECK(cells[std::string(kerf::edge_keys::ploughing_model)] == "wave");
}

TEST_CASE("The key reference comes from the tables the scenes are read with", "[scene][keys]") {
  const std::string all = kerf::analytic_scene_keys_markdown();
  for (const auto& section : kerf::analytic_scene_sections()) {
    CHECK_THAT(all, Contains("#### `" + section + "` ("));
    CHECK(kerf::analytic_scene_keys_markdown(section).rfind("#### `" + section + "`", 0) == 0);
  }
  CHECK_THROWS_WITH(kerf::analytic_scene_keys_markdown("modles"), Contains("SECTION = modles") && Contains("'models'"));
  // Defaults as printed are the ones a scene gets (the member initialisers, written once).
  CHECK_THAT(all, Contains("| `clearance_deg` | deg | a value in (0, 90) | 7 |"));
  // (the force models' list also holds the toy model of toy_force_model_test.cpp, registered in this program)
  CHECK_THAT(all, Contains("| `force` | - | `auto`, `merchant`, `liu_li`, `oxley`") &&
                      Contains("| `auto` | the force model;"));
  auto doc = orthogonal_scene();
  doc["models"].erase("force");
  const auto scene = kerf::parse_analytic_scene(doc);
  CHECK(scene.force_auto);
  CHECK(scene.clearance_rad == kerf::units::deg_to_rad(7.0));
  CHECK(scene.params<kerf::ChipTermParams>().liu_li.lower_limit_margin_rad == kerf::units::deg_to_rad(1.0));
  CHECK(scene.contact_shear_angle == kerf::ShearAngleModel::merchant);
  // Registry names become the enums their lines construct; the order of contact-length names is kept.
  doc = orthogonal_scene();
  doc["models"]["shear_angle"] = "lee_shaffer";
  doc["models"]["friction_closure"] = "constant";
  doc["models"]["contact_length"] = Json::array({"vinogradov_mssp", "altintas"});
  doc["models"]["contact_shear_angle"] = "mssp";
  const auto named = kerf::parse_analytic_scene(doc);
  CHECK(named.shear_angle == kerf::ShearAngleSource::lee_shaffer);
  CHECK(named.params<kerf::ChipTermParams>().liu_li.closure == kerf::FrictionClosure::constant);
  REQUIRE(named.contact_lengths.size() == 2);
  CHECK(named.contact_lengths[0].column == "contact_length_vinogradov_mssp_mm");
  CHECK(named.contact_lengths[1].model == kerf::ContactLengthModel::altintas);
  CHECK(named.contact_lengths[1].shear_angle == kerf::ShearAngleModel::lee_shaffer);
  doc["models"]["contact_length"] = Json::array({"altintas_mep", "vinogradov", "altintas_mep"});
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc),
                    "models.contact_length = altintas_mep: expected each "
                    "contact-length model named once");
  doc = orthogonal_scene();
  doc["models"]["force"] = "trepanning";
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc), Contains("models.force = trepanning: expected an orthogonal-cut"));
}

namespace kerf {
// src/material.cpp, outside the public headers: the keys the material loader accepts in each group.
const std::vector<std::string>& material_group_keys(const std::string& group_name);
}  // namespace kerf

TEST_CASE("The material groups' key tables hold the keys the material loader accepts", "[scene][keys][material]") {
  // The loader (src/material.cpp) refuses a key of no group before any model reads it; the tables are what the
  // models read with: the two lists must be the same keys.
  for (const auto& section : kerf::material_key_sections()) {
    const std::string group(section.name.substr(std::string_view("material.").size()));
    std::vector<std::string> table_keys;
    const std::string md = section.markdown();
    for (std::size_t at = md.find("\n| `"); at != std::string::npos; at = md.find("\n| `", at + 1)) {
      const std::size_t start = at + 4;
      table_keys.push_back(md.substr(start, md.find('`', start) - start));
    }
    auto loader_keys = kerf::material_group_keys(group);
    std::sort(table_keys.begin(), table_keys.end());
    std::sort(loader_keys.begin(), loader_keys.end());
    INFO(group);
    CHECK(table_keys == loader_keys);
  }
  // A default the table prints is the one the model gets (psic's microstructure leaves the Taylor factor out).
  const auto psic = kerf::load_material(Json("psic"), "material");
  Json inline_material = {{"elastic", *psic.group("elastic")}, {"microstructure", *psic.group("microstructure")}};
  inline_material["microstructure"].erase("taylor_factor");
  inline_material["microstructure"].erase("boundary_spacing_um");
  const auto record = kerf::load_material(inline_material, "material");
  CHECK_THAT(kerf::analytic_scene_keys_markdown("material.microstructure"),
             Contains("| `taylor_factor` | - | a positive value | 3.06 |"));
  const auto micro = kerf::microstructure_from_material(record, "material");
  CHECK(micro.hall_petch.taylor_factor == 3.06);
  CHECK(micro.dislocation.taylor_factor == 3.06);
  CHECK_THAT(micro.dislocation.boundary_spacing_m, WithinRel(micro.hall_petch.grain_size_m, 1e-12));  // default: D
}
