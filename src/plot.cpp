#include "kerf/plot.hpp"

#include <fmt/format.h>
#include <plplot.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "kerf/error.hpp"
#include "kerf/io.hpp"

namespace kerf {

namespace {

// cmap0 layout: 0 background (white), 1 black (axes, text), 2 light grey (grid), 3.. the data palette
// (Tableau 10: distinguishable, and safe for the common colour-vision deficiencies in its first five).
constexpr int kBlack = 1, kGrid = 2, kPaletteStart = 3;
constexpr std::array<std::array<int, 3>, 8> kPalette = {{{31, 119, 180},
                                                         {255, 127, 14},
                                                         {44, 160, 44},
                                                         {214, 39, 40},
                                                         {148, 103, 189},
                                                         {127, 127, 127},
                                                         {140, 86, 75},
                                                         {227, 119, 194}}};
constexpr int kBandStart = kPaletteStart + static_cast<int>(kPalette.size());  // the same colours, translucent
constexpr std::array<const char*, 10> kMarkers = {"●", "▲", "■", "◆", "▼", "○", "△", "□", "◇", "▽"};

int palette_index(int color) {
  return kPaletteStart + std::abs(color) % static_cast<int>(kPalette.size());
}
int band_index(int color) {
  return kBandStart + std::abs(color) % static_cast<int>(kPalette.size());
}
const char* marker_glyph(int marker) {
  return kMarkers[static_cast<std::size_t>(std::abs(marker)) % kMarkers.size()];
}

struct Extent {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool valid() const { return lo <= hi; }
};

void check_sizes(const PlotSeries& s, std::size_t index) {
  const std::string field = fmt::format("figure.series[{}] '{}'", index, s.label);
  if (s.x.size() != s.y.size()) {
    throw InputError(field, fmt::format("{} x and {} y values", s.x.size(), s.y.size()), "as many x as y values");
  }
  if (!s.x_error.empty() && s.x_error.size() != s.x.size()) {
    throw InputError(field + ".x_error", fmt::format("{} values", s.x_error.size()), "one per point or none");
  }
  if (!s.y_error.empty() && s.y_error.size() != s.y.size()) {
    throw InputError(field + ".y_error", fmt::format("{} values", s.y_error.size()), "one per point or none");
  }
}

double error_at(const std::vector<double>& e, std::size_t i) {
  return e.empty() || !std::isfinite(e[i]) ? 0.0 : std::abs(e[i]);
}

/// [lo, hi] widened by a margin; a degenerate range is opened around its value.
std::pair<double, double> padded(Extent e, double margin_fraction) {
  if (e.hi - e.lo <= 1e-12 * std::max(std::abs(e.lo), std::abs(e.hi))) {
    const double half = e.lo == 0.0 ? 1.0 : 0.1 * std::abs(e.lo);
    return {e.lo - half, e.hi + half};
  }
  const double m = margin_fraction * (e.hi - e.lo);
  return {e.lo - m, e.hi + m};
}

/// Finite points of a series (PLplot draws NaN as garbage).
struct Points {
  std::vector<PLFLT> x, y;
  std::vector<std::size_t> index;
};
Points finite_points(const PlotSeries& s) {
  Points p;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
      p.x.push_back(s.x[i]);
      p.y.push_back(s.y[i]);
      p.index.push_back(i);
    }
  }
  return p;
}

/// The inside corner whose box (45 % of the width, 40 % of the height) holds the fewest points and bands.
std::string best_corner(const FigureSpec& fig, const std::pair<double, double>& xr,
                        const std::pair<double, double>& yr) {
  const std::array<std::string, 4> corners = {"top_left", "top_right", "bottom_right", "bottom_left"};
  std::array<int, 4> counts{};
  const auto count_point = [&](double x, double y) {
    const double u = (x - xr.first) / (xr.second - xr.first), v = (y - yr.first) / (yr.second - yr.first);
    if (u < 0.45 && v > 0.6) ++counts[0];
    if (u > 0.55 && v > 0.6) ++counts[1];
    if (u > 0.55 && v < 0.4) ++counts[2];
    if (u < 0.45 && v < 0.4) ++counts[3];
  };
  for (const auto& s : fig.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) count_point(s.x[i], s.y[i]);
    }
  }
  for (const auto& b : fig.bands) {
    for (std::size_t i = 0; i < b.x.size(); ++i) {
      count_point(b.x[i], b.y_low[i]);
      count_point(b.x[i], b.y_high[i]);
    }
  }
  std::size_t best = 0;
  for (std::size_t k = 1; k < corners.size(); ++k) {
    if (counts[k] < counts[best]) best = k;
  }
  return corners[best];
}

