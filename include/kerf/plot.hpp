#pragma once
// PNG figures for the force reports, drawn with PLplot's pngcairo device: points with error bars, lines,
// shaded bands, a legend, axis labels with units. A figure is described by a FigureSpec and rendered in one
// call; the file is written atomically (a temporary file beside it, then a rename).
//
//   kerf::FigureSpec fig;
//   fig.title = "Parity";
//   fig.x_label = "F#dn#u, measured (N)";   // F subscript n
//   fig.series.push_back({"kerf", measured, predicted, {}, {}, kerf::SeriesStyle::points, 0, 0});
//   kerf::render_png(fig, "out/parity_axial_force.png");
//
// Labels are UTF-8 with PLplot's escapes (#d subscript, #u superscript). PLplot keeps its state in the library:
// render_png() opens its own stream, closes it, and holds lock_plplot() meanwhile, so it may be called from
// several threads (the drawings are serialised).
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace kerf {

enum class SeriesStyle { points, line, dashed_line, points_and_line };

struct PlotSeries {
  std::string label;           ///< legend text (empty: not in the legend)
  std::vector<double> x, y;
  std::vector<double> x_error;  ///< half-widths of horizontal error bars (empty: none; NaN entries: none)
  std::vector<double> y_error;  ///< half-widths of vertical error bars
  SeriesStyle style = SeriesStyle::points;
  int color = 0;   ///< index into the palette (0: blue, 1: orange, 2: green, 3: red, 4: purple, 5: grey, ...)
  int marker = 0;  ///< 0 circle, 1 triangle, 2 square, 3 diamond, 4 down-triangle; 5-9 the same, hollow
};

/// A shaded region between two curves over the same x.
struct PlotBand {
  std::string label;
  std::vector<double> x, y_low, y_high;
  int color = 5;
};

struct FigureSpec {
  std::string title;
  std::string x_label, y_label;
  std::vector<PlotBand> bands;      ///< drawn first
  std::vector<PlotSeries> series;   ///< drawn in order
  std::optional<double> x_min, x_max, y_min, y_max;  ///< default: the data range with a margin
  bool equal_axes = false;          ///< same range on both axes (parity plots)
  /// best (the emptiest inside corner), top_left, top_right, bottom_right, bottom_left (inside the axes) or
  /// outside_right (beside a narrower plot)
  std::string legend_position = "best";
  int width_px = 1200, height_px = 900;
};

/// The one lock around PLplot's library-wide state: every drawing (render_png, the DEM pictures) holds it
/// from opening its stream to closing it.
std::unique_lock<std::mutex> lock_plplot();

/// Renders the figure to a PNG. Throws InputError for a figure that cannot be drawn (no finite points,
/// mismatched sizes) and std::runtime_error when the file cannot be written.
void render_png(const FigureSpec& figure, const std::filesystem::path& path);

}  // namespace kerf
