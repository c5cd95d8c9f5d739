// Specimen pictures with PLplot's pngcairo device.
#include "kerf/dem/png.hpp"

#include <plplot/plplot.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "kerf/plot.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

void write_specimen_png(const std::filesystem::path& path, const Simulation& sim, const std::string& title,
                        const std::optional<std::array<double, 4>>& view_m) {
  const auto& p = sim.particles();
  if (p.size() == 0) return;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (std::size_t i = 0; i < p.size(); ++i) {
    x0 = std::min(x0, p.x[i] - p.radius[i]), x1 = std::max(x1, p.x[i] + p.radius[i]);
    y0 = std::min(y0, p.y[i] - p.radius[i]), y1 = std::max(y1, p.y[i] + p.radius[i]);
  }
  if (view_m) x0 = (*view_m)[0], x1 = (*view_m)[1], y0 = (*view_m)[2], y1 = (*view_m)[3];
  // Millimetres on the axes; about 1000 pixels along the longer side.
  const double mx = units::m_to_mm(1.0);
  const double aspect = (y1 - y0) / (x1 - x0);
  const int width = aspect > 1 ? static_cast<int>(1000 / aspect) + 120 : 1100;
  const int height = aspect > 1 ? 1100 : static_cast<int>(1000 * aspect) + 120;
  draw_png_with_plplot(path, width, height, [] {
    plscolbg(255, 255, 255);
    plscol0(1, 0, 0, 0);        // axes, labels
    plscol0(2, 170, 170, 170);  // disks
    plscol0(3, 220, 30, 30);    // tension cracks
    plscol0(4, 30, 70, 220);    // shear cracks
  }, [&] {
    plcol0(1);
    plschr(0, 0.75);
    plenv(x0 * mx, x1 * mx, y0 * mx, y1 * mx, 1, 0);
    pllab("x (mm)", "y (mm)", (title + "; cracks: red tension, blue shear").c_str());
    plcol0(2);
    plwidth(0.5);
    for (std::size_t i = 0; i < p.size(); ++i) plarc(p.x[i] * mx, p.y[i] * mx, p.radius[i] * mx, p.radius[i] * mx, 0, 360, 0, 0);
    plwidth(2.0);
    for (const auto& c : sim.cracks()) {
      plcol0(c.mode == BreakMode::tension ? 3 : 4);
      const double dx = 0.5 * c.length_m * std::cos(c.orientation_rad), dy = 0.5 * c.length_m * std::sin(c.orientation_rad);
      pljoin((c.x_m - dx) * mx, (c.y_m - dy) * mx, (c.x_m + dx) * mx, (c.y_m + dy) * mx);
    }
    // Walls (platens, the cutting tool) in black, clipped to the picture.
    plcol0(1);
    for (const auto& w : sim.walls())
      if (w.enabled) pljoin(w.x0 * mx, w.y0 * mx, w.x1 * mx, w.y1 * mx);
  });
}

void write_cut_forces_png(const std::filesystem::path& path, const CutResult& result, double steady_from_m) {
  FigureSpec fig;
  fig.title = "cut: force on the tool";
  fig.x_label = "tool travel (mm)";
  fig.y_label = fmt::format("force per {:g} mm width (N)", units::m_to_mm(result.width_m));
  PlotSeries main{"main force", {}, {}, {}, {}, SeriesStyle::line, 0, 0};
  PlotSeries thrust{"thrust force", {}, {}, {}, {}, SeriesStyle::line, 1, 0};
  for (const auto& s : result.samples) {
    main.x.push_back(units::m_to_mm(s.travel_m)), main.y.push_back(s.main_force_n);
    thrust.x.push_back(units::m_to_mm(s.travel_m)), thrust.y.push_back(s.thrust_force_n);
  }
  const double x0 = units::m_to_mm(steady_from_m), x1 = main.x.empty() ? x0 : main.x.back();
  PlotSeries main_mean{fmt::format("mean {:.3g} N (steady part)", result.main_force_n), {x0, x1},
                       {result.main_force_n, result.main_force_n}, {}, {}, SeriesStyle::dashed_line, 0, 0};
  PlotSeries thrust_mean{fmt::format("mean {:.3g} N (steady part)", result.thrust_force_n), {x0, x1},
                         {result.thrust_force_n, result.thrust_force_n}, {}, {}, SeriesStyle::dashed_line, 1, 0};
  fig.series = {main, thrust, main_mean, thrust_mean};
  fig.legend_position = "top_left";
  render_png(fig, path);
}

}  // namespace kerf::dem
