#pragma once
// The force-report layer: compares predicted with measured forces and writes a report directory.
//
// Data come as DataSets (rows of conditions and quantity values, SI inside), usually read from an experiment
// CSV whose '#' comments are its citation. Prediction rows are matched to measured rows by their conditions
// (numbers within a relative tolerance, text exactly). Measured rows with the same conditions are replicates:
// their mean and standard deviation are the measurement a prediction is judged against, and the report says
// whether the prediction lies inside mean +- 1 SD (and +- 2 SD). Per quantity: n, mean |error|, max |error|,
// bias (mean signed error), all relative to the measured (group) mean, in percent (metrics.hpp).
//
// Width basis: every force carries one — a total force over a stated width (Yang et al. 2018's experiments: 25.4 mm;
// its 2D DEM: 1 mm) or a force per unit width. Comparing forces whose bases differ needs an explicit choice;
// ComparisonSpec::views asks for the direct comparison as published, the per-unit-width one, or both.
//
//   kerf::CsvTable table = kerf::read_csv_file(kerf::data_directory() / "experiments/k9_trepanning.csv");
//   kerf::ComparisonSpec spec = ...;                               // conditions and quantities
//   kerf::DataSet measured = kerf::dataset_from_csv(table, spec, {...columns...});
//   kerf::Comparison c = kerf::compare(spec, measured, {kerf::PredictedSet{predicted_dataset, model_curve}});
//   kerf::write_report(c, "out/k9");   // report.md, comparison.csv, summary.json, *.png
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kerf/csv_table.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/metrics.hpp"

namespace kerf {

/// A display unit: label for text ("µm/s"), suffix for CSV headers and JSON keys ("um_per_s"), and its size in
/// SI (1 µm/s = 1e-6 m/s).
struct Unit {
  std::string label;
  std::string suffix;
  double si = 1.0;
};

/// What a force number refers to.
struct WidthBasis {
  enum class Kind { not_applicable, total, per_unit_width };
  Kind kind = Kind::not_applicable;  ///< not_applicable: torques, or anything that is not a force on a width
  double width_m = 0.0;              ///< for total: the width the force acts over

