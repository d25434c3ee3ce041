#pragma once
// LbmSolver's templated passes, for lbm_solver.cpp and for the translation units that compile one
// collision operator's pass with flags of its own (collide_les.cpp). Internal to lbm/.
#include "lbm/forcing/mass_source.hpp"
#include "lbm/forcing/moment_store.hpp"
#include "lbm/forcing/porous.hpp"
#include "lbm/lbm_solver.hpp"
#include "lbm/stream_collide.hpp"

#include <type_traits>

namespace lbdem::lbm {

template <class T, class Fn>
void LbmSolver::with_forcing(const LatticeFields<T>& lat, Fn&& fn, bool accumulate) const {
  const Vec3& b = settings_.body_force;
  const CellForce uniform{b.x(), b.y(), b.z()};
  const bool field = !lat.force[0].empty();
  if (has_porosity()) {
    const auto porous = [&](auto applied) {
      using Base = decltype(applied);
      const auto with_beta = [&]<bool kF>() {
        if (accumulate && !lat.u_sum[0].empty()) {
          PorousMedium<T, Base, true, kF> policy{applied, lat.inv_eps.data(), lat.alpha.data(),
                                                 beta_};
          for (int a = 0; a < 3; ++a) policy.u_sum[a] = lat.u_sum[std::size_t(a)].data();
          fn(policy);
        } else {
          fn(PorousMedium<T, Base, false, kF>{applied, lat.inv_eps.data(), lat.alpha.data(),
                                              beta_});
        }
      };
      if (beta_ > 0)
        with_beta.template operator()<true>();
      else
        with_beta.template operator()<false>();
    };
    if (field)
      porous(FieldForce{lat.force[0].data(), lat.force[1].data(), lat.force[2].data(), uniform});
    else
      porous(UniformForce{uniform});
  } else if (field)
    fn(FieldForce{lat.force[0].data(), lat.force[1].data(), lat.force[2].data(), uniform});
  else if (!b.isZero())
    fn(UniformForce{uniform});
  else
    fn(NoForce{});
}

/// The forcing policies whose collision adds the pending mass sources itself (WithMassSource):
/// those of a coupled step, porous with the velocity sums, the only runs with a source field. Any
/// other has them added by a pass before it (one more compiled kernel per policy otherwise).
template <class F>
inline constexpr bool kFusesMassSource = false;
template <class S, class Base, bool kF>
inline constexpr bool kFusesMassSource<PorousMedium<S, Base, true, kF>> = true;

template <class Op>
void LbmSolver::collide_pass(const Op& op) {
  with_lattice([&](auto& lat) {
    using T = typename std::decay_t<decltype(lat)>::value_type;
    with_forcing(
        lat,
        [&](const auto& forcing) {
          using F = std::decay_t<decltype(forcing)>;
          const auto collide = [&](const auto& policy) {
            using P = std::decay_t<decltype(policy)>;
            if constexpr (kFusesMassSource<F>)
              if (mass_pending_) {
                mass_pending_ = false;
                const WithMassSource<P> sourced{policy, mass_source_storage_.data()};
                return stream_collide(lat.pdf, state_, op, sourced, &runs_);
              }
            settle_mass_sources();
            stream_collide(lat.pdf, state_, op, policy, &runs_);
          };
          if (!keep_moments_) return collide(forcing);
          collide(StoreMoments<F, T>{forcing, lat.moment_fields()});
        },
        true);
  });
}

// The regularized LES pass is compiled in collide_les.cpp only (with wider vectors; see there).
extern template void LbmSolver::collide_pass(const RegularizedLes&);

}  // namespace lbdem::lbm
