// Result tables (kerf/result_table.hpp) as a CSV file's columns: the header and the lines from one table.
#include "kerf/result_table.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <optional>

namespace {
struct Line {
  double depth_m;
  int count;
  const char* mode;
  std::optional<double> extra;  ///< a column of some files only
};
KERF_RESULT_KEY(depth_um)
}  // namespace

TEST_CASE("result tables: a CSV file's header and lines", "[result_table]") {
  using kerf::result_if, kerf::result_number, kerf::result_value;
  const kerf::ResultTable<Line> table{
      result_number<Line>(depth_um, kerf::units::kUm, "a depth", [](const Line& l) { return l.depth_m; }),
      result_value<Line>("count", "", "a count", [](const Line& l) { return l.count; }),
      result_value<Line>("mode", "", "a text", [](const Line& l) { return l.mode; }),
      result_if(result_value<Line>("extra", "", "an optional column", [](const Line& l) { return *l.extra; }),
                [](const Line& l) { return l.extra.has_value(); })};
  CHECK(kerf::results_csv_header(table) == "depth_um,count,mode,extra\n");
  CHECK(kerf::results_csv_header(table, Line{0, 0, "", std::nullopt}) == "depth_um,count,mode\n");
  // A real as csv_number writes it (shortest round trip, empty when not finite), an integer in full, a text escaped.
  CHECK(kerf::results_csv_row(table, Line{2.5e-6, 123456789, "a, b", 0.1}) == "2.5,123456789,\"a, b\",0.1\n");
  CHECK(kerf::results_csv_row(table, Line{NAN, -3, "x", std::nullopt}) == ",-3,x\n");
  // Another text for the reals.
  const auto six = [](double v) { return fmt::format("{:.3g}", v); };
  CHECK(kerf::results_csv_row(table, Line{1.0 / 3 * 1e-6, 7, "x", 2.0 / 3}, +six) == "0.333,7,x,0.667\n");
}
