#pragma once
// The registry of DEM contact models by name (one line per model in dem/contact_models.cpp).
//
// A scene names the model of bonded contacts and of unjointed contacts; an unknown name is an InputError
// that lists the valid ones:
//
//   ContactModel m = contact_model_by_name("flat_joint", "material.bond_model");
#include <span>
#include <string>
#include <string_view>

namespace kerf::dem {

enum class ContactModel { linear, flat_joint };

struct ContactModelEntry {
  std::string_view name;         ///< the scene name, same as the file pair (dem/<name>.cpp)
  ContactModel model;
  bool bonded;                   ///< true: installed as a joint between neighbours; false: forms on overlap
  std::string_view description;
};

/// Every registered model.
std::span<const ContactModelEntry> contact_models();

/// The model called `name`, which must be bonded (or not) as asked; else InputError on `path`.
const ContactModelEntry& contact_model_by_name(const std::string& name, bool bonded, const std::string& path);

}  // namespace kerf::dem
