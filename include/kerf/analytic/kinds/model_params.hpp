#pragma once
// A model's parameters as a unit of its own, as a DEM law's are: the unit declares its parameter block (ModelParams:
// its keys among the scene's `models`, and the objects of its own under `models`), its registry line carries it
// (AnalyticModelInfo::params, analytic/registry.cpp), and the orthogonal scene composes the blocks of the registry's
// lines into its `models` section (kinds/scene.cpp): it reads, range-checks and lists them without naming their
// types. The scene keeps each block's values in a ModelParamsSet; a unit reads its own through the scene.
//
//   struct ToyParams { double specific_force_Pa = 2e9; };
//   const kerf::FieldTable<ToyParams>& toy_fields();    // number_field("toy_specific_force_MPa", ...)
//   const kerf::ModelParams toy_params{.fields = [] { return kerf::scene_params_fields(toy_fields()); }};
//   double k_c = scene.params<ToyParams>().specific_force_Pa;   // its defaults where the scene gave none
#include <any>
#include <list>
#include <span>
#include <string>
#include <string_view>

#include "kerf/field_table.hpp"
#include "kerf/json_reader.hpp"

namespace kerf {

struct AnalyticScene;  // scene.hpp

/// The parameter blocks of a scene, one per type, each made from its defaults when first written.
class ModelParamsSet {
 public:
  /// The block of type P: the scene's values, or P's defaults (its member initialisers) where it holds none.
  template <class P>
  const P& get() const {
    for (const auto& block : blocks_)
      if (const P* p = std::any_cast<P>(&block)) return *p;
    static const P defaults{};
    return defaults;
  }
  /// The block of type P, made from its defaults at the first call.
  template <class P>
  P& get() {
    for (auto& block : blocks_)
      if (P* p = std::any_cast<P>(&block)) return *p;
    return std::any_cast<P&>(blocks_.emplace_back(std::in_place_type<P>));
  }

 private:
  std::list<std::any> blocks_;  ///< a list: a block's reference stays valid when another block is added
};

/// An object of a block's own under `models` (models.quadrature, models.transition): read into the scene, and a
/// section of the key reference.
struct ModelParamsObject {
  std::string_view section;  ///< "models.quadrature": the section's name, the object's key after "models."
  std::string_view about;    ///< the key reference's line on it
  /// Reads (and range-checks) its fields into the scene; the caller finds the object and finishes it.
  void (*read)(ObjectReader& object, AnalyticScene& scene) = nullptr;
  std::string (*markdown)() = nullptr;  ///< its key table (fields_markdown of the table read())

  /// Its key under `models` ("quadrature").
  std::string_view key() const { return section.substr(section.find('.') + 1); }
};

/// A model's parameter block, as its unit declares it and its registry line carries it.
struct ModelParams {
  /// Its keys among the scene's `models`, as fields of the scene (scene_params_fields of the block's table).
  FieldTable<AnalyticScene> (*fields)() = nullptr;
  std::span<const ModelParamsObject> objects = {};  ///< its objects under `models`, in the order they are read
};

/// The fields of a block's table (P's) as fields of the scene, through scene.params<P>(): a ModelParams::fields.
template <class P, class S = AnalyticScene>
FieldTable<S> scene_params_fields(const FieldTable<P>& table) {
  return fields_of_part<S>(
      table, [](auto& scene) -> auto& { return scene.template params<P>(); });
}

}  // namespace kerf
