// The study's scheduler (dem/study/study_scheduler.cpp): which items it hands out and when a condition is done, driven
// here with made-up results completed in shuffled orders by a varying number of workers, against the prefix rule
// computed independently; and the reading of study files.
#include "kerf/dem/study/study.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "kerf/error.hpp"

using namespace kerf::dem;
using kerf::Json;

namespace {

/// A made-up result of item (condition, seed): scattered around 10 with a spread that grows with the condition.
double value_of(int condition, std::uint64_t seed) {
  std::mt19937_64 engine(seed * 7919 + static_cast<std::uint64_t>(condition));
  std::normal_distribution<double> normal(10.0, 0.6 + 0.4 * condition);
  return normal(engine);
}

StudySpec adaptive_spec(int conditions) {
  StudySpec spec;
  spec.conditions.resize(static_cast<std::size_t>(conditions));
  spec.replicates.policy = ReplicatePolicy::adaptive;
  spec.replicates.min_count = 5;
  spec.replicates.max_count = 40;
  spec.replicates.target_relative_sem = 0.03;
  spec.replicates.results = {"x"};
  spec.base_seed = 11;
  return spec;
}

/// The count the rule gives, computed here: the smallest n >= min whose first n values meet the target, or max.
int expected_count(const StudySpec& spec, int condition) {
  const StudyReplicates& p = spec.replicates;
  std::vector<double> v;
  for (int n = 1; n <= p.max_count; ++n) {
    v.push_back(value_of(condition, spec.base_seed + static_cast<std::uint64_t>(n - 1)));
    if (n < p.min_count) continue;
    double mean = 0;
    for (double x : v) mean += x;
    mean /= n;
    double ss = 0;
    for (double x : v) ss += (x - mean) * (x - mean);
    const double sem = std::sqrt(ss / (n - 1)) / std::sqrt(static_cast<double>(n));
    if (sem <= p.target_relative_sem * std::abs(mean)) return n;
  }
  return p.max_count;
}

/// Runs the scheduler with `workers` items in flight at most, completing a random one each time; items whose
/// seed is in `failing` fail. Returns the table.
std::vector<StudyItemResult> drive(StudyScheduler& s, int workers, std::uint64_t shuffle,
                                   const std::vector<std::uint64_t>& failing = {}) {
  std::mt19937 pick(static_cast<std::mt19937::result_type>(shuffle));
  std::vector<StudyItem> in_flight;
  int guard = 0;
  while (!s.finished()) {
    REQUIRE(++guard < 100000);
    while (static_cast<int>(in_flight.size()) < workers)
      if (const auto item = s.next())
        in_flight.push_back(*item);
      else
        break;
    REQUIRE(!in_flight.empty());  // never stuck: something runs until the study is done
    const std::size_t k = std::uniform_int_distribution<std::size_t>(0, in_flight.size() - 1)(pick);
    StudyItemResult r;
    r.item = in_flight[k];
    in_flight.erase(in_flight.begin() + static_cast<std::ptrdiff_t>(k));
    r.ok = std::find(failing.begin(), failing.end(), r.item.seed) == failing.end();
    if (r.ok)
      r.results = {{"x", value_of(r.item.condition, r.item.seed)}, {"y", 1.0}};
    else
      r.error = "bad";
    s.complete(r);
  }
  return s.table();
}

}  // namespace

TEST_CASE("study: adaptive counts follow the prefix rule whatever the workers and the order of completion") {
  const StudySpec spec = adaptive_spec(3);
  std::vector<int> want;
  for (int c = 0; c < 3; ++c) want.push_back(expected_count(spec, c));
  // The made-up spreads must make the conditions stop at two counts at least, some after more than min_count.
  INFO("counts " << want[0] << ", " << want[1] << ", " << want[2]);
  CHECK(std::set<int>(want.begin(), want.end()).size() >= 2);
  CHECK(*std::max_element(want.begin(), want.end()) > spec.replicates.min_count);
  std::vector<StudyItemResult> first;
  for (const int workers : {1, 2, 5, 17})
    for (const std::uint64_t shuffle : {1u, 2u, 3u}) {
      INFO("workers " << workers << ", shuffle " << shuffle);
      StudyScheduler s(spec);
      const std::vector<StudyItemResult> table = drive(s, workers, shuffle);
      for (int c = 0; c < 3; ++c) CHECK(s.count(c) == want[static_cast<std::size_t>(c)]);
      REQUIRE(table.size() == static_cast<std::size_t>(want[0] + want[1] + want[2]));
      for (std::size_t i = 0; i < table.size(); ++i) {  // condition-major, replicates in seed order
        const StudyItem& it = table[i].item;
        CHECK(it.seed == spec.base_seed + static_cast<std::uint64_t>(it.replicate));
        if (i > 0 && table[i - 1].item.condition == it.condition)
          CHECK(it.replicate == table[i - 1].item.replicate + 1);
      }
      if (first.empty()) first = table;
      for (std::size_t i = 0; i < table.size(); ++i) CHECK(table[i].results == first[i].results);
    }
}

