#include "kerf/comparison_config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "kerf/error.hpp"

namespace kerf {

namespace {

const std::map<std::string, Unit>& unit_table() {
  static const std::map<std::string, Unit> table = {
      {"", {"", "", 1.0}},
      {"nm", {"nm", "nm", 1e-9}},
      {"mm", {"mm", "mm", 1e-3}},
      {"um", {"µm", "um", 1e-6}},
      {"um/s", {"µm/s", "um_per_s", 1e-6}},
      {"mm/s", {"mm/s", "mm_per_s", 1e-3}},
      {"m/s", {"m/s", "m_per_s", 1.0}},
      {"m/min", {"m/min", "m_per_min", 1.0 / 60.0}},
      {"rpm", {"rev/min", "rpm", 1.0 / 60.0}},
      {"deg", {"°", "deg", 0.017453292519943295}},
      {"N", {"N", "N", 1.0}},
      {"mN", {"mN", "mN", 1e-3}},
      {"kN", {"kN", "kN", 1e3}},
      {"N m", {"N·m", "N_m", 1.0}},
      {"N/mm", {"N/mm", "N_per_mm", 1e3}},
      {"K", {"K", "K", 1.0}},
      {"MPa", {"MPa", "MPa", 1e6}},
      {"GPa", {"GPa", "GPa", 1e9}},
      {"1/s", {"1/s", "per_s", 1.0}},
      {"um/rev", {"µm/rev", "um_per_rev", 1e-6}},
  };
  return table;
}

struct SideSpec {
  CsvBinding binding;
  std::filesystem::path file;
};

SideSpec read_side(ObjectReader& side, const ComparisonSpec& spec, const std::filesystem::path& base) {
  SideSpec out;
  out.file = side.get_string("file");
  if (out.file.is_relative()) out.file = (base / out.file).lexically_normal();
  out.binding.name = side.get_string("name");
  if (auto filter = side.find_object("filter")) {
    for (const auto& [column, value] : side.get("filter").items()) {
      filter->ignore(column);
      if (!value.is_string()) {
        throw InputError(filter->key_path(column), json_value_text(value), "the text the column must hold");
      }
      out.binding.row_filter.emplace_back(column, value.get<std::string>());
    }
  }
  ObjectReader columns = side.get_object("columns");
  for (const auto& c : spec.conditions) {
    out.binding.condition_columns.push_back(columns.get_string(c.key));
    out.binding.condition_si.push_back(c.unit.si);
  }
  std::vector<WidthBasis> bases;
  WidthBasis basis = WidthBasis::none();
  if (const Json* width = side.find("width")) {
    const std::string path = side.key_path("width");
    if (width->is_string()) {
      if (width->get<std::string>() != "per_unit_width") {
        throw InputError(path, width->get<std::string>(),
                         R"("per_unit_width", {"mm": width} or {"column_mm": column})");
      }
      basis = WidthBasis::per_unit_width();
    } else {
      ObjectReader w(*width, path);
      if (w.has("column_mm")) {
        out.binding.width_column_mm = w.get_string("column_mm");
        basis = WidthBasis::total(0.0);  // filled from the column
      } else {
        basis = WidthBasis::total(w.get_number("mm", Range::positive(), "mm") * 1e-3);
      }
      w.finish({"mm", "column_mm"});
    }
  }
  for (const auto& q : spec.quantities) {
    // A quantity the set does not hold is simply absent from its columns.
    out.binding.quantity_columns.push_back(columns.has(q.key) ? columns.get_string(q.key) : "");
    out.binding.quantity_si.push_back(q.unit.si);
    // Torques (a unit without a force) never carry a width basis.
    out.binding.bases.push_back(q.unit.suffix == "N" || q.unit.suffix == "N_per_mm" ? basis : WidthBasis::none());
  }
  columns.finish();
  side.finish();
  return out;
}

}  // namespace

const std::vector<std::string>& unit_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [name, unit] : unit_table()) n.push_back(name);
    return n;
  }();
  return names;
}

