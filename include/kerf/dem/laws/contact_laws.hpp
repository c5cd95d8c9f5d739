#pragma once
// The registry of the DEM's contact laws: the bonded laws (installed between neighbours at genesis) and the
// unbonded contact laws (formed on overlap, disk-disk and disk-wall). A material names one of each
// (material.bond_model, material.contact_model); the engine instantiates its loops once per law and
// dispatches once per loop (std::visit), never per contact.
//
// A law is a parameter struct with its name, description and field table (kerf/field_table.hpp) and the
// functions of the concepts below, overloaded on that struct. Adding a law is its own file pair, its type in
// one of the two lists below, and its tests: docs/dem-contact-laws.md.
//
//   BondLaw law = law_by_name<BondLaw>("flat_joint", "material.bond_model");
//   read_law(reader, law);                     // its keys from the material object, validated
//   std::visit([](const auto& p) { ... }, law);
#include <concepts>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "kerf/dem/laws/flat_joint.hpp"
#include "kerf/dem/laws/law.hpp"
#include "kerf/dem/laws/linear_contact.hpp"
#include "kerf/dem/laws/parallel_bond.hpp"
#include "kerf/dem/laws/softening_flat_joint.hpp"
#include "kerf/field_table.hpp"

namespace kerf::dem {

/// What every law's parameter struct has: a name, a description, a field table and a validation.
template <class P>
concept LawParams = requires(const P& p) {
  { P::kName } -> std::convertible_to<std::string_view>;
  { P::kDescription } -> std::convertible_to<std::string_view>;
  { P::fields() } -> std::same_as<const FieldTable<P>&>;
  { P::validated(p) } -> std::same_as<P>;
};

/// A bond law's update and energy from the elements' shear forces and bonded flags alone (the flat joint, the
/// parallel bond).
template <class P>
concept BondLawWithoutState = requires(const P& p, const BondGeometry& g, const BondKinematics& k, double* shear,
                                       const std::uint8_t* bonded, BreakMode* breaks) {
  { bond_update(p, g, k, shear, bonded, breaks) } -> std::same_as<BondResult>;
  { bond_energy(p, g, k, shear, bonded) } -> std::same_as<double>;
};

/// A bond law with a state of its own per element besides (the softening flat joint's damage): it names its doubles
/// per element (P::kElementState, each name the element_<name> key of a specimen file); its update and energy take
/// the bond's `state` too, bond_elements(p) * kElementState.size() doubles (element e's at [e * m, (e + 1) * m)),
/// and bond_element_broken sets an element's state when the engine applies its break. The engine keeps these
/// doubles (BondStore::element_state: zero at installation, copied with the joints, checkpointed, saved in
/// specimens) without reading them; what they mean is the law's.
template <class P>
concept BondLawWithState = requires(const P& p, const BondGeometry& g, const BondKinematics& k, double* shear,
                                    const std::uint8_t* bonded, BreakMode* breaks, double* state) {
  { P::kElementState.size() } -> std::convertible_to<std::size_t>;
  { std::string_view(P::kElementState[0]) } -> std::same_as<std::string_view>;
  { bond_update(p, g, k, shear, bonded, breaks, state) } -> std::same_as<BondResult>;
  { bond_energy(p, g, k, shear, bonded, state) } -> std::same_as<double>;
  { bond_element_broken(p, state) } -> std::same_as<void>;
};

/// Doubles of law state per element: P::kElementState.size() for a BondLawWithState, else 0.
template <class P>
constexpr int bond_state_size() {
  if constexpr (BondLawWithState<P>)
    return static_cast<int>(P::kElementState.size());
  else
    return 0;
}

/// The names of the law's state per element (empty for a law without).
template <class P>
constexpr std::span<const std::string_view> bond_state_names() {
  if constexpr (BondLawWithState<P>)
    return P::kElementState;
  else
    return {};
}

/// A bonded law: its stiffness and strength as the shared block `bond` (BondStiffnessStrength: what calibration
/// moves), per-bond state of bond_elements() elements (a shear force and a bonded flag each, and the law's own
/// doubles for a BondLawWithState), the geometry fixed at installation, the force update (breaks only flagged, applied
/// by the engine after the loop), when a bond hands its pair to the unbonded contact, its time-step stiffness, strain
/// energy and the place of a broken element (crack events).
template <class P>
concept BondLawParams = LawParams<P> &&
    (BondLawWithoutState<P> != BondLawWithState<P>)&&requires(const P& p, const BondGeometry& g,
                                                              const BondKinematics& k, const BondResult& r,
                                                              const std::uint8_t* bonded) {
  { p.bond } -> std::same_as<const BondStiffnessStrength&>;
  { bond_elements(p) } -> std::same_as<int>;
  { bond_keeps_contact(p) } -> std::same_as<bool>;
  { bond_retires_on_break(p) } -> std::same_as<bool>;
  { bond_geometry(p, 1.0, 1.0, 1.0) } -> std::same_as<BondGeometry>;
  { bond_retires(p, g, k, r, 1.0, bonded) } -> std::same_as<bool>;
  { bond_time_step_stiffness(p, g) } -> std::same_as<TimeStepStiffness>;
  { bond_element_place(p, g, 0) } -> std::same_as<ElementPlace>;
};

/// An unbonded contact law: the force from the overlap and the shear increment (shear state one double per
/// contact), its time-step stiffness and energy, the same law with another friction coefficient, and its
/// effective modulus E* and stiffness ratio kappa* (the genesis servo, the p-wave speed and calibration use them).
template <class P>
concept ContactLawParams = LawParams<P> && requires(const P& p, double& shear) {
  { contact_update(p, 1.0, 1.0, 1.0, 1.0, 1.0, shear) } -> std::same_as<ContactResult>;
  { contact_time_step_stiffness(p, 1.0, 1.0, 1.0) } -> std::same_as<TimeStepStiffness>;
  { contact_energy(p, 1.0, 1.0, 1.0, 1.0, 1.0) } -> std::same_as<double>;
  { with_friction(p, 0.5) } -> std::same_as<P>;
  { p.effective_modulus_Pa } -> std::same_as<const double&>;
  { p.stiffness_ratio } -> std::same_as<const double&>;
};

// The laws. The first of each list is the default.
using BondLaw = std::variant<FlatJointParams, ParallelBondParams, SofteningFlatJointParams>;
using ContactLaw = std::variant<LinearContactParams>;

namespace detail {
template <class V>
struct AllLaws;
template <class... P>
struct AllLaws<std::variant<P...>> {
  static constexpr bool bond = (BondLawParams<P> && ...);
  static constexpr bool contact = (ContactLawParams<P> && ...);
};
}  // namespace detail
static_assert(detail::AllLaws<BondLaw>::bond, "every bond law supplies the functions of BondLawParams");
static_assert(detail::AllLaws<ContactLaw>::contact, "every contact law supplies the functions of ContactLawParams");

/// The registered names of a law list, in order.
template <class V>
std::vector<std::string> law_names() {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    return std::vector<std::string>{std::string(std::variant_alternative_t<I, V>::kName)...};
  }
  (std::make_index_sequence<std::variant_size_v<V>>{});
}

