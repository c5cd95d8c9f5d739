// libFuzzer target: the scene reader and the predict path of kerf-forces (docs/hardening.md).
//
// The input is a scene file's text. Whatever it holds, kerf must answer with a prediction, an InputError or a
// ModelError: any other exception, a crash, a sanitizer report or a non-finite written number is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/trepanning/trepanning_results.hpp"
#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const kerf::Json document = kerf::parse_json_text(text, "fuzz.json");
    const auto scene = kerf::parse_scene(document, nullptr);
    scene->predict();
    // The kind's forces (orthogonal: cutting and thrust; trepanning: axial force and torque) are written as
    // numbers: an empty cell is a force that was not finite.
    for (const auto& [name, cell] : kerf::scene_columns(*scene)) {
      const bool force = name == kerf::prediction_keys::cutting_force_N ||
                         name == kerf::prediction_keys::thrust_force_N ||
                         name == kerf::trepanning_keys::axial_force_N || name == kerf::trepanning_keys::torque_N_m;
      if (force && cell.empty()) std::abort();
    }
  } catch (const kerf::InputError&) {
  } catch (const kerf::ModelError&) {
  }
  return 0;
}
