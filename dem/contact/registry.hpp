#pragma once
// Name -> law table (docs/architecture.md, Adding a normal contact law): the config names a normal
// law, a rolling model and a cohesion model; make_law_table() instantiates the one composed
// ContactLaw and its per-material-pair parameters. The solver dispatches once per step with
// std::visit.
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

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

inline const std::vector<std::string> kNormalLaws = {"linear", "hertz_mindlin"};
inline const std::vector<std::string> kRollingModels = {"none", "constant_torque", "epsd"};
inline const std::vector<std::string> kCohesionModels = {"none", "van_der_waals"};

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
  if constexpr (std::is_same_v<typename Law::Normal, LinearSpringDashpot>) {
    p.normal = LinearSpringDashpot::from(m, s.kt_ratio);
  } else {
    p.normal = HertzMindlin::from(m);
  }
  p.friction = m.friction;
  p.tangential_damping = s.tangential_damping;
  if constexpr (Law::Rolling::active) p.rolling = {m.rolling_friction, s.rolling_arm_factor};
  if constexpr (Law::Cohesion::active) p.cohesion = {m.hamaker, s.h_min, s.h_max};
  return p;
}

using NormalVariant = std::variant<LinearSpringDashpot, HertzMindlin>;
using RollingVariant = std::variant<NoRolling, ConstantTorqueRolling, EpsdRolling>;
using CohesionVariant = std::variant<NoCohesion, VanDerWaals>;

template <class N, class R, class C>
using TableOf = LawTable<ContactLaw<N, R, C>>;

using AnyLawTable = std::variant<TableOf<LinearSpringDashpot, NoRolling, NoCohesion>,
                                 TableOf<LinearSpringDashpot, NoRolling, VanDerWaals>,
                                 TableOf<LinearSpringDashpot, ConstantTorqueRolling, NoCohesion>,
                                 TableOf<LinearSpringDashpot, ConstantTorqueRolling, VanDerWaals>,
                                 TableOf<LinearSpringDashpot, EpsdRolling, NoCohesion>,
                                 TableOf<LinearSpringDashpot, EpsdRolling, VanDerWaals>,
                                 TableOf<HertzMindlin, NoRolling, NoCohesion>,
                                 TableOf<HertzMindlin, NoRolling, VanDerWaals>,
                                 TableOf<HertzMindlin, ConstantTorqueRolling, NoCohesion>,
                                 TableOf<HertzMindlin, ConstantTorqueRolling, VanDerWaals>,
                                 TableOf<HertzMindlin, EpsdRolling, NoCohesion>,
                                 TableOf<HertzMindlin, EpsdRolling, VanDerWaals>>;

/// Builds the table for the named laws; materials double as wall materials (walls name one).
/// Throws InputError (key "contact.normal" etc.) for unknown names.
AnyLawTable make_law_table(const ContactSettings& s, const std::vector<Material>& materials);

}  // namespace lbdem::dem