PLINT legend_position(const std::string& where) {
  PLINT inside = PL_POSITION_INSIDE;
  if (where == "outside_right") return PL_POSITION_OUTSIDE | PL_POSITION_RIGHT;
  if (where == "best") return inside | PL_POSITION_TOP | PL_POSITION_RIGHT;  // resolved by best_corner() first
  if (where == "top_right") return inside | PL_POSITION_TOP | PL_POSITION_RIGHT;
  if (where == "bottom_right") return inside | PL_POSITION_BOTTOM | PL_POSITION_RIGHT;
  if (where == "bottom_left") return inside | PL_POSITION_BOTTOM | PL_POSITION_LEFT;
  if (where == "top_left") return inside | PL_POSITION_TOP | PL_POSITION_LEFT;
  throw InputError("figure.legend_position", where,
                   "one of 'best', 'top_left', 'top_right', 'bottom_right', 'bottom_left', 'outside_right'");
}

/// Draws markers as polygons (exactly centred, unlike text glyphs): `marker` 0-4 filled, 5-9 hollow.
void draw_markers(const Points& p, int marker, double radius_mm) {
  // World units per millimetre, from the viewport in millimetres and the window in world units.
  PLFLT spx0, spx1, spy0, spy1, vx0, vx1, vy0, vy1, wx0, wx1, wy0, wy1;
  plgspa(&spx0, &spx1, &spy0, &spy1);
  plgvpd(&vx0, &vx1, &vy0, &vy1);
  plgvpw(&wx0, &wx1, &wy0, &wy1);
  const double x_per_mm = (wx1 - wx0) / ((vx1 - vx0) * (spx1 - spx0));
  const double y_per_mm = (wy1 - wy0) / ((vy1 - vy0) * (spy1 - spy0));
  const int shape = std::abs(marker) % 5;
  const bool hollow = std::abs(marker) % 10 >= 5;
  // Unit outlines: circle, triangle, square, diamond, down-triangle (equal visual area, roughly).
  std::vector<std::pair<double, double>> outline;
  const double pi = 3.14159265358979323846;
  switch (shape) {
    case 0:
      for (int k = 0; k < 32; ++k) outline.emplace_back(std::cos(2 * pi * k / 32), std::sin(2 * pi * k / 32));
      break;
    case 1:
      outline = {{0.0, 1.25}, {-1.1, -0.65}, {1.1, -0.65}};
      break;
    case 2:
      outline = {{-0.88, -0.88}, {0.88, -0.88}, {0.88, 0.88}, {-0.88, 0.88}};
      break;
    case 3:
      outline = {{0.0, 1.2}, {1.0, 0.0}, {0.0, -1.2}, {-1.0, 0.0}};
      break;
    default:
      outline = {{0.0, -1.25}, {-1.1, 0.65}, {1.1, 0.65}};
      break;
  }
  for (std::size_t k = 0; k < p.x.size(); ++k) {
    std::vector<PLFLT> px, py;
    for (const auto& [ux, uy] : outline) {
      px.push_back(p.x[k] + ux * radius_mm * x_per_mm);
      py.push_back(p.y[k] + uy * radius_mm * y_per_mm);
    }
    if (hollow) {
      px.push_back(px.front());
      py.push_back(py.front());
      plline(static_cast<PLINT>(px.size()), px.data(), py.data());
    } else {
      plfill(static_cast<PLINT>(px.size()), px.data(), py.data());
    }
  }
}