  static WidthBasis none() { return {}; }
  static WidthBasis total(double width_m) { return {Kind::total, width_m}; }
  static WidthBasis per_unit_width() { return {Kind::per_unit_width, 0.0}; }
  void validate(const std::string& path) const;  ///< total needs a positive width (path.width_mm)
  /// "total over 25.4 mm width", "per unit width", "no width basis".
  std::string describe() const;
  bool operator==(const WidthBasis&) const = default;
};

/// A force in one basis expressed per unit width (SI: N/m): a total is divided by its width. InputError for
/// not_applicable (field "width_basis").
double to_per_unit_width(double value, const WidthBasis& from);
/// Converts between bases through the per-unit-width value (total 25.4 mm -> total 1 mm divides by 25.4).
double convert_width_basis(double value, const WidthBasis& from, const WidthBasis& to);

/// A condition value: text, and its SI number when it is numeric.
struct ConditionValue {
  std::string text;
  std::optional<double> si;
  static ConditionValue number(double si_value);
  static ConditionValue label(std::string text);
};
/// Numbers match when |a - b| <= tol max(|a|, |b|); text matches exactly; a number never matches text.
bool conditions_match(const ConditionValue& a, const ConditionValue& b, double relative_tolerance);
bool conditions_match(const std::vector<ConditionValue>& a, const std::vector<ConditionValue>& b,
                      double relative_tolerance);

struct ConditionSpec {
  std::string key;    ///< "feed_rate": CSV header feed_rate_um_per_s
  std::string label;  ///< "Feed rate v#df#u"
  Unit unit;          ///< display unit (empty suffix for text conditions)
  bool numeric = true;
  std::string header() const;  ///< key + "_" + unit suffix (key alone for text)
};

struct QuantitySpec {
  std::string key;                                  ///< "axial_force": CSV headers axial_force_measured_N, ...
  std::string label;                                ///< "Axial force F#dn#u"
  Unit unit;                                        ///< display unit of the quantity as published ("N", "N m")
  Unit per_width_unit = {"N/mm", "N_per_mm", 1e3};  ///< display unit of the per-unit-width view
};

enum class WidthView { as_published, per_unit_width };
std::string_view width_view_name(WidthView view);  ///< "as_published", "per_unit_width"

struct ComparisonSpec {
  std::string title;
  std::string description;
  std::vector<ConditionSpec> conditions;
  std::vector<QuantitySpec> quantities;
  double relative_tolerance = 1e-6;  ///< for matching numeric conditions
  /// Which views to report. Empty: as_published where the bases agree; an InputError where they differ (the
  /// caller must choose). per_unit_width needs force bases on both sides.
  std::vector<WidthView> views;
  /// Values to mark on a condition's axis (a dashed vertical line in its figures, e.g. a critical depth).
  struct Mark {
    std::string condition;  ///< the condition's key
    double value_si = 0.0;
    std::string label;  ///< the legend entry ("d_c = 36 nm")
  };
  std::vector<Mark> marks;
  void validate() const;
};

struct DataRow {
  std::vector<ConditionValue> conditions;  ///< in ComparisonSpec::conditions order
  std::vector<double> values;              ///< per quantity, SI; NaN where the set has no value
  std::size_t line = 0;                    ///< source line (0: not from a file)
  bool outside_model_range = false;        ///< a prediction's: its model does not hold at these conditions
};

struct DataSet {
  std::string name;                    ///< "Yu et al. 2023, Table 4 (measured)"
  std::string source;                  ///< the file, if any
  std::vector<std::string> citations;  ///< the CSV's comment lines
  std::vector<WidthBasis> bases;       ///< per quantity
  std::vector<DataRow> rows;
};

/// Which CSV columns hold a data set's conditions and quantities, and which rows belong to it.
struct CsvBinding {
  std::string name;
  std::vector<std::string> condition_columns;                   ///< one per spec condition, in its units
  std::vector<double> condition_si;                             ///< SI size of each column's unit (numeric conditions)
  std::vector<std::string> quantity_columns;                    ///< one per spec quantity; "" when the set lacks it
  std::vector<double> quantity_si;                              ///< SI size of each column's unit
  std::vector<WidthBasis> bases;                                ///< one per spec quantity
  std::vector<std::pair<std::string, std::string>> row_filter;  ///< keep rows whose column equals the text
  /// When set, a column holding each row's width (in mm): total bases take their width from it, and rows of
  /// one set must agree (InputError naming the cell otherwise).
  std::string width_column_mm;
};
/// Builds a data set from a table; InputError naming file:line: column for bad cells.
DataSet dataset_from_csv(const CsvTable& table, const ComparisonSpec& spec, const CsvBinding& binding);

/// A model's value at any conditions (SI, per quantity, in the prediction's bases), for smooth model lines.
using ModelCurve = std::function<std::vector<double>(const std::vector<ConditionValue>& conditions)>;

struct PredictedSet {
  DataSet data;
  ModelCurve curve;  ///< optional: plots draw the curve, else they join the predicted points
};

/// One set of conditions, measured (possibly replicated) and predicted.
struct GroupComparison {
  std::vector<ConditionValue> conditions;
  std::vector<double> measured;             ///< the replicates, SI in the view's basis
  std::vector<std::size_t> measured_rows;   ///< their indices in the measured data set
  std::vector<std::size_t> measured_lines;  ///< their source lines
  SampleStatistics measured_stats;
  std::vector<double> predicted;  ///< predicted rows with these conditions (replicate runs)
  SampleStatistics predicted_stats;
  double error_percent = 0.0;                   ///< (predicted mean - measured mean) / measured mean
  std::vector<double> row_error_percent;        ///< (predicted mean - replicate) / replicate, per measured row
  bool has_scatter = false;                     ///< two or more replicates
  bool within_1sd = false, within_2sd = false;  ///< predicted mean inside mean +- 1 (2) SD; only with scatter
  bool outside_model_range = false;  ///< a predicted row of the group lies outside its model's range (figures: hollow)
};

struct QuantityComparison {
  std::size_t quantity = 0;    ///< index into spec.quantities
  std::size_t prediction = 0;  ///< index into the predictions
  WidthView view = WidthView::as_published;
  std::string key;                             ///< "axial_force", or "main_force_per_width" for the per-unit-width view
  Unit unit;                                   ///< display unit of this view
  WidthBasis measured_basis, predicted_basis;  ///< of the values in this view
  std::vector<GroupComparison> groups;         ///< matched groups, in measured order
  ErrorMetrics metrics;                        ///< over the groups (vs the measured means)
  ErrorMetrics row_metrics;                    ///< over every measured row
  std::size_t n_with_scatter = 0, n_within_1sd = 0, n_within_2sd = 0;
  std::vector<std::vector<ConditionValue>> unmatched;  ///< measured groups with no prediction
  std::string note;  ///< e.g. "width bases differ: compared as published, without scaling"
};

struct Comparison {
  ComparisonSpec spec;
  DataSet measured;
  std::vector<PredictedSet> predictions;
  std::vector<QuantityComparison> results;  ///< per prediction, quantity and view

  /// The result for a quantity key ("axial_force", "main_force_per_width") and prediction; throws if absent.
  const QuantityComparison& result(const std::string& key, std::size_t prediction = 0) const;
};

/// Matches and compares. InputError when the spec is invalid, a data set's shape does not fit the spec, the
/// bases differ without an explicit view, or a quantity has no matched row at all.
Comparison compare(const ComparisonSpec& spec, const DataSet& measured, const std::vector<PredictedSet>& predictions);

/// Extra content for a report (e.g. a calibration section).
struct ReportOptions {
  std::string extra_markdown;           ///< appended to report.md
  Json extra_summary = Json::object();  ///< merged into summary.json under "extra"
  bool plots = true;
};

/// Writes report.md, comparison.csv, summary.json and the plots (parity_<key>.png, <key>_vs_<condition>.png)
/// into `out_dir`. Everything is rendered into a staging folder inside `out_dir` first and checked; only then
/// are the files renamed into place, so a failure leaves the previous report files untouched and no partial
/// file behind. Returns the paths written.
std::vector<std::filesystem::path> write_report(const Comparison& comparison, const std::filesystem::path& out_dir,
                                                const ReportOptions& options = {});

/// The texts of the report without writing anything (for tests and for the CLI's --stdout).
std::string report_markdown(const Comparison& comparison, const ReportOptions& options = {},
                            const std::vector<std::string>& plot_files = {});
std::string comparison_csv(const Comparison& comparison);
Json summary_json(const Comparison& comparison, const ReportOptions& options = {});

}  // namespace kerf
