#pragma once
// A prediction's CSV row, cell by cell: a scene kind writes its columns once (name and formatted value, in
// column order) to a CellWriter; ColumnCollector gathers them as (name, text) pairs, the sweep writes the texts
// straight into its CSV (no string per cell).
//
//   kerf::ColumnCollector row;
//   row.number("cutting_force_N", 12.5);   // "12.5": the shortest text that reads back as the same double
//   row.text("material", "p-SiC, 6H");     // "\"p-SiC, 6H\"" (CSV-escaped)
//   kerf::Columns columns = std::move(row.columns);
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kerf/result_table.hpp"

namespace kerf {

/// One CSV row as (column name, cell text) pairs; the text is CSV-escaped, empty for no value.
using Columns = std::vector<std::pair<std::string, std::string>>;

class CellWriter {
 public:
  virtual ~CellWriter() = default;
  /// The cell's final text (already escaped; empty: no value).
  virtual void cell(std::string_view name, std::string_view text) = 0;

  /// csv_number(value): the shortest round-trip text, empty when not finite.
  void number(std::string_view name, double value);
  /// number(value) when `present`, else an empty cell.
  void optional_number(std::string_view name, bool present, double value);
  /// An input converted back from SI, rounded to 15 significant digits first (the scene's 0.05 um reads 0.05,
  /// not the 0.049999999999999996 of the round trip through metres).
  void input(std::string_view name, double value);
  /// csv_escape(text).
  void text(std::string_view name, std::string_view text);
};

/// The row's cells of a result table (kerf/result_table.hpp): each field present for `r`, a null value an empty
/// cell, a text escaped, an input echoed back rounded (CellWriter::input).
template <class R>
void write_result_cells(const ResultTable<R>& table, const R& r, CellWriter& w) {
  for (const auto& f : table) {
    if (f.present && !f.present(r)) continue;
    const Json v = f.get(r);
    if (v.is_string())
      w.text(f.key, v.template get_ref<const std::string&>());
    else if (v.is_null())
      w.cell(f.key, {});
    else if (f.input_echo)
      w.input(f.key, v.template get<double>());
    else
      w.number(f.key, v.template get<double>());
  }
}

/// Gathers the cells as Columns.
class ColumnCollector final : public CellWriter {
 public:
  Columns columns;
  void cell(std::string_view name, std::string_view text) override { columns.emplace_back(name, text); }
};

}  // namespace kerf