/// PLplot's own choice of the major tick spacing and the labels' decimals on a linear axis (pldtik and pldprec in
/// fixed form, which scale_by_a_power_of_ten leaves every axis in), so that the layout can make room for the
/// labels before PLplot draws them: the spacing is then passed to plbox explicitly, the same as it would choose.
struct AxisTicks {
  double step = 1.0;
  int subticks = 4;
  int decimals = 0;
};
AxisTicks linear_ticks(double lo, double hi) {
  double t1 = std::log10(std::fabs(hi - lo));
  int np = static_cast<int>(std::floor(t1));
  t1 -= np;
  AxisTicks t;
  double t2 = 2.0;
  if (t1 > 0.7781512503)
    t2 = 2.0, t.subticks = 4;
  else if (t1 > 0.4771212549)
    t2 = 1.0, t.subticks = 5;
  else if (t1 > 0.1760912591)
    t2 = 5.0, t.subticks = 5, --np;
  else
    t2 = 2.0, t.subticks = 4, --np;
  t.step = t2 * std::pow(10.0, np);
  t.decimals = std::max(-static_cast<int>(std::floor(std::log10(t.step))), 0);
  return t;
}

/// The width of the widest tick label on [lo, hi], in character heights (digits 0.84, '.' 0.42, '-' 0.48: the
/// advances of the cairo devices' sans font at PLplot's character height).
double widest_tick_label(double lo, double hi, const AxisTicks& t) {
  double widest = 0.0;
  for (double k = std::ceil(lo / t.step - 1e-9); k <= std::floor(hi / t.step + 1e-9); k += 1.0) {
    double width = 0.0;
    for (char c : fmt::format("{:.{}f}", k * t.step, t.decimals)) width += c == '.' ? 0.42 : c == '-' ? 0.48 : 0.84;
    widest = std::max(widest, width);
  }
  return widest;
}

/// A label's length in characters as drawn: UTF-8 code points, PLplot's #u and #d escapes left out.
double drawn_length(const std::string& text) {
  double n = 0.0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '#' && i + 1 < text.size() && (text[i + 1] == 'u' || text[i + 1] == 'd'))
      ++i;
    else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80)
      n += 1.0;
  }
  return n;
}

