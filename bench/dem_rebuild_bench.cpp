// DEM benchmark of the neighbour rebuild: the wall time per step and the DEM's phase shares (the
// rebuild is the neighbour search phase) of two cases.
//
// column (default): a nearly empty domain, one particle of r = 42.5 um settling through a
// 4 x 4 x 60 mm box, a 42 x 42 x 641 = 1.13e6-cell grid at the cut-off 2r + skin, skin 0.2 r. It
// starts at 1 m/s downwards with dt = 1e-5 s, so it moves more than skin/2 every step and the
// neighbour list is rebuilt at every step: a step costs what a rebuild costs. --n N places N
// particles on a lattice of spacing 4r in the top of the box (a dilute feed).
//
// bed: the settled Hertz-Mindlin bed of lbdem-bench-dem (bench/dem_bench.cpp, same particles,
// walls and steps), loaded from that program's cache (run lbdem-bench-dem --n N first).
//
// --rebuild-every K forces a rebuild every K steps (on the bed: the cost of one rebuild of a dense
// packing). Prints the wall time per step, particle-steps/s, the rebuilds, the phase shares and a
// hash of the final state (equal for bitwise equal runs) for each thread count.
#include <omp.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/h5.hpp"
#include "core/phase_timer.hpp"
#include "dem/dem_solver.hpp"

using namespace lbdem;

