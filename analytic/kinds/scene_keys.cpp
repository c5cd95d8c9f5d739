#include "kerf/analytic/kinds/scene_keys.hpp"

#include <charconv>
#include <string>

namespace kerf {

namespace {
/// The value's text in the key's unit; the text as it was where it is no number ("(missing)").
std::string value_in_key_unit(const std::string& si_text, const FieldUnit& unit) {
  double si = 0.0;
  const char* end = si_text.data() + si_text.size();
  const auto [stop, error] = std::from_chars(si_text.data(), end, si);
  if (error != std::errc{} || stop != end) return si_text;
  return format_value(unit.from_si(si));
}
}  // namespace

InputError at_scene_key(const InputError& e, std::span<const SceneKeyOf> keys) {
  for (const auto& k : keys) {
    if (e.field() != k.field) continue;
    std::string expected = e.expected();
    const std::string si_tail = " in " + std::string(k.si_unit);
    if (!k.si_unit.empty() && expected.ends_with(si_tail)) {
      expected.replace(expected.size() - si_tail.size(), si_tail.size(), " in " + std::string(k.unit.symbol));
    }
    return InputError(std::string(k.key), value_in_key_unit(e.value(), k.unit), expected);
  }
  return e;
}

}  // namespace kerf