// Long (~140 lines) for a reason: one PLplot page drawn in the order PLplot's state machine needs (viewport, axes,
// bands, series, error bars, legend); its pieces share that state rather than values.
void draw(const FigureSpec& fig, const std::pair<double, double>& xr, const std::pair<double, double>& yr,
          const std::string& legend_where) {
  pladv(0);
  const bool legend_outside = fig.legend_position == "outside_right";
  // Margins that hold every label inside the canvas (issue 55 item 4; tests/cli/figures_canvas.sh checks the
  // canvas's edge), in character heights: the y axis title beyond its widest tick label, with room beyond it for a
  // superscript ("strain (10^-6)"); the x axis title with room below it for a subscript ("a_c (mm)"); the last
  // x tick label whole at the right edge.
  PLFLT default_height = 0.0, char_mm = 0.0, page_x0 = 0.0, page_x1 = 0.0, page_y0 = 0.0, page_y1 = 0.0;
  plgchr(&default_height, &char_mm);
  plgspa(&page_x0, &page_x1, &page_y0, &page_y1);
  const double page_w = (page_x1 - page_x0) / char_mm, page_h = (page_y1 - page_y0) / char_mm;  // in characters
  const AxisTicks y_ticks = linear_ticks(yr.first, yr.second);
  const double y_label_disp = std::max(4.6, 0.57 + widest_tick_label(yr.first, yr.second, y_ticks) + 1.15);
  const double x_half_label =
      fig.x_log ? 1.0 : 0.5 * widest_tick_label(xr.first, xr.second, linear_ticks(xr.first, xr.second));
  const double left = std::max(0.12, (y_label_disp + 1.25) / page_w);
  // A legend beside the axes: 3 % and 7 % of the axes' width (its offset and its symbols' column), 2.56 characters of
  // spacing and padding and 0.78 of a character per letter at the legend's size (0.8 of the axes'), within the canvas
  // (but the axes at least a quarter of it wide).
  double legend_letters = 0.0;
  for (const auto& band : fig.bands) legend_letters = std::max(legend_letters, drawn_length(band.label));
  for (const auto& s : fig.series) legend_letters = std::max(legend_letters, drawn_length(s.label));
  const double legend_text = 0.8 * (2.56 + 0.78 * legend_letters) / page_w;
  const double right = legend_outside ? std::clamp((0.995 + 0.1 * left - legend_text) / 1.1, left + 0.25, 0.62)
                                      : std::min(0.96, 1.0 - (x_half_label + 0.25) / page_w);
  const double bottom = std::max(0.12, (2.9 + 1.15 + 0.25) / page_h);
  plvpor(left, right, bottom, 0.91);
  plwind(xr.first, xr.second, yr.first, yr.second);

  // Grid, then the bands, the data, and the frame on top.
  plcol0(kGrid);
  plwidth(1.0);
  plbox(fig.x_log ? "gl" : "g", fig.x_tick_step, 0, "g", y_ticks.step, y_ticks.subticks);

  for (const auto& band : fig.bands) {
    plcol0(band_index(band.color));
    std::vector<PLFLT> px, py;
    for (std::size_t i = 0; i < band.x.size(); ++i) {
      px.push_back(band.x[i]);
      py.push_back(band.y_high[i]);
    }
    for (std::size_t i = band.x.size(); i-- > 0;) {
      px.push_back(band.x[i]);
      py.push_back(band.y_low[i]);
    }
    plfill(static_cast<PLINT>(px.size()), px.data(), py.data());
  }

  for (const auto& s : fig.series) {
    Points p = finite_points(s);
    if (p.x.empty() || s.legend_only) continue;
    const PLINT n = static_cast<PLINT>(p.x.size());
    plcol0(palette_index(s.color));
    const bool has_line = s.style != SeriesStyle::points;
    const bool has_points = s.style == SeriesStyle::points || s.style == SeriesStyle::points_and_line;
    if (has_line) {
      pllsty(s.style == SeriesStyle::dashed_line ? 3 : 1);
      plwidth(2.5);
      plline(n, p.x.data(), p.y.data());
      pllsty(1);
    }
    plwidth(1.8);
    plsmin(0.0, 1.6);  // error-bar caps
    for (std::size_t k = 0; k < p.x.size(); ++k) {
      const std::size_t i = p.index[k];
      const double ex = error_at(s.x_error, i), ey = error_at(s.y_error, i);
      PLFLT x = p.x[k], y = p.y[k];
      if (ey > 0.0) {
        PLFLT lo = y - ey, hi = y + ey;
        plerry(1, &x, &lo, &hi);
      }
      if (ex > 0.0) {
        PLFLT lo = x - ex, hi = x + ex;
        plerrx(1, &lo, &hi, &y);
      }
    }
    if (has_points) {
      plwidth(2.0);
      draw_markers(p, s.marker, 3.0);
    }
  }

  plcol0(kBlack);
  plwidth(1.5);
  plsmin(0.0, 1.0);
  // Tick labels as plain numbers (0.002, 15000): PLplot's "(x10^-3)" exponent label sits outside the axes, where
  // the title or the canvas edge clips it.
  plsxax(12, 0);
  plsyax(12, 0);
  plbox(fig.x_log ? "bcnstl" : "bcnst", fig.x_tick_step, fig.x_tick_step > 0 ? 1 : 0, "bcnstv", y_ticks.step,
        y_ticks.subticks);
  plmtex("b", 2.9, 0.5, 0.5, fig.x_label.c_str());
  plmtex("l", y_label_disp, 0.5, 0.5, fig.y_label.c_str());
  plschr(0.0, 1.45);
  plmtex("t", 1.4, 0.5, 0.5, fig.title.c_str());
  plschr(0.0, 1.25);

  // Legend: bands as colour boxes, series as line and/or symbol.
  std::vector<PLINT> opts, text_colors, box_colors, box_patterns, line_colors, line_styles, symbol_colors,
      symbol_numbers;
  std::vector<PLFLT> box_scales, box_widths, line_widths, symbol_scales;
  std::vector<std::string> texts, symbols;
  for (const auto& band : fig.bands) {
    if (band.label.empty()) continue;
    opts.push_back(PL_LEGEND_COLOR_BOX);
    texts.push_back(band.label);
    box_colors.push_back(band_index(band.color));
    line_styles.push_back(1);
    symbols.emplace_back("");
  }
  for (const auto& s : fig.series) {
    if (s.label.empty() || (finite_points(s).x.empty() && !s.legend_only)) continue;
    PLINT opt = 0;
    if (s.style != SeriesStyle::points) opt |= PL_LEGEND_LINE;
    if (s.style == SeriesStyle::points || s.style == SeriesStyle::points_and_line) opt |= PL_LEGEND_SYMBOL;
    opts.push_back(opt);
    texts.push_back(s.label);
    box_colors.push_back(palette_index(s.color));
    line_styles.push_back(s.style == SeriesStyle::dashed_line ? 3 : 1);
    symbols.emplace_back(marker_glyph(s.marker));
  }
  const std::size_t n = opts.size();
  if (n == 0) return;
  text_colors.assign(n, kBlack);
  box_patterns.assign(n, 0);
  box_scales.assign(n, 0.9);
  box_widths.assign(n, 1.0);
  line_colors = box_colors;
  line_widths.assign(n, 2.5);
  symbol_colors = box_colors;
  symbol_scales.assign(n, 0.95);
  symbol_numbers.assign(n, 1);
  std::vector<const char*> text_ptrs, symbol_ptrs;
  for (const auto& t : texts) text_ptrs.push_back(t.c_str());
  for (const auto& s : symbols) symbol_ptrs.push_back(s.c_str());
  PLFLT legend_width = 0.0, legend_height = 0.0;
  plscol0a(0, 255, 255, 255, 0.9);
  plschr(0.0, 1.0);
  pllegend(&legend_width, &legend_height, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, legend_position(legend_where),
           legend_outside ? 0.03 : 0.02, 0.02, 0.07, 0, kBlack, 1, 0, 0, static_cast<PLINT>(n), opts.data(), 1.0, 1.0,
           1.8, 0.0, text_colors.data(), text_ptrs.data(), box_colors.data(), box_patterns.data(), box_scales.data(),
           box_widths.data(), line_colors.data(), line_styles.data(), line_widths.data(), symbol_colors.data(),
           symbol_scales.data(), symbol_numbers.data(), symbol_ptrs.data());
  plschr(0.0, 1.25);
}

}  // namespace

