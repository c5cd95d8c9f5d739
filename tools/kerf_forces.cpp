// kerf-forces: quick cutting-force predictions and parameter sweeps from a scene file.
//
//   kerf-forces predict SCENE.json [--set key.path=value]... [--csv FILE]
//   kerf-forces sweep SCENE.json --vary key.path=START:STOP:COUNT[:log] [--vary ...] --csv FILE
//   kerf-forces compare SCENE.json --experiments FILE.csv [--map a=b]... [--fit] [--pool] --out DIR
//   kerf-forces report COMPARISON.json --out DIR   (measured and predicted CSV files named in a JSON file)
//   kerf-forces regime SCENE.json (the ductile-brittle critical depth and the regime of the scene's cut)
//   kerf-forces models            (the registered models)
//   kerf-forces materials         (the bundled material library)
//
// Exit status: 0 success, 2 usage or input error (the message names the field, value and what was
// expected), 3 a model failed on valid input or a result would not be finite, 4 an output cannot be written
// (checked before any work), 1 anything else.
#include <fmt/format.h>
#include <omp.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <filesystem>
#include <cmath>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "kerf/analytic/critical_depth.hpp"
#include "kerf/analytic/evaluate.hpp"
#include "kerf/analytic/scene_compare.hpp"
#include "kerf/analytic/predict.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/analytic/scene.hpp"
#include "kerf/comparison_config.hpp"
#include "kerf/csv_table.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/plot.hpp"
#include "kerf/material.hpp"
#include "kerf/report.hpp"
#include "kerf/units.hpp"
#include "kerf/version.hpp"

