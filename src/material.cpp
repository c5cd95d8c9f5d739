#include "kerf/material.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

#include "kerf/error.hpp"
#include "kerf/install.hpp"

namespace kerf {

const std::vector<std::string>& material_group_names() {
  static const std::vector<std::string> names = {"elastic", "thermal", "johnson_cook", "microstructure",
                                                 "oxley",   "brittle", "dem"};
  return names;
}

const std::vector<std::string>& material_group_keys(const std::string& group_name) {
  // The keys of the analytic groups' field tables (analytic/kinds/material_models.cpp), written again here because
  // the tables live in kerf_analytic, which links this library (kerf_core; kerf-dem loads materials without
  // it): tests/analytic/scene_test.cpp checks that the two lists hold the same keys. The "dem" group is
  // checked by the DEM's own reader (dem/laws/material.cpp), key by key.
  static const std::map<std::string, std::vector<std::string>> keys = {
      {"elastic", {"youngs_modulus_GPa", "poissons_ratio", "shear_modulus_GPa"}},
      {"thermal",
       {"density_kg_per_m3", "property_reference_temperature_K", "conductivity_W_per_m_K",
        "conductivity_slope_W_per_m_K2", "specific_heat_J_per_kg_K", "specific_heat_slope_J_per_kg_K2"}},
      {"johnson_cook",
       {"A_MPa", "B_MPa", "C", "m", "n", "reference_strain_rate_per_s", "room_temperature_K", "melting_temperature_K"}},
      {"microstructure",
       {"taylor_factor", "burgers_vector_nm", "grain_size_um", "critical_grain_size_nm", "grain_boundary_stress_ratio",
        "hall_petch_coefficient_MPa_sqrt_m", "alpha", "boundary_constant_k", "misorientation_deg",
        "boundary_spacing_um", "interior_dislocation_density_per_m2"}},
      {"oxley", {"eta", "psi"}},
      {"brittle",
       {"hardness_GPa", "fracture_toughness_MPa_sqrt_m", "constraint_factor", "tensile_strength_MPa",
        "compressive_strength_MPa"}},
  };
  static const std::vector<std::string> any;
  const auto it = keys.find(group_name);
  return it == keys.end() ? any : it->second;
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
  static const std::filesystem::path installed = installed_data_directory();  // include/kerf/install.hpp
  return installed.empty() ? std::filesystem::path(KERF_DEFAULT_DATA_DIR) : installed;
}

std::vector<std::filesystem::path> material_directories() {
  std::vector<std::filesystem::path> dirs;
  if (const char* search = std::getenv("KERF_MATERIAL_PATH"); search && *search) {
    const std::string text = search;
    for (std::size_t start = 0; start <= text.size();) {
      const std::size_t colon = std::min(text.find(':', start), text.size());
      if (colon > start) dirs.emplace_back(text.substr(start, colon - start));
      start = colon + 1;
    }
  }
  dirs.push_back(data_directory() / "materials");
  return dirs;
}

namespace {

/// The file of a library material: the first directory of the search path that holds NAME.json.
std::optional<std::filesystem::path> library_material_file(const std::string& name) {
  for (const auto& dir : material_directories()) {
    const auto file = dir / (name + ".json");
    std::error_code error;
    if (std::filesystem::is_regular_file(file, error)) return file;
  }
  return std::nullopt;
}

bool names_a_file(const std::string& spec) {
  return spec.find('/') != std::string::npos || std::filesystem::path(spec).extension() == ".json";
}

}  // namespace

std::vector<std::string> library_material_names() {
  std::set<std::string> names;
  for (const auto& dir : material_directories()) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
      if (entry.path().extension() == ".json") names.insert(entry.path().stem().string());
    }
  }
  return {names.begin(), names.end()};
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
    const auto& valid = material_group_keys(group_name);
    for (const auto& [key, value] : object.at(group_name).items()) {
      const std::string key_path = fmt::format("{}.{}.{}", path, group_name, key);
      if (!valid.empty() && std::find(valid.begin(), valid.end(), key) == valid.end()) {
        throw InputError(key_path, json_value_text(value),
                         fmt::format("a key of the {} group: {}", group_name, describe_choices(key, valid)));
      }
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

MaterialRecord load_material(const Json& spec, const std::string& path, const std::string& needed_group) {
  if (spec.is_object()) {
    MaterialRecord record = material_from_json(spec, path, /*require_provenance=*/false);
    record.origin = "inline";
    return record;
  }
  if (!spec.is_string()) {
    throw InputError(path, json_value_text(spec), "a material name, a material file (.json) or an inline object");
  }
  const std::string name = spec.get<std::string>();
  if (names_a_file(name)) {
    // A material of the user's own, by path: the library's form, provenance optional.
    std::error_code error;
    if (!std::filesystem::is_regular_file(name, error)) {
      throw InputError(path, name, "a readable material file (a path with '/' or ending in .json)");
    }
    MaterialRecord record = material_from_json(read_json_file(name), path, /*require_provenance=*/false);
    if (record.name == "inline") record.name = std::filesystem::path(name).stem().string();
    record.origin = name;
    return record;
  }
  const auto file = library_material_file(name);
  if (!file) {
    std::string where;
    for (const auto& dir : material_directories()) where += (where.empty() ? "" : ", ") + dir.string();
    // Only the materials this use can take: a DEM scene suggests none without a "dem" group.
    std::vector<std::string> names;
    for (const auto& candidate : library_material_names()) {
      if (!needed_group.empty()) {
        try {
          const auto candidate_file = library_material_file(candidate);
          const Json document = read_json_file(candidate_file->string());
          if (!document.is_object() || !document.contains(needed_group)) continue;
        } catch (const std::exception&) {
          continue;  // a library file that does not read is not a suggestion
        }
      }
      names.push_back(candidate);
    }
    throw InputError(path, name,
                     describe_choices(name, names) +
                         (needed_group.empty() ? "" : fmt::format(" (the materials with a '{}' group)", needed_group)) +
                         " from " + where + " (or a material file by its path)");
  }
  MaterialRecord record = material_from_json(read_json_file(file->string()), path, /*require_provenance=*/true);
  record.origin = file->string();
  return record;
}

std::vector<LibraryMaterial> library_materials() {
  std::vector<LibraryMaterial> out;
  for (const auto& name : library_material_names()) {
    LibraryMaterial entry{name, std::nullopt, ""};
    try {
      entry.record = load_material(Json(name), "material");
    } catch (const InputError& e) {
      entry.error = e.what();
    }
    out.push_back(std::move(entry));
  }
  return out;
}

}  // namespace kerf
