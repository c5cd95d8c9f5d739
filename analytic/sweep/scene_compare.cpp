#include "kerf/analytic/sweep/scene_compare.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>

#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/trepanning/trepanning.hpp"
#include "kerf/analytic/trepanning/trepanning_results.hpp"
#include "kerf/analytic/trepanning/trepanning_scene.hpp"
#include "kerf/comparison_config.hpp"
#include "kerf/csv_table.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

// Prediction columns that can be compared with measurements, and their units.
const std::map<std::string, std::string>& comparable_quantities() {
  static const std::map<std::string, std::string> quantities = {{std::string(prediction_keys::cutting_force_N), "N"},
                                                                {std::string(prediction_keys::thrust_force_N), "N"},
                                                                {std::string(trepanning_keys::axial_force_N), "N"},
                                                                {std::string(trepanning_keys::torque_N_m), "N m"}};
  return quantities;
}

/// A unit a key or column name ends with, and what it measures ("_um" is a length in um).
struct UnitSuffix {
  std::string suffix, unit, dimension;
};
const std::vector<UnitSuffix>& unit_suffixes() {
  // Longer suffixes first: "_um_per_s" before "_um", "_N_m" before "_N".
  static const std::vector<UnitSuffix> suffixes = {{"_um_per_s", "um/s", "speed"},
                                                   {"_mm_per_s", "mm/s", "speed"},
                                                   {"_m_per_s", "m/s", "speed"},
                                                   {"_um_s", "um/s", "speed"},
                                                   {"_mm_s", "mm/s", "speed"},
                                                   {"_m_per_min", "m/min", "speed"},
                                                   {"_rpm", "rpm", "rotation speed"},
                                                   {"_deg", "deg", "angle"},
                                                   {"_nm", "nm", "length"},
                                                   {"_um", "um", "length"},
                                                   {"_mm", "mm", "length"},
                                                   {"_N_m", "N m", "torque"},
                                                   {"_Nm", "N m", "torque"},
                                                   {"_kN", "kN", "force"},
                                                   {"_mN", "mN", "force"},
                                                   {"_N", "N", "force"}};
  return suffixes;
}

/// The unit suffix a key or column name ends with; nullptr when none is known.
const UnitSuffix* find_unit_suffix(const std::string& key) {
  for (const auto& u : unit_suffixes()) {
    if (key.size() > u.suffix.size() && key.ends_with(u.suffix)) return &u;
  }
  return nullptr;
}

/// The unit a key's suffix names ("feed_rate_um_per_s" -> um/s) and the key without it.
std::pair<std::string, Unit> split_unit(const std::string& key, const std::string& path) {
  if (const UnitSuffix* u = find_unit_suffix(key)) {
    return {key.substr(0, key.size() - u->suffix.size()), unit_named(u->unit, path)};
  }
  return {key, unit_named("", path)};
}

/// The unit of a CSV column bound to a scene key or prediction column `key`: the column's own suffix when it
/// names a unit of the same kind (the values are converted), the key's when the column names none. A column
/// whose suffix names another kind of unit is refused.
Unit column_unit(const std::string& key, const std::string& column, const std::string& mapping,
                 std::vector<std::string>& notes) {
  const UnitSuffix* key_unit = find_unit_suffix(key);
  const UnitSuffix* column_suffix = find_unit_suffix(column);
  if (!column_suffix || !key_unit) {
    if (key_unit && column != key) {
      notes.push_back(
          fmt::format("CSV column {} names no unit: taken in {}, the unit of {}", column, key_unit->unit, key));
    }
    return split_unit(key, "--map").second;
  }
  if (column_suffix->dimension != key_unit->dimension) {
    throw InputError(
        "--map", mapping,
        fmt::format("a CSV column in a unit of {} like {}'s {} (the column's name says {}, a unit of {})",
                    key_unit->dimension, key, key_unit->unit, column_suffix->unit, column_suffix->dimension));
  }
  if (column_suffix->unit != key_unit->unit) {
    notes.push_back(fmt::format("CSV column {} converted from {} to {}, the unit of {}", column, column_suffix->unit,
                                key_unit->unit, key));
  }
  return unit_named(column_suffix->unit, "--map");
}

