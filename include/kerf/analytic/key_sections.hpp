#pragma once
// One section of the analytic scenes' key reference (`kerf-forces keys`, docs/scenes.md): its name
// ("models.trepanning"), where it applies, and its Markdown table, printed from the field table the section is
// read with (kerf/field_table.hpp).
#include <functional>
#include <string>
#include <string_view>

namespace kerf {

struct SceneKeySection {
  std::string_view name, about;
  std::function<std::string()> markdown;
};

}  // namespace kerf
