#pragma once
// Materials: the bundled library in data/materials/ and inline scene materials.
//
// A material file is JSON with a name, a title and groups of properties. Each property is a number with its
// unit in its key, written either bare (inline scene materials) or with its provenance (library files):
//
//   "johnson_cook": { "A_MPa": {"value": 553.1, "source": "Jaspers & Dautzenberg 2002"},
//                     "m":     {"value": 1.0,   "assumed": "why this value"} }
//
// The shared layer checks the form and keeps the provenance; each module reads and validates the groups it
// needs (the analytic models: elastic, thermal, johnson_cook, microstructure, oxley, brittle; the DEM: dem).
//
//   kerf::MaterialRecord steel = kerf::load_material(kerf::Json("aisi_1045"), "material");
//   const kerf::Json* jc = steel.group("johnson_cook");   // {"A_MPa": 553.1, ...}
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kerf/json_reader.hpp"

namespace kerf {

/// The groups a material may hold.
const std::vector<std::string>& material_group_names();

struct MaterialRecord {
  std::string name;
  std::string title;
  std::string origin;                             ///< the file it came from, or "inline"
  Json groups = Json::object();                   ///< group -> {key: number}; provenance stripped
  std::map<std::string, std::string> provenance;  ///< "group.key" -> "source: ..." or "assumed: ..."

  /// The group's object, or nullptr when the material has no such group.
  const Json* group(const std::string& group_name) const;
  /// Throws InputError naming `path`.group when the group is missing (`purpose` says who needs it).
  const Json& require_group(const std::string& group_name, const std::string& path, const std::string& purpose) const;
};

/// The directory of bundled data: $KERF_DATA_DIR if set, else the source tree's data/ (compiled in).
std::filesystem::path data_directory();

/// Names of the materials in data/materials/ (file stems), sorted.
std::vector<std::string> library_material_names();

/// Parses a material object. With `require_provenance`, every number must carry "source" or "assumed".
MaterialRecord material_from_json(const Json& object, const std::string& path, bool require_provenance);

/// A scene's `material`: a library name, a file (a string with '/' or ending in .json: "/path/glass.json",
/// provenance optional), or an inline object. Unknown names list the library; with `needed_group` ("dem"), only
/// the library's materials that have that group.
MaterialRecord load_material(const Json& spec, const std::string& path, const std::string& needed_group = "");

/// One material of the bundled library as listings show it: its record, or why it did not load.
struct LibraryMaterial {
  std::string name;
  std::optional<MaterialRecord> record;
  std::string error;  ///< the InputError's message when `record` is empty
};

/// Every bundled material (library_material_names()), each loaded; one that fails to load is listed with its error.
std::vector<LibraryMaterial> library_materials();

}  // namespace kerf