void check_figure_path(const std::filesystem::path& path, const std::string& field) {
  const std::string extension = path.extension().string();
  if (path.filename() == "-" || (extension != ".png" && extension != ".svg" && extension != ".pdf")) {
    throw InputError(field, path.string(),
                     "a figure file named .png, .svg or .pdf (figures are not written to standard output)");
  }
}

void draw_png_with_plplot(const std::filesystem::path& path, int width_px, int height_px,
                          const std::function<void()>& before_init, const std::function<void()>& draw) {
  namespace fs = std::filesystem;
  // The file the extension names (PNG or SVG), then the same drawing as a PDF beside it (vector, for papers):
  // cairo's page is the PNG's size in points, so both look alike. A .pdf path is the PDF alone.
  check_figure_path(path, path.string());
  const std::string extension = path.extension().string();
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  fs::path pdf = path;
  pdf.replace_extension(".pdf");
  std::vector<std::pair<const char*, fs::path>> outputs;
  if (extension != ".pdf") outputs.emplace_back(extension == ".svg" ? "svgcairo" : "pngcairo", path);
  outputs.emplace_back("pdfcairo", pdf);
  for (const auto& [device, file] : outputs) {
    const fs::path temporary = TemporaryFile::reserve(file, file.extension().string());
    {
      // PLplot keeps library-wide state: one drawing at a time, on a stream of its own, closed with plend1()
      // (plend() would end every stream).
      static std::mutex plplot_state;  // guards a library resource, not model state
      const std::lock_guard<std::mutex> lock(plplot_state);
      PLINT previous_stream = 0, stream = 0;
      plgstrm(&previous_stream);
      plmkstrm(&stream);
      plsdev(device);
      plsfnam(temporary.c_str());
      plspage(0.0, 0.0, width_px, height_px, 0, 0);
      if (before_init) before_init();
      plinit();
      draw();
      plend1();
      plsstrm(previous_stream);
    }
    std::error_code error;
    if (!fs::exists(temporary, error) || fs::file_size(temporary, error) == 0) {
      fs::remove(temporary, error);
      TemporaryFile::release(temporary);
      throw OutputError(file.string(), fmt::format("PLplot ({}) did not write it", device));
    }
    move_into_place(temporary, file);
  }
}

