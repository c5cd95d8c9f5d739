// The registry of contact models: one line per model.
#include "kerf/dem/contact_models.hpp"

#include <array>
#include <vector>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"

namespace kerf::dem {

namespace {
constexpr std::array kRegistry = {
    ContactModelEntry{"linear", ContactModel::linear, false, "linear spring with Coulomb friction (dem/linear_contact)"},
    ContactModelEntry{"flat_joint", ContactModel::flat_joint, true, "Potyondy's 2D flat joint (dem/flat_joint)"},
};
}  // namespace

std::span<const ContactModelEntry> contact_models() { return kRegistry; }

const ContactModelEntry& contact_model_by_name(const std::string& name, bool bonded, const std::string& path) {
  std::vector<std::string> valid;
  for (const auto& entry : kRegistry) {
    if (entry.bonded != bonded) continue;
    if (entry.name == name) return entry;
    valid.emplace_back(entry.name);
  }
  throw InputError(path, name, describe_choices(name, valid));
}

}  // namespace kerf::dem