struct ConditionBinding {
  std::string scene_path;  ///< "cut.feed_rate_um_per_s"
  std::string column;      ///< CSV column
  Unit unit;               ///< the column's
};
struct QuantityBinding {
  std::string prediction_column;  ///< the prediction's column (trepanning_keys::axial_force_N, ...)
  std::string column;             ///< CSV column
  Unit unit;                      ///< the column's
};

/// Leaves of the scene's tool and cut objects (and cut.turning), by name.
std::map<std::string, std::string> scene_condition_keys(const Json& document) {
  std::map<std::string, std::string> keys;
  for (const char* group : {"tool", "cut"}) {
    const auto it = document.find(group);
    if (it == document.end() || !it->is_object()) continue;
    for (const auto& [key, value] : it->items()) {
      if (value.is_number()) keys[key] = std::string(group) + "." + key;
      if (value.is_object()) {
        for (const auto& [inner, inner_value] : value.items()) {
          if (inner_value.is_number()) keys[inner] = std::string(group) + "." + key + "." + inner;
        }
      }
    }
  }
  return keys;
}

/// "feed_rate" -> "Feed rate": plot and table labels.
std::string label_of(const std::string& key) {
  std::string label = key;
  std::replace(label.begin(), label.end(), '_', ' ');
  if (!label.empty()) label[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(label[0])));
  return label;
}

void set_path(Json& document, const std::string& path, double value) {
  apply_override(document, fmt::format("{}={}", path, value), "--experiments");
}

double column_value(const Columns& columns, const std::string& name) {
  for (const auto& [column, value] : columns) {
    if (column == name) {
      double x = 0.0;
      if (!parse_number(value, x)) throw ModelError("compare", fmt::format("prediction column {} is empty", name));
      return x;
    }
  }
  throw ModelError("compare", fmt::format("the scene predicts no column {}", name));
}

}  // namespace

