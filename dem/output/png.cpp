// Specimen pictures with PLplot's pngcairo device.
#include "kerf/dem/output/png.hpp"

#include <fmt/format.h>
#include <plplot/plplot.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
  // The walls (the tool, platens) in the picture too, with a margin: a tool above the specimen is not clipped.
  for (const auto& w : sim.walls()) {
    if (!w.enabled) continue;
    x0 = std::min({x0, w.x0, w.x1}), x1 = std::max({x1, w.x0, w.x1});
    y0 = std::min({y0, w.y0, w.y1}), y1 = std::max({y1, w.y0, w.y1});
  }
  const double margin = 0.02 * std::max(x1 - x0, y1 - y0);
  x0 -= margin, x1 += margin, y0 -= margin, y1 += margin;
  if (view_m) {  // a fixed view (a cut's frames share it) keeps its x range but reaches up to the walls' tops
    const double wall_top = y1;
    x0 = (*view_m)[0], x1 = (*view_m)[1], y0 = (*view_m)[2], y1 = std::max((*view_m)[3], wall_top);
  }
  // Millimetres on the axes; about 1000 pixels along the longer side.
  const double mx = units::m_to_mm(1.0);
  const double aspect = (y1 - y0) / (x1 - x0);
  const int width = aspect > 1 ? static_cast<int>(1000 / aspect) + 120 : 1100;
  const int height = aspect > 1 ? 1100 : static_cast<int>(1000 * aspect) + 120;
  draw_png_with_plplot(
      path, width, height,
      [] {
        plscolbg(255, 255, 255);
        plscol0(1, 0, 0, 0);        // axes, labels
        plscol0(2, 170, 170, 170);  // disks
        plscol0(3, 220, 30, 30);    // tension cracks
        plscol0(4, 30, 70, 220);    // shear cracks
        plscol0(5, 200, 200, 200);  // held disks (filled)
        plscol0(6, 0, 130, 60);     // walls: the tool, platens
      },
      [&] {
        plcol0(1);
        plschr(0, 0.75);
        plenv(x0 * mx, x1 * mx, y0 * mx, y1 * mx, 1, 0);
        pllab("x (mm)", "y (mm)", "");
        // The title and, under it, the key in two lines above the frame: nothing of the specimen is covered.
        plmtex("t", 4.0, 0.5, 0.5, title.c_str());
        const bool any_held = std::any_of(p.group.begin(), p.group.end(), [](auto g) { return g > 0; });
        const bool any_wall =
            std::any_of(sim.walls().begin(), sim.walls().end(), [](const Wall& w) { return w.enabled; });
        const std::string key = std::string(any_held ? "grey fill = held disks" : "") +
                                (any_held && any_wall ? "; " : "") + (any_wall ? "green = walls (tool, platens)" : "");
        if (!sim.cracks().empty()) plmtex("t", 2.6, 0.5, 0.5, "cracks: red = tension, blue = shear");
        if (!key.empty()) plmtex("t", 1.2, 0.5, 0.5, key.c_str());
        plcol0(5);
        for (std::size_t i = 0; i < p.size(); ++i)
          if (p.group[i] > 0) plarc(p.x[i] * mx, p.y[i] * mx, p.radius[i] * mx, p.radius[i] * mx, 0, 360, 0, 1);
        plcol0(2);
        plwidth(0.5);
        for (std::size_t i = 0; i < p.size(); ++i)
          plarc(p.x[i] * mx, p.y[i] * mx, p.radius[i] * mx, p.radius[i] * mx, 0, 360, 0, 0);
        plwidth(2.0);
        for (const auto& c : sim.cracks()) {
          plcol0(c.mode == BreakMode::tension ? 3 : 4);
          const double dx = 0.5 * c.length_m * std::cos(c.orientation_rad),
                       dy = 0.5 * c.length_m * std::sin(c.orientation_rad);
          pljoin((c.x_m - dx) * mx, (c.y_m - dy) * mx, (c.x_m + dx) * mx, (c.y_m + dy) * mx);
        }
        // Walls (platens, the cutting tool) in thick green, clipped to the picture.
        plcol0(6);
        plwidth(4.0);
        for (const auto& w : sim.walls())
          if (w.enabled) pljoin(w.x0 * mx, w.y0 * mx, w.x1 * mx, w.y1 * mx);
      });
}

void write_cut_forces_png(const std::filesystem::path& path, const CutResult& result) {
  FigureSpec fig;
  fig.title = "cut: force on the tool";
  fig.x_label = "tool travel (mm)";
  // Per mm of width, whatever the specimen's thickness: the force on the tool divided by the width it cuts.
  const double width_mm = units::m_to_mm(result.width_m);
  fig.y_label = "force per unit width (N/mm)";
  PlotSeries main{"cutting force", {}, {}, {}, {}, SeriesStyle::line, 0, 0};
  PlotSeries thrust{"thrust force", {}, {}, {}, {}, SeriesStyle::line, 1, 0};
  for (const auto& s : result.samples) {
    main.x.push_back(units::m_to_mm(s.travel_m)), main.y.push_back(s.main_force_N / width_mm);
    thrust.x.push_back(units::m_to_mm(s.travel_m)), thrust.y.push_back(s.thrust_force_N / width_mm);
  }
  // The means over the travel they cover, and whether that is a steady cut (CutResult::steady).
  const double x0 = units::m_to_mm(result.steady_from_travel_m), x1 = units::m_to_mm(result.steady_to_travel_m);
  const auto mean_label = [&](double force_N) {
    return fmt::format("mean {:.3g} N/mm over {:.3g}-{:.3g} mm{}", force_N / width_mm, x0, x1,
                       result.steady ? "" : " (NOT STEADY)");
  };
  const double main_mean_N_per_mm = result.main_force_N / width_mm,
               thrust_mean_N_per_mm = result.thrust_force_N / width_mm;
  PlotSeries main_mean{mean_label(result.main_force_N),
                       {x0, x1},
                       {main_mean_N_per_mm, main_mean_N_per_mm},
                       {},
                       {},
                       SeriesStyle::dashed_line,
                       0,
                       0};
  PlotSeries thrust_mean{mean_label(result.thrust_force_N),
                         {x0, x1},
                         {thrust_mean_N_per_mm, thrust_mean_N_per_mm},
                         {},
                         {},
                         SeriesStyle::dashed_line,
                         1,
                         0};
  if (!result.steady) fig.title += " (means NOT STEADY)";
  fig.series = {main, thrust, main_mean, thrust_mean};
  leave_room_for_legend(fig);
  render_png(fig, path);
}

