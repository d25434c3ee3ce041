// DEM benchmark: the settled Hertz-Mindlin bed of bench/peers (case 2), same particles,
// material, walls, time steps, skin and step counts as the LIGGGHTS and LAMMPS inputs there:
//   d = 1 mm, rho = 2500, E = 5e6, nu = 0.3, e = 0.5, mu = 0.5, simple-cubic lattice a = 1.05 mm,
//   50 x 50 x NZ sites, v = 0.05 sin(k.x) m/s, 5 walls, gravity; settle 20,000 steps of 1e-5 s
//   (untimed, cached), then 500 untimed + NSTEPS timed steps of 1e-6 s. --side S makes the
//   footprint S x S sites (bench/size.py: a bed of fixed depth and growing area, so that every size
//   has the same contacts per particle; the peers' case is S = 50).
// Prints particle-steps/s = N NSTEPS / T_loop and the contact number Z for each thread count.
#include <omp.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "core/h5.hpp"
#include "core/memory.hpp"
#include "dem/dem_solver.hpp"

using namespace lbdem;

namespace {

constexpr double kA = 1.05e-3;  // lattice spacing [m]

dem::DemSolver make_bed(int side, int nz, double dt) {
  dem::Material m;
  m.name = "glass";
  m.density = 2500;
  m.youngs_modulus = 5e6;
  m.poisson_ratio = 0.3;
  m.restitution = 0.5;
  m.friction = 0.5;
  dem::DemSettings s;
  s.dt = dt;
  s.gravity = Vec3(0, 0, -9.81);
  s.skin = 1e-4;  // 0.1 d, as the peers
  const double L = side * kA;
  s.domain.lo = Vec3::Zero();
  s.domain.hi = Vec3(L, L, (nz + 10) * kA);
  dem::DemSolver sol(s, {m});
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      if (a == 2 && side == 1) continue;  // no lid
      dem::PlaneWall p;
      p.point = side ? s.domain.hi : s.domain.lo;
      p.normal = Vec3::Zero();
      p.normal[a] = side ? -1 : 1;
      dem::Wall w;
      w.name = "wall" + std::to_string(sol.walls().size());
      w.shape = p;
      sol.add_wall(w);
    }
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const Vec3 x((i + 0.5) * kA, (j + 0.5) * kA, (k + 0.5) * kA);
        const Vec3 v(0.05 * std::sin(12989.8 * x[0] + 78233.0 * x[1] + 37719.0 * x[2]),
                     0.05 * std::sin(39346.0 * x[0] + 11135.0 * x[1] + 83155.0 * x[2]),
                     0.05 * std::sin(73156.0 * x[0] + 52235.0 * x[1] + 9151.0 * x[2]));
        sol.add_particle(x, v, 0.5e-3, 0);
      }
  return sol;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lbdem DEM benchmark (settled Hertz-Mindlin bed of bench/peers)"};
  int n = 20000, steps = 0, settle = 20000, side = 50;
  std::vector<int> threads = {1, 2};
  std::string cache = (std::filesystem::temp_directory_path() / "lbdem-bench").string();
  app.add_option("--n", n, "particles: side^2 x layers (20000 or 100000 at side 50)");
  app.add_option("--side", side, "sites per footprint edge (50: the peers' case)")
      ->check(CLI::Range(2, 46340));  // side^2 fits an int
  app.add_option("--steps", steps, "timed steps (default 5000 for N <= 20000, else 1000)");
  app.add_option("--settle", settle, "settling steps of 1e-5 s");
  app.add_option("--threads", threads, "thread counts");
  app.add_option("--cache", cache, "folder for the settled bed");
  CLI11_PARSE(app, argc, argv);
  const MemoryUse base = memory_use();  // the program before any particle
  if (n <= 0 || n % (side * side)) {
    std::fprintf(stderr,
                 "lbdem-bench-dem: --n %d is not a positive multiple of side^2 = %d; fix: give "
                 "--n as a multiple of %d\n",
                 n, side * side, side * side);
    return 2;
  }
  const int nz = n / (side * side);
  if (steps <= 0) steps = n <= 20000 ? 5000 : 1000;
  std::filesystem::create_directories(cache);
  const std::string bed = cache + "/bed_N" + std::to_string(n) +
                          (side == 50 ? "" : "_side" + std::to_string(side)) + "_settle" +
                          std::to_string(settle) + "_layout" +
                          std::to_string(dem::DemSolver::kCheckpointLayout) + ".h5";
  if (!std::filesystem::exists(bed)) {
    std::fprintf(stderr, "settling N=%d: %d steps of 1e-5 s (cached in %s) ...\n", n, settle,
                 bed.c_str());
    auto sol = make_bed(side, nz, 1e-5);
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < settle; ++k) sol.step();
    std::fprintf(stderr, "settled in %.1f s (%.3g particle-steps/s)\n", seconds_since(t0),
                 double(n) * settle / seconds_since(t0));
    H5Out f(bed);
    sol.save(f);
    f.commit();
  }
  for (int t : threads) {
    omp_set_num_threads(t);
    auto sol = make_bed(side, nz, 1e-6);
    sol.load(H5In(bed));
    for (int k = 0; k < 500; ++k) sol.step();
    const auto rebuilds0 = sol.rebuilds();
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) sol.step();
    const double loop = seconds_since(t0);
    const MemoryUse memory = memory_use();
    const double z = 2.0 * double(sol.contacts_pp()) / double(sol.particles().size());
    // FNV-1a of the final positions and velocities: equal for bitwise equal runs (the scaling
    // study compares thread counts with it).
    std::uint64_t hash = 1469598103934665603ull;
    for (const auto* field : {&sol.particles().x, &sol.particles().v}) {
      const auto* b = reinterpret_cast<const unsigned char*>(field->data());
      for (std::size_t k = 0; k < field->size() * sizeof((*field)[0]); ++k)
        hash = (hash ^ b[k]) * 1099511628211ull;
    }
    std::printf(
        "%-10s %-44s %5d %14.4g  %-18s loop_s=%.3f rebuilds_in_window=%lld state_hash=%016llx "
        "rss_bytes=%zu base_rss_bytes=%zu peak_bytes=%zu\n",
        "lbdem",
        ("Hertz-Mindlin bed N=" + std::to_string(n) + ", dt=1e-6, " + std::to_string(steps) +
         " st, Z=" + std::to_string(z).substr(0, 4))
            .c_str(),
        t, double(sol.particles().size()) * steps / loop, "particle-steps/s", loop,
        static_cast<long long>(sol.rebuilds() - rebuilds0), static_cast<unsigned long long>(hash),
        memory.resident, base.resident, memory.peak);
    std::fflush(stdout);
  }
  return 0;
}