namespace {

/// The CSV's columns bound to scene conditions and predicted quantities.
struct Bindings {
  std::vector<ConditionBinding> conditions;
  std::vector<QuantityBinding> quantities;
};

/// Explicit mappings first, then columns matched by name; the columns left unused go to out.unused_columns and a
/// note. No quantity, or no condition without --pool, is an InputError.
Bindings bind_columns(const CsvTable& table, const Json& scene_document, const std::filesystem::path& experiments_csv,
                      const SceneComparisonOptions& options, const std::vector<std::string>& predicted_names,
                      SceneComparison& out) {
  const auto has_prediction = [&](const std::string& name) {
    return std::find(predicted_names.begin(), predicted_names.end(), name) != predicted_names.end();
  };
  std::vector<ConditionBinding> conditions;
  std::vector<QuantityBinding> quantities;
  std::vector<std::string> bound_columns;
  for (const auto& mapping : options.mappings) {
    const auto eq = mapping.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == mapping.size()) {
      throw InputError("--map", mapping, "scene.key.path=csv_column or prediction_column=csv_column");
    }
    const std::string left = mapping.substr(0, eq), column = mapping.substr(eq + 1);
    table.column_index(column);  // InputError listing the columns when absent
    if (left.find('.') != std::string::npos) {
      const std::string leaf = left.substr(left.rfind('.') + 1);
      conditions.push_back({left, column, column_unit(leaf, column, mapping, out.notes)});
    } else {
      if (!comparable_quantities().contains(left) || !has_prediction(left)) {
        std::vector<std::string> valid;
        for (const auto& [name, unit] : comparable_quantities())
          if (has_prediction(name)) valid.push_back(name);
        throw InputError("--map", left, "a prediction column of this scene: " + describe_choices(left, valid));
      }
      quantities.push_back({left, column, column_unit(left, column, mapping, out.notes)});
    }
    bound_columns.push_back(column);
  }
  const auto scene_keys = scene_condition_keys(scene_document);
  for (const auto& column : table.header) {
    if (std::find(bound_columns.begin(), bound_columns.end(), column) != bound_columns.end()) continue;
    if (comparable_quantities().contains(column) && has_prediction(column)) {
      quantities.push_back({column, column, unit_named(comparable_quantities().at(column), "--experiments")});
    } else if (auto it = scene_keys.find(column); it != scene_keys.end() && column != "width_mm") {
      conditions.push_back({it->second, column, split_unit(column, "--experiments").second});
    }
  }
  for (const auto& q : quantities) bound_columns.push_back(q.column);
  for (const auto& c : conditions) bound_columns.push_back(c.column);
  for (const auto& column : table.header) {
    if (column == "width_mm" || std::find(bound_columns.begin(), bound_columns.end(), column) != bound_columns.end()) {
      continue;
    }
    out.unused_columns.push_back(column);
  }
  if (!out.unused_columns.empty()) {
    out.notes.push_back(fmt::format("CSV columns not used (neither a condition nor a quantity; --map binds them): {}",
                                    fmt::join(out.unused_columns, ", ")));
  }
  if (quantities.empty()) {
    throw InputError("--experiments", experiments_csv.string(),
                     "a column named like a prediction (cutting_force_N, thrust_force_N, axial_force_N, torque_N_m) "
                     "or --map prediction_column=csv_column");
  }
  if (conditions.empty() && !options.pool) {
    // Every row would be taken at the scene's own condition, as replicates of one measurement: say so, unasked.
    std::vector<std::string> keys;
    for (const auto& [name, path] : scene_condition_keys(scene_document))
      if (name != "width_mm") keys.push_back(name);
    throw InputError(
        "--experiments", experiments_csv.string(),
        fmt::format("a column that sets a condition: named like a key of the scene's tool or cut ({}) or "
                    "bound by --map scene.key.path=column; none matched ({}; --pool, in Python pool=True, "
                    "takes every row as a measurement at the scene's own condition)",
                    fmt::join(keys, ", "),
                    out.unused_columns.empty() ? std::string("the CSV has no other column")
                                               : fmt::format("unused: {}", fmt::join(out.unused_columns, ", "))));
  }
  return {std::move(conditions), std::move(quantities)};
}

/// The comparison's conditions and quantities in their units (into out.comparison.spec) and the measured rows,
/// with their width bases explicit (both views where the measured and the scene's widths differ).
DataSet measured_data(const CsvTable& table, const Bindings& bindings, const std::filesystem::path& experiments_csv,
                      const SceneComparisonOptions& options, const AnalyticCase& kind, SceneComparison& out) {
  const auto& [conditions, quantities] = bindings;
  // Forces that scale with a width (orthogonal cutting's; not trepanning's axial force and torque).
  const std::optional<double> force_width_m = kind.force_width_m();
  const bool per_width = force_width_m.has_value();
  ComparisonSpec& spec = out.comparison.spec;
  spec.title = fmt::format("{} against {}", kind.comparison_title(), experiments_csv.filename().string());
  CsvBinding measured_binding;
  measured_binding.name = experiments_csv.filename().string();
  for (const auto& c : conditions) {
    const auto [key, unit] = split_unit(c.scene_path.substr(c.scene_path.rfind('.') + 1), "--map");
    spec.conditions.push_back({key, label_of(key), unit, true});
    measured_binding.condition_columns.push_back(c.column);
    measured_binding.condition_si.push_back(c.unit.si);
    out.notes.push_back(fmt::format("condition {} <- CSV column {}", c.scene_path, c.column));
  }
  const double scene_width_m = force_width_m.value_or(0.0);
  WidthBasis measured_basis = WidthBasis::total(scene_width_m);
  if (table.has_column("width_mm")) {
    measured_binding.width_column_mm = "width_mm";
    out.notes.push_back("measured forces act over the width in the CSV column width_mm");
  } else if (options.measured_width_mm) {
    measured_basis = WidthBasis::total(*options.measured_width_mm * 1e-3);
    out.notes.push_back(
        fmt::format("measured forces act over {} mm (--measured-width-mm)", *options.measured_width_mm));
  } else if (per_width) {
    out.notes.push_back(
        fmt::format("measured forces assumed to act over the scene's width, {} mm (the CSV has no "
                    "width_mm column; set --measured-width-mm otherwise)",
                    units::m_to_mm(scene_width_m)));
  }
  for (const auto& q : quantities) {
    const auto [key, unit] = split_unit(q.prediction_column, "--map");
    spec.quantities.push_back({key, label_of(key), unit});
    measured_binding.quantity_columns.push_back(q.column);
    measured_binding.quantity_si.push_back(q.unit.si);
    const bool force = unit.suffix == "N" && per_width;
    measured_binding.bases.push_back(force ? measured_basis : WidthBasis::none());
    out.notes.push_back(fmt::format("quantity {} <- CSV column {}", q.prediction_column, q.column));
  }
  DataSet measured = dataset_from_csv(table, spec, measured_binding);
  const bool widths_differ = per_width && (!measured_binding.width_column_mm.empty() ||
                                           std::abs(measured_basis.width_m - scene_width_m) > 1e-12 * scene_width_m);
  if (widths_differ) spec.views = {WidthView::as_published, WidthView::per_unit_width};
  return measured;
}

