#include "kerf/material.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "kerf/error.hpp"

namespace kerf {

const std::vector<std::string>& material_group_names() {
  static const std::vector<std::string> names = {"elastic", "thermal", "johnson_cook", "microstructure",
                                                 "oxley",   "brittle", "dem"};
  return names;
}

const Json* MaterialRecord::group(const std::string& group_name) const {
  auto it = groups.find(group_name);
  return it == groups.end() ? nullptr : &*it;
}

const Json& MaterialRecord::require_group(const std::string& group_name, const std::string& path,
                                          const std::string& purpose) const {
  if (const Json* g = group(group_name)) return *g;
  throw InputError(fmt::format("{}.{}", path, group_name), fmt::format("(missing in material '{}')", name),
                   fmt::format("a '{}' group: {} needs it", group_name, purpose));
}

std::filesystem::path data_directory() {
  if (const char* dir = std::getenv("KERF_DATA_DIR"); dir && *dir) return dir;
  return KERF_DEFAULT_DATA_DIR;
}

std::vector<std::string> library_material_names() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(data_directory() / "materials", error)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

MaterialRecord material_from_json(const Json& object, const std::string& path, bool require_provenance) {
  ObjectReader reader(object, path);
  MaterialRecord record;
  record.name = reader.get_string_or("name", "inline");
  record.title = reader.get_string_or("title", record.name);
  reader.ignore("description");
  for (const auto& group_name : material_group_names()) {
    auto group = reader.find_object(group_name);
    if (!group) continue;
    Json plain = Json::object();
    for (const auto& [key, value] : object.at(group_name).items()) {
      const std::string key_path = fmt::format("{}.{}.{}", path, group_name, key);
      group->ignore(key);
      if (value.is_number()) {
        if (require_provenance) {
          throw InputError(key_path, json_value_text(value), R"({"value": ..., "source": "..."} or "assumed")");
        }
        plain[key] = value;
        continue;
      }
      if (group_name == "dem" && !value.is_object()) {  // the DEM group also holds names and counts
        plain[key] = value;
        continue;
      }
      ObjectReader property(value, key_path);
      plain[key] = property.get("value");
      const Json* source = property.find("source");
      const Json* assumed = property.find("assumed");
      if (source && source->is_string()) {
        record.provenance[group_name + "." + key] = "source: " + source->get<std::string>();
      } else if (assumed && assumed->is_string()) {
        record.provenance[group_name + "." + key] = "assumed: " + assumed->get<std::string>();
      } else if (require_provenance) {
        throw InputError(key_path, json_value_text(value), "a \"source\" or an \"assumed\" string beside the value");
      }
      property.finish();
    }
    record.groups[group_name] = std::move(plain);
  }
  reader.finish();
  return record;
}

MaterialRecord load_material(const Json& spec, const std::string& path) {
  if (spec.is_object()) {
    MaterialRecord record = material_from_json(spec, path, /*require_provenance=*/false);
    record.origin = "inline";
    return record;
  }
  if (!spec.is_string()) throw InputError(path, json_value_text(spec), "a material name or an inline object");
  const std::string name = spec.get<std::string>();
  const auto names = library_material_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw InputError(path, name, describe_choices(name, names) + " from " + (data_directory() / "materials").string());
  }
  const auto file = data_directory() / "materials" / (name + ".json");
  MaterialRecord record = material_from_json(read_json_file(file.string()), path, /*require_provenance=*/true);
  record.origin = file.string();
  return record;
}

}  // namespace kerf
