// libFuzzer target: the scene reader and the predict path of kerf-forces (docs/hardening.md).
//
// The input is a scene file's text. Whatever it holds, kerf must answer with a prediction, an InputError or a
// ModelError: any other exception, a crash, a sanitizer report or a non-finite written number is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "kerf/analytic/evaluate.hpp"
#include "kerf/analytic/predict.hpp"
#include "kerf/analytic/scene.hpp"
#include "kerf/analytic/trepanning_scene.hpp"
#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const kerf::Json document = kerf::parse_json_text(text, "fuzz.json");
    if (kerf::is_trepanning_scene(document)) {
      const kerf::TrepanningScene scene = kerf::parse_trepanning_scene(document);
      const auto forces = kerf::trepanning_forces(scene.tool, scene.cut, scene.groups);
      if (!std::isfinite(forces.axial_force_N) || !std::isfinite(forces.torque_N_m)) std::abort();
    } else {
      const kerf::AnalyticScene scene = kerf::parse_analytic_scene(document);
      const kerf::Prediction p = kerf::predict(scene);
      if (!std::isfinite(p.cutting_force_N) || !std::isfinite(p.thrust_force_N)) std::abort();
      (void)kerf::prediction_columns(scene, p);
    }
  } catch (const kerf::InputError&) {
  } catch (const kerf::ModelError&) {
  }
  return 0;
}