namespace {

using kerf::Json;

Json load_scene_document(const std::string& path, const std::vector<std::string>& overrides) {
  Json document = kerf::read_json_file(path);
  for (const auto& assignment : overrides) kerf::apply_override(document, assignment);
  return document;
}

std::string csv_text(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::string text = kerf::csv_line(header);
  for (const auto& row : rows) text += kerf::csv_line(row);
  return text;
}

void print_prediction(std::FILE* text, const std::string& scene_path, const kerf::AnalyticScene& scene,
                      const kerf::Prediction& p) {
  using kerf::units::m_to_mm;
  using kerf::units::m_to_um;
  using kerf::units::pa_to_mpa;
  using kerf::units::rad_to_deg;
  const double width_mm = m_to_mm(p.width_m);
  fmt::print(text, "scene             {}\n", scene_path);
  fmt::print(text, "material          {} ({})\n", scene.material.name, scene.material.title);
  fmt::print(text, "force model       {}{}\n", kerf::force_model_name(p.force_model),
             scene.force_choice_reason.empty() ? "" : " (auto: " + scene.force_choice_reason + ")");
  fmt::print(text, "cut               t0 = {:.6g} um, width = {:.6g} mm, speed = {:.6g} m/min\n",
             m_to_um(p.uncut_chip_thickness_m), width_mm, kerf::units::m_per_s_to_m_per_min(scene.speed_m_per_s));
  fmt::print(text, "tool              rake = {:.6g} deg, edge radius = {:.6g} um\n", rad_to_deg(scene.rake_rad),
             m_to_um(scene.edge_radius_m));
  fmt::print(text, "cutting force     {:.6g} N  ({:.6g} N/mm)\n", p.cutting_force_N, p.cutting_force_N / width_mm);
  fmt::print(text, "thrust force      {:.6g} N  ({:.6g} N/mm)\n", p.thrust_force_N, p.thrust_force_N / width_mm);
  fmt::print(text, "shear angle       {:.4g} deg\n", rad_to_deg(p.shear_angle_rad));
  if (p.has_friction) {
    const bool from_scene = scene.friction_angle_rad && p.force_model != kerf::ForceModel::oxley &&
                            std::fabs(*scene.friction_angle_rad - p.friction_angle_rad) <= 1e-9;
    fmt::print(text, "friction angle    {:.4g} deg (from {})\n", rad_to_deg(p.friction_angle_rad),
               p.force_model == kerf::ForceModel::oxley ? "the extended-Oxley solution"
               : from_scene                             ? scene.friction_origin
                                                        : fmt::format("the {} friction closure at the nominal rake",
                                                                      kerf::friction_closure_name(scene.liu_li.closure)));
  }
  fmt::print(text, "chip ratio        {:.4g} (chip thickness {:.6g} um)\n", p.chip_ratio, m_to_um(p.chip_thickness_m));
  fmt::print(text,
             "flow stress       {:.6g} MPa (JC {:.6g} + Hall-Petch {:.6g} + dislocation {:.6g}); k_s = {:.6g} MPa\n",
             pa_to_mpa(p.flow.total_Pa), pa_to_mpa(p.flow.johnson_cook_Pa), pa_to_mpa(p.flow.hall_petch_Pa),
             pa_to_mpa(p.flow.dislocation_Pa), pa_to_mpa(p.flow.shear_Pa));
  fmt::print(text, "at                strain {:.4g}, strain rate {:.4g} 1/s, temperature {:.5g} K\n", p.state.strain,
             p.state.strain_rate_per_s, p.state.temperature_K);
  if (scene.critical_depth_m) {
    fmt::print(text, "regime            {} (critical depth d_c = {:.3g} nm)\n", p.regime,
               kerf::units::m_to_nm(*scene.critical_depth_m));
  }
  for (const auto& [column, length_m] : p.contact_lengths_m) {
    const std::string name = column.substr(0, column.size() - 3);
    if (length_m) fmt::print(text, "{:<17} {:.6g} mm\n", name, m_to_mm(*length_m));
    if (!length_m) fmt::print(text, "{:<17} not applicable (see the warnings)\n", name);
  }
  if (p.liu_li) {
    const auto& l = *p.liu_li;
    fmt::print(
        text, "edge integral     from {:.4g} deg to {:.4g} deg (stagnation {:.4g} deg{}); ploughed layer {:.6g} um\n",
        rad_to_deg(l.lower_limit_rad), rad_to_deg(l.upper_limit_rad), rad_to_deg(l.stagnation_angle_rad),
        l.pole_rad ? fmt::format(", pole {:.4g} deg", rad_to_deg(*l.pole_rad)) : "", m_to_um(l.ploughed_thickness_m));
    fmt::print(text,
               "edge part         cutting {:.6g} N, thrust {:.6g} N (the thrust depends strongly on the lower limit)\n",
               l.edge.cutting_N_per_m * p.width_m, l.edge.thrust_N_per_m * p.width_m);
    if (p.ploughing) {
      const auto& w = *p.ploughing;
      fmt::print(text, "ploughing part    cutting {:.6g} N, thrust {:.6g} N (wave model, f = {:.4g}, chord {:.6g} um at "
                 "{:.4g} deg)\n",
                 w.force.cutting_N_per_m * p.width_m, w.force.thrust_N_per_m * p.width_m, p.friction_factor,
                 m_to_um(w.chord_m), rad_to_deg(w.factors.attack_angle_rad));
    } else {
      fmt::print(text, "ploughing part    none (models.ploughing = {})\n", kerf::ploughing_model_name(scene.ploughing));
    }
  }
  if (p.oxley) {
    fmt::print(text,
               "oxley             C0 = {:.4g}, delta = {:.4g}, interface T = {:.5g} K, contact length {:.6g} mm\n",
               p.oxley->strain_rate_constant_C0, p.oxley->delta, p.oxley->interface_temperature_K,
               m_to_mm(p.oxley->contact_length_m));
  }
  const auto fired = p.guards.fired();
  if (fired.empty()) fmt::print(text, "guards            none fired\n");
  for (auto guard : fired)
    fmt::print(text, "guard             {}: {}\n", kerf::guard_name(guard), kerf::guard_policy(guard));
  for (const auto& w : p.warnings) fmt::print(text, "warning           {}\n", w);
}

/// Where the human-readable text goes: standard error when the CSV goes to standard output (`--csv -`), so that
/// `kerf-forces predict SCENE --csv - > out.csv` writes nothing but the CSV there.
std::FILE* text_stream(const std::string& csv) {
  return csv == "-" ? stderr : stdout;
}

void write_row_csv(const std::string& csv, const kerf::Columns& columns) {
  std::vector<std::string> header, values;
  for (const auto& [name, value] : columns) {
    header.push_back(name);
    values.push_back(value);
  }
  kerf::write_file_atomically(csv, csv_text(header, {values}));
}

int run_predict_trepanning(const std::string& scene_path, const Json& document, const std::string& csv) {
  const kerf::TrepanningScene scene = kerf::parse_trepanning_scene(document);
  const kerf::TrepanningForces forces = kerf::trepanning_forces(scene.tool, scene.cut, scene.groups);
  std::FILE* text = text_stream(csv);
  fmt::print(text, "scene             {}\n", scene_path);
  fmt::print(text, "material          {} ({})\n", scene.material.name, scene.material.title);
  fmt::print(text, "force model       trepanning (seed 002 Eqs. 21-22, brittle regime)\n");
  fmt::print(text, "tool              outer diameter {:.6g} mm, inner diameter {:.6g} mm\n",
             kerf::units::m_to_mm(scene.tool.outer_diameter_m), kerf::units::m_to_mm(scene.tool.inner_diameter_m));
  fmt::print(text, "cut               feed rate {:.6g} um/s, spindle speed {:.6g} rpm ({:.6g} um/rev)\n",
             kerf::units::m_to_um(scene.cut.feed_rate_m_per_s), scene.cut.spindle_speed_rev_per_s * 60.0,
             kerf::units::m_to_um(forces.feed_per_rev_m));
  fmt::print(text, "axial force       {:.6g} N\n", forces.axial_force_N);
  fmt::print(text, "torque            {:.6g} N m\n", forces.torque_N_m);
  fmt::print(text,
             "lumped groups     K_F = H tan(phi) = {:.6g} MPa, K_M = H (1 + pi tan(phi) mu / 2) = {:.6g} MPa ({})\n",
             kerf::units::pa_to_mpa(scene.groups.axial_group_Pa), kerf::units::pa_to_mpa(scene.groups.torque_group_Pa),
             scene.groups_origin);
  const kerf::Columns columns = kerf::trepanning_columns(scene, forces);
  if (scene.grits) {
    const auto d = kerf::trepanning_grit_diagnostics(scene.tool, scene.cut, scene.groups, *scene.grits);
    fmt::print(text,
               "per grit          {:.4g} grits, {:.4g} cutting edges, depth {:.4g} nm, normal {:.4g} mN, tangential "
               "{:.4g} mN (Eqs. 1-20)\n",
               d.grit_count, d.cutting_edges, kerf::units::m_to_nm(d.grit_depth_m), 1e3 * d.grit_normal_force_N,
               1e3 * d.grit_tangential_force_N);
    for (const auto& [name, value] : columns) {
      if (name == "grit_regime" && !value.empty())
        fmt::print(text, "grit regime       {} (each grit's depth against d_c)\n", value);
    }
  }
  if (!csv.empty()) write_row_csv(csv, columns);
  return 0;
}

int run_predict(const std::string& scene_path, const std::vector<std::string>& overrides, const std::string& csv) {
  const Json document = load_scene_document(scene_path, overrides);
  if (kerf::is_trepanning_scene(document)) return run_predict_trepanning(scene_path, document, csv);
  const kerf::AnalyticScene scene = kerf::parse_analytic_scene(document);
  const kerf::Prediction prediction = kerf::predict(scene);
  print_prediction(text_stream(csv), scene_path, scene, prediction);
  if (!csv.empty()) write_row_csv(csv, kerf::prediction_columns(scene, prediction));
  return 0;
}

int run_regime(const std::string& scene_path, const std::vector<std::string>& overrides) {
  const Json document = load_scene_document(scene_path, overrides);
  if (kerf::is_trepanning_scene(document)) {
    fmt::print("{}: the trepanning model is a brittle-regime model (seed 002); the depth each grit cuts depends on "
               "the grit density, which the scene does not give\n", scene_path);
    return 0;
  }
  const kerf::AnalyticScene scene = kerf::parse_analytic_scene(document);
  const auto properties = kerf::brittle_properties(scene.material, "material");
  const double critical = kerf::critical_depth_m(properties);
  const double depth = scene.uncut_chip_thickness_m;
  const auto regime = kerf::classify_regime(depth, critical);
  fmt::print("material          {} (E = {:.4g} GPa, H = {:.4g} GPa, K_c = {:.4g} MPa m^0.5)\n", scene.material.name,
             kerf::units::pa_to_gpa(properties.youngs_modulus_Pa), kerf::units::pa_to_gpa(properties.hardness_Pa),
             kerf::units::pa_to_mpa(properties.fracture_toughness_Pa_sqrt_m));
  fmt::print("critical depth    d_c = 0.15 (E/H) (K_c/H)^2 = {:.4g} nm (Bifano, Dow & Scattergood 1991)\n",
             kerf::units::m_to_nm(critical));
  fmt::print("uncut thickness   {:.4g} nm ({:.3g} d_c)\n", kerf::units::m_to_nm(depth), depth / critical);
  fmt::print("regime            {}\n", kerf::cutting_regime_name(regime));
  switch (regime) {
    case kerf::CuttingRegime::ductile:
      fmt::print("model to use      the ductile-regime analytic models (merchant, liu_li, oxley)\n");
      break;
    case kerf::CuttingRegime::transition:
      fmt::print("model to use      neither cleanly (d_c to 3 d_c): the ductile models overestimate the chip's "
                 "integrity, the DEM resolves the cracks (kerf-dem)\n");
      break;
    case kerf::CuttingRegime::brittle:
      fmt::print("model to use      the DEM (kerf-dem) for cutting, or the trepanning model for abrasive drilling\n");
      break;
  }
  return 0;
}

int run_compare(const std::string& scene_path, const std::vector<std::string>& overrides,
                const std::string& experiments, const std::vector<std::string>& mappings, bool fit, bool pool,
                std::optional<double> measured_width_mm, const std::string& out_dir) {
  const Json document = load_scene_document(scene_path, overrides);
  kerf::SceneComparisonOptions options;
  options.mappings = mappings;
  options.fit = fit;
  options.pool = pool;
  options.measured_width_mm = measured_width_mm;
  kerf::SceneComparison result = kerf::compare_scene(document, experiments, options);
  result.comparison.spec.description = fmt::format("Scene {} against {}.", scene_path, experiments);
  const auto files = kerf::write_report(result.comparison, out_dir, result.report);
  for (const auto& r : result.comparison.results) {
    fmt::print("{:<28} n = {:<3} mean |error| {:6.2f} %   max |error| {:6.2f} %   bias {:+6.2f} %\n", r.key,
               r.metrics.n, r.metrics.mean_abs_error_percent, r.metrics.max_abs_error_percent, r.metrics.bias_percent);
  }
  if (result.calibration) {
    const auto& c = *result.calibration;
    fmt::print("fitted            K_F = {:.6g} MPa (leave-one-out mean |error| {:.2f} %), K_M = {:.6g} MPa "
               "(leave-one-out {:.2f} %)\n",
               kerf::units::pa_to_mpa(c.axial.value_Pa), c.axial.loo.mean_abs_error_percent,
               kerf::units::pa_to_mpa(c.torque.value_Pa), c.torque.loo.mean_abs_error_percent);
  }
  if (!result.unused_columns.empty()) {
    fmt::print("unused columns    {} (neither a condition nor a quantity; --map binds them)\n",
               fmt::join(result.unused_columns, ", "));
  }
  for (const auto& row : result.rows) {
    if (row.guards.empty() && (row.regime.empty() || row.regime == "ductile")) continue;
    fmt::print("line {:<12} regime {}, guards {}\n", row.line, row.regime.empty() ? "-" : row.regime,
               row.guards.empty() ? "none" : row.guards);
  }
  fmt::print("report            {} ({} files)\n", out_dir, files.size());
  return 0;
}

int run_report(const std::string& config_path, const std::string& out_dir) {
  const kerf::Comparison comparison = kerf::run_comparison(kerf::read_comparison_config(config_path));
  const auto files = kerf::write_report(comparison, out_dir);
  for (const auto& r : comparison.results) {
    fmt::print("{:<28} n = {:<3} mean |error| {:7.2f} %   max |error| {:7.2f} %   bias {:+7.2f} %\n", r.key,
               r.metrics.n, r.metrics.mean_abs_error_percent, r.metrics.max_abs_error_percent, r.metrics.bias_percent);
  }
  fmt::print("report            {} ({} files)\n", out_dir, files.size());
  return 0;
}

struct Axis {
  std::string path;
  std::vector<double> values;
  bool log_spacing = false;  ///< START:STOP:COUNT:log (the figure then draws this axis logarithmically)
};

Axis parse_axis(const std::string& spec) {
  const auto fail = [&](const std::string& why) { throw kerf::InputError("--vary", spec, why); };
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0) fail("key.path=START:STOP:COUNT[:log] or key.path=A,B,C");
  Axis axis{spec.substr(0, eq), {}};
  std::vector<std::string> parts;
  std::string rest = spec.substr(eq + 1);
  if (rest.find(':') == std::string::npos) {  // a list of values: A,B,C
    for (std::size_t start = 0; start <= rest.size();) {
      const std::size_t comma = std::min(rest.find(',', start), rest.size());
      double value = 0.0;
      if (!kerf::parse_number(std::string_view(rest).substr(start, comma - start), value)) {
        fail("a list of numbers A,B,C (or START:STOP:COUNT[:log])");
      }
      axis.values.push_back(value);
      start = comma + 1;
    }
    return axis;
  }
  for (std::size_t start = 0;;) {
    const auto colon = rest.find(':', start);
    parts.push_back(rest.substr(start, colon == std::string::npos ? std::string::npos : colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts.size() < 3 || parts.size() > 4 || (parts.size() == 4 && parts[3] != "log" && parts[3] != "lin")) {
    fail("START:STOP:COUNT with an optional :log or :lin");
  }
  double start = 0, stop = 0;
  long count = 0;
  try {
    std::size_t used = 0;
    start = std::stod(parts[0], &used);
    if (used != parts[0].size()) fail("a number for START");
    stop = std::stod(parts[1], &used);
    if (used != parts[1].size()) fail("a number for STOP");
    count = std::stol(parts[2], &used);
    if (used != parts[2].size()) fail("an integer COUNT");
  } catch (const std::logic_error&) {
    fail("numbers in START:STOP:COUNT");
  }
  if (!std::isfinite(start) || !std::isfinite(stop)) fail("finite START and STOP");
  if (count < 1 || count > 10'000'000) fail("COUNT in [1, 10000000]");
  const bool log_spacing = parts.size() == 4 && parts[3] == "log";
  axis.log_spacing = log_spacing;
  if (log_spacing && !(start > 0 && stop > 0)) fail("positive START and STOP for :log spacing");
  for (long i = 0; i < count; ++i) {
    const double f = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
    // Rounded to 15 significant digits: 0.05, not 0.049999999999999996, for a grid from 0.01 in steps of 0.01.
    const double value = log_spacing ? start * std::pow(stop / start, f) : start + (stop - start) * f;
    if (!std::isfinite(value)) fail("START and STOP whose difference is finite");
    axis.values.push_back(std::stod(fmt::format("{:.15g}", value)));
  }
  return axis;
}

/// The sweep's figure: cutting (solid) and thrust (dashed) force against the first varied key, one colour per
/// value of the second (the first 6 of them; further keys at their first value), refused points left out; the
/// axes labelled from the keys' unit suffixes, the material, scene and width in the title and y label, the
/// legend (a row per colour and one per line style) beside the plot. PNG with a PDF beside it.
void plot_sweep(const std::string& path, const std::string& scene_path, const Json& base,
                kerf::MaterialCache& materials, const std::vector<std::string>& axis_paths,
                const std::vector<std::vector<double>>& axis_values, const std::vector<std::string>& names,
                const std::function<std::vector<double>(std::size_t)>& coordinates,
                const std::function<const std::vector<std::string>*(std::size_t)>& row_values, std::size_t n_points,
                bool x_log) {
  kerf::FigureSpec fig;
  fig.x_log = x_log;
  fig.x_label = kerf::key_label(axis_paths[0]);
  std::string material;
  try {
    const auto& record = materials.get(base.at("material"), "material");
    // The title, where it fits the figure's width beside the scene's file name; else the library name.
    material = record.title.empty() || record.title.size() > 40 ? record.name : record.title;
  } catch (const std::exception&) {
    material = "material?";  // the scene's own errors are the sweep's to report, not the figure's
  }
  fig.title = fmt::format("{}: {}", material, std::filesystem::path(scene_path).filename().string());
  // The width the forces are for: the scene's, stated; per mm of width where the width is swept.
  const auto width_axis =
      static_cast<std::size_t>(std::find(axis_paths.begin(), axis_paths.end(), "cut.width_mm") - axis_paths.begin());
  const Json* width = nullptr;
  if (base.contains("cut") && base["cut"].is_object() && base["cut"].contains("width_mm")) width = &base["cut"]["width_mm"];
  const bool per_mm = width_axis < axis_paths.size();
  if (per_mm) {
    fig.y_label = "force per mm of width (N/mm)";
  } else if (width && width->is_number()) {
    fig.y_label = fmt::format("force for a width of {:g} mm (N)", width->get<double>());
  } else {
    fig.y_label = "force for the cut's engaged width (N)";
  }
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  // Colours 0-4 and 6: grey (5) is the line-style key's.
  constexpr std::array<int, 6> kColors = {0, 1, 2, 3, 4, 6};
  const std::size_t n_second = axis_values.size() > 1 ? std::min<std::size_t>(kColors.size(), axis_values[1].size()) : 1;
  std::vector<kerf::PlotSeries> keys;
  for (std::size_t k = 0; k < n_second; ++k) {
    bool drawn = false;
    for (const auto& [name, dashed] : {std::pair{std::string("cutting_force_N"), false}, std::pair{std::string("thrust_force_N"), true}}) {
      const std::size_t c = column(name);
      if (c == names.size()) continue;
      kerf::PlotSeries series;
      series.style = dashed ? kerf::SeriesStyle::dashed_line : kerf::SeriesStyle::line;
      series.color = kColors[k];
      for (std::size_t i = 0; i < n_points; ++i) {
        const auto x = coordinates(i);
        if (axis_values.size() > 1 && x[1] != axis_values[1][k]) continue;
        bool first_of_the_rest = true;  // further axes: their first value
        for (std::size_t a = 2; a < axis_values.size(); ++a) first_of_the_rest = first_of_the_rest && x[a] == axis_values[a][0];
        if (!first_of_the_rest) continue;
        const auto* values = row_values(i);
        if (!values || values->at(c).empty()) continue;  // refused
        series.x.push_back(x[0]);
        series.y.push_back(std::stod(values->at(c)) / (per_mm ? x[width_axis] : 1.0));
      }
      if (series.x.empty()) continue;
      drawn = true;
      fig.series.push_back(std::move(series));
    }
    if (drawn && axis_values.size() > 1) {
      const std::string label = kerf::key_label(axis_paths[1]);
      const auto open = label.rfind(" (");
      kerf::PlotSeries key;
      key.label = open == std::string::npos
                      ? fmt::format("{} = {:g}", label, axis_values[1][k])
                      : fmt::format("{} = {:g} {}", label.substr(0, open), axis_values[1][k],
                                    label.substr(open + 2, label.size() - open - 3));
      key.style = kerf::SeriesStyle::line;
      key.color = kColors[k];
      key.legend_only = true;
      keys.push_back(std::move(key));
    }
  }
  if (fig.series.empty()) throw kerf::InputError("--plot", path, "a sweep with cutting_force_N or thrust_force_N values");
  for (const auto& [label, dashed] : {std::pair{"cutting force", false}, std::pair{"thrust force", true}}) {
    kerf::PlotSeries key;
    key.label = label;
    key.style = dashed ? kerf::SeriesStyle::dashed_line : kerf::SeriesStyle::line;
    key.color = 5;
    key.legend_only = true;
    keys.push_back(std::move(key));
  }
  fig.series.insert(fig.series.end(), keys.begin(), keys.end());
  fig.legend_position = "outside_right";
  kerf::render_png(fig, path);
}

int run_sweep(const std::string& scene_path, const std::vector<std::string>& overrides,
              const std::vector<std::string>& vary_specs, const std::string& csv, const std::string& plot) {
  const Json base = load_scene_document(scene_path, overrides);
  std::vector<Axis> axes;
  std::size_t n_points = 1;
  for (const auto& spec : vary_specs) {
    axes.push_back(parse_axis(spec));
    n_points *= axes.back().values.size();
    if (n_points > 50'000'000) throw kerf::InputError("--vary", spec, "a grid of at most 50 million points");
  }
  kerf::MaterialCache materials;

  // The column set depends only on the models the scene asks for: take the names from the unvaried scene.
  const std::vector<std::string> names = kerf::scene_column_names(base, &materials);
  // A key the scene does not read would refuse every point: an input error now, not a CSV of errors.
  for (const auto& axis : axes) {
    kerf::check_varied_key(base, fmt::format("{}={}", axis.path, axis.values[0]), "--vary", &materials);
  }

  struct Row {
    std::vector<std::string> values;
    std::string error;
  };
  std::vector<Row> rows(n_points);
  const auto coordinates = [&](std::size_t index) {
    std::vector<double> x(axes.size());
    for (std::size_t a = axes.size(); a-- > 0;) {
      x[a] = axes[a].values[index % axes[a].values.size()];
      index /= axes[a].values.size();
    }
    return x;
  };

  kerf::Progress progress("sweep", n_points);
  constexpr std::size_t kChunk = 4096;
  for (std::size_t begin = 0; begin < n_points; begin += kChunk) {
    const std::size_t end = std::min(n_points, begin + kChunk);
#pragma omp parallel for schedule(dynamic, 64)
    for (std::size_t i = begin; i < end; ++i) {
      Json document = base;
      const auto x = coordinates(i);
      try {
        for (std::size_t a = 0; a < axes.size(); ++a) {
          kerf::apply_override(document, fmt::format("{}={}", axes[a].path, x[a]), "--vary");
        }
        for (auto& column : kerf::evaluate_scene_columns(document, &materials)) {
          rows[i].values.push_back(std::move(column.second));
        }
        if (rows[i].values.size() != names.size()) rows[i] = {{}, "internal: the column set changed"};
      } catch (const std::exception& e) {
        rows[i].error = e.what();
      } catch (...) {  // nothing may leave the parallel region
        rows[i].error = "internal: an unknown exception";
      }
    }
    progress.advance(end - begin);
  }
  progress.finish();
  std::size_t n_failed = 0;
  for (const auto& row : rows) n_failed += row.error.empty() ? 0 : 1;

  std::vector<std::string> header;
  for (const auto& axis : axes) header.push_back(kerf::csv_escape(axis.path));
  header.insert(header.end(), names.begin(), names.end());
  header.push_back("error");
  std::string text = kerf::csv_line(header);
  for (std::size_t i = 0; i < n_points; ++i) {
    std::vector<std::string> fields;
    for (double x : coordinates(i)) fields.push_back(kerf::csv_number(x));
    if (rows[i].error.empty()) {
      fields.insert(fields.end(), rows[i].values.begin(), rows[i].values.end());
    } else {
      fields.resize(fields.size() + names.size());
    }
    fields.push_back(kerf::csv_escape(rows[i].error));
    text += kerf::csv_line(fields);
  }
  kerf::write_file_atomically(csv, text);
  if (!plot.empty()) {
    std::vector<std::string> paths;
    std::vector<std::vector<double>> values;
    for (const auto& axis : axes) paths.push_back(axis.path), values.push_back(axis.values);
    plot_sweep(plot, scene_path, base, materials, paths, values, names, coordinates,
               [&](std::size_t i) { return rows[i].error.empty() ? &rows[i].values : nullptr; }, n_points,
               axes[0].log_spacing);
  }
  fmt::print(stderr, "kerf-forces: {} points written to {} ({} refused with an error, see the 'error' column)\n",
             n_points, csv, n_failed);

  // A force that falls as the chip thickens is a model that switched branch or left its domain (issue 22): say
  // so, with the first place it happens, for each force column along a varied uncut chip thickness.
  for (std::size_t a = 0; a < axes.size(); ++a) {
    if (axes[a].path != "cut.uncut_chip_thickness_um") continue;
    std::size_t stride = 1;
    for (std::size_t b = a + 1; b < axes.size(); ++b) stride *= axes[b].values.size();
    const std::size_t n_h = axes[a].values.size();
    for (const char* force : {"cutting_force_N", "thrust_force_N"}) {
      const auto column = std::find(names.begin(), names.end(), force);
      if (column == names.end()) continue;
      const auto c = static_cast<std::size_t>(column - names.begin());
      std::vector<std::optional<double>> values(n_points);
      for (std::size_t i = 0; i < n_points; ++i) {
        if (rows[i].error.empty()) values[i] = std::stod(rows[i].values[c]);
      }
      const std::vector<std::size_t> falls = kerf::falling_points(values, stride, n_h);
      const std::size_t n_falls = falls.size();
      std::string first;
      if (!falls.empty()) {
        const std::size_t i = falls.front(), j = i - stride;
        first = fmt::format("{:.6g} N at {:.6g} um to {:.6g} N at {:.6g} um", *values[j], coordinates(j)[a], *values[i],
                            coordinates(i)[a]);
      }
      if (n_falls > 0) {
        fmt::print(stderr,
                   "kerf-forces: warning: {} falls as cut.uncut_chip_thickness_um grows at {} point(s), first from {}: "
                   "the model may have changed branch or left its domain there\n",
                   force, n_falls, first);
      }
    }
  }
  return 0;
}

int list_models() {
  for (const auto& m : kerf::analytic_models()) {
    fmt::print("models.{:<17} {:<17} {}{}\n", m.kind, m.name, m.summary, m.needs.empty() ? "" : fmt::format(" [needs {}]", m.needs));
  }
  return 0;
}

int list_materials() {
  for (const auto& name : kerf::library_material_names()) {
    try {
      const auto record = kerf::load_material(Json(name), "material");
      std::string groups;
      for (const auto& [group, values] : record.groups.items()) groups += (groups.empty() ? "" : ", ") + group;
      fmt::print("{:<20} {} [{}]\n", name, record.title, groups);
    } catch (const kerf::InputError& e) {
      fmt::print("{:<20} (invalid: {})\n", name, e.what());
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"kerf-forces: analytic cutting-force predictions (ductile regime) and sweeps"};
  app.require_subcommand(1);
  app.set_version_flag("--version", kerf::version_line("kerf-forces"));
  std::string scene_path, csv, plot;
  std::vector<std::string> overrides, vary;
  int threads = 0;

  auto* predict = app.add_subcommand("predict", "predict the forces of one scene");
  predict->add_option("scene", scene_path, "scene file (JSON)")->required();
  predict->add_option("--set", overrides, "override a scene value: key.path=value (repeatable)");
  predict->add_option("--csv", csv, "also write the result as one CSV row to this file");

  auto* sweep = app.add_subcommand("sweep", "evaluate a grid of scenes (cartesian product of --vary axes)");
  sweep->add_option("scene", scene_path, "scene file (JSON)")->required();
  sweep->add_option("--set", overrides, "override a scene value: key.path=value (repeatable)");
  sweep->add_option("--vary", vary, "an axis: key.path=START:STOP:COUNT[:log] or key.path=A,B,C (repeatable)")->required();
  sweep->add_option("--csv", csv, "CSV file to write")->required();
  sweep->add_option("--plot", plot, "also a figure (PNG, with a PDF beside it): cutting and thrust force against the "
                                    "first varied key, a line per value of the second");
  sweep->add_option("--threads", threads, "threads (default: all cores)")->check(CLI::Range(1, 1024));

  std::string experiments, out_dir;
  std::vector<std::string> mappings;
  bool fit = false, pool = false;
  std::optional<double> measured_width_mm;
  auto* compare = app.add_subcommand("compare", "hold a scene against measured forces: report.md, CSV, JSON, plots");
  compare->add_option("scene", scene_path, "scene file (JSON)")->required();
  compare->add_option("--set", overrides, "override a scene value: key.path=value (repeatable)");
  compare->add_option("--experiments", experiments, "experiment CSV ('#' lines are its citation)")->required();
  compare->add_option("--map", mappings,
                      "bind a CSV column: scene.key.path=column (a condition) or prediction_column=column");
  compare->add_flag("--fit", fit, "fit the trepanning model's lumped groups to the measured rows first");
  compare->add_flag("--pool", pool,
                    "compare a CSV none of whose columns sets a condition: every row a measurement at the scene's own "
                    "condition (without it such a CSV is refused)");
  compare->add_option("--measured-width-mm", measured_width_mm, "width the measured forces act over (mm)")
      ->check(CLI::PositiveNumber);
  compare->add_option("--out", out_dir, "directory for the report")->required();

  std::string config_path;
  auto* report = app.add_subcommand("report", "compare CSV data sets described in a comparison file (JSON)");
  report->add_option("comparison", config_path, "comparison file (JSON), e.g. data/comparisons/*.json")->required();
  report->add_option("--out", out_dir, "directory for the report")->required();

  auto* regime = app.add_subcommand("regime", "ductile-brittle critical depth and the regime of the scene's cut");
  regime->add_option("scene", scene_path, "scene file (JSON)")->required();
  regime->add_option("--set", overrides, "override a scene value: key.path=value (repeatable)");

  auto* models = app.add_subcommand("models", "list the registered models");
  auto* materials = app.add_subcommand("materials", "list the bundled material library");

  const auto error = [](const std::string& what, int status) {
    fmt::print(stderr, "kerf-forces: error: {}\n", kerf::printable(what));
    return status;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    return error(e.what(), kerf::kExitInputError);
  }
  try {
    if (threads > 0) omp_set_num_threads(threads);
    // The outputs are checked before any work: an unwritable place fails now, not after the sweep.
    for (const auto* command : {predict, sweep}) {
      if (*command && command->count("--csv") > 0) {
        if (csv.empty()) throw kerf::InputError("--csv", "\"\"", "a file name (leave --csv out for no CSV)");
        kerf::check_writable_file(csv);
      }
    }
    if ((*compare || *report) && out_dir.empty()) throw kerf::InputError("--out", "\"\"", "a directory name");
    if (*compare || *report) kerf::check_writable_directory(out_dir);
    if (*predict) return run_predict(scene_path, overrides, csv);
    if (*sweep) return run_sweep(scene_path, overrides, vary, csv, plot);
    if (*compare)
      return run_compare(scene_path, overrides, experiments, mappings, fit, pool, measured_width_mm, out_dir);
    if (*regime) return run_regime(scene_path, overrides);
    if (*report) return run_report(config_path, out_dir);
    if (*models) return list_models();
    if (*materials) return list_materials();
  } catch (const std::exception&) {
    return kerf::report_error("kerf-forces");
  }
  return 0;
}
