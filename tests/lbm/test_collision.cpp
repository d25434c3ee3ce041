// Single-cell properties of the D3Q19 equilibrium and of the BGK and TRT operators with Guo
// forcing, against their defining moment identities (no lattice, no streaming).
#include <catch2/catch.hpp>

#include "lbm/cell.hpp"
#include "lbm/collision/collision_model.hpp"
#include "lbm/equilibrium.hpp"

#include <array>
#include <cmath>

using namespace lbdem::lbm;

namespace {

struct Moments {
  double rho = 0;
  std::array<double, 3> j{};
  std::array<std::array<double, 3>, 3> pi{};
};

Moments moments_of(const double (&f)[kQ]) {
  Moments m;
  for (int q = 0; q < kQ; ++q) {
    const int c[3] = {kCx[q], kCy[q], kCz[q]};
    m.rho += f[q];
    for (int a = 0; a < 3; ++a) {
      m.j[a] += c[a] * f[q];
      for (int b = 0; b < 3; ++b) m.pi[a][b] += c[a] * c[b] * f[q];
    }
  }
  return m;
}

// A non-equilibrium cell: equilibrium at (rho, u) plus a deterministic perturbation.
void perturbed(double (&f)[kQ], double rho, const double (&u)[3]) {
  for (int q = 0; q < kQ; ++q)
    f[q] = equilibrium(q, rho, u[0], u[1], u[2]) * (1.0 + 0.05 * std::sin(1.7 * q + 0.3));
}

template <class Op>
void check_conservation(const Op& op) {
  const double u0[3] = {0.04, -0.02, 0.03};
  const CellForce force{1e-3, -2e-3, 5e-4};
  double f[kQ];
  perturbed(f, 1.02, u0);
  const Moments before = moments_of(f);
  // Unforced: mass and momentum are collision invariants. 1e-15: a few roundings of O(1) sums.
  double g[kQ];
  std::copy(f, f + kQ, g);
  op.template relax<false>(g, cell_moments<false>(g, {}), {});
  Moments after = moments_of(g);
  CHECK(after.rho == Approx(before.rho).margin(1e-15));
  for (int a = 0; a < 3; ++a) CHECK(after.j[a] == Approx(before.j[a]).margin(1e-15));
  // Guo forcing: mass unchanged and momentum gains exactly F per step (Guo et al. 2002, eq. 8:
  // the relaxed -F/2 offset of u gives omega F/2, the source (1 - omega/2) F; together F).
  std::copy(f, f + kQ, g);
  op.template relax<true>(g, cell_moments<true>(g, force), force);
  after = moments_of(g);
  const double df[3] = {force.fx, force.fy, force.fz};
  CHECK(after.rho == Approx(before.rho).margin(1e-15));
  for (int a = 0; a < 3; ++a) CHECK(after.j[a] - before.j[a] == Approx(df[a]).margin(1e-15));
}

}  // namespace

TEST_CASE("D3Q19 equilibrium has the moments rho, rho u, rho cs^2 I + rho u u", "[lbm]") {
  const double rho = 1.03, u[3] = {0.05, -0.03, 0.02};
  double f[kQ];
  for (int q = 0; q < kQ; ++q) f[q] = equilibrium(q, rho, u[0], u[1], u[2]);
  const Moments m = moments_of(f);
  // The second-order equilibrium reproduces moments 0-2 exactly (Qian et al. 1992); 1e-15 covers
  // the rounding of 19-term sums of O(0.1) values.
  CHECK(m.rho == Approx(rho).margin(1e-15));
  for (int a = 0; a < 3; ++a) {
    CHECK(m.j[a] == Approx(rho * u[a]).margin(1e-15));
    for (int b = 0; b < 3; ++b)
      CHECK(m.pi[a][b] == Approx((a == b ? rho * kCs2 : 0.0) + rho * u[a] * u[b]).margin(1e-15));
  }
  const CellMoments cm = cell_moments<false>(f, {});
  CHECK(cm.rho == Approx(rho).margin(1e-15));
  CHECK(cm.ux == Approx(u[0]).margin(1e-15));
}

TEST_CASE("BGK and TRT conserve mass and momentum and add exactly F with Guo forcing", "[lbm]") {
  check_conservation(Bgk::from_tau(0.7));
  check_conservation(Trt::from_tau(0.7));
  check_conservation(Trt::from_tau(1.9, 0.25));
}

TEST_CASE("TRT rates from tau and the magic parameter", "[lbm]") {
  const Trt t = Trt::from_tau(0.8);
  CHECK(t.omega_plus == Approx(1.0 / 0.8));
  CHECK(t.magic() == Approx(3.0 / 16.0).epsilon(1e-14));
  CHECK(t.viscosity() == Approx((0.8 - 0.5) / 3.0).epsilon(1e-14));
  // BGK is TRT with omega- = omega+: both give the same post-collision state.
  const double u0[3] = {0.01, 0.02, -0.01};
  double a[kQ], b[kQ];
  perturbed(a, 1.0, u0);
  std::copy(a, a + kQ, b);
  const CellForce force{1e-4, 0, 0};
  Bgk::from_tau(0.9).relax<true>(a, cell_moments<true>(a, force), force);
  Trt{1.0 / 0.9, 1.0 / 0.9}.relax<true>(b, cell_moments<true>(b, force), force);
  for (int q = 0; q < kQ; ++q) CHECK(a[q] == Approx(b[q]).margin(1e-16));
  CHECK_THROWS(Trt::from_tau(0.5));
  CHECK_THROWS(Bgk::from_tau(0.4));
}
