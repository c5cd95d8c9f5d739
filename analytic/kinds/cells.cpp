#include "kerf/analytic/kinds/cells.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "kerf/io.hpp"

namespace kerf {

void CellWriter::number(std::string_view name, double value) {
  if (!std::isfinite(value)) return cell(name, {});
  char buffer[64];  // the shortest round trip of a double needs at most 25 characters
  const char* end = fmt::format_to(buffer, FMT_COMPILE("{}"), value);  // as csv_number, without a heap string
  cell(name, std::string_view(buffer, static_cast<std::size_t>(end - buffer)));
}

void CellWriter::optional_number(std::string_view name, bool present, double value) {
  if (!present) return cell(name, {});
  number(name, value);
}

void CellWriter::input(std::string_view name, double value) {
  char buffer[64];  // 15 significant digits, sign, point and exponent
  *fmt::format_to(buffer, FMT_COMPILE("{:.15g}"), value) = '\0';
  // std::stod's reading: std::out_of_range where the text is beyond a double (a subnormal).
  errno = 0;
  const double rounded = std::strtod(buffer, nullptr);
  if (errno == ERANGE) throw std::out_of_range("stod");
  number(name, rounded);
}

void CellWriter::text(std::string_view name, std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return cell(name, text);
  cell(name, csv_escape(text));
}

}  // namespace kerf
