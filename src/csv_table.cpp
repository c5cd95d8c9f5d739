#include "kerf/csv_table.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"

namespace kerf {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

/// Splits one line into RFC 4180 fields ("" inside quotes is a quote). Quoted fields may not span lines.
std::vector<std::string> split_line(std::string_view line, const std::string& where) {
  std::vector<std::string> fields;
  std::string field;
  std::size_t i = 0;
  bool start = true;
  while (true) {
    if (start && i < line.size() && line[i] == '"') {
      const std::size_t open = i++;
      while (true) {
        if (i >= line.size()) {
          throw InputError(fmt::format("{}:{}", where, open + 1), std::string(line.substr(open)),
                           "a closing quote on the same line");
        }
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        field += line[i++];
      }
      if (i < line.size() && line[i] != ',') {
        throw InputError(fmt::format("{}:{}", where, i + 1), std::string(line.substr(i)),
                         "a comma or the end of the line after a closing quote");
      }
    } else {
      while (i < line.size() && line[i] != ',') field += line[i++];
    }
    fields.push_back(std::move(field));
    field.clear();
    if (i >= line.size()) break;
    ++i;  // the comma
    start = true;
  }
  return fields;
}

}  // namespace

bool parse_number(std::string_view text, double& value) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

bool CsvTable::has_column(std::string_view name) const {
  for (const auto& h : header) {
    if (h == name) return true;
  }
  return false;
}

std::size_t CsvTable::column_index(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return i;
  }
  throw InputError(fmt::format("{}: column", source), std::string(name),
                   "a column of the table: " + describe_choices(name, header));
}

const std::string& CsvTable::text(std::size_t row, std::size_t column) const {
  return rows.at(row).at(column);
}

std::string CsvTable::cell_location(std::size_t row, std::size_t column) const {
  return fmt::format("{}:{}: column {} '{}'", source, row_lines.at(row), column + 1, header.at(column));
}

double CsvTable::number(std::size_t row, std::size_t column) const {
  double value = 0.0;
  const std::string& cell = text(row, column);
  if (!parse_number(cell, value)) {
    throw InputError(cell_location(row, column), cell.empty() ? "(empty)" : cell, "a number");
  }
  return value;
}

CsvTable parse_csv(std::string_view text, const std::string& source) {
  CsvTable table;
  table.source = source;
  std::size_t line_number = 0, position = 0;
  bool have_header = false;
  // A spreadsheet's "CSV UTF-8" starts with a byte-order mark: not part of the first column's name.
  if (text.starts_with("\xEF\xBB\xBF")) position = 3;
  while (position < text.size()) {
    std::size_t end = text.find('\n', position);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(position, end - position);
    position = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (trim(line).empty()) continue;
    if (line.front() == '#') {
      line.remove_prefix(1);
      if (!line.empty() && line.front() == ' ') line.remove_prefix(1);
      table.comments.emplace_back(line);
      continue;
    }
    const std::string where = fmt::format("{}:{}", source, line_number);
    auto fields = split_line(line, where);
    if (!have_header) {
      std::set<std::string> seen;
      for (std::size_t i = 0; i < fields.size(); ++i) {
        fields[i] = std::string(trim(fields[i]));
        if (fields[i].empty()) throw InputError(fmt::format("{}: column {}", where, i + 1), "(empty)", "a column name");
        if (!seen.insert(fields[i]).second) {
          throw InputError(fmt::format("{}: column {}", where, i + 1), fields[i], "a column name used only once");
        }
      }
      table.header = std::move(fields);
      have_header = true;
      continue;
    }
    if (fields.size() != table.header.size()) {
      throw InputError(where, fmt::format("{} fields", fields.size()),
                       fmt::format("{} fields, as in the header", table.header.size()));
    }
    table.rows.push_back(std::move(fields));
    table.row_lines.push_back(line_number);
  }
  if (!have_header) throw InputError(source, "(no header line)", "a CSV table with a header line");
  return table;
}

CsvTable read_csv_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "(cannot be read)", "a readable CSV file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_csv(text.str(), path.string());
}

}  // namespace kerf
