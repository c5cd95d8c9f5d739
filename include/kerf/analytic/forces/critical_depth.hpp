#pragma once
// Which regime a cut is in: the ductile-to-brittle critical depth of Bifano, Dow & Scattergood (1991),
// docs/physics-analytic.md §6:
//
//   d_c = 0.15 (E / H) (K_c / H)^2
//
// with Young's modulus E, hardness H and fracture toughness K_c (SI: Pa, Pa, Pa m^0.5 -> m). It is tens of
// nanometres for glasses and SiC. Below d_c material flows (the ductile analytic models apply, Shao et al. 2013); well
// above it material is removed by fracture (the DEM or the brittle trepanning model, Yu et al. 2023).
//
// Transition band (kerf's choice, documented in RegimeBand): the coefficient 0.15 is an empirical fit (Bifano
// et al. chose it so that d_c marks the depth where fracture damage first appears on ground surfaces) and E,
// H, K_c vary by grade and by test method, so d_c is uncertain by a factor of about 2-3. Depths from d_c to
// 3 d_c are labelled `transition`: fracture has started but ductile removal still carries part of the cut,
// and neither model's assumptions hold cleanly there.
//
//   kerf::BrittleProperties k9 = kerf::brittle_properties(kerf::load_material(kerf::Json("k9_glass"), "material"),
//                                                         "material");
//   double dc_m = kerf::critical_depth_m(k9);                         // ~24 nm
//   kerf::CuttingRegime r = kerf::classify_regime(0.1e-3, dc_m);     // brittle
#include <string>
#include <string_view>

#include "kerf/material.hpp"

namespace kerf {

struct BrittleProperties {
  double youngs_modulus_Pa = 0.0;             ///< E > 0 (material group elastic.youngs_modulus_GPa)
  double hardness_Pa = 0.0;                   ///< H > 0 (brittle.hardness_GPa)
  double fracture_toughness_Pa_sqrt_m = 0.0;  ///< K_c > 0 (brittle.fracture_toughness_MPa_sqrt_m)

  /// Names path.elastic.youngs_modulus_GPa, path.brittle.hardness_GPa, path.brittle.fracture_toughness_MPa_sqrt_m.
  void validate(const std::string& path) const;
};

/// Reads E, H and K_c from a material; InputError names the missing group or key (path.brittle.hardness_GPa)
/// and says the critical depth needs it.
BrittleProperties brittle_properties(const MaterialRecord& material, const std::string& path);

/// d_c = 0.15 (E / H) (K_c / H)^2 in m (Bifano et al. 1991). Validates its input.
double critical_depth_m(const BrittleProperties& properties);

enum class CuttingRegime { ductile, transition, brittle };
std::string_view cutting_regime_name(CuttingRegime regime);  ///< "ductile", "transition", "brittle"

/// depth < d_c: ductile; d_c <= depth < brittle_factor d_c: transition; beyond: brittle.
struct RegimeBand {
  double brittle_factor = 3.0;  ///< >= 1; 1 removes the transition band

  void validate(const std::string& path) const;
};

/// Classifies a depth of cut (or per-grit depth) against d_c. InputError, naming its own field, for a negative or
/// non-finite depth (depth_m) or a non-positive d_c (critical_depth_m).
CuttingRegime classify_regime(double depth_m, double critical_depth_m, const RegimeBand& band = {});

}  // namespace kerf
