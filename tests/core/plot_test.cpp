#include "kerf/plot.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "kerf/error.hpp"

namespace fs = std::filesystem;

TEST_CASE("A figure renders to a PNG atomically", "[plot]") {
  const fs::path dir = fs::path(KERF_BINARY_DIR) / "test_output" / "plot";
  fs::remove_all(dir);
  kerf::FigureSpec fig;
  fig.title = "Test";
  fig.x_label = "x (mm)";
  fig.y_label = "F#dc#u (N)";
  fig.bands.push_back({"band", {0, 1}, {0, 0.5}, {0.5, 1.5}, 5});
  fig.series.push_back(
      {"points", {0.1, 0.5, 0.9}, {0.2, NAN, 1.0}, {}, {0.1, 0.1, NAN}, kerf::SeriesStyle::points, 0, 0});
  fig.series.push_back({"line", {0, 1}, {0, 1}, {}, {}, kerf::SeriesStyle::line, 1, 0});
  kerf::render_png(fig, dir / "figure.png");
  std::ifstream in(dir / "figure.png", std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  CHECK(std::string(signature + 1, 3) == "PNG");
  // The same drawing as a PDF beside it (for papers).
  std::ifstream pdf(dir / "figure.pdf", std::ios::binary);
  char head[5] = {};
  pdf.read(head, 5);
  CHECK(std::string(head, 5) == "%PDF-");
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) files.insert(entry.path().filename().string());
  CHECK(files == std::set<std::string>{"figure.pdf", "figure.png"});  // no temporary file left
}

TEST_CASE("Figures PLplot cannot draw are refused before PLplot sees them", "[plot][errors]") {
  const fs::path path = fs::path(KERF_BINARY_DIR) / "test_output" / "plot" / "bad.png";
  kerf::FigureSpec empty;
  empty.series.push_back({"nan", {NAN}, {1.0}, {}, {}, kerf::SeriesStyle::points, 0, 0});
  CHECK_THROWS_AS(kerf::render_png(empty, path), kerf::InputError);
  kerf::FigureSpec mismatched;
  mismatched.series.push_back({"xy", {1.0, 2.0}, {1.0}, {}, {}, kerf::SeriesStyle::points, 0, 0});
  CHECK_THROWS_AS(kerf::render_png(mismatched, path), kerf::InputError);
  kerf::FigureSpec legend;
  legend.legend_position = "middle";
  legend.series.push_back({"p", {1.0}, {1.0}, {}, {}, kerf::SeriesStyle::points, 0, 0});
  CHECK_THROWS_AS(kerf::render_png(legend, path), kerf::InputError);
  CHECK_FALSE(fs::exists(path));
}

TEST_CASE("plot: sort_by_x orders the points and carries their error bars, ties in their order") {
  kerf::PlotSeries s;
  s.x = {3, 1, 2, 1};
  s.y = {30, 10, 20, 11};
  s.y_error = {0.3, 0.1, 0.2, 0.11};
  kerf::sort_by_x(s);
  CHECK(s.x == std::vector<double>{1, 1, 2, 3});
  CHECK(s.y == std::vector<double>{10, 11, 20, 30});
  CHECK(s.y_error == std::vector<double>{0.1, 0.11, 0.2, 0.3});
  CHECK(s.x_error.empty());  // none stays none
}

TEST_CASE("plot: room for the legend keeps every interval bar on the axes", "[plot]") {
  // A point whose bar reaches far above and below every other point: the y range must hold the bar's ends.
  kerf::FigureSpec fig;
  fig.series.push_back({"a", {1, 2}, {0.4, 0.35}, {}, {0.1, 0.35}, kerf::SeriesStyle::points, 0, 0});
  fig.series.push_back({"b", {3}, {0.5}, {}, {NAN}, kerf::SeriesStyle::points, 1, 1});
  kerf::leave_room_for_legend(fig);
  REQUIRE(fig.y_min);
  REQUIRE(fig.y_max);
  CHECK(*fig.y_min <= 0.35 - 0.35);
  CHECK(*fig.y_max >= 0.35 + 0.35);
  CHECK(*fig.y_max > 0.7 + 0.1 * 0.7);  // and above the bars, room for the legend's rows
}

TEST_CASE("plot: a tick spacing must be a non-negative number on a linear axis", "[plot][errors]") {
  // Its own folder: the atomic-render test above checks what its folder holds, and ctest runs them side by side.
  const fs::path path = fs::path(KERF_BINARY_DIR) / "test_output" / "plot_ticks" / "ticks.png";
  kerf::FigureSpec fig;
  fig.series.push_back({"p", {1.0, 2.0}, {1.0, 2.0}, {}, {}, kerf::SeriesStyle::points, 0, 0});
  fig.x_tick_step = -1;
  CHECK_THROWS_WITH(kerf::render_png(fig, path), Catch::StartsWith("figure.x_tick_step = -1"));
  fig.x_tick_step = 1, fig.x_log = true;
  CHECK_THROWS_AS(kerf::render_png(fig, path), kerf::InputError);
  fig.x_log = false;
  CHECK_NOTHROW(kerf::render_png(fig, path));
}