/// --fit: a trepanning scene's two lumped groups fitted to the measured rows (out.calibration, the report's
/// calibration section and summary); the groups are written into `document`.
void fit_lumped_groups(Json& document, const Bindings& bindings, const DataSet& measured,
                       const std::filesystem::path& experiments_csv, MaterialCache& materials, SceneComparison& out) {
  const auto& [conditions, quantities] = bindings;
  const ComparisonSpec& spec = out.comparison.spec;
  const TrepanningScene scene = parse_trepanning_scene(document, &materials);
  std::vector<TrepanningObservation> observations;
  const auto axial = std::find_if(quantities.begin(), quantities.end(),
                                  [](const auto& q) { return q.prediction_column == trepanning_keys::axial_force_N; });
  const auto torque = std::find_if(quantities.begin(), quantities.end(),
                                   [](const auto& q) { return q.prediction_column == trepanning_keys::torque_N_m; });
  if (axial == quantities.end() || torque == quantities.end()) {
    throw InputError("--fit", experiments_csv.string(), "measured axial_force_N and torque_N_m columns to fit");
  }
  // The measured rows hold SI values (each column converted from its unit): back to the scene keys' units.
  const auto axial_index = static_cast<std::size_t>(axial - quantities.begin());
  const auto torque_index = static_cast<std::size_t>(torque - quantities.begin());
  for (const auto& row : measured.rows) {
    Json row_document = document;
    for (std::size_t i = 0; i < conditions.size(); ++i) {
      set_path(row_document, conditions[i].scene_path, row.conditions[i].si.value_or(0.0) / spec.conditions[i].unit.si);
    }
    const TrepanningScene row_scene = parse_trepanning_scene(row_document, &materials);
    observations.push_back({row_scene.cut, row.values[axial_index], row.values[torque_index]});
  }
  out.calibration = calibrate_trepanning(scene.tool, observations);
  const auto& fit = *out.calibration;
  document["models"]["trepanning"] = {{"axial_group_MPa", units::pa_to_mpa(fit.groups.axial_group_Pa)},
                                      {"torque_group_MPa", units::pa_to_mpa(fit.groups.torque_group_Pa)}};
  out.report.extra_markdown = fmt::format(
      "## Calibration (--fit)\n\nRelative least squares (GSL) of the two lumped groups on {} rows:\n\n"
      "| group | value (MPa) | std. error (MPa) | mean abs error % | max abs error % | bias % | "
      "leave-one-out mean abs % | leave-one-out max abs % |\n|---|---|---|---|---|---|---|---|\n"
      "| K_F = H tan(phi) | {:.1f} | {:.1f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |\n"
      "| K_M = H (1 + pi tan(phi) mu / 2) | {:.1f} | {:.1f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |\n",
      observations.size(), units::pa_to_mpa(fit.axial.value_Pa), units::pa_to_mpa(fit.axial.standard_error_Pa),
      fit.axial.fit.mean_abs_error_percent, fit.axial.fit.max_abs_error_percent, fit.axial.fit.bias_percent,
      fit.axial.loo.mean_abs_error_percent, fit.axial.loo.max_abs_error_percent, units::pa_to_mpa(fit.torque.value_Pa),
      units::pa_to_mpa(fit.torque.standard_error_Pa), fit.torque.fit.mean_abs_error_percent,
      fit.torque.fit.max_abs_error_percent, fit.torque.fit.bias_percent, fit.torque.loo.mean_abs_error_percent,
      fit.torque.loo.max_abs_error_percent);
  out.report.extra_summary["fit"] = {{"axial_group_MPa", units::pa_to_mpa(fit.axial.value_Pa)},
                                     {"torque_group_MPa", units::pa_to_mpa(fit.torque.value_Pa)},
                                     {"axial_force",
                                      {{"mean_abs_error_percent", fit.axial.fit.mean_abs_error_percent},
                                       {"loo_mean_abs_error_percent", fit.axial.loo.mean_abs_error_percent},
                                       {"loo_max_abs_error_percent", fit.axial.loo.max_abs_error_percent}}},
                                     {"torque",
                                      {{"mean_abs_error_percent", fit.torque.fit.mean_abs_error_percent},
                                       {"loo_mean_abs_error_percent", fit.torque.loo.mean_abs_error_percent},
                                       {"loo_max_abs_error_percent", fit.torque.loo.max_abs_error_percent}}}};
}

