#pragma once
// The flow stress of a glass or ceramic from its hardness (docs/models.md, "Glass and ceramics"): hardness is a
// mean contact pressure, not a yield stress; the two are tied by a constraint factor C = H / Y.
//
//   given            Y = H / C, C from the material (brittle.constraint_factor; glasses 1.5-2, Marsh 1964)
//   marsh            H / Y = B + K ln(E / Y)                        (Marsh, Proc. R. Soc. A 279:420, 1964)
//   johnson_cavity   H / Y = (2/3) [1 + ln(E* tan(beta) / (3 Y))]   (Johnson, J. Mech. Phys. Solids 18:115, 1970)
//
// with E* = E / (1 - nu^2) and beta = 19.7 deg, the face inclination of the cone of a Vickers indenter's area.
// The two cavity forms are implicit in Y: H = Y C(E / Y). kerf takes the root with C >= 1 (Y at most H, on the
// branch where H rises with Y); a material whose H / E needs C < 1 in that form is refused (InputError on
// brittle.hardness_GPa, with the largest H / E the form allows: 0.212 for Marsh, 0.0724 (1 - nu^2)^-1 for
// Johnson). Soda-lime glass (H / E* = 0.073) lies just beyond Johnson's reach: the cavity model does not hold
// for glass, whose hardness is partly densification (docs/models.md). No rate or temperature dependence: a glass at
// room temperature far below its transition temperature; kerf cites no source for one.
//
//   kerf::HardnessFlowParams glass{.hardness_Pa = 5.5e9, .youngs_modulus_Pa = 71e9, .poissons_ratio = 0.23,
//                                  .constraint_factor = 1.7};
//   double y_Pa = kerf::hardness_yield_stress_Pa(glass, kerf::ConstraintModel::given);   // 3.24 GPa
#include <optional>
#include <string>
#include <string_view>

namespace kerf {

enum class ConstraintModel { given, marsh, johnson_cavity };
std::string_view constraint_model_name(ConstraintModel model);  ///< "hardness", "hardness_marsh", ...

struct HardnessFlowParams {
  double hardness_Pa = 0.0;                 ///< H > 0 (material brittle.hardness_GPa)
  double youngs_modulus_Pa = 0.0;           ///< E > H (material elastic.youngs_modulus_GPa)
  double poissons_ratio = 0.0;              ///< nu in [0, 0.5) (material elastic.poissons_ratio), for Johnson's E*
  std::optional<double> constraint_factor;  ///< C = H / Y >= 1 (brittle.constraint_factor), for `given`

  /// Names path.brittle.hardness_GPa, path.elastic.youngs_modulus_GPa, path.brittle.constraint_factor.
  void validate(const std::string& path, ConstraintModel model) const;
};

/// Marsh's constants, H / Y = B + K ln(E / Y), as later reviews quote his fit (docs/models.md: his own fit was
/// in Hill's cavity parameter; the form's B is uncertain by about 0.2).
inline constexpr double kMarshB = 0.07;
inline constexpr double kMarshK = 0.60;
/// Face inclination of the cone with a Vickers pyramid's area-to-depth ratio (semi-angle 70.3 deg).
inline constexpr double kVickersConeInclinationDeg = 19.7;

/// The constraint factor H / Y of a form at E / Y = `modulus_over_yield` (Johnson's uses E* / Y).
double constraint_factor(ConstraintModel model, double modulus_over_yield, double poissons_ratio);
/// The largest H / E the implicit forms give with a constraint factor of at least 1 (Y <= H); +inf for given.
double largest_hardness_over_modulus(ConstraintModel model, double poissons_ratio);
/// The yield stress Y in Pa (validated input; for the implicit forms the root with C >= 1).
double hardness_yield_stress_Pa(const HardnessFlowParams& params, ConstraintModel model);

}  // namespace kerf
