// Scene kind "synthetic", for tests only (constructed only when the environment has KERF_DEM_TEST_KINDS=1;
// not in the kind list users see): no simulation, one result `value` drawn from a normal distribution
// N(mean, std^2) by the packing seed, so that a study's adaptive stopping can be checked against a known
// distribution in milliseconds. Section "synthetic": mean, std, sleep_s (wall time to spend, for tests that
// kill a study mid-way), fail_above (a value above it fails the item with a ModelError; default: never).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <thread>

#include "common.hpp"
#include "kerf/error.hpp"

namespace kerf::dem::kinds {

namespace {

class SyntheticKind final : public SceneKind {
 public:
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
    if (value > fail_above_) throw ModelError("synthetic", fmt::format("value {} above fail_above", value));
    Json summary{{"kind", "synthetic"},
                 {"seed", common.specimen.seed},
                 {"results", {{"value", value}, {"value_squared", value * value}}},
                 {"wall_time_s", sleep_s_}};
    write_summary(run.options, run.doc, summary);
    return {0, summary, {}};
  }

 private:
  double mean_ = 1, std_ = 0.1, sleep_s_ = 0, fail_above_ = std::numeric_limits<double>::infinity();
};

}  // namespace

std::unique_ptr<SceneKind> make_synthetic_kind() {
  return std::make_unique<SyntheticKind>();
}

}  // namespace kerf::dem::kinds