void write_stress_strain_png(const std::filesystem::path& path, const LabTestResult& result, const std::string& title) {
  const double strain_scale = 100;  // axial strain in %
  FigureSpec fig;
  fig.title = title;
  fig.x_label = "axial strain (%)";
  fig.y_label = "axial stress (MPa)";
  PlotSeries curve{"stress-strain curve", {}, {}, {}, {}, SeriesStyle::line, 0, 0};
  for (const auto& c : result.curve)
    curve.x.push_back(strain_scale * c.axial_strain), curve.y.push_back(units::pa_to_mpa(c.stress_Pa));
  fig.series.push_back(curve);
  const double peak = units::pa_to_mpa(result.peak_stress_Pa);
  if (result.youngs_modulus_Pa > 0) {
    // The secant E (lab_test.hpp: from the origin to 50 % of the peak), drawn over its fit range and on to
    // the peak's stress as a thinner guide.
    const double half_strain = 0.5 * result.peak_stress_Pa / result.youngs_modulus_Pa;
    fig.series.push_back(
        {fmt::format("secant E = {:.3g} GPa (fit: 0-50 % of the peak)", units::pa_to_gpa(result.youngs_modulus_Pa)),
         {0, strain_scale * half_strain},
         {0, 0.5 * peak},
         {},
         {},
         SeriesStyle::line,
         3,
         0});
    fig.series.push_back({"",
                          {strain_scale * half_strain, strain_scale * 2 * half_strain},
                          {0.5 * peak, peak},
                          {},
                          {},
                          SeriesStyle::dashed_line,
                          3,
                          0});
  }
  fig.series.push_back({fmt::format("peak {:.3g} MPa at {:.3g} %", peak, strain_scale * result.strain_at_peak),
                        {strain_scale * result.strain_at_peak},
                        {peak},
                        {},
                        {},
                        SeriesStyle::points,
                        1,
                        3});
  fig.x_min = 0;
  fig.y_min = 0;
  fig.y_max = 1.4 * peak;  // room for the legend above the curve
  fig.legend_position = "top_left";
  render_png(fig, path);
}

void write_load_deflection_png(const std::filesystem::path& path, const std::vector<ToughnessResult>& results,
                               const std::string& title) {
  FigureSpec fig;
  fig.title = title;
  fig.x_label = "load-point deflection (µm)";
  fig.y_label = results.empty() ? "load (N)"
                                : fmt::format("load per {:g} mm thickness (N)", units::m_to_mm(results[0].thickness_m));
  double peak_max = 0;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const ToughnessResult& r = results[k];
    PlotSeries curve{k == 0 ? std::string("load on the load roller") : std::string(),
                     {},
                     {},
                     {},
                     {},
                     SeriesStyle::line,
                     static_cast<int>(k % 6),
                     0};
    PlotSeries smooth{k == 0 ? std::string("averaged over the peak window") : std::string(),
                      {},
                      {},
                      {},
                      {},
                      SeriesStyle::dashed_line,
                      static_cast<int>(k % 6),
                      0};
    for (const auto& s : r.curve) {
      curve.x.push_back(units::m_to_um(s.deflection_m)), curve.y.push_back(s.load_N);
      smooth.x.push_back(units::m_to_um(s.deflection_m)), smooth.y.push_back(s.smoothed_load_N);
    }
    fig.series.push_back(curve);
    fig.series.push_back(smooth);
    peak_max = std::max(peak_max, r.raw_peak_load_N);
  }
  for (std::size_t k = 0; k < results.size(); ++k) {
    const ToughnessResult& r = results[k];
    const std::string label = k == 0 ? fmt::format("averaged peak {:.3g} N: K#dIC#u {:.3g} MPa m#u1/2#d", r.peak_load_N,
                                                   units::pa_to_mpa(r.fracture_toughness_Pa_sqrt_m))
                                     : std::string();
    // One packing: the peak in red, to stand out of its own curve.
    fig.series.push_back({label,
                          {units::m_to_um(r.deflection_at_peak_m)},
                          {r.peak_load_N},
                          {},
                          {},
                          SeriesStyle::points,
                          results.size() == 1 ? 3 : static_cast<int>(k % 6),
                          3});
  }
  if (results.size() > 1) {  // the other packings' colours, said in the legend
    PlotSeries others{results.size() == 2 ? "the second packing: the same"
                                          : fmt::format("packings 2-{}: the same, a colour each", results.size()),
                      {},
                      {},
                      {},
                      {},
                      SeriesStyle::line,
                      1,
                      0};
    others.legend_only = true;
    fig.series.push_back(others);
  }
  fig.x_min = 0;
  fig.y_min = 0;
  fig.y_max = 1.4 * peak_max;  // room for the legend above the curves
  fig.legend_position = "top_left";
  render_png(fig, path);
}

}  // namespace kerf::dem
