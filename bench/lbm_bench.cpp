// LBM benchmark: the periodic Taylor-Green box of bench/peers (case 1), exactly as Palabos
// runs it there: D3Q19 BGK, double, tau = 0.6, rho = 1 and
//   u = u0 (sin x cos y cos z, -cos x sin y cos z, 0),  x = 2 pi (i + 1/2) / N,  u0 = 0.05,
// 20 untimed warm-up steps, then 200 timed steps. MLUPS = N^3 steps / wall of the timed loop.
// E_ratio = <u^2> after / before the timed window; linear theory: exp(-6 nu k^2 t), k = 2 pi / N.
//
// --scheme aa (default) runs the solver's kernel, the in-place AA pattern. The two-lattice
// alternatives it was chosen against (lbm/stream_collide.hpp) run with --scheme ab (pull, ordinary
// stores) and nt (pull, each finished row written with non-temporal stores), periodic only, on the
// same per-cell kernel (nt on rows padded to 64 B), so the choice can be re-measured elsewhere.
#include <immintrin.h>
#include <omp.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/memory.hpp"
#include "core/timer.hpp"
#include "lbm/lbm_solver.hpp"
#include "lbm/moments.hpp"
#include "lbm/stream_collide.hpp"

using namespace lbdem;
using namespace lbdem::lbm;