void leave_room_for_legend(FigureSpec& figure) {
  double y_low = 0, y_high = 0;
  int rows = 0;
  for (const auto& series : figure.series) {
    rows += series.label.empty() ? 0 : 1;
    for (std::size_t i = 0; i < series.y.size(); ++i) {
      const double y = series.y[i], e = error_at(series.y_error, i);  // the interval bars drawn whole too
      if (std::isfinite(y)) y_low = std::min(y_low, y - e), y_high = std::max(y_high, y + e);
    }
  }
  const double range = y_high > y_low ? y_high - y_low : 1.0;
  figure.y_min = y_low - 0.03 * range;  // points at the extremes drawn whole
  figure.y_max = y_high + range * (0.1 + 0.09 * rows);
  figure.legend_position = "top_left";
}

namespace {
/// A logarithmic x axis: PLplot draws log10(x) with the labels of x ("l" in plbox).
FigureSpec with_log10_x(FigureSpec fig) {
  const auto to_log = [](std::vector<double>& xs, const std::string& field) {
    for (double& x : xs) {
      if (std::isfinite(x) && !(x > 0.0)) {
        throw InputError(field, format_value(x), "positive x values on a logarithmic x axis");
      }
      x = std::log10(x);
    }
  };
  for (std::size_t k = 0; k < fig.series.size(); ++k) {
    if (!fig.series[k].x_error.empty()) {
      throw InputError(fmt::format("figure.series[{}].x_error", k), "(given)",
                       "no x error bars on a logarithmic x axis");
    }
    to_log(fig.series[k].x, fmt::format("figure.series[{}].x", k));
  }
  for (std::size_t k = 0; k < fig.bands.size(); ++k) to_log(fig.bands[k].x, fmt::format("figure.bands[{}].x", k));
  for (auto* limit : {&fig.x_min, &fig.x_max}) {
    if (!*limit) continue;
    std::vector<double> one{**limit};
    to_log(one, "figure.x_range");
    *limit = one[0];
  }
  return fig;
}

/// A linear axis whose values are all tiny or huge (|v| < 0.01 or >= 1e5) is drawn in a power of ten that is a
/// multiple of 3, said in the axis label ("force (10^-3 N)"): PLplot's own "(x10^-3)" sits outside the axes where
/// the title or the canvas edge clips it, and plain labels of many digits run into the axis title.
void scale_by_a_power_of_ten(FigureSpec& fig, bool x) {
  double largest = 0.0;
  for (const auto& s : fig.series) {
    if (s.legend_only) continue;
    for (double v : x ? s.x : s.y)
      if (std::isfinite(v)) largest = std::max(largest, std::fabs(v));
  }
  if (!(largest > 0.0) || (largest >= 0.01 && largest < 1e5)) return;
  const int exponent = 3 * static_cast<int>(std::floor(std::log10(largest) / 3.0));
  const double factor = std::pow(10.0, -exponent);
  const auto scale = [&](std::vector<double>& values) {
    for (double& v : values) v *= factor;
  };
  for (auto& s : fig.series) {
    scale(x ? s.x : s.y);
    scale(x ? s.x_error : s.y_error);
  }
  for (auto& b : fig.bands) {
    if (x)
      scale(b.x);
    else
      scale(b.y_low), scale(b.y_high);
  }
  for (auto* limit : x ? std::array{&fig.x_min, &fig.x_max} : std::array{&fig.y_min, &fig.y_max})
    if (*limit) **limit *= factor;
  if (x) fig.x_tick_step *= factor;
  std::string& label = x ? fig.x_label : fig.y_label;
  const std::string power = fmt::format("10#u{}#d", exponent);
  const auto open = label.rfind(" (");
  label = open != std::string::npos && label.back() == ')'
              ? label.substr(0, open + 2) + power + " " + label.substr(open + 2)
              : label + " (" + power + ")";
}
}  // namespace

