#pragma once
// An analytic scene: the JSON file a user writes, validated into SI parameter structs. Only the models the scene
// names are built. Each section is read through a field table (kerf/field_table.hpp) in analytic/kinds/scene.cpp: the
// defaults are the member initialisers below (and the models' parameter blocks' own), and docs/scenes.md's key
// tables are the tables' output (`kerf-forces keys`, analytic_scene_keys_markdown).
//
//   kerf::Json doc = kerf::read_json_file("data/scenes/psic_liu_li.json");
//   kerf::apply_override(doc, "tool.edge_radius_um=0.2");
//   kerf::AnalyticScene scene = kerf::parse_analytic_scene(doc);
//   kerf::Prediction p = kerf::predict(scene);                      // predict.hpp
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "kerf/analytic/flow_stress/flow_stress.hpp"
#include "kerf/analytic/flow_stress/thermal.hpp"
#include "kerf/analytic/forces/contact_length.hpp"
#include "kerf/analytic/forces/shear_angle.hpp"
#include "kerf/analytic/kinds/force_model.hpp"
#include "kerf/analytic/kinds/material_models.hpp"
#include "kerf/analytic/kinds/model_params.hpp"
#include "kerf/analytic/kinds/round_nose.hpp"
#include "kerf/material.hpp"
#include "kerf/units.hpp"

namespace kerf {

struct AnalyticModelInfo;  // registry.hpp

/// r / t0 below which the edge changes the force by only a few percent: models.force = auto takes the
/// sharp-tool model there, and the sharp-tool models warn above it.
inline constexpr double kSharpEdgeRatio = 0.05;
enum class DeformationModel { room_temperature, given, oxley };
enum class ShearAngleSource { merchant, lee_shaffer, chip_ratio };
enum class TurningThickness { equivalent, maximum };

/// One requested contact-length column: the model and the shear-angle relation (MEP or MSSP) it uses.
struct ContactLengthRequest {
  ContactLengthModel model;
  ShearAngleModel shear_angle;  ///< merchant = MEP, lee_shaffer = MSSP
  std::string column;           ///< "contact_length_lee_shaffer_mm"
};

struct TurningScene {
  RoundNoseTurning geometry;
  TurningThickness thickness = TurningThickness::equivalent;
  TurningChip chip;
};

struct AnalyticScene {
  std::shared_ptr<const MaterialRecord> material;  ///< shared with the MaterialCache (a sweep's points share it)

  // Tool
  double rake_rad = 0.0;
  double edge_radius_m = 0.0;
  double clearance_rad = units::deg_to_rad(7.0);  ///< tool.clearance_deg (recorded, not used by the ductile models)

  // Cut (for turning, thickness and width come from the round-nose chip)
  double uncut_chip_thickness_m = 0.0;
  double width_m = 0.0;
  double speed_m_per_s = 0.0;
  double workpiece_temperature_K = 293.15;  ///< default: the Johnson-Cook room temperature, else this
  std::optional<TurningScene> turning;
  std::optional<double> friction_angle_rad;  ///< given, from a friction coefficient, or from measured forces
  std::string friction_origin;               ///< "friction_angle_deg", "friction_coefficient", "measured forces"
  std::optional<double> chip_ratio;
  std::optional<double> friction_factor;  ///< tau / k on the edge, for the ploughing model (else from beta)
  std::optional<DeformationState> given_state;
  std::optional<double> given_strain_rate_per_s;  ///< for the room_temperature deformation model

  // Models
  /// The registry line of the force model named, or of the one 'auto' chose (set by parse_analytic_scene).
  const AnalyticModelInfo* force = nullptr;
  bool force_auto = true;           ///< the scene asked for 'auto' (CSV columns then cover every choice)
  std::string force_choice_reason;  ///< why 'auto' chose the force model (empty when named)
  FlowStressModel flow_stress;
  std::vector<std::string> flow_stress_terms = {"johnson_cook"};
  bool flow_stress_named = false;  ///< the scene named models.flow_stress (else a glass takes its hardness term)
  DeformationModel deformation = DeformationModel::room_temperature;
  ShearAngleSource shear_angle = ShearAngleSource::merchant;
  ShearAngleModel contact_shear_angle = ShearAngleModel::merchant;  ///< of contact-length names without a suffix
  std::vector<ContactLengthRequest> contact_lengths;

  /// Bifano's ductile-brittle critical depth, when the material has E, hardness and toughness.
  std::optional<double> critical_depth_m;

  // The models' own parameters: each block declared by its unit and carried by its registry line
  // (kinds/model_params.hpp), read through the unit's field tables (kinds/scene.cpp composes the `models` section of
  // the registry's blocks) and validated there, once. A unit reads its block with params<P>(): ChipTermParams
  // (forces/chip_term.hpp), TransitionParams (forces/transition_model.hpp), OxleyModelParams (forces/oxley_model.hpp).
  ModelParamsSet model_params;
  /// The parameter block of type P: the scene's values, or P's defaults where the scene gave none.
  template <class P>
  const P& params() const {
    return model_params.get<P>();
  }
  template <class P>
  P& params() {
    return model_params.get<P>();
  }

  /// The force model of `force`'s line (kinds/force_model.hpp).
  const OrthogonalForceModel& force_model() const;
};

/// Caches library materials between scenes of a sweep (a file is read once). Thread-safe: sweeps parse
/// scenes on several threads.
class MaterialCache {
 public:
  const MaterialRecord& get(const Json& spec, const std::string& path) { return *share(spec, path); }
  /// The record as get() gives it, shared.
  std::shared_ptr<const MaterialRecord> share(const Json& spec, const std::string& path);

  /// derive(record, "material") (johnson_cook_from_material, ...), computed once per record and function:
  /// `record` must be one this cache returned. A failure is not kept: the next call throws it again.
  template <class T>
  T derived(const MaterialRecord& record, T (*derive)(const MaterialRecord&, const std::string&)) {
    const auto key = std::make_pair(static_cast<const void*>(&record), reinterpret_cast<std::uintptr_t>(derive));
    {
      std::lock_guard lock(mutex_);
      if (auto it = derived_.find(key); it != derived_.end()) return *static_cast<const T*>(it->second.get());
    }
    auto value = std::make_shared<const T>(derive(record, "material"));
    std::lock_guard lock(mutex_);
    return *static_cast<const T*>(derived_.try_emplace(key, std::move(value)).first->second.get());
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const MaterialRecord>> records_;
  std::map<std::pair<const void*, std::uintptr_t>, std::shared_ptr<const void>> derived_;
};

/// A kerf-dem scene (one with a "kind") given to the analytic models: InputError naming its kind and the program
/// that runs it, before any other key is read. The analytic scene parsers call it first.
void refuse_dem_scene(const Json& document);

/// Validates a scene document. Throws InputError naming the first bad field.
AnalyticScene parse_analytic_scene(const Json& document, MaterialCache* cache = nullptr);

/// The sections of the analytic scenes' key reference ("tool", "cut", "cut.turning", ..., "models.trepanning"), in
/// the order analytic_scene_keys_markdown prints them (a name may stand for two tables: the orthogonal and the
/// trepanning scene's `tool`).
std::vector<std::string> analytic_scene_sections();
/// The key reference of one section ("" for all) as Markdown, from the field tables the parsers read with
/// (`kerf-forces keys`, docs/scenes.md): "#### `tool` (about)" and a table per section. An unknown section is an
/// InputError on SECTION listing the valid ones.
std::string analytic_scene_keys_markdown(const std::string& section = "");

}  // namespace kerf
