// kerf-dem-test-kinds: kerf-dem (tools/kerf_dem.hpp) with the test suite's own scene kind, registered here and
// nowhere in the library (kerf/dem/scene.hpp: register_scene_kind), for the CLI tests that need it
// (tests/cli/dem_study_cli.sh). The production kerf-dem refuses it as any unknown kind.
//
// Kind "synthetic": no simulation, one result `value` drawn from a normal distribution N(mean, std^2) by the packing
// seed, so that a study's adaptive stopping can be checked against a known distribution in milliseconds. Section
// "synthetic": mean, std, sleep_s (wall time to spend, for tests that kill a study mid-way), fail_above (a value above
// it fails the item with a ModelError; default: never).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <thread>

#include "kerf/dem/scene.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"
#include "kerf_dem.hpp"

namespace {

using namespace kerf;
using namespace kerf::dem;

class SyntheticKind final : public SceneKind {
 public:
  std::string name() const override { return "synthetic"; }

  void read(ObjectReader& root, const SceneCommon&) override {
    if (auto s = root.find_object("synthetic")) {
      mean_ = s->get_number_or("mean", mean_, Range::any(), "");
      std_ = s->get_number_or("std", std_, Range::non_negative(), "");
      sleep_s_ = s->get_number_or("sleep_s", sleep_s_, Range::closed(0, 60), "s");
      fail_above_ = s->get_number_or("fail_above", fail_above_, Range::any(), "");
      s->finish();
    }
  }

  SceneOutcome run(const SceneCommon& common, const SceneRun& run) override {
    // A standard normal variate from the seed alone (Box-Muller on two 53-bit uniforms of mt19937_64), so the
    // value is the same on every platform.
    std::mt19937_64 engine(common.specimen.seed);
    const auto uniform = [&] { return (static_cast<double>(engine() >> 11) + 0.5) * 0x1.0p-53; };
    const double u1 = uniform(), u2 = uniform();
    const double z = std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
    const double value = mean_ + std_ * z;
    std::this_thread::sleep_for(std::chrono::duration<double>(sleep_s_));
    if (value > fail_above_) throw ModelError(name(), fmt::format("value {} above fail_above", value));
    Json summary{{"kind", name()},
                 {"seed", common.specimen.seed},
                 {"results", {{"value", value}, {"value_squared", value * value}}},
                 {"wall_time_s", sleep_s_}};
    // As the library's kinds write theirs (dem/kinds/common.cpp: write_summary).
    if (Json provenance = summary_provenance(run.options, run.doc); !provenance.is_null())
      summary["provenance"] = std::move(provenance);
    write_file_atomically(run.options.out / "summary.json", summary.dump(2) + "\n");
    return {0, summary, {}};
  }

 private:
  double mean_ = 1, std_ = 0.1, sleep_s_ = 0, fail_above_ = std::numeric_limits<double>::infinity();
};

std::unique_ptr<SceneKind> make_synthetic_kind() {
  return std::make_unique<SyntheticKind>();
}

}  // namespace

int main(int argc, char** argv) {
  register_scene_kind(make_synthetic_kind);
  return kerf_dem_main(argc, argv);
}
