#include "kerf/analytic/registry.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <set>
#include <string>
#include <vector>

#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/contact_length.hpp"
#include "kerf/analytic/forces/transition_model.hpp"
#include "kerf/analytic/kinds/scene.hpp"

using kerf::Json;

TEST_CASE("The registry maps a name to its model by the name, not by the line's position", "[registry]") {
  // A positional mapping (the index of the name among its kind's lines) gives other models once the lines
  // are reordered; the name's own enum value does not.
  const auto& registry = kerf::analytic_models();
  auto reversed = registry;
  std::reverse(reversed.begin(), reversed.end());
  int with_enum = 0;
  for (const auto& m : registry) {
    CAPTURE(m.kind, m.name);
    CHECK(kerf::registered_id(reversed, m.kind, m.name) == kerf::registered_id(registry, m.kind, m.name));
    with_enum += m.id >= 0 ? 1 : 0;
  }
  CHECK(with_enum >= 15);

  // Each name constructs the model that carries that name (the name functions are switches on the enum).
  const std::vector<kerf::AnalyticModelInfo>* lists[] = {&registry, &reversed};
  for (const auto* list : lists) {
    for (const char* name : {"merchant", "liu_li", "oxley"}) {
      const auto* line = kerf::registered_line(*list, "force", name);
      REQUIRE(line);
      CHECK(line->orthogonal != nullptr);
    }
    for (const char* name : {"constant", "merchant", "lee_shaffer"}) {
      CHECK(kerf::friction_closure_name(
                kerf::registered_model<kerf::FrictionClosure>("friction_closure", name, *list)) == name);
    }
    for (const char* name : {"stagnation", "pole"}) {
      CHECK(kerf::lower_limit_rule_name(kerf::registered_model<kerf::LowerLimitRule>("lower_limit", name, *list)) ==
            name);
    }
    for (const char* name : {"altintas", "vinogradov", "lee_shaffer"}) {
      CHECK(kerf::contact_length_model_name(
                kerf::registered_model<kerf::ContactLengthModel>("contact_length", name, *list)) == name);
    }
    for (const char* name : {"none", "wave"}) {
      CHECK(kerf::ploughing_model_name(kerf::registered_model<kerf::PloughingModel>("ploughing", name, *list)) == name);
    }
    CHECK(kerf::registered_model<kerf::ShearAngleSource>("shear_angle", "chip_ratio", *list) ==
          kerf::ShearAngleSource::chip_ratio);
    CHECK(kerf::registered_model<kerf::ShearAngleSource>("shear_angle", "lee_shaffer", *list) ==
          kerf::ShearAngleSource::lee_shaffer);
    CHECK(kerf::registered_model<kerf::DeformationModel>("deformation", "given", *list) ==
          kerf::DeformationModel::given);
    CHECK(kerf::registered_model<kerf::DeformationModel>("deformation", "oxley", *list) ==
          kerf::DeformationModel::oxley);
  }
}

TEST_CASE("Within a kind, each registered enum value belongs to one name", "[registry]") {
  std::set<std::pair<std::string, int>> seen;
  for (const auto& m : kerf::analytic_models()) {
    if (m.id < 0) continue;
    CAPTURE(m.kind, m.name);
    CHECK(seen.emplace(std::string(m.kind), m.id).second);
  }
  CHECK_THROWS_AS(kerf::registered_model<kerf::DeformationModel>("deformation", "no_such_model"), std::logic_error);
  CHECK_FALSE(kerf::registered_id(kerf::analytic_models(), "force", "auto").has_value());  // handled by name
}

TEST_CASE("A scene constructs the models it names", "[registry][scene]") {
  Json doc = Json::parse(R"({
    "material": "a2024_t351",
    "tool": {"rake_deg": 10, "edge_radius_um": 1},
    "cut": {"uncut_chip_thickness_um": 10, "width_mm": 1, "speed_m_per_min": 60, "friction_coefficient": 0.3,
            "chip_ratio": 0.4},
    "models": {"force": "merchant", "shear_angle": "chip_ratio", "friction_closure": "lee_shaffer",
               "lower_limit": "pole", "contact_length": ["vinogradov_mssp", "altintas"],
               "quadrature": {"rule": "gsl_qag"}}
  })");
  const auto scene = kerf::parse_analytic_scene(doc);
  CHECK(scene.force->name == "merchant");
  CHECK(scene.shear_angle == kerf::ShearAngleSource::chip_ratio);
  CHECK(scene.params<kerf::ChipTermParams>().liu_li.closure == kerf::FrictionClosure::lee_shaffer);
  CHECK(scene.params<kerf::ChipTermParams>().liu_li.lower_limit == kerf::LowerLimitRule::pole);
  CHECK(scene.params<kerf::ChipTermParams>().liu_li.quadrature.rule == kerf::QuadratureRule::gsl_qag);
  REQUIRE(scene.contact_lengths.size() == 2);
  CHECK(scene.contact_lengths[0].model == kerf::ContactLengthModel::vinogradov);
  CHECK(scene.contact_lengths[0].shear_angle == kerf::ShearAngleModel::lee_shaffer);
  CHECK(scene.contact_lengths[1].model == kerf::ContactLengthModel::altintas);
}
