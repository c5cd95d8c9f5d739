#pragma once
// One section of a scene key reference (`kerf-forces keys`, `kerf-dem keys`; docs/scenes.md, docs/dem-keys.md):
// its name ("models.trepanning"), where it applies, and its Markdown table, printed from the field table the
// section is read with (kerf/field_table.hpp). The two programs' references are lists of these.
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"

namespace kerf {

struct SceneKeySection {
  std::string_view name, about;
  std::function<std::string()> markdown;
};

/// The sections' names, each once, in the list's order.
inline std::vector<std::string> key_section_names(const std::vector<SceneKeySection>& sections) {
  std::vector<std::string> names;
  for (const auto& s : sections)
    if (std::find(names.begin(), names.end(), s.name) == names.end()) names.emplace_back(s.name);
  return names;
}

/// The Markdown key tables of every section (`section` empty) or of the sections of that name; an unknown name
/// is an InputError on SECTION listing the valid ones.
inline std::string key_sections_markdown(const std::vector<SceneKeySection>& sections, const std::string& section) {
  std::string md;
  for (const auto& s : sections)
    if (section.empty() || s.name == section)
      md += fmt::format("{}#### `{}` ({})\n\n{}", md.empty() ? "" : "\n", s.name, s.about, s.markdown());
  if (md.empty()) throw InputError("SECTION", section, describe_choices(section, key_section_names(sections)));
  return md;
}

}  // namespace kerf