namespace {

double mean_u2(const PdfField<double>& pdf, AaState s) {
  std::vector<Vec3> u;
  moment_fields(pdf, s, NoForce{}, FlagField(pdf.grid()), nullptr, &u);
  double e = 0;
  for (const Vec3& v : u) e += v.squaredNorm();
  return e / double(u.size());
}

double mean_u2(const LbmSolver& solver) {
  std::vector<Vec3> u;
  solver.raw_velocity(u);
  double e = 0;
  for (const Vec3& v : u) e += v.squaredNorm();
  return e / double(u.size());
}

/// Copies one row of nx values with streaming stores where 32-byte aligned.
void stream_row(double* dst, const double* src, int nx) {
  int x = 0;
#ifdef __AVX__
  for (; x < nx && reinterpret_cast<std::uintptr_t>(dst + x) % 32; ++x) dst[x] = src[x];
  for (; x + 4 <= nx; x += 4) _mm256_stream_pd(dst + x, _mm256_loadu_pd(src + x));
#endif
  for (; x < nx; ++x) dst[x] = src[x];
}

/// Two-lattice pull step src -> dst: f_q(x) is read from x - c_q of src, collided, written to x.
template <bool kNonTemporal>
void two_lattice_step(const PdfField<double>& src, PdfField<double>& dst, const Bgk& op) {
  const Grid& g = src.grid();
  const int nx = g.nx();
  for_each_row(g, [&](int y, int z) {
    thread_local std::vector<double> row;
    row.resize(std::size_t(kQ) * nx);
    for_each_x_range(g, [&](int x0, int x1) {
      const Index n0 = g.index(x0, y, z);
      const auto off = g.neighbor_offsets(x0, y, z);
      const double* in[kQ];
      double* out[kQ];
      for (int q = 0; q < kQ; ++q) {
        in[q] = src.dir(q) + n0 + off[opposite(q)];
        out[q] = kNonTemporal ? row.data() + q * nx + x0 : dst.dir(q) + n0;
      }
      collide_cells(op, NoForce{}, in, out, n0, x1 - x0);
    });
    if constexpr (kNonTemporal) {
      for (int q = 0; q < kQ; ++q)
        stream_row(dst.dir(q) + g.index(0, y, z), row.data() + q * nx, nx);
      _mm_sfence();  // streaming stores are weakly ordered: publish before the next step reads
    }
  });
}

struct Run {
  double mlups, e_ratio;
  std::uint64_t hash = 0;  // FNV-1a of the final populations (solver scheme): bitwise checks
  MemoryUse memory;        // right after the timed loop, before any copy for the hash
};

// FNV-1a over the bytes of n doubles: equal hashes for bitwise equal states (the scaling study
// compares thread counts with it).
std::uint64_t fnv1a(const double* p, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  for (std::size_t k = 0; k < n * sizeof(double); ++k) h = (h ^ b[k]) * 1099511628211ull;
  return h;
}

Run run(const std::string& scheme, int n, int steps, int warmup, const Bgk& op, double u0,
        bool porous, Precision precision) {
  LbmSettings s;
  s.nx = s.ny = s.nz = n;
  s.precision = precision;
  s.collision = op;
  if (porous) s.collision = Trt::from_tau(1.0 / op.omega);
  LbmSolver solver(s);
  if (porous) {
    // The coupled gas kernel of a fluidized bed (coupling/coupler.cpp): TRT, the Guo-Zhao porous
    // form with per-cell eps and Darcy drag, a per-cell force and the velocity sums. The values
    // only need to be admissible: the cost does not depend on them.
    const std::size_t cells = std::size_t(n) * n * n;
    solver.enable_porosity();
    solver.enable_velocity_sum();
    solver.set_porosity_field(std::vector<double>(cells, 0.7), std::vector<double>(cells, 1e-3));
    solver.set_force_field(std::vector<Vec3>(cells, Vec3(0.0, 0.0, -1e-7)));
  }
  const double k = 2.0 * kPi / n;
  solver.initialize([&](int i, int j, int l, double& rho, Vec3& u) {
    const double x = k * (i + 0.5), y = k * (j + 0.5), z = k * (l + 0.5);
    rho = 1.0;
    u = u0 * Vec3(std::sin(x) * std::cos(y) * std::cos(z), -std::cos(x) * std::sin(y) * std::cos(z),
                  0.0);
  });
  if (scheme == "aa" || porous) {
    for (int w = 0; w < warmup; ++w) solver.step();
    const double e0 = mean_u2(solver);
    Stopwatch clock;
    for (int w = 0; w < steps; ++w) solver.step();
    const double wall = clock.seconds();
    const MemoryUse memory = memory_use();
    std::vector<double> f;  // interior populations only: the padding is never written
    f.reserve(std::size_t(kQ) * n * n * n);
    double cell[kQ];
    for (int l = 0; l < n; ++l)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          solver.cell_populations(i, j, l, cell);
          f.insert(f.end(), cell, cell + kQ);
        }
    return {double(n) * n * n * steps / wall / 1e6, mean_u2(solver) / e0, fnv1a(f.data(), f.size()),
            memory};
  }
  // Streaming stores need rows starting on 64-byte boundaries (grid.hpp); copy cell by cell.
  const Grid padded(n, n, n, {true, true, true}, scheme == "nt");
  PdfField<double> a(padded), b(padded);
  for (int l = 0; l < n; ++l)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        double cell[kQ];
        solver.cell_populations(i, j, l, cell);
        for (int q = 0; q < kQ; ++q) {
          a.set(q, padded.index(i, j, l), cell[q]);
          b.set(q, padded.index(i, j, l), cell[q]);
        }
      }
  PdfField<double>* cur[2] = {&a, &b};
  auto advance = [&](int count) {
    for (int w = 0; w < count; ++w) {
      if (scheme == "nt")
        two_lattice_step<true>(*cur[0], *cur[1], op);
      else
        two_lattice_step<false>(*cur[0], *cur[1], op);
      std::swap(cur[0], cur[1]);
    }
  };
  advance(warmup);
  const double e0 = mean_u2(*cur[0], AaState::natural);
  Stopwatch clock;
  advance(steps);
  const double wall = clock.seconds();
  return {double(n) * n * n * steps / wall / 1e6, mean_u2(*cur[0], AaState::natural) / e0, 0,
          memory_use()};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lbdem LBM benchmark (periodic Taylor-Green box of bench/peers, case 1)"};
  std::vector<int> sizes = {64, 128}, threads = {1, 2};
  std::vector<std::string> schemes = {"aa"};
  int steps = 200, warmup = 20;
  double tau = 0.6, u0 = 0.05;
  bool porous = false;
  std::vector<std::string> precisions = {"double"};
  app.add_option("--n", sizes, "cube edges N (cells)");
  app.add_option("--threads", threads, "OpenMP thread counts");
  app.add_option("--steps", steps, "timed steps")->check(CLI::PositiveNumber);
  app.add_option("--warmup", warmup, "untimed steps before the timed window");
  app.add_option("--tau", tau, "BGK relaxation time")->check(CLI::Range(0.5001, 10.0));
  app.add_option("--u0", u0, "velocity amplitude (lattice units)");
  app.add_option("--scheme", schemes,
                 "aa (solver), ab (two lattices), nt (two lattices, NT stores)")
      ->check(CLI::IsMember({"aa", "ab", "nt"}));
  app.add_flag("--porous", porous,
               "the coupled gas kernel instead: TRT, porous form, per-cell force, velocity sums "
               "(scheme aa)");
  app.add_option("--precision", precisions,
                 "precision of the AA kernel: double, single (populations f - w, per-cell fields "
                 "and arithmetic in float; lbm/cell.hpp)")
      ->check(CLI::IsMember({"double", "single"}));
  CLI11_PARSE(app, argc, argv);
  const bool any_float = std::count(precisions.begin(), precisions.end(), "single") > 0;
  if (any_float && std::count(schemes.begin(), schemes.end(), "aa") != long(schemes.size())) {
    std::fprintf(stderr,
                 "lbdem-bench-lbm: --precision single runs the solver's AA kernel only; "
                 "fix: drop --scheme or give --scheme aa\n");
    return 2;
  }
  if (porous && (schemes.size() != 1 || schemes.front() != "aa")) {
    std::fprintf(stderr,
                 "lbdem-bench-lbm: --porous runs the solver's AA kernel only; "
                 "fix: drop --scheme or give --scheme aa\n");
    return 2;
  }

  const MemoryUse base = memory_use();  // the program before any lattice
  const Bgk op = Bgk::from_tau(tau);
  for (const std::string& precision : precisions)
    for (const std::string& scheme : schemes)
      for (int n : sizes)
        for (int t : threads) {
          omp_set_num_threads(t);
          const bool f32 = precision == "single";
          const Run r = run(scheme, n, steps, warmup, op, u0, porous,
                            f32 ? Precision::float32 : Precision::float64);
          const double k = 2.0 * kPi / n;
          const double theory = std::exp(-6.0 * op.viscosity() * k * k * steps);
          // Bytes per cell update for the roofline: 19 loads + 19 stores of 8 B (4 B in float);
          // ordinary stores on two lattices also read each destination line first (write-allocate),
          // 456 B. Single runs are labelled "lbdem-single" so that the double parsers skip them.
          const double bytes = f32 ? 152 : scheme == "ab" ? 456 : 304;
          std::printf(
              "%s LBM TGV N=%d, %d thread(s): %.1f MLUPS, E_ratio %.4f (theory %.3f), scheme %s, "
              "%.0f B/cell = %.1f GB/s%s state_hash=%016llx rss_bytes=%zu base_rss_bytes=%zu "
              "peak_bytes=%zu\n",
              f32 ? "lbdem-single" : "lbdem", n, t, r.mlups, r.e_ratio, theory,
              porous ? "aa" : scheme.c_str(), bytes, r.mlups * bytes / 1e3,
              porous ? " (porous TRT kernel with Darcy drag: the theory is the free decay, not "
                       "this one)"
                     : "",
              static_cast<unsigned long long>(r.hash), r.memory.resident, base.resident,
              r.memory.peak);
          std::fflush(stdout);
        }
  return 0;
}