TEST_CASE("study: fixed counts hand out each item once, seeds base + k") {
  StudySpec spec;
  spec.conditions.resize(4);
  spec.replicates.count = 3;
  spec.base_seed = 100;
  StudyScheduler s(spec);
  CHECK(s.queued() == 12);
  std::map<std::pair<int, std::uint64_t>, int> seen;
  while (const auto item = s.next()) ++seen[{item->condition, item->seed}];
  CHECK(seen.size() == 12);
  for (const auto& [key, n] : seen) {
    CHECK(n == 1);
    CHECK(key.second >= 100);
    CHECK(key.second < 103);
  }
  CHECK(s.running() == 12);
  CHECK(s.queued() == 0);
  CHECK_FALSE(s.finished());
}

TEST_CASE("study: a failed item ends its adaptive condition there and a missing target result fails the item") {
  StudySpec spec = adaptive_spec(2);
  // Condition 0's third packing fails: the condition stops with 3 items, the last one failed.
  StudyScheduler s(spec);
  const auto table = drive(s, 4, 9, {spec.base_seed + 2});
  CHECK(s.count(0) == 3);
  CHECK(s.count(1) == 3);  // the same seed fails in every condition
  REQUIRE(table.size() == 6);
  CHECK_FALSE(table[2].ok);
  CHECK(table[1].ok);

  spec.replicates.results = {"no_such_result"};
  StudyScheduler t(spec);
  drive(t, 2, 4);
  CHECK(t.count(0) == 1);
  const auto rows = t.table();
  REQUIRE(rows.size() == 2);
  CHECK_FALSE(rows[0].ok);
  CHECK(rows[0].error.find("no_such_result") != std::string::npos);
  CHECK(rows[0].error.find("x, y") != std::string::npos);  // and names the results there are
}

TEST_CASE("study: the grid is every combination (first key slowest) and a list keeps its order") {
  const Json grid = Json::parse(R"({"scene": {"kind": "tension"},
      "conditions": {"grid": {"loading.speed_m_per_s": [0.1, 0.2, 0.3], "specimen.seed": [4, 5]}}})");
  const StudySpec s = read_study(grid, "study.json");
  REQUIRE(s.conditions.size() == 6);
  CHECK(s.varied_keys == std::vector<std::string>{"loading.speed_m_per_s", "specimen.seed"});
  for (std::size_t i = 0; i < 6; ++i) {
    CHECK(s.conditions[i].values[0].second == Json::parse(R"([0.1, 0.2, 0.3])")[i / 2]);
    CHECK(s.conditions[i].values[1].second == Json::parse("[4, 5]")[i % 2]);
  }
  const Json list = Json::parse(R"({"scene": {"kind": "tension"},
      "conditions": {"list": [{"loading.speed_m_per_s": 0.2}, {"specimen.seed": 3, "loading.speed_m_per_s": 0.1}]}})");
  const StudySpec l = read_study(list, "study.json");
  REQUIRE(l.conditions.size() == 2);
  CHECK(l.varied_keys == std::vector<std::string>{"loading.speed_m_per_s", "specimen.seed"});
  CHECK(l.conditions[1].values.size() == 2);
  // A base scene that loads its specimen cannot have packings that differ in seed.
  const Json file = Json::parse(R"({"scene": {"kind": "tension", "specimen": {"file": "study_test.cpp"}},
      "replicates": {"count": 2}})");
  try {
    read_study(file, std::string(KERF_SOURCE_DIR) + "/tests/dem/study.json");
    FAIL("no error");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "replicates");
  }
}