/// A column's text, unquoted; empty when the row has no such column.
std::string column_text(const Columns& columns, const std::string& name) {
  for (const auto& [column, value] : columns) {
    if (column != name) continue;
    return value.size() >= 2 && value.front() == '"' ? value.substr(1, value.size() - 2) : value;
  }
  return {};
}

/// The critical depth on a depth-of-cut condition's axis (its figures draw it), from a row that has one.
void mark_critical_depth(const Columns& columns, const Bindings& bindings, ComparisonSpec& spec) {
  const std::string critical = column_text(columns, std::string(prediction_keys::critical_depth_nm));
  if (critical.empty()) return;
  const double critical_nm = std::stod(critical);
  for (std::size_t i = 0; i < bindings.conditions.size(); ++i) {
    const std::string& key = spec.conditions[i].key;
    const bool marked =
        std::any_of(spec.marks.begin(), spec.marks.end(), [&](const auto& m) { return m.condition == key; });
    if (bindings.conditions[i].scene_path != "cut.uncut_chip_thickness_um" || marked) continue;
    spec.marks.push_back({key, critical_nm * 1e-9, fmt::format("d#dc#u = {:.3g} nm", critical_nm)});
  }
}

/// What predict prints beside the forces: the regime against the critical depth and the guards that fired.
RowDiagnostics row_diagnostics(std::size_t line, const AnalyticCase& scene, const Columns& columns) {
  RowDiagnostics diagnostics{line, "", scene.guard_names(), scene.warnings()};
  for (const std::string_view name : {prediction_keys::regime, trepanning_keys::grit_regime})
    if (std::string regime = column_text(columns, std::string(name)); !regime.empty()) diagnostics.regime = regime;
  return diagnostics;
}

