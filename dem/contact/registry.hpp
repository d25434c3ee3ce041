#pragma once
// Name -> law table (docs/architecture.md, Adding a normal contact law): the config names a normal
// law, a rolling model and a cohesion model; make_law_table() instantiates the one composed
// ContactLaw and its per-material-pair parameters. The solver dispatches once per step with
// std::visit.
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "core/variant_names.hpp"
#include "dem/contact/contact_law.hpp"
#include "dem/material.hpp"

namespace lbdem::dem {

struct ContactSettings {
  std::string normal = "hertz_mindlin";  // linear | hertz_mindlin
  std::string rolling = "none";          // none | constant_torque | epsd
  std::string cohesion = "none";         // none | van_der_waals
  double rolling_arm_factor = 1.0;       // torque arm / R* [-]
  double kt_ratio = 2.0 / 7.0;           // linear law: k_t / k_n [-]
  bool tangential_damping = true;
  double h_min = 4e-10;  // van der Waals minimum separation [m]
  double h_max = 1e-5;   // van der Waals cut-off [m]
};

// The models a config may name, one type each; the names below and every law table are derived
// from these lists, so a model is added here and in its own header (docs/architecture.md, Adding a
// normal contact law).
using NormalVariant = std::variant<LinearSpringDashpot, HertzMindlin>;
using RollingVariant = std::variant<NoRolling, ConstantTorqueRolling, EpsdRolling>;
using CohesionVariant = std::variant<NoCohesion, VanDerWaals>;
static_assert(variant_names_unique<NormalVariant>(), "two normal laws share a name");
static_assert(variant_names_unique<RollingVariant>(), "two rolling models share a name");
static_assert(variant_names_unique<CohesionVariant>(), "two cohesion models share a name");

/// The `name` of each alternative of a variant, in its order.
template <class V>
std::vector<std::string> model_names() {
  return []<std::size_t... I>(std::index_sequence<I...>) {
    return std::vector<std::string>{std::string(std::variant_alternative_t<I, V>::name)...};
  }
  (std::make_index_sequence<std::variant_size_v<V>>{});
}

inline const std::vector<std::string> kNormalLaws = model_names<NormalVariant>();
inline const std::vector<std::string> kRollingModels = model_names<RollingVariant>();
inline const std::vector<std::string> kCohesionModels = model_names<CohesionVariant>();

/// Per-pair parameters of one law: particle-particle (nm x nm) and particle-wall (nm x n_wall_mat).
template <class Law>
struct LawTable {
  using law_type = Law;
  std::vector<typename Law::Params> pp;
  std::vector<typename Law::Params> pw;
  int n_materials = 0;
  double range = 0;  // largest interaction distance beyond touch [m]
  const typename Law::Params& particle(int a, int b) const { return pp[a * n_materials + b]; }
  const typename Law::Params& wall(int a, int w) const { return pw[a * n_materials + w]; }
};

template <class Law>
typename Law::Params law_params(const MaterialPair& m, const ContactSettings& s) {
  typename Law::Params p{};
  p.normal = Law::Normal::from(m, s.kt_ratio);
  p.friction = m.friction;
  p.tangential_damping = s.tangential_damping;
  if constexpr (Law::Rolling::active) p.rolling = {m.rolling_friction, s.rolling_arm_factor};
  if constexpr (Law::Cohesion::active) p.cohesion = {m.hamaker, s.h_min, s.h_max};
  return p;
}

template <class N, class R, class C>
using TableOf = LawTable<ContactLaw<N, R, C>>;

/// Every combination of the three lists as one variant of law tables (normal-major, then
/// rolling, then cohesion): each is instantiated once, dispatched once per step with std::visit.
template <class NV, class RV, class CV>
struct LawProduct;
template <class... N, class... R, class... C>
struct LawProduct<std::variant<N...>, std::variant<R...>, std::variant<C...>> {
  template <class Ni, class Ri>
  using WithCohesion = std::tuple<TableOf<Ni, Ri, C>...>;
  template <class Ni>
  using WithRolling = decltype(std::tuple_cat(std::declval<WithCohesion<Ni, R>>()...));
  template <class T>
  struct AsVariant;
  template <class... T>
  struct AsVariant<std::tuple<T...>> {
    using type = std::variant<T...>;
  };
  using type =
      typename AsVariant<decltype(std::tuple_cat(std::declval<WithRolling<N>>()...))>::type;
};
using AnyLawTable = LawProduct<NormalVariant, RollingVariant, CohesionVariant>::type;

/// The normal law of that name (InputError, key "contact.normal", for an unknown one).
NormalVariant normal_law(const std::string& name);

/// Builds the table for the named laws; materials double as wall materials (walls name one).
/// Throws InputError (key "contact.normal" etc.) for unknown names.
AnyLawTable make_law_table(const ContactSettings& s, const std::vector<Material>& materials);

}  // namespace lbdem::dem
