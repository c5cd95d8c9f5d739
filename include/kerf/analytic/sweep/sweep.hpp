#pragma once
// A parameter sweep over analytic scenes: the cartesian product of varied keys, each point a scene of the base
// document with the point's values set, parsed, predicted and written as one CSV row. kerf-forces sweep and
// Python's kerf.sweep both run this; one policy for them: a key the scene does not read is an InputError before
// any point runs (exit 2 / kerf.InputError); a point whose value the models refuse (InputError, ModelError)
// keeps its message in the 'error' column; any other exception is a fault of the program and stops the sweep.
//
//   kerf::SweepGrid grid(document, {kerf::parse_sweep_axis("cut.uncut_chip_thickness_um=0.1:1:10"),
//                                   kerf::parse_sweep_axis("tool.edge_radius_um=0,0.1,0.2")}, "--vary");
//   std::vector<kerf::SweepRow> rows = grid.run();        // on OpenMP's threads
//   std::string csv = grid.csv_text(rows);                // the axes, the prediction's columns, error
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/json_reader.hpp"

namespace kerf {

/// One varied key and its values.
struct SweepAxis {
  std::string key;                 ///< dotted scene key, "cut.uncut_chip_thickness_um"
  std::string spec;                ///< as the user gave it (the CLI's key=START:STOP:COUNT; messages)
  std::vector<Json> values;        ///< the value each point sets
  std::vector<std::string> texts;  ///< each value as written (messages name key=text)
  std::vector<double> numbers;     ///< the values as numbers (the CLI grammar's; empty for other values)
  bool log_spacing = false;        ///< START:STOP:COUNT:log (a figure draws this axis logarithmically)
};

/// The CLI's axis: key.path=START:STOP:COUNT[:log|:lin] (values rounded to 15 significant digits) or
/// key.path=A,B,C: numbers, or names and any other values as --set reads them (models.force=merchant,liu_li,
/// material=psic,k9_glass: a categorical axis, without numbers). InputError naming `option_name` and the spec.
SweepAxis parse_sweep_axis(const std::string& spec, const std::string& option_name = "--vary");

/// An axis of values given as JSON texts (Python's: json.dumps of each value), each read as a --set value.
SweepAxis sweep_axis_from_texts(std::string key, std::vector<std::string> texts);

/// One point's outcome: the prediction's cells (CSV text of its columns, joined by commas) or the error that
/// refused it; the guards and warnings as lists when run(true).
struct SweepRow {
  std::string cells;
  std::string error;
  std::vector<std::string> guards;
  std::vector<std::string> warnings;
};

class SweepGrid {
 public:
  /// Checks the grid (at most 50 million points) and each axis's key against the scene (check_varied_key:
  /// InputError naming `option_name`), and fixes the column names: the unvaried scene's, or with categorical axes
  /// (a model or material varied) the union of each combination's columns, in order of first appearance; a point
  /// leaves the columns its scene lacks empty.
  SweepGrid(Json base, std::vector<SweepAxis> axes, std::string option_name);

  std::size_t size() const { return n_points_; }
  const std::vector<SweepAxis>& axes() const { return axes_; }
  const std::vector<std::string>& column_names() const { return names_; }
  /// The varied keys' column names, in axis order: the key, or key + "_varied" where a prediction column has the
  /// key's name (`material`: the prediction's column is the record's name, the axis's the value as given).
  std::vector<std::string> axis_column_names() const;
  /// The value index of `point` on axis `a` (row-major: the last axis varies fastest).
  std::size_t value_index(std::size_t point, std::size_t a) const;
  /// The points between neighbours along axis `a`.
  std::size_t stride(std::size_t a) const;

  /// Evaluates every point on OpenMP's threads; `lists` also keeps each point's guards and warnings.
  /// `on_progress(n)` is called (on the calling thread) as each chunk of n points finishes.
  std::vector<SweepRow> run(bool lists = false, const std::function<void(std::size_t)>& on_progress = {}) const;

  /// The CSV: a header (the axes' keys, the column names, error) and a row per point (the axes' numbers,
  /// the cells or empty cells, the escaped error).
  std::string csv_text(const std::vector<SweepRow>& rows) const;

  const Json& base() const { return base_; }
  MaterialCache& materials() const { return materials_; }

 private:
  void evaluate(std::size_t point, Json& document, SweepRow& row, bool lists) const;
  void union_categorical_columns();

  Json base_;
  std::vector<SweepAxis> axes_;
  std::string option_name_;
  std::vector<std::string> names_;
  std::size_t n_points_ = 1;
  bool independent_keys_ = true;  ///< no key is another's prefix: a point's document can be the last one's
  bool varying_columns_ = false;  ///< categorical axes: a point's cells are placed by name into the union
  std::unordered_map<std::string, std::size_t> column_index_;  ///< name -> position, when varying_columns_
  mutable MaterialCache materials_;
};

/// The fields of a row's cells as they stand in the CSV (a quoted field keeps its quotes).
std::vector<std::string_view> split_cells(std::string_view cells);
/// The number in field `column` of `cells`; nullopt when empty or not a number.
std::optional<double> cell_number(std::string_view cells, std::size_t column);

/// The numbers of the column `name` (nullopt at a refused point, an empty cell, or without such a column).
std::vector<std::optional<double>> column_numbers(const SweepGrid& grid, const std::vector<SweepRow>& rows,
                                                  std::string_view name);

/// The texts of the column `name` (unquoted; nullopt at a refused point or without such a column).
std::vector<std::optional<std::string>> column_texts(const SweepGrid& grid, const std::vector<SweepRow>& rows,
                                                     std::string_view name);

/// The sweep's summary line: points, refused, rows per regime, within and outside the model's range, and per
/// guard ("60 points: 0 refused; regime 21 ductile, 12 transition, 27 brittle; within the model's range 21,
/// outside 39; guards none 60"), each count the rows' own.
std::string sweep_summary(const SweepGrid& grid, const std::vector<SweepRow>& rows);

/// The sweep's figure (sweep_report.cpp): cutting (solid) and thrust (dashed) force against the first varied
/// key, one colour per value of the second (the first 6 of them; further keys at their first value), refused
/// points left out; a marker at every computed point, hollow where the row is outside its model's range
/// (within_model_range = no); the critical depth d_c as a vertical line where the first key is the depth of cut;
/// the axes labelled from the keys' unit suffixes, the material in the title, the width in the y label, the
/// legend (a row per colour and one per line style) beside the plot. PNG with a PDF beside it.
/// The axes must be numeric (parse_sweep_axis).
void plot_sweep(const SweepGrid& grid, const std::vector<SweepRow>& rows, const std::string& path,
                const std::string& scene_path);

/// A force that falls as the chip thickens is a model that switched branch or left its domain (issue 22): one
/// line per force column along a varied cut.uncut_chip_thickness_um where that happens, with the first place.
std::vector<std::string> falling_force_warnings(const SweepGrid& grid, const std::vector<SweepRow>& rows);

}  // namespace kerf