std::string key_label(std::string_view key_path) {
  std::string key(key_path.substr(key_path.rfind('.') == std::string_view::npos ? 0 : key_path.rfind('.') + 1));
  const Unit* unit = nullptr;
  for (const auto& [name, candidate] : unit_table()) {
    const std::string tail = "_" + candidate.suffix;
    if (candidate.suffix.empty() || key.size() <= tail.size() || !key.ends_with(tail)) continue;
    if (!unit || candidate.suffix.size() > unit->suffix.size()) unit = &candidate;  // m_per_min, not min
  }
  if (unit) key.resize(key.size() - unit->suffix.size() - 1);
  std::replace(key.begin(), key.end(), '_', ' ');
  return unit ? fmt::format("{} ({})", key, unit->label) : key;
}

Unit unit_named(const std::string& name, const std::string& path) {
  const auto it = unit_table().find(name);
  if (it == unit_table().end()) throw InputError(path, name, describe_choices(name, unit_names()));
  return it->second;
}

ComparisonConfig parse_comparison_config(const Json& document, const std::filesystem::path& base) {
  ObjectReader root(document, "");
  ComparisonConfig config;
  ComparisonSpec& spec = config.spec;
  spec.title = root.get_string_or("title", "Force comparison");
  spec.description = root.get_string_or("description", "");  // quoted at the top of report.md
  spec.relative_tolerance = root.get_number_or("relative_tolerance", 1e-6, Range{0.0, 0.5, false, true}, "");

  const Json& conditions = root.get("conditions");
  if (!conditions.is_array()) throw InputError("conditions", json_value_text(conditions), "an array of conditions");
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    ObjectReader c(conditions[i], fmt::format("conditions[{}]", i));
    ConditionSpec cs;
    cs.key = c.get_string("key");
    cs.label = c.get_string_or("label", cs.key);
    cs.numeric = !c.get_bool_or("text", false);
    cs.unit = cs.numeric ? unit_named(c.get_string_or("unit", ""), c.key_path("unit")) : Unit{};
    c.finish({"unit"});
    spec.conditions.push_back(std::move(cs));
  }
  const Json& quantities = root.get("quantities");
  if (!quantities.is_array() || quantities.empty()) {
    throw InputError("quantities", json_value_text(quantities), "a non-empty array of quantities");
  }
  for (std::size_t i = 0; i < quantities.size(); ++i) {
    ObjectReader q(quantities[i], fmt::format("quantities[{}]", i));
    QuantitySpec qs;
    qs.key = q.get_string("key");
    qs.label = q.get_string_or("label", qs.key);
    qs.unit = unit_named(q.get_string("unit"), q.key_path("unit"));
    q.finish();
    spec.quantities.push_back(std::move(qs));
  }
  if (const Json* views = root.find("views")) {
    if (!views->is_array()) throw InputError("views", json_value_text(*views), "an array of view names");
    for (std::size_t i = 0; i < views->size(); ++i) {
      const Json& v = (*views)[i];
      const std::string name = v.is_string() ? v.get<std::string>() : json_value_text(v);
      if (name == "as_published") {
        spec.views.push_back(WidthView::as_published);
      } else if (name == "per_unit_width") {
        spec.views.push_back(WidthView::per_unit_width);
      } else {
        throw InputError(fmt::format("views[{}]", i), name, describe_choices(name, {"as_published", "per_unit_width"}));
      }
    }
  }
  spec.validate();

  ObjectReader measured = root.get_object("measured");
  const SideSpec m = read_side(measured, spec, base);
  config.measured = dataset_from_csv(read_csv_file(m.file), spec, m.binding);
  const Json& predictions = root.get("predictions");
  if (!predictions.is_array() || predictions.empty()) {
    throw InputError("predictions", json_value_text(predictions), "a non-empty array of predicted data sets");
  }
  for (std::size_t i = 0; i < predictions.size(); ++i) {
    ObjectReader p(predictions[i], fmt::format("predictions[{}]", i));
    const SideSpec side = read_side(p, spec, base);
    config.predictions.push_back(dataset_from_csv(read_csv_file(side.file), spec, side.binding));
  }
  root.finish();
  return config;
}

ComparisonConfig read_comparison_config(const std::filesystem::path& file) {
  return parse_comparison_config(read_json_file(file.string()), file.parent_path());
}

Comparison run_comparison(const ComparisonConfig& config) {
  std::vector<PredictedSet> predictions;
  for (const auto& p : config.predictions) predictions.push_back({p, {}});
  return compare(config.spec, config.measured, predictions);
}

}  // namespace kerf
