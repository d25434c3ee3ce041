#pragma once
// LbmSolver's templated passes, for lbm_solver.cpp and for the translation units that compile one
// collision operator's pass with flags of its own (collide_les.cpp). Internal to lbm/.
#include "lbm/forcing/moment_store.hpp"
#include "lbm/forcing/porous.hpp"
#include "lbm/lbm_solver.hpp"
#include "lbm/stream_collide.hpp"

#include <type_traits>

namespace lbdem::lbm {

template <class Fn>
void LbmSolver::with_forcing(Fn&& fn, bool accumulate) const {
  const Vec3& b = settings_.body_force;
  const CellForce uniform{b.x(), b.y(), b.z()};
  if (has_porosity()) {
    const auto porous = [&](auto applied) {
      using Base = decltype(applied);
      const auto with_beta = [&]<bool kF>() {
        if (accumulate && has_velocity_sum()) {
          PorousMedium<Base, true, kF> policy{applied, inv_eps_.data(), alpha_.data(), beta_};
          for (int a = 0; a < 3; ++a) policy.u_sum[a] = u_sum_[std::size_t(a)].data();
          fn(policy);
        } else {
          fn(PorousMedium<Base, false, kF>{applied, inv_eps_.data(), alpha_.data(), beta_});
        }
      };
      if (beta_ > 0)
        with_beta.template operator()<true>();
      else
        with_beta.template operator()<false>();
    };
    if (has_force_field())
      porous(FieldForce{force_[0].data(), force_[1].data(), force_[2].data(), uniform});
    else
      porous(UniformForce{uniform});
  } else if (has_force_field())
    fn(FieldForce{force_[0].data(), force_[1].data(), force_[2].data(), uniform});
  else if (!b.isZero())
    fn(UniformForce{uniform});
  else
    fn(NoForce{});
}

template <class Op>
void LbmSolver::collide_pass(const Op& op) {
  with_forcing(
      [&](const auto& forcing) {
        const auto collide = [&](const auto& policy) {
          with_pdf([&](auto& pdf) { stream_collide(pdf, state_, op, policy, &runs_); });
        };
        if (cell_moments_[0].empty()) return collide(forcing);
        const MomentFields out{
            cell_moments_[0].data(),
            {cell_moments_[1].data(), cell_moments_[2].data(), cell_moments_[3].data()}};
        collide(StoreMoments<std::decay_t<decltype(forcing)>>{forcing, out});
      },
      true);
}

// The regularized LES pass is compiled in collide_les.cpp only (with wider vectors; see there).
extern template void LbmSolver::collide_pass(const RegularizedLes&);

}  // namespace lbdem::lbm