void render_png(const FigureSpec& figure, const std::filesystem::path& path) {
  FigureSpec fig = figure.x_log ? with_log10_x(figure) : figure;
  if (!fig.x_log) scale_by_a_power_of_ten(fig, true);
  scale_by_a_power_of_ten(fig, false);
  // Validate everything PLplot would otherwise exit() on.
  if (!(std::isfinite(fig.x_tick_step) && fig.x_tick_step >= 0.0) || (fig.x_log && fig.x_tick_step > 0.0))
    throw InputError("figure.x_tick_step", format_value(figure.x_tick_step),
                     "a non-negative spacing (0: PLplot's choice), 0 on a logarithmic axis");
  Extent xe, ye;
  bool any_point = false;
  for (std::size_t k = 0; k < fig.series.size(); ++k) {
    const auto& s = fig.series[k];
    check_sizes(s, k);
    if (s.legend_only) continue;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      any_point = true;
      const double ex = error_at(s.x_error, i), ey = error_at(s.y_error, i);
      xe.add(s.x[i] - ex);
      xe.add(s.x[i] + ex);
      ye.add(s.y[i] - ey);
      ye.add(s.y[i] + ey);
    }
  }
  for (std::size_t k = 0; k < fig.bands.size(); ++k) {
    const auto& b = fig.bands[k];
    if (b.x.size() != b.y_low.size() || b.x.size() != b.y_high.size() || b.x.size() < 2) {
      throw InputError(fmt::format("figure.bands[{}]", k), fmt::format("{} x values", b.x.size()),
                       "at least 2 x values with as many y_low and y_high");
    }
    for (std::size_t i = 0; i < b.x.size(); ++i) {
      if (!std::isfinite(b.x[i]) || !std::isfinite(b.y_low[i]) || !std::isfinite(b.y_high[i])) {
        throw InputError(fmt::format("figure.bands[{}]", k), "a non-finite value", "finite band coordinates");
      }
    }
  }
  if (!any_point) throw InputError(fmt::format("figure '{}'", fig.title), "(no finite points)", "data to plot");
  if (fig.width_px < 200 || fig.height_px < 150) {
    throw InputError("figure.size_px", fmt::format("{}x{}", fig.width_px, fig.height_px), "at least 200x150 pixels");
  }
  legend_position(fig.legend_position);  // validates

  auto xr = padded(xe, 0.06), yr = padded(ye, 0.08);
  if (fig.equal_axes) {
    const double lo = std::min(xr.first, yr.first), hi = std::max(xr.second, yr.second);
    xr = yr = {lo, hi};
  }
  if (fig.x_min) xr.first = *fig.x_min;
  if (fig.x_max) xr.second = *fig.x_max;
  if (fig.y_min) yr.first = *fig.y_min;
  if (fig.y_max) yr.second = *fig.y_max;
  if (!(xr.first < xr.second) || !(yr.first < yr.second)) {
    throw InputError(fmt::format("figure '{}' axes", fig.title),
                     fmt::format("x [{}, {}], y [{}, {}]", xr.first, xr.second, yr.first, yr.second),
                     "increasing axis limits");
  }

  const auto colours = [] {
    plscmap0n(kBandStart + static_cast<int>(kPalette.size()));
    plscol0(0, 255, 255, 255);
    plscol0(kBlack, 0, 0, 0);
    plscol0(kGrid, 225, 225, 225);
    for (std::size_t i = 0; i < kPalette.size(); ++i) {
      const int c = static_cast<int>(i);
      plscol0(kPaletteStart + c, kPalette[i][0], kPalette[i][1], kPalette[i][2]);
      plscol0a(kBandStart + c, kPalette[i][0], kPalette[i][1], kPalette[i][2], 0.18);
    }
  };
  draw_png_with_plplot(path, fig.width_px, fig.height_px, colours, [&] {
    plschr(0.0, 1.25);
    draw(fig, xr, yr, fig.legend_position == "best" ? best_corner(fig, xr, yr) : fig.legend_position);
  });
}

void sort_by_x(PlotSeries& s) {
  std::vector<std::size_t> order(s.x.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.x[a] < s.x[b]; });
  const auto permuted = [&](const std::vector<double>& v) {
    if (v.size() != order.size()) return v;  // none (empty)
    std::vector<double> out(v.size());
    for (std::size_t i = 0; i < order.size(); ++i) out[i] = v[order[i]];
    return out;
  };
  s.x = permuted(s.x), s.y = permuted(s.y), s.x_error = permuted(s.x_error), s.y_error = permuted(s.y_error);
}

}  // namespace kerf