/// The model's predictions at each measured row's conditions (with each row's diagnostics into out.rows) and
/// the model curve for the plots.
PredictedSet predictions(const Json& document, const Bindings& bindings, const DataSet& measured, bool per_width,
                         double scene_width_m, const SceneComparisonOptions& options, SceneComparison& out) {
  const auto& conditions = bindings.conditions;
  const auto& quantities = bindings.quantities;
  const ComparisonSpec& spec = out.comparison.spec;
  // The curve is evaluated at many points for the plots: one material cache serves them all.
  auto cache = std::make_shared<MaterialCache>();
  const auto scene_at = [document, conditions, spec, cache](const std::vector<ConditionValue>& at) {
    Json d = document;
    for (std::size_t i = 0; i < conditions.size(); ++i) {
      set_path(d, conditions[i].scene_path, at[i].si.value_or(0.0) / spec.conditions[i].unit.si);
    }
    auto scene = parse_scene(d, cache.get());
    scene->predict();
    return scene;
  };
  const auto values_of = [quantities, spec](const Columns& columns) {
    std::vector<double> values;
    for (std::size_t q = 0; q < quantities.size(); ++q) {
      values.push_back(column_value(columns, quantities[q].prediction_column) * spec.quantities[q].unit.si);
    }
    return values;
  };
  const auto predict_at = [scene_at, values_of](const std::vector<ConditionValue>& at) {
    return values_of(scene_columns(*scene_at(at)));
  };
  DataSet predicted;
  predicted.name = options.fit ? "model (fitted)" : "model";
  for (std::size_t q = 0; q < quantities.size(); ++q) {
    const bool force = spec.quantities[q].unit.suffix == "N" && per_width;
    predicted.bases.push_back(force ? WidthBasis::total(scene_width_m) : WidthBasis::none());
  }
  for (const auto& row : measured.rows) {
    DataRow p;
    p.conditions = row.conditions;
    const auto scene = scene_at(row.conditions);  // one prediction gives the row's values and diagnostics
    const Columns columns = scene_columns(*scene);
    p.values = values_of(columns);
    p.outside_model_range = column_text(columns, "within_model_range") == "no";
    mark_critical_depth(columns, bindings, out.comparison.spec);
    predicted.rows.push_back(std::move(p));
    out.rows.push_back(row_diagnostics(row.line, *scene, columns));
  }
  return PredictedSet{predicted, predict_at};
}

/// The report's notes: how the columns were matched, and each row's regime, guards and warnings.
std::string matching_notes(const SceneComparison& out) {
  std::string notes = "\n## How the columns were matched\n\n";
  for (const auto& n : out.notes) notes += "- " + n + "\n";
  notes +=
      "\n## Regime and guards per row\n\nThe regime of each row's prediction against the ductile-brittle critical "
      "depth (empty when the material has none) and the guards that fired (a force set by a guard's policy is "
      "not the model's own).\n\n| CSV line | regime | guards | warnings |\n|---|---|---|---|\n";
  for (const auto& r : out.rows) {
    notes += fmt::format("| {} | {} | {} | {} |\n", r.line, r.regime.empty() ? "-" : r.regime,
                         r.guards.empty() ? "none" : fmt::format("{}", fmt::join(r.guards, ";")),
                         r.warnings.empty() ? "-" : fmt::format("{}", fmt::join(r.warnings, "; ")));
  }
  return notes;
}

}  // namespace

SceneComparison compare_scene(const Json& scene_document, const std::filesystem::path& experiments_csv,
                              const SceneComparisonOptions& options) {
  SceneComparison out;
  const CsvTable table = read_csv_file(experiments_csv);
  MaterialCache materials;
  const auto kind = parse_scene(scene_document, &materials);
  const Bindings bindings =
      bind_columns(table, scene_document, experiments_csv, options, scene_column_names(*kind), out);
  const DataSet measured = measured_data(table, bindings, experiments_csv, options, *kind, out);
  Json document = scene_document;
  if (options.fit) {
    if (!kind->fits_lumped_groups()) {
      throw InputError("--fit", "(given)", "a trepanning scene: the fit calibrates its two lumped groups");
    }
    fit_lumped_groups(document, bindings, measured, experiments_csv, materials, out);
  }
  const std::optional<double> force_width_m = kind->force_width_m();
  const PredictedSet predicted =
      predictions(document, bindings, measured, force_width_m.has_value(), force_width_m.value_or(0.0), options, out);
  out.comparison = compare(out.comparison.spec, measured, {predicted});
  out.report.extra_markdown += matching_notes(out);
  return out;
}

}  // namespace kerf
