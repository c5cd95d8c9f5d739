// The report's inputs: width bases, conditions, and data sets read from CSV (kerf/report.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "report_internal.hpp"

namespace kerf {

using namespace report_detail;

// ---- Width basis -------------------------------------------------------------------------------------

void WidthBasis::validate(const std::string& path) const {
  if (kind == Kind::total) check_number(width_m * 1e3, path + ".width_mm", Range::positive(), "mm");
}

std::string WidthBasis::describe() const {
  switch (kind) {
    case Kind::total:
      return fmt::format("total force over a {} mm width", number_text(width_m * 1e3));
    case Kind::per_unit_width:
      return "force per unit width";
    case Kind::not_applicable:
      break;
  }
  return "no width basis";
}

double to_per_unit_width(double value, const WidthBasis& from) {
  from.validate("width_basis");
  switch (from.kind) {
    case WidthBasis::Kind::total:
      return value / from.width_m;
    case WidthBasis::Kind::per_unit_width:
      return value;
    case WidthBasis::Kind::not_applicable:
      break;
  }
  throw InputError("width_basis", from.describe(),
                   "a force with a width basis (total over a width, or per unit width)");
}

double convert_width_basis(double value, const WidthBasis& from, const WidthBasis& to) {
  const double per_width = to_per_unit_width(value, from);
  to.validate("width_basis");
  switch (to.kind) {
    case WidthBasis::Kind::total:
      return per_width * to.width_m;
    case WidthBasis::Kind::per_unit_width:
      return per_width;
    case WidthBasis::Kind::not_applicable:
      break;
  }
  throw InputError("width_basis", to.describe(), "a force with a width basis (total over a width, or per unit width)");
}

// ---- Conditions --------------------------------------------------------------------------------------

ConditionValue ConditionValue::number(double si_value) {
  return {fmt::format("{}", si_value), si_value};
}
ConditionValue ConditionValue::label(std::string text) {
  return {std::move(text), std::nullopt};
}

bool conditions_match(const ConditionValue& a, const ConditionValue& b, double relative_tolerance) {
  if (a.si.has_value() != b.si.has_value()) return false;
  if (!a.si) return a.text == b.text;
  return std::abs(*a.si - *b.si) <= relative_tolerance * std::max(std::abs(*a.si), std::abs(*b.si));
}

bool conditions_match(const std::vector<ConditionValue>& a, const std::vector<ConditionValue>& b,
                      double relative_tolerance) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!conditions_match(a[i], b[i], relative_tolerance)) return false;
  }
  return true;
}

std::string ConditionSpec::header() const {
  return unit.suffix.empty() ? key : key + "_" + unit.suffix;
}

std::string_view width_view_name(WidthView view) {
  return view == WidthView::as_published ? "as_published" : "per_unit_width";
}

void ComparisonSpec::validate() const {
  if (quantities.empty()) throw InputError("comparison.quantities", "(none)", "at least one quantity to compare");
  check_number(relative_tolerance, "comparison.relative_tolerance", Range{0.0, 0.5, false, true}, "");
  std::set<std::string> keys;
  for (const auto& c : conditions) {
    if (c.key.empty() || !keys.insert(c.key).second) {
      throw InputError("comparison.conditions", c.key.empty() ? "(empty)" : c.key, "unique, non-empty keys");
    }
    if (c.numeric && !(c.unit.si > 0.0)) {
      throw InputError("comparison.conditions." + c.key + ".unit", format_value(c.unit.si), "a positive SI size");
    }
  }
  for (const auto& q : quantities) {
    if (q.key.empty() || !keys.insert(q.key).second) {
      throw InputError("comparison.quantities", q.key.empty() ? "(empty)" : q.key, "unique, non-empty keys");
    }
    if (!(q.unit.si > 0.0) || !(q.per_width_unit.si > 0.0)) {
      throw InputError("comparison.quantities." + q.key + ".unit", format_value(q.unit.si), "a positive SI size");
    }
  }
}

// ---- Data sets ---------------------------------------------------------------------------------------

DataSet dataset_from_csv(const CsvTable& table, const ComparisonSpec& spec, const CsvBinding& b) {
  spec.validate();
  const std::string where = fmt::format("{} binding '{}'", table.source, b.name);
  if (b.condition_columns.size() != spec.conditions.size() || b.condition_si.size() != spec.conditions.size()) {
    throw InputError(where + ".condition_columns", fmt::format("{} columns", b.condition_columns.size()),
                     fmt::format("{} columns and unit sizes, one per condition", spec.conditions.size()));
  }
  if (b.quantity_columns.size() != spec.quantities.size() || b.quantity_si.size() != spec.quantities.size() ||
      b.bases.size() != spec.quantities.size()) {
    throw InputError(where + ".quantity_columns", fmt::format("{} columns", b.quantity_columns.size()),
                     fmt::format("{} columns, unit sizes and width bases, one per quantity", spec.quantities.size()));
  }
  std::vector<std::pair<std::size_t, std::string>> filters;
  for (const auto& [column, value] : b.row_filter) filters.emplace_back(table.column_index(column), value);
  std::vector<std::size_t> condition_index, quantity_index;
  for (const auto& c : b.condition_columns) condition_index.push_back(table.column_index(c));
  for (const auto& q : b.quantity_columns) {
    quantity_index.push_back(q.empty() ? std::numeric_limits<std::size_t>::max() : table.column_index(q));
  }
  const bool has_width_column = !b.width_column_mm.empty();
  const std::size_t width_index = has_width_column ? table.column_index(b.width_column_mm) : 0;

  DataSet set;
  set.name = b.name;
  set.source = table.source;
  set.citations = table.comments;
  set.bases = b.bases;
  std::optional<double> width_m;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    bool keep = true;
    for (const auto& [column, value] : filters) keep = keep && table.text(r, column) == value;
    if (!keep) continue;
    DataRow row;
    row.line = table.row_lines[r];
    for (std::size_t c = 0; c < spec.conditions.size(); ++c) {
      if (spec.conditions[c].numeric) {
        row.conditions.push_back(ConditionValue::number(table.number(r, condition_index[c]) * b.condition_si[c]));
      } else {
        row.conditions.push_back(ConditionValue::label(table.text(r, condition_index[c])));
      }
    }
    for (std::size_t q = 0; q < spec.quantities.size(); ++q) {
      row.values.push_back(b.quantity_columns[q].empty() ? kNaN
                                                         : table.number(r, quantity_index[q]) * b.quantity_si[q]);
    }
    if (has_width_column) {
      const double w = table.number(r, width_index) * 1e-3;
      if (!(w > 0.0) || (width_m && std::abs(*width_m - w) > 1e-9 * w)) {
        throw InputError(
            table.cell_location(r, width_index), table.text(r, width_index),
            width_m ? fmt::format("the width of the other rows of '{}' ({} mm)", b.name, number_text(*width_m * 1e3))
                    : std::string("a positive width in mm"));
      }
      width_m = w;
    }
    set.rows.push_back(std::move(row));
  }
  if (set.rows.empty()) throw InputError(where, "(no rows)", "at least one row passing the row filter");
  if (width_m) {
    for (auto& basis : set.bases) {
      if (basis.kind == WidthBasis::Kind::total) basis.width_m = *width_m;
    }
  }
  for (std::size_t q = 0; q < set.bases.size(); ++q) set.bases[q].validate(where + ".bases[" + std::to_string(q) + "]");
  return set;
}

}  // namespace kerf
