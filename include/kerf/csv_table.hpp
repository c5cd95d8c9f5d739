#pragma once
// Reading the experiment tables in data/experiments/: RFC 4180 CSV with '#' comment lines that carry the
// source (citation) of the data. The comments are kept so that a report can quote them.
//
//   kerf::CsvTable t = kerf::read_csv_file("data/experiments/k9_trepanning.csv");
//   t.comments[1];                                  // "Source: Yu et al. 2023, Table 4 (...)"
//   std::size_t col = t.column_index("torque_test_Nm");
//   double m = t.number(0, col);                    // 4.63
//   // a bad cell: InputError "k9_trepanning.csv:7: column 4 'torque_test_Nm' = abc: expected a number"
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace kerf {

struct CsvTable {
  std::string source;                          ///< the file (or name) used in error messages
  std::vector<std::string> comments;           ///< '#' lines, without the '#' and one following space
  std::vector<std::string> header;             ///< column names
  std::vector<std::vector<std::string>> rows;  ///< cells (unquoted), one vector per data line
  std::vector<std::size_t> row_lines;          ///< 1-based line number of each row in the file

  bool has_column(std::string_view name) const;
  /// InputError naming the source and listing the columns (with a near-miss suggestion) when absent.
  std::size_t column_index(std::string_view name) const;
  const std::string& text(std::size_t row, std::size_t column) const;
  /// The cell as a finite number; InputError "source:line: column k 'name'" otherwise.
  double number(std::size_t row, std::size_t column) const;
  /// "source:line: column k 'name'", the field of errors about one cell.
  std::string cell_location(std::size_t row, std::size_t column) const;
};

/// Parses CSV text (a leading UTF-8 byte-order mark and CRLF line ends are accepted). Blank lines are skipped; lines
/// starting with '#' are comments; the first other line is the header. InputError (field "source:line" or
/// "source:line:char") for an unterminated quote, text after a closing quote, a row with a different number of fields
/// than the header, an empty or duplicate column name, or no header.
CsvTable parse_csv(std::string_view text, const std::string& source);

/// Reads and parses a file (InputError naming the file when it cannot be read).
CsvTable read_csv_file(const std::filesystem::path& path);

/// Parses a number the way the table does ("1.5", " 2e-3 "); nullopt-like: returns false when it is not one.
bool parse_number(std::string_view text, double& value);

}  // namespace kerf