/// The law called `name` with its default parameters; InputError on `path` listing the valid names.
template <class V>
V law_by_name(const std::string& name, const std::string& path) {
  V law;
  bool found = false;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((!found && std::variant_alternative_t<I, V>::kName == name ? (law.template emplace<I>(), found = true) : false),
     ...);
  }
  (std::make_index_sequence<std::variant_size_v<V>>{});
  if (!found) throw InputError(path, name, describe_choices(name, law_names<V>()));
  return law;
}

/// The name of the law held.
template <class V>
std::string_view law_name(const V& law) {
  return std::visit([](const auto& p) { return std::string_view(std::decay_t<decltype(p)>::kName); }, law);
}

/// Reads the law's keys present in the reader's object (others keep their value) and validates the result;
/// errors name the reader's path. The reader's finish() is the caller's.
template <class V>
void read_law(ObjectReader& reader, V& law) {
  std::visit(
      [&](auto& p) {
        using P = std::decay_t<decltype(p)>;
        // The reader's errors name the whole path already; validated() names the key alone.
        const P raw = read_fields(reader, P::fields(), p);
        p = with_path(reader.path(), [&] { return P::validated(raw); });
      },
      law);
}

/// The law's keys and values (in the keys' units).
template <class V>
Json law_to_json(const V& law) {
  return std::visit([](const auto& p) { return fields_to_json(std::decay_t<decltype(p)>::fields(), p); }, law);
}

/// The key reference of every law of a list, one Markdown table per law.
template <class V>
std::string laws_markdown() {
  std::string md;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((md += fmt::format("`{}`: {}\n\n{}\n", std::variant_alternative_t<I, V>::kName,
                        std::variant_alternative_t<I, V>::kDescription,
                        fields_markdown(std::variant_alternative_t<I, V>::fields()))),
     ...);
  }
  (std::make_index_sequence<std::variant_size_v<V>>{});
  return md;
}

}  // namespace kerf::dem
