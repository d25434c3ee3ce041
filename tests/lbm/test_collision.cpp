// Single-cell properties of the D3Q19 equilibrium and of the BGK and TRT operators with Guo
// forcing, against their defining moment identities (no lattice, no streaming); and the single-
// precision collision (float arithmetic on f_q - w_q, cell.hpp) against the double one.
#include <catch2/catch.hpp>

#include "lbm/cell.hpp"
#include "lbm/collision/collision_model.hpp"
#include "lbm/equilibrium.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string_view>

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

/// Largest difference between one collision in float on the shifted populations f_q - w_q
/// (cell.hpp, kShifted) and the same collision in double, in units of u_f A: u_f = 2^-24 is
/// float's unit round-off and A = max_q |f_q - w_q| over the pre- and post-collision double
/// states, the size of what float holds. `unshifted` gets the same measure for the error the
/// double collision makes when its input and output are merely rounded to float as f_q itself
/// (storage without the shift).
struct SingleError {
  double shifted = 0, unshifted = 0;
};

template <bool kForced, class Op>
SingleError single_vs_double(const Op& op, const double (&f)[kQ], const CellForce& force,
                             double inv_eps) {
  constexpr double kUnitRoundoff = 0x1p-24;
  double fd[kQ];
  std::copy(f, f + kQ, fd);
  CellMoments m = cell_moments<kForced>(fd, force);
  m.inv_eps = inv_eps;
  op.template relax<kForced>(fd, m, force);

  float fs[kQ];
  for (int q = 0; q < kQ; ++q) fs[q] = float(f[q] - kW[q]);
  const CellForceT<float> force_s{float(force.fx), float(force.fy), float(force.fz)};
  CellMomentsT<float> ms = cell_moments<kForced>(fs, force_s);
  ms.inv_eps = float(inv_eps);
  op.template relax<kForced>(fs, ms, force_s);

  double fu[kQ];  // unshifted storage: f rounded to float, double collision, rounded again
  for (int q = 0; q < kQ; ++q) fu[q] = double(float(f[q]));
  CellMoments mu = cell_moments<kForced>(fu, force);
  mu.inv_eps = inv_eps;
  op.template relax<kForced>(fu, mu, force);
  for (int q = 0; q < kQ; ++q) fu[q] = double(float(fu[q]));

  double a = 0;
  for (int q = 0; q < kQ; ++q) a = std::max({a, std::abs(f[q] - kW[q]), std::abs(fd[q] - kW[q])});
  SingleError e;
  for (int q = 0; q < kQ; ++q) {
    e.shifted = std::max(e.shifted, std::abs(double(fs[q]) + kW[q] - fd[q]));
    e.unshifted = std::max(e.unshifted, std::abs(fu[q] - fd[q]));
  }
  e.shifted /= kUnitRoundoff * a;
  e.unshifted /= kUnitRoundoff * a;
  return e;
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

TEST_CASE("Single-precision collision on f - w matches the double collision to a few float ulps",
          "[lbm]") {
  // Random near-equilibrium cells as a resolved flow has them: rho = 1 +- 1e-2, |u| <= 0.05 in a
  // random direction, the equilibrium times 1 + 2e-3 r_q (r_q in [-1, 1]: a non-equilibrium part
  // of a strain rate of order 1e-3), a force of up to 1e-4 per component, inv_eps 1 and 1/0.6.
  // One collision in double (the reference) and in float on f_q - w_q (float fs[kQ]: float always
  // means shifted, cell.hpp), compared per population.
  //
  // Bound. Everything float holds and computes is of the size A = max_q |f_q - w_q| (about
  // w_q (|drho| + 3 |c.u|) <= 0.17 w_q; the equilibrium is formed shifted, w_q (drho + rho (3 c.u
  // + ...)), so no O(w_q) term is ever formed and cancelled). The input rounding is u_f A / 2
  // (u_f = 2^-24); the moment sums are trees of depth <= 5 over terms <= A, so drho and j carry
  // a few u_f A each; the equilibrium's terms (w_q rho 3 c.u, w_q rho 4.5 (c.u)^2 / eps), the
  // relaxation f + omega (feq - f) and the source add one to three roundings of values <= A
  // each, and the LES adds the rounded stress and its local tau (a square root of a sum of
  // positive terms). Round-off of up to 10-20 u_f A is then the expected range: bound 32 u_f A
  // (2^-19 A). Measured 4.7-8.8 u_f A over all operators, with and without force and porosity.
  // A term formed at O(w_q) size and cancelled (an equilibrium formed unshifted, then w_q
  // subtracted) would err by u_f w_q / 2, 3 u_f A for the fast cells and thousands of u_f A for
  // the slow ones: a tenth of the draw has rho - 1, u and the non-equilibrium part 1000 times
  // smaller, where A ~ 1.7e-4 w_q.
  //
  // Without the shift, f_q itself rounded to float before and after the same double collision
  // (no float arithmetic at all) errs by up to u_f w_q / 2 per population: about 3 u_f A for the
  // fast cells, and w_q / (2 A) ~ 3000 u_f A for the slow ones. Its worst case over the draw must
  // exceed the shifted computation's by a factor 100 at least (the rationale of DDF shifting,
  // pdf_field.hpp; measured 3e4 to 1.4e6 u_f A).
  //
  // Not visible in one collision, but systematic over many: the shifted equilibrium multiplies
  // by float(w_q), whose moments are sum_q float(w_q) = 1 + 1.5e-8 and sum_q float(w_q) c_qx^2 =
  // (1 + 7.45e-9) / 3, a relative bias of ~ 1e-8 in the mass and momentum of the equilibrium,
  // well inside the bound here (u_f = 6e-8), which flows that change step by step accumulate.
  // The kernel removes the mass part by setting the rest population from the cell's mass
  // (cell.hpp, rest_from_mass); the momentum part stays (test_les.cpp, shear wave in single).
  struct Named {
    std::string_view name;
    CollisionModel op;
  };
  const std::array<Named, 5> ops = {{
      {"BGK tau 0.7", Bgk::from_tau(0.7)},
      {"TRT tau 0.7", Trt::from_tau(0.7)},
      {"TRT tau 0.51", Trt::from_tau(0.51)},
      {"regularized LES tau 0.52 C_s 0.17", RegularizedLes::from_tau(0.52, 0.17)},
      {"regularized LES tau 0.5001 C_s 0.1", RegularizedLes::from_tau(0.5001, 0.1)},
  }};
  std::mt19937 gen(20261207u);  // raw mt19937 output is fixed by the standard
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * (double(gen()) / 4294967296.0);
  };
  for (const Named& named : ops) {
    for (const double inv_eps : {1.0, 1.0 / 0.6}) {
      SingleError worst_forced, worst_free;
      for (int sample = 0; sample < 2000; ++sample) {
        // Slow cells too: a tenth of the draw has rho - 1 and u a thousand times smaller.
        const double scale = sample % 10 == 0 ? 1e-3 : 1.0;
        const double rho = 1.0 + scale * uniform(-1e-2, 1e-2);
        double u[3];
        const double z = uniform(-1, 1), phi = uniform(0, 2 * M_PI),
                     speed = scale * uniform(0, 0.05);
        u[0] = speed * std::sqrt(1 - z * z) * std::cos(phi);
        u[1] = speed * std::sqrt(1 - z * z) * std::sin(phi);
        u[2] = speed * z;
        double f[kQ];
        for (int q = 0; q < kQ; ++q)
          f[q] = equilibrium(q, rho, u[0], u[1], u[2], inv_eps) *
                 (1.0 + 2e-3 * scale * uniform(-1, 1));
        const CellForce force{uniform(-1e-4, 1e-4), uniform(-1e-4, 1e-4), uniform(-1e-4, 1e-4)};
        std::visit(
            [&](const auto& op) {
              const SingleError a = single_vs_double<false>(op, f, {}, inv_eps);
              const SingleError b = single_vs_double<true>(op, f, force, inv_eps);
              worst_free.shifted = std::max(worst_free.shifted, a.shifted);
              worst_free.unshifted = std::max(worst_free.unshifted, a.unshifted);
              worst_forced.shifted = std::max(worst_forced.shifted, b.shifted);
              worst_forced.unshifted = std::max(worst_forced.unshifted, b.unshifted);
            },
            named.op);
      }
      INFO(named.name << ", 1/eps " << inv_eps << ": largest |f_float - f_double| / (u_f A) "
                      << worst_free.shifted << " unforced, " << worst_forced.shifted
                      << " forced; f rounded to float without the shift " << worst_free.unshifted
                      << ", " << worst_forced.unshifted);
      CHECK(worst_free.shifted < 32);
      CHECK(worst_forced.shifted < 32);
      CHECK(worst_free.unshifted > 100 * worst_free.shifted);
      CHECK(worst_forced.unshifted > 100 * worst_forced.shifted);
    }
  }
}
