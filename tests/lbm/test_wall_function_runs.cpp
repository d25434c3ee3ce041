// lbm/boundary/wall_function.hpp: the flat-face kernel (runs of storage neighbours on one
// axis-aligned face) against the general per-cell kernel. Equivalence, not validation (the law
// itself is tested in test_wall_function.cpp, whose flat box faces now take the flat kernel).
// Both evaluate the same formulas; the general one takes the normal, tangent basis and the
// pseudo-inverse of M_t from an eigen-decomposition (3 I on a flat face to a few ulp) and
// multiplies in another order, so they agree to round-off: 1e-14 of the populations (about 700
// ulp of values near 0.1; measured 3e-17), where a wrong sign or factor in the flat kernel moves
// them by the slip terms, about 1e-3. The populations and moments are random and mutually
// inconsistent, so the slip bounds, the zero-speed case and both branches of the law all occur.
#include <catch2/catch.hpp>

#include "lbm/boundary/bounce_back.hpp"
#include "lbm/boundary/wall_function.hpp"
#include "lbm/pdf_field.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using lbdem::Index;
using lbdem::Vec3;
using namespace lbdem::lbm;

TEST_CASE("LBM: the flat-face wall-function kernel matches the general one to round-off", "[lbm]") {
  // Periodic 150 x 12 x 10 box: floor and lid (z faces), a 6 x 5 x 4 block (x, y and z faces) and
  // a staircase sphere (radius 2.6) for the general kernel. The periodic x edges split the floor's
  // rows (a wrapped link ends a run); the rows beside the block and the sphere leave runs of up to
  // 148 cells, so the kernel's 64-cell chunks are crossed.
  const Grid g(150, 12, 10, {true, true, true});
  FlagField flags(g);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        const bool plate = z == 0 || z == g.nz() - 1;
        const bool block = x >= 3 && x < 9 && y >= 3 && y < 8 && z >= 3 && z < 7;
        const bool sphere = std::hypot(x - 14.5, y - 6.0, z - 5.0) < 2.6;
        if (plate || block || sphere) flags.set(x, y, z, 1);
      }
  BounceBackLinks links = build_links(flags, 1)[0];
  const WallFunctionCells flat = build_wall_function_cells(links, true);
  const WallFunctionCells general = build_wall_function_cells(links, false);
  std::size_t in_runs = 0, runs = 0, longest = 0;
  for (std::size_t u = 0; u + 1 < flat.unit_first.size(); ++u)
    if (flat.unit_flat[u]) {
      ++runs;
      in_runs += flat.unit_first[u + 1] - flat.unit_first[u];
      longest = std::max<std::size_t>(longest, flat.unit_first[u + 1] - flat.unit_first[u]);
    }
  INFO(in_runs << " of " << flat.size() << " wall cells in " << runs << " flat runs, the longest "
               << longest);
  CHECK(in_runs > flat.size() / 2);
  CHECK(runs > 20);
  CHECK(longest > 128);  // more than two of the kernel's 64-cell chunks
  CHECK(std::count(general.unit_flat.begin(), general.unit_flat.end(), 1) == 0);

  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  PdfField<double> base(g);
  for (Index k = 0; k < base.size(); ++k) base.data()[k] = 0.02 + 0.1 * uni(rng);
  const std::size_t n = std::size_t(g.storage_cells());
  std::vector<double> rho(n), ux(n), uy(n), uz(n);
  for (std::size_t c = 0; c < n; ++c) {
    rho[c] = 0.9 + 0.2 * uni(rng);
    const double scale = uni(rng) < 0.1 ? 0.0 : (uni(rng) < 0.5 ? 1e-4 : 0.08);
    ux[c] = scale * (2 * uni(rng) - 1);
    uy[c] = scale * (2 * uni(rng) - 1);
    uz[c] = scale * (2 * uni(rng) - 1);
  }
  // Purely normal flow at some floor cells: zero tangential speed with a nonzero velocity.
  for (int x = 0; x < 5; ++x)
    ux[std::size_t(g.index(x, 1, 1))] = uy[std::size_t(g.index(x, 1, 1))] = 0;
  const MomentFields<double> moments{rho.data(), {ux.data(), uy.data(), uz.data()}};
  const WernerWengle law{2e-4};
  const double rho_w = 1.0;

  for (const AaState state : {AaState::natural, AaState::swapped}) {
    PdfField<double> a(g), b(g);
    std::copy(base.data(), base.data() + base.size(), a.data());
    std::copy(base.data(), base.data() + base.size(), b.data());
    BounceBackLinks la = links, lb = links;
    const Vec3 origin(3.0, -2.0, 1.0);
    const WallLoad fa = apply_wall_function(a, state, la, flat, law, moments, rho_w, origin);
    const WallLoad fb = apply_wall_function(b, state, lb, general, law, moments, rho_w, origin);
    double max_diff = 0, max_corr = 0;
    for (Index k = 0; k < a.size(); ++k)
      max_diff = std::max(max_diff, std::abs(a.data()[k] - b.data()[k]));
    for (std::size_t k = 0; k < links.size(); ++k) {
      max_diff = std::max(max_diff, std::abs(la.correction[k] - lb.correction[k]));
      max_corr = std::max(max_corr, std::abs(lb.correction[k]));
    }
    INFO("largest difference " << max_diff << ", largest slip term " << max_corr);
    CHECK(max_corr > 1e-3);  // the comparison is not between two no-slip walls
    CHECK(max_diff < 1e-14);
    // Sums of about 2,000 cells' forces (each about 1) and torques (arms up to 20 cells).
    CHECK((fa.force - fb.force).norm() < 1e-12 * fb.force.norm() + 1e-12);
    CHECK((fa.torque - fb.torque).norm() < 1e-12 * fb.torque.norm() + 1e-11);
    CHECK(std::abs(fa.mass - fb.mass) < 1e-13);
  }
  // Single precision (f - w in float, the moments in float, the slip computed in float): both
  // kernels agree with the double kernel (on the same rounded moments and slots) to float's
  // arithmetic. Per link: the links' tangential momentum (five to nine slots of |f - w| <= 0.12)
  // rounds at about 2^-24 x 0.5 = 3e-8, times the pseudo-inverse 3 over rho_w gives 1e-7 in the
  // slip, and the term 6 w_q c_q . u_s (w_q <= 1/18) carries 3e-8 of it, plus the rounding of the
  // reflected value, 2^-24 x 0.12 = 7e-9: bound 1e-7 per slot. Per cell the force sums up to nine
  // links' 2 (f - w) + corr, each off by at most that: bound 1e-6 per cell, summed over the cells
  // (linear, the worst case). A slot written without its w shift would be off by w_q >= 1/36, a
  // force without the shift's constant by A / 3 per cell.
  std::vector<float> rho_f(rho.begin(), rho.end()), ux_f(ux.begin(), ux.end()),
      uy_f(uy.begin(), uy.end()), uz_f(uz.begin(), uz.end());
  std::vector<double> rho_r(rho_f.begin(), rho_f.end()), ux_r(ux_f.begin(), ux_f.end()),
      uy_r(uy_f.begin(), uy_f.end()), uz_r(uz_f.begin(), uz_f.end());
  const MomentFields<float> moments_f{rho_f.data(), {ux_f.data(), uy_f.data(), uz_f.data()}};
  const MomentFields<double> moments_r{rho_r.data(), {ux_r.data(), uy_r.data(), uz_r.data()}};
  for (const AaState state : {AaState::natural, AaState::swapped}) {
    PdfField<double> ref(g);
    PdfField<float> a(g), b(g);
    std::copy(base.data(), base.data() + base.size(), ref.data());
    for (int q = 0; q < kQ; ++q)
      for (Index k = 0; k < g.storage_cells(); ++k) {
        a.set(q, k, base.get(q, k));
        b.set(q, k, base.get(q, k));
        ref.set(q, k, a.get(q, k));  // the double reference starts from the same rounded values
      }
    BounceBackLinks la = links, lb = links, lr = links;
    const WallLoad fa = apply_wall_function(a, state, la, flat, law, moments_f, rho_w);
    const WallLoad fb = apply_wall_function(b, state, lb, general, law, moments_f, rho_w);
    const WallLoad fr = apply_wall_function(ref, state, lr, flat, law, moments_r, rho_w);
    double flat_general = 0, float_double = 0;
    for (int q = 0; q < kQ; ++q)
      for (Index k = 0; k < g.storage_cells(); ++k) {
        flat_general = std::max(flat_general, std::abs(a.get(q, k) - b.get(q, k)));
        float_double = std::max(float_double, std::abs(a.get(q, k) - ref.get(q, k)));
      }
    INFO("float: flat - general " << flat_general << ", float - double " << float_double);
    CHECK(flat_general < 1e-7);
    CHECK(float_double < 1e-7);
    const double force_bound = 1e-6 * double(flat.size());
    INFO("force: flat " << (fa.force - fr.force).norm() << ", general "
                        << (fb.force - fr.force).norm() << " of " << fr.force.norm());
    CHECK((fa.force - fr.force).norm() < force_bound);
    CHECK((fb.force - fr.force).norm() < force_bound);
    CHECK(std::abs(fa.mass - fr.mass) < 1e-7 * double(links.size()));
    // Torque about the origin: each cell's force error times its arm, at most 151 cells (the
    // box's diagonal). The flat kernel sums it per run as (x_0 - o) x F + e_x x sum_j j f_j; a
    // wrong arm or sign there is off by a run's force times its length, far above this.
    INFO("torque: flat " << (fa.torque - fr.torque).norm() << ", general "
                         << (fb.torque - fr.torque).norm() << " of " << fr.torque.norm());
    CHECK((fa.torque - fr.torque).norm() < 151 * force_bound);
    CHECK((fb.torque - fr.torque).norm() < 151 * force_bound);
  }
}
