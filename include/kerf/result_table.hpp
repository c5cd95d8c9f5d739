#pragma once
// One result table per result struct: the output twin of FieldTable (kerf/field_table.hpp), the single description
// of a struct's results as users read them.
//
// Each result names its key (with the unit suffix users read: "subsurface_damage_depth_um"), the unit and the
// conversion from SI, a one-line description and how to get the value from the struct. What a run writes
// (summary.json, CSV columns), the key reference in the docs and the readers' key names (kerf.result_keys in
// Python) all come from the table:
//
//   struct Counts { double depth_m = 0; int cracks = 0; };
//   const ResultTable<Counts> kCountResults{
//       result_number<Counts>(keys::depth_um, units::kUm, "the deepest crack", [](auto& c) { return c.depth_m; }),
//       result_value<Counts>(keys::cracks, "", "broken joints", [](auto& c) { return Json(c.cracks); })};
//   write_results(kCountResults, counts, summary["results"]);    // key -> value in the key's unit
//   std::string md = results_markdown(kCountResults);             // | key | unit | meaning |
//
// A CSV file's columns are a table too, one row struct per line of the file:
//
//   std::string csv = results_csv_header(kColumns);
//   for (const auto& row : rows) csv += results_csv_row(kColumns, row);  // csv_number's text for a real
//
// Keys are declared once as named constants (KERF_RESULT_KEY: the identifier is the key), which the table and
// every C++ reader use; a misspelt key is then a compile error, not a missing value.
#include <fmt/format.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kerf/field_table.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"

/// A result key as a named constant whose name is the key (`KERF_RESULT_KEY(width_mm)`: kerf::...::width_mm is
/// "width_mm"), written once.
#define KERF_RESULT_KEY(name) inline constexpr std::string_view name = #name;

