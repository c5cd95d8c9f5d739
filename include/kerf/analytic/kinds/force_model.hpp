#pragma once
// A force model of the orthogonal kind as one unit, as a DEM law is one (dem/laws/): what the kind calls to predict
// with it, and what the model owns besides its physics: its details (kept in the prediction) and how they are
// written (its CSV columns, a result table, and its lines of the report). The kind calls these and never asks which
// model a scene names; the model's registry line carries the unit (analytic/registry.cpp). How to add one:
// docs/analytic-models.md.
//
//   void predict_toy(const kerf::AnalyticScene&, const kerf::OxleyResult*, kerf::Prediction& p);
//   const kerf::ResultTable<kerf::PredictionReport>& toy_results();   // its columns (kerf/result_table.hpp)
//   const kerf::OrthogonalForceModel toy_force_model{.predict = &predict_toy, .results = &toy_results};
#include <cstdio>
#include <string>
#include <string_view>

#include "kerf/result_table.hpp"

namespace kerf {

struct AnalyticScene;     // scene.hpp
struct Prediction;        // predict.hpp
struct OxleyResult;       // forces/oxley.hpp
struct PredictionReport;  // predict.hpp

struct OrthogonalForceModel {
  /// Fills p's forces, shear angle, friction angle, chip ratio and thickness, deformation state and flow stress
  /// (and its own details: p.details), with its guards and warnings; p arrives with the width, the thickness, the
  /// regime and the Oxley details set. `oxley`: the extended-Oxley solve at t0 where the scene asked for one (force
  /// oxley or deformation oxley), else nullptr. Throws InputError / ModelError.
  void (*predict)(const AnalyticScene& scene, const OxleyResult* oxley, Prediction& p) = nullptr;
  /// The model is the extended-Oxley solve: the scene reads the material's johnson_cook, thermal and oxley
  /// groups for it; it predicts its own friction angle (no friction data needed, the scene's is not used), its
  /// flow stress is Johnson-Cook alone, and it ignores the edge (the ploughing columns stay empty).
  bool solves_oxley = false;
  /// The CSV carries the Liu-Li edge-integral and ploughing-model columns (forces/chip_term.hpp, edge_results).
  bool edge_columns = false;
  /// `auto` only: picks the model for the scene as read (the name of another force line) and says why.
  std::string_view (*choose)(const AnalyticScene& scene, std::string* reason) = nullptr;
  /// The deepest cut a model that spans the ductile-brittle transition was held against: no warning above the
  /// critical depth, one beyond this depth. 0: a ductile-regime model, warned above the critical depth.
  double validated_depth_m = 0.0;
  /// Its own CSV columns, a result table of its details, in the row's order (after the shared columns and the edge
  /// and Oxley details, before the turning cut's): the row, the docs' column tables and Python's key names
  /// (kerf-forces results) come from it. Its getters read an empty prediction too (before predict(): the column
  /// names). nullptr: no columns of its own.
  const ResultTable<PredictionReport>& (*results)() = nullptr;
  /// Its own lines of the text report (after the edge integral's, before the Oxley solve's).
  void (*print)(std::FILE* text, const AnalyticScene& scene, const Prediction& p) = nullptr;
};

// What the units share (kinds/predict.cpp); the chip term that Merchant, Liu-Li and the transition model share is a
// unit of its own (forces/chip_term.hpp).

/// Two friction angles closer than this are the same (rounding of the closures' identities).
inline constexpr double kSameAngle_rad = 1e-9;

/// Contact lengths (Berezvai et al. 2019, Eqs. 1-4) of the scene's requests with the prediction's own friction angle.
/// A variant outside its domain is not applicable: its cell stays empty, the guard and a warning say why.
void add_contact_lengths(const AnalyticScene& scene, double friction_angle_rad, Prediction& p);
/// The sharp-tool models (Merchant, Oxley) ignore the edge: a warning, with `model_and_remedy`, when it is not small
/// against t0.
void warn_if_edge_ignored(const AnalyticScene& scene, const char* model_and_remedy, Prediction& p);

}  // namespace kerf