namespace {

dem::Material glass() {
  dem::Material m;
  m.name = "glass";
  m.density = 2500;
  m.youngs_modulus = 5e6;
  m.poisson_ratio = 0.3;
  m.restitution = 0.5;
  m.friction = 0.5;
  return m;
}

dem::Wall plane(const Vec3& point, int axis, double sign, const std::string& name) {
  dem::PlaneWall p;
  p.point = point;
  p.normal = Vec3::Zero();
  p.normal[axis] = sign;
  dem::Wall w;
  w.name = name;
  w.shape = p;
  return w;
}

dem::DemSolver make_column(int n, double radius, double dt, const Vec3& box) {
  dem::DemSettings s;
  s.dt = dt;
  s.gravity = Vec3(0, 0, -9.81);
  s.skin = 0.2 * radius;
  s.domain.lo = Vec3::Zero();
  s.domain.hi = box;
  dem::DemSolver sol(s, {glass()});
  sol.add_wall(plane(Vec3::Zero(), 2, 1, "floor"));
  const double a = 4 * radius;
  const int nx = std::max(1, static_cast<int>(box[0] / a));
  const int ny = std::max(1, static_cast<int>(box[1] / a));
  for (int k = 0; k < n; ++k) {
    const int i = k % nx, j = (k / nx) % ny, l = k / (nx * ny);
    const Vec3 x =
        n == 1 ? Vec3(0.5 * box[0], 0.5 * box[1], box[2] - a)
               : Vec3((i + 0.5) * box[0] / nx, (j + 0.5) * box[1] / ny, box[2] - (l + 1) * a);
    sol.add_particle(x, Vec3(0, 0, -1.0), radius, 0);
  }
  return sol;
}

// bench/dem_bench.cpp's bed: the walls and settings its checkpoint was written with.
dem::DemSolver make_bed(int side, int nz) {
  constexpr double kA = 1.05e-3;
  dem::DemSettings s;
  s.dt = 1e-6;
  s.gravity = Vec3(0, 0, -9.81);
  s.skin = 1e-4;
  const double L = side * kA;
  s.domain.lo = Vec3::Zero();
  s.domain.hi = Vec3(L, L, (nz + 10) * kA);
  dem::DemSolver sol(s, {glass()});
  for (int a = 0; a < 3; ++a)
    for (int hi = 0; hi < 2; ++hi) {
      if (a == 2 && hi == 1) continue;  // no lid
      sol.add_wall(plane(hi ? s.domain.hi : s.domain.lo, a, hi ? -1 : 1,
                         "wall" + std::to_string(sol.walls().size())));
    }
  return sol;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lbdem DEM benchmark of the neighbour rebuild"};
  std::string which = "column";
  int n = 1, steps = 0, rebuild_every = 0;
  double radius = 42.5e-6, dt = 1e-5;
  std::vector<double> box = {4e-3, 4e-3, 60e-3};
  std::vector<int> threads = {1, 2};
  std::string cache = (std::filesystem::temp_directory_path() / "lbdem-bench").string();
  app.add_option("--case", which, "column or bed")->check(CLI::IsMember({"column", "bed"}));
  app.add_option("--n", n, "particles (column: 1; bed: 20000)")->check(CLI::PositiveNumber);
  app.add_option("--steps", steps, "timed steps (column: 2000; bed: 5000)");
  app.add_option("--radius", radius, "column: particle radius [m]")->check(CLI::PositiveNumber);
  app.add_option("--dt", dt, "column: time step [s]")->check(CLI::PositiveNumber);
  app.add_option("--box", box, "column: box edges [m]")->expected(3);
  app.add_option("--threads", threads, "thread counts");
  app.add_option("--rebuild-every", rebuild_every,
                 "force a neighbour rebuild every this many steps (0: only where the skin asks)");
  app.add_option("--cache", cache, "bed: lbdem-bench-dem's folder of settled beds");
  CLI11_PARSE(app, argc, argv);
  const bool bed = which == "bed";
  if (bed && n == 1) n = 20000;
  if (steps <= 0) steps = bed ? 5000 : 2000;
  const std::string bed_file = cache + "/bed_N" + std::to_string(n) + "_settle20000_layout" +
                               std::to_string(dem::DemSolver::kCheckpointLayout) + ".h5";
  if (bed && (n % 2500 || !std::filesystem::exists(bed_file))) {
    std::fprintf(stderr,
                 "lbdem-bench-dem-rebuild: no settled bed %s; fix: run lbdem-bench-dem --n %d\n",
                 bed_file.c_str(), n);
    return 2;
  }
  const Vec3 edges(box[0], box[1], box[2]);
  for (int t : threads) {
    omp_set_num_threads(t);
    auto sol = bed ? make_bed(50, n / 2500) : make_column(n, radius, dt, edges);
    if (bed) sol.load(H5In(bed_file));
    for (int k = 0; k < (bed ? 500 : 1); ++k) sol.step();  // untimed: first rebuild, warm-up
    const auto rebuilds0 = sol.rebuilds();
    PhaseTimer::global().reset();
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) {
      if (rebuild_every > 0 && k % rebuild_every == 0) sol.remove_particles({});  // none removed
      sol.step();
    }
    const double loop =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const PhaseTimer& pt = PhaseTimer::global();
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a of positions and velocities
    for (const auto* field : {&sol.particles().x, &sol.particles().v}) {
      const auto* b = reinterpret_cast<const unsigned char*>(field->data());
      for (std::size_t k = 0; k < field->size() * sizeof((*field)[0]); ++k)
        hash = (hash ^ b[k]) * 1099511628211ull;
    }
    std::printf(
        "%s n=%zu threads=%d steps=%d us_per_step=%.2f particle_steps_per_s=%.4g rebuilds=%lld "
        "us_per_rebuild=%.1f share_rebuild=%.3f share_pairs=%.3f share_walls_kick=%.3f "
        "share_integration=%.3f loop_s=%.3f state_hash=%016llx\n",
        which.c_str(), sol.particles().size(), t, steps, 1e6 * loop / steps,
        double(sol.particles().size()) * steps / loop,
        static_cast<long long>(sol.rebuilds() - rebuilds0),
        1e6 * pt.seconds(Phase::dem_neighbour_search) /
            std::max<double>(1, double(sol.rebuilds() - rebuilds0)),
        pt.seconds(Phase::dem_neighbour_search) / loop, pt.seconds(Phase::dem_pair_contacts) / loop,
        pt.seconds(Phase::dem_walls_and_kick) / loop, pt.seconds(Phase::dem_integration) / loop,
        loop, static_cast<unsigned long long>(hash));
    std::fflush(stdout);
  }
  return 0;
}
