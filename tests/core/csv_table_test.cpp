#include "kerf/csv_table.hpp"

#include <catch2/catch.hpp>

#include "kerf/error.hpp"

namespace {
std::string error_of(const std::string& text) {
  try {
    const auto t = kerf::parse_csv(text, "x.csv");
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      for (std::size_t c = 0; c < t.header.size(); ++c) t.number(r, c);
    }
  } catch (const kerf::InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST_CASE("CSV tables keep their comments and unquote fields", "[csv]") {
  const auto t =
      kerf::parse_csv("# Source: a paper, Table 4\n#no space\n\na,b,c\r\n1,\"x, \"\"y\"\"\",3\n\n4,,6\n", "x.csv");
  REQUIRE(t.comments.size() == 2);
  CHECK(t.comments[0] == "Source: a paper, Table 4");
  CHECK(t.comments[1] == "no space");
  CHECK(t.header == std::vector<std::string>{"a", "b", "c"});
  REQUIRE(t.rows.size() == 2);
  CHECK(t.text(0, 1) == "x, \"y\"");
  CHECK(t.row_lines == std::vector<std::size_t>{5, 7});
  CHECK(t.number(1, 2) == 6.0);
  CHECK(t.column_index("c") == 2);
}

TEST_CASE("The bundled experiment tables parse", "[csv]") {
  for (const char* name :
       {"k9_trepanning.csv", "soda_lime_orthogonal_cutting.csv", "soda_lime_dem_microparameters.csv"}) {
    const auto t = kerf::read_csv_file(std::string(KERF_SOURCE_DIR) + "/data/experiments/" + name);
    CHECK_FALSE(t.comments.empty());
    CHECK_FALSE(t.rows.empty());
  }
  const auto k9 = kerf::read_csv_file(std::string(KERF_SOURCE_DIR) + "/data/experiments/k9_trepanning.csv");
  CHECK(k9.rows.size() == 8);
  CHECK(k9.number(0, k9.column_index("torque_test_Nm")) == 4.63);
  CHECK(k9.comments[1].find("Table 4") != std::string::npos);
}

TEST_CASE("Malformed CSV names the file, line and column", "[csv][errors]") {
  CHECK(error_of("a,b\n1,2\n3,abc\n") == "x.csv:3: column 2 'b' = abc: expected a number");
  CHECK(error_of("a,b\n1,2\n3,\n") == "x.csv:3: column 2 'b' = (empty): expected a number");
  CHECK(error_of("# c\na,b\n1,2,3\n") == "x.csv:3 = 3 fields: expected 2 fields, as in the header");
  CHECK(error_of("a,b\n1,\"2\n") == "x.csv:2:3 = \"2: expected a closing quote on the same line");
  CHECK(error_of("a,b\n\"1\"x,2\n") ==
        "x.csv:2:4 = x,2: expected a comma or the end of the line after a closing quote");
  CHECK(error_of("a,a\n1,2\n") == "x.csv:1: column 2 = a: expected a column name used only once");
  CHECK(error_of("# only a comment\n") == "x.csv = (no header line): expected a CSV table with a header line");
  CHECK(error_of("a,b\n1,inf\n") == "x.csv:2: column 2 'b' = inf: expected a number");
  const auto t = kerf::parse_csv("a,b\n1,2\n", "x.csv");
  CHECK_THROWS_WITH(t.column_index("bb"),
                    "x.csv: column = bb: expected a column of the table: one of 'a', 'b' (did you mean 'b'?)");
  CHECK_THROWS_AS(kerf::read_csv_file("/nonexistent/file.csv"), kerf::InputError);
}
