#pragma once
// PNG figures (each with a PDF beside it) for the force reports, drawn with PLplot's cairo devices: points with error
// bars, lines, shaded bands, a legend, axis labels with units. A figure is described by a FigureSpec and rendered in
// one call; the file is written atomically (a temporary file beside it, then a rename).
//
//   kerf::FigureSpec fig;
//   fig.title = "Parity";
//   fig.x_label = "F#dn#u, measured (N)";   // F subscript n
//   fig.series.push_back({"kerf", measured, predicted, {}, {}, kerf::SeriesStyle::points, 0, 0});
//   kerf::render_png(fig, "out/parity_axial_force.png");
//
// Labels are UTF-8 with PLplot's escapes (#d subscript, #u superscript). PLplot keeps its state in the library:
// render_png() draws through draw_png_with_plplot(), which gives it a stream of its own under one lock, so
// it may be called from several threads (the drawings are serialised).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace kerf {

enum class SeriesStyle { points, line, dashed_line, points_and_line };

struct PlotSeries {
  std::string label;  ///< legend text (empty: not in the legend)
  std::vector<double> x, y;
  std::vector<double> x_error;  ///< half-widths of horizontal error bars (empty: none; NaN entries: none)
  std::vector<double> y_error;  ///< half-widths of vertical error bars
  SeriesStyle style = SeriesStyle::points;
  int color = 0;   ///< index into the palette (0: blue, 1: orange, 2: green, 3: red, 4: purple, 5: grey, ...)
  int marker = 0;  ///< 0 circle, 1 triangle, 2 square, 3 diamond, 4 down-triangle; 5-9 the same, hollow
  /// A legend entry only (no data drawn): a key for a colour or a line style that several series share.
  bool legend_only = false;
};

/// Orders the series' points by x (a stable sort; its error bars, where it has them, move with their points).
void sort_by_x(PlotSeries& series);

/// A shaded region between two curves over the same x.
struct PlotBand {
  std::string label;
  std::vector<double> x, y_low, y_high;
  int color = 5;
};

struct FigureSpec {
  std::string title;
  std::string x_label, y_label;
  std::vector<PlotBand> bands;                       ///< drawn first
  std::vector<PlotSeries> series;                    ///< drawn in order
  std::optional<double> x_min, x_max, y_min, y_max;  ///< default: the data range with a margin
  bool equal_axes = false;                           ///< same range on both axes (parity plots)
  bool x_log = false;                                ///< a logarithmic x axis (every x positive; no x error bars)
  double x_tick_step = 0.0;  ///< the x axis's major tick spacing (0: PLplot's choice; e.g. 1 for numbered categories)
  /// best (the emptiest inside corner), top_left, top_right, bottom_right, bottom_left (inside the axes) or
  /// outside_right (beside a narrower plot)
  std::string legend_position = "best";
  int width_px = 1200, height_px = 900;
};

/// Draws one PNG with PLplot's pngcairo device and the same drawing as a PDF beside it (pdfcairo; `path` with
/// the extension .pdf, for papers): a stream of its own, `before_init` (colour maps, background) before
/// plinit, then `draw`; under one lock around PLplot's library-wide state, so callers on several threads are
/// serialised. Each file is written to a temporary file beside it, then moved into place (whole or not at
/// all); std::runtime_error when PLplot wrote nothing. render_png and the DEM pictures use it.
/// A figure's file name: .png or .svg (a PDF beside it) or .pdf; InputError naming `field` for '-' or another
/// extension. The drawing functions check it; a command checks its option before any work.
void check_figure_path(const std::filesystem::path& path, const std::string& field);

void draw_png_with_plplot(const std::filesystem::path& path, int width_px, int height_px,
                          const std::function<void()>& before_init, const std::function<void()>& draw);

/// Sets the y range to the data's with room above it for a top-left legend (a row per labelled series), so
/// that the legend covers none of the data; call once the series are in.
void leave_room_for_legend(FigureSpec& figure);

/// Renders the figure to a PNG (and the PDF beside it). Throws InputError for a figure that cannot be drawn (no finite
/// points, mismatched sizes) and std::runtime_error when the file cannot be written.
void render_png(const FigureSpec& figure, const std::filesystem::path& path);

}  // namespace kerf