namespace kerf {

/// One result: the key (with its unit suffix), the unit, what it means and its value (in the key's unit).
template <class R>
struct ResultField {
  std::string key;
  std::string_view unit;  ///< as the docs print it: "um", "N/mm"; empty for a count, a share, a flag, a text
  std::string doc;
  std::function<Json(const R&)> get;  ///< the value as written (a number in the key's unit, a count, null, ...)
  std::function<bool(const R&)> present = {};  ///< whether the run writes it (empty: always)
  /// An input echoed back beside the results (a prediction's row): a CSV cell rounds it to 15 significant digits.
  bool input_echo = false;
};

template <class R>
using ResultTable = std::vector<ResultField<R>>;

/// A real result, held in SI by the struct (`si`), written in `unit` (its FieldUnit::from_si, the conversion the
/// input side reads with).
template <class R, class Get>
ResultField<R> result_number(std::string_view key, FieldUnit unit, std::string_view doc, Get si) {
  return {std::string(key), unit.symbol, std::string(doc),
          [from_si = unit.from_si, si](const R& r) { return Json(from_si(si(r))); }};
}

/// An input echoed back beside the results, held in SI by the struct (`si`), written in `unit` (result_number).
template <class R, class Get>
ResultField<R> result_input(std::string_view key, FieldUnit unit, std::string_view doc, Get si) {
  ResultField<R> f = result_number<R>(key, unit, doc, si);
  f.input_echo = true;
  return f;
}

/// A result written as its getter gives it (a count, a flag, a text, a number that may be null); `unit` for the docs.
template <class R, class Get>
ResultField<R> result_value(std::string_view key, std::string_view unit, std::string_view doc, Get get) {
  return {std::string(key), unit, std::string(doc), [get](const R& r) { return Json(get(r)); }};
}

/// A result written as its getter gives it where `has(r)` holds, else null: the row keeps the column, with an empty
/// cell where this run has no value (a detail of a model that did not run, a pole the edge has not).
template <class R, class Has, class Get>
ResultField<R> result_or_null(std::string_view key, std::string_view unit, std::string_view doc, Has has, Get get) {
  return result_value<R>(key, unit, doc, [has, get](const R& r) { return has(r) ? Json(get(r)) : Json(); });
}

/// `field`, written only when `present(r)` holds (a result of an option: the edge zone's, the energy books').
template <class R, class Present>
ResultField<R> result_if(ResultField<R> field, Present present) {
  field.present = present;
  return field;
}

/// The key suffix of a unit: "_um" for "um", "_N_per_mm" for "N/mm", "_percent" for "%", "_MPa_sqrt_m" for
/// "MPa sqrt(m)", "" for none.
inline std::string result_unit_suffix(std::string_view unit) {
  if (unit.empty()) return "";
  std::string suffix = "_";
  for (const char c : unit) {
    if (c == '/')
      suffix += "_per_";
    else if (c == '%')
      suffix += "percent";
    else if (c == ' ' || c == '(')
      suffix += '_';
    else if (c != ')')
      suffix += c;
  }
  return suffix;
}

/// Writes each result present for `r` into `into` (an object), key -> value.
template <class R>
void write_results(const ResultTable<R>& table, const R& r, Json& into) {
  for (const auto& f : table)
    if (!f.present || f.present(r)) into[f.key] = f.get(r);
}

/// write_results into a new object.
template <class R>
Json results_to_json(const ResultTable<R>& table, const R& r) {
  Json j = Json::object();
  write_results(table, r, j);
  return j;
}

/// The value of `key` for `r` (whether or not the run writes it: a report may print what the row leaves out);
/// std::logic_error for a key not in the table.
template <class R>
Json result_of(const ResultTable<R>& table, const R& r, std::string_view key) {
  for (const auto& f : table)
    if (f.key == key) return f.get(r);
  throw std::logic_error("result_of: no result " + std::string(key));
}

/// The table's keys, in its order.
template <class R>
std::vector<std::string> result_keys(const ResultTable<R>& table) {
  std::vector<std::string> keys;
  for (const auto& f : table) keys.push_back(f.key);
  return keys;
}

/// A CSV file's header: the keys of its columns, those present for `r` (a file whose columns depend on the run, not on
/// the line: `r` any line of the file, or one made for the header; its getters are not called).
template <class R>
std::string results_csv_header(const ResultTable<R>& table, const R& r) {
  std::vector<std::string> keys;
  for (const auto& f : table)
    if (!f.present || f.present(r)) keys.push_back(f.key);
  return csv_line(keys);
}

/// A file's header with every column of `table`.
template <class R>
std::string results_csv_header(const ResultTable<R>& table) {
  return csv_line(result_keys(table));
}

/// A value as a CSV cell: a real as `real` writes it (csv_number: the shortest text that reads back as the same
/// double, empty when not finite), an integer in full, a flag true or false, a text escaped (csv_escape), null empty.
inline std::string result_csv_cell(const Json& v, std::string (*real)(double) = csv_number) {
  if (v.is_number_float()) return real(v.get<double>());
  if (v.is_string()) return csv_escape(v.get_ref<const std::string&>());
  if (v.is_null()) return "";
  return v.dump();
}

/// The line of `r` in a CSV file of `table`'s columns: the cells of the columns present for `r`
/// (result_csv_cell, with `real` for the reals).
template <class R>
std::string results_csv_row(const ResultTable<R>& table, const R& r, std::string (*real)(double) = csv_number) {
  std::vector<std::string> cells;
  for (const auto& f : table)
    if (!f.present || f.present(r)) cells.push_back(result_csv_cell(f.get(r), real));
  return csv_line(cells);
}

/// The key reference of a table as a Markdown table: key, unit, meaning; without the header, rows to append.
template <class R>
std::string results_markdown(const ResultTable<R>& table, bool with_header = true) {
  std::string md = with_header ? "| key | unit | meaning |\n|---|---|---|\n" : "";
  for (const auto& f : table)
    md += fmt::format("| `{}` | {} | {} |\n", f.key, f.unit.empty() ? "-" : std::string(f.unit), f.doc);
  return md;
}

/// `keys` as a Python class of constants (`name = "name"`, one a line) named `name`, with `doc` as its docstring: a
/// generated module's part, so that Python reads a result by its name, not by a literal.
inline std::string results_python_class(std::string_view name, std::string_view doc,
                                        const std::vector<std::string>& keys) {
  std::string py = fmt::format("\n\nclass {}:\n    \"\"\"{}\"\"\"\n\n", name, doc);
  for (const auto& key : keys) py += fmt::format("    {} = \"{}\"\n", key, key);
  return py;
}

/// The end of a generated module of results_python_class: keys(table), a class's keys in its order.
inline std::string results_python_keys_function() {
  return "\n\ndef keys(table):\n"
         "    \"\"\"The keys of a table above, in its order.\"\"\"\n"
         "    return [value for name, value in vars(table).items() if not name.startswith(\"_\")]\n";
}

}  // namespace kerf
