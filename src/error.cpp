#include "kerf/error.hpp"

#include <fmt/format.h>

namespace kerf {

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else if (c == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
               static_cast<unsigned char>(text[i + 1]) <= 0x9f) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned char>(text[++i]));  // a C1 control in UTF-8
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

InputError::InputError(std::string field, std::string value, std::string expected)
    : std::runtime_error(printable(fmt::format("{} = {}: expected {}", field, value, expected))),
      field_(std::move(field)),
      value_(std::move(value)),
      expected_(std::move(expected)) {}

InputError InputError::or_from(InputError other) && {
  other_ = std::make_shared<const InputError>(std::move(other));
  return std::move(*this);
}

InputError InputError::with_prefix(const std::string& prefix) const {
  InputError prefixed(prefix + "." + field_, value_, expected_);
  if (other_) prefixed.other_ = std::make_shared<const InputError>(other_->with_prefix(prefix));
  return prefixed;
}

ModelError::ModelError(const std::string& model, const std::string& reason)
    : std::runtime_error(printable(fmt::format("model '{}': {}", model, reason))) {}

OutputError::OutputError(const std::string& path, const std::string& reason)
    : std::runtime_error(printable(fmt::format("cannot write '{}': {}", path, reason))) {}

std::string format_value(double value) {
  return fmt::format("{:.6g}", value);
}

int report_error(std::string_view program) {
  const auto line = [&](const char* what) { fmt::print(stderr, "{}: error: {}\n", program, printable(what)); };
  try {
    throw;
  } catch (const InputError& e) {
    line(e.what());
    return kExitInputError;
  } catch (const ModelError& e) {
    line(e.what());
    return kExitModelError;
  } catch (const OutputError& e) {
    line(e.what());
    return kExitOutputError;
  } catch (const std::exception& e) {
    line(e.what());
    return 1;
  }
}

}  // namespace kerf
