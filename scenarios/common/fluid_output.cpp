#include "scenarios/common/fluid_output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "core/deterministic_sum.hpp"
#include "core/error.hpp"
#include "lbm/d3q19.hpp"
#include "run/xdmf.hpp"

namespace lbdem::scenarios {

using run::GasGrid;
using run::write_fluid_xdmf;

namespace fs = std::filesystem;

namespace {

bool open_face(const FluidFace& f) {
  return f.kind == "inlet" || f.kind == "outlet";
}

std::string snapshot_name(std::size_t k) {
  char name[64];
  std::snprintf(name, sizeof name, "snapshots/fluid_%06zu.h5", k);
  return name;
}

}  // namespace

std::vector<std::string> fluid_columns(const FluidConfig& c) {
  std::vector<std::string> cols = {"gas_mean_speed_m_s", "gas_kinetic_energy_J", "gas_mass_kg"};
  for (int f = 0; f < 6; ++f)
    if (open_face(c.faces[std::size_t(f)]))
      cols.push_back("gas_mass_flow_" + std::string(lbm::BoxFaces::kNames[std::size_t(f)]) +
                     "_kg_s");
  for (const char* a : {"x", "y", "z"})
    cols.push_back(std::string("gas_force_on_walls_") + a + "_N");
  cols.push_back("gas_mass_balance_error_kg");
  return cols;
}

std::vector<double> fluid_values(const lbm::LbmSolver& s, const FluidConfig& c) {
  const lbm::LatticeUnits u = c.units();
  std::vector<double> rho;
  std::vector<Vec3> vel;
  s.density(rho);
  s.velocity(vel);
  // Fixed-block sums: the same bits at any thread count (docs/architecture.md). Solid cells read
  // rho = 0.
  const double fluid_cells = deterministic_sum(
      rho.size(), [&](std::size_t i) { return rho[i] > 0 ? 1.0 : 0.0; }, 0.0);
  const double speed = deterministic_sum(
      vel.size(), [&](std::size_t i) { return vel[i].norm(); }, 0.0);
  const double energy = deterministic_sum(
      vel.size(), [&](std::size_t i) { return 0.5 * rho[i] * vel[i].squaredNorm(); }, 0.0);
  const double mass = deterministic_sum(
      rho.size(), [&](std::size_t i) { return rho[i]; }, 0.0);
  const double cell_mass = c.density * c.dx * c.dx * c.dx;  // rho_lu = 1 in one cell [kg]
  const double v = u.velocity_to_si(1.0);
  std::vector<double> out = {fluid_cells > 0 ? v * speed / fluid_cells : 0.0,
                             cell_mass * v * v * energy, cell_mass * mass};
  for (int f = 0; f < 6; ++f)
    if (open_face(c.faces[std::size_t(f)]))
      out.push_back(u.mass_flow_to_si(s.mass_flow(s.face_body(f))));
  Vec3 walls = Vec3::Zero();  // faces in a fixed order: the same bits at any thread count
  for (int f = 0; f < 6; ++f) {
    const std::string& kind = c.faces[std::size_t(f)].kind;
    if (kind == "wall" || kind == "moving_wall") walls += s.wall_force_mean2(s.face_body(f));
  }
  for (int a = 0; a < 3; ++a) out.push_back(u.force_to_si(walls[a]));
  // What the gas holds less what it started with and what the boundaries gave it: round-off.
  out.push_back(cell_mass * (s.total_mass() - s.initial_mass() - s.exchanged_mass()));
  return out;
}

void write_fluid_snapshot(const std::string& dir, const lbm::LbmSolver& s, const FluidConfig& c,
                          const std::vector<double>& times,
                          const std::vector<run::SnapshotArray>& extra) {
  const lbm::LatticeUnits u = c.units();
  const std::size_t index = times.size() - 1;
  const std::size_t nx = std::size_t(c.cells[0]), ny = std::size_t(c.cells[1]),
                    nz = std::size_t(c.cells[2]);
  std::vector<double> rho, porosity;
  std::vector<Vec3> vel;
  s.density(rho);
  s.velocity(vel);
  s.porosity(porosity);  // 1 in gas without particles, 0 in solid cells
  std::vector<double> velocity(3 * vel.size()), pressure(rho.size());
  const double v = u.velocity_to_si(1.0);
  for (std::size_t i = 0; i < vel.size(); ++i)
    for (int a = 0; a < 3; ++a) velocity[3 * i + std::size_t(a)] = v * vel[i][a];
  // p - p_ref = (rho - rho_ref) c_s^2 (lattice), rho_ref = 1; solid cells (rho = 0) read 0. In
  // the porous form (lbm/forcing/porous.hpp) rho c_s^2 is eps p, the pressure the momentum
  // balance carries; the coupling, which sets eps, decides what it reports.
  for (std::size_t i = 0; i < rho.size(); ++i)
    pressure[i] = rho[i] > 0 ? u.pressure_to_si((rho[i] - 1.0) * lbm::kCs2) : 0.0;
  // 1 in solid cells (walls, the jet mill's outside of its chamber), 0 in gas cells.
  const lbm::Grid& g = s.grid();
  std::vector<std::uint8_t> solid(rho.size(), 0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        if (!s.flags().fluid(g.index(x, y, z))) solid[std::size_t(g.compact_index(x, y, z))] = 1;
  fs::create_directories(dir + "/snapshots");
  {
    H5Out f(dir + "/" + snapshot_name(index));
    f.attr("time_s", times.back());
    f.write_array("/velocity_m_per_s", velocity, {nz, ny, nx, 3});
    f.write_array("/pressure_Pa", pressure, {nz, ny, nx});
    f.write_array("/porosity", porosity, {nz, ny, nx});
    f.write_array("/solid", solid, {nz, ny, nx});
    for (const run::SnapshotArray& a : extra) f.write("/" + a.name, a.values);
    f.commit();
  }
  const Vec3 origin = c.cell_centre(0, 0, 0);
  H5Out master(dir + "/fluid.h5");
  master.write("/time_s", times);
  master.group("/grid");
  master.write("/grid/origin_m", std::vector<double>{origin[0], origin[1], origin[2]});
  master.write("/grid/lower_corner_m", std::vector<double>{c.lo[0], c.lo[1], c.lo[2]});
  master.write("/grid/spacing_m", std::vector<double>{c.dx, c.dx, c.dx});
  master.write("/grid/cells", std::vector<std::int32_t>{c.cells[0], c.cells[1], c.cells[2]});
  master.attr("pressure_reference_density_kg_m3", c.density);
  master.group("/snapshots");
  for (std::size_t k = 0; k <= index; ++k) {
    char link[32];
    std::snprintf(link, sizeof link, "/snapshots/%06zu", k);
    master.external_link(link, snapshot_name(k), "/");
  }
  master.commit();
  write_fluid_xdmf(dir, times, GasGrid{c.lo, c.dx, c.cells});
}

std::optional<std::string> check_fluid_health(const lbm::LbmSolver& s, const FluidConfig& c,
                                              double time, std::int64_t dem_step) {
  const auto bad = s.find_unhealthy(1 - kHealthyDensity, 1 + kHealthyDensity, kHealthySpeed);
  if (!bad) return std::nullopt;
  const lbm::LatticeUnits u = c.units();
  const Vec3 x = c.cell_centre(bad->x, bad->y, bad->z);
  return "gas diverged at t = " + to_text(time) + " s (DEM step " + std::to_string(dem_step) +
         ", gas step " + std::to_string(s.steps()) + "): cell (" + std::to_string(bad->x) + ", " +
         std::to_string(bad->y) + ", " + std::to_string(bad->z) + ") at " + vec_text(x) +
         " m has rho/rho_ref = " + to_text(bad->rho) + " and speed " +
         to_text(u.velocity_to_si(bad->speed)) + " m/s (healthy: " + to_text(1 - kHealthyDensity) +
         " - " + to_text(1 + kHealthyDensity) + ", below " +
         to_text(u.velocity_to_si(kHealthySpeed)) +
         " m/s); the last checkpoint and output are kept; fix: " + c.divergence_fix();
}

std::optional<std::string> check_fluid_mach(const lbm::LbmSolver& s, const FluidConfig& c,
                                            double time) {
  // The fastest fluid cell (the first of equals in storage order: the same for any thread count),
  // so that the step the fix names covers the whole gas.
  std::vector<Vec3> vel;
  s.velocity(vel);  // solids read 0
  std::size_t fastest = 0;
  double top = 0;
  for (std::size_t k = 0; k < vel.size(); ++k)
    if (const double v = vel[k].norm(); v > top) top = v, fastest = k;
  const double limit = kWarnMach * std::sqrt(lbm::kCs2);  // lattice speed at Mach kWarnMach
  if (!(top > limit)) return std::nullopt;
  const std::size_t nx = std::size_t(c.cells[0]), ny = std::size_t(c.cells[1]);
  const int x = int(fastest % nx), y = int(fastest / nx % ny), z = int(fastest / (nx * ny));
  const Vec3 at = c.cell_centre(x, y, z);
  const double speed = c.units().velocity_to_si(top);
  // The step that puts this speed at lattice velocity 0.1 takes top / 0.1 times as many steps;
  // offered only if the start-up checks accept exactly that (a shorter step brings tau nearer
  // 1/2, and the pressure rule may already set a shorter one).
  const std::vector<std::string> drop =
      c.dt_from == "fluid.dt" ? std::vector<std::string>{"dt"} : std::vector<std::string>{};
  const std::string refused =
      c.try_change
          ? c.try_change({{"max_speed", to_text(speed, 12)}, {"lattice_velocity", "0.1"}}, drop)
          : std::string();
  if (!refused.empty())
    return "warning: fluid: the gas reached lattice Mach " + to_text(top / std::sqrt(lbm::kCs2)) +
           " at t = " + to_text(time) + " s: " + to_text(speed) + " m/s at cell (" +
           std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
           "), its fastest; the run goes on; the step for that speed (fluid.max_speed = " +
           to_text(speed) +
           " at fluid.lattice_velocity = 0.1) would not pass the start-up "
           "checks (" +
           refused + "); fix: slower inflows";
  return "warning: fluid: the gas reached lattice Mach " + to_text(top / std::sqrt(lbm::kCs2)) +
         " at t = " + to_text(time) + " s: " + to_text(speed) + " m/s at cell (" +
         std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + "), [" +
         to_text(at[0]) + ", " + to_text(at[1]) + ", " + to_text(at[2]) +
         "] m, its fastest (the weakly compressible gas's errors grow as Ma^2; presets keep "
         "Mach 0.17); the run goes on; fix: a gas step of at most " +
         to_text(0.1 * c.dx / speed) + " s (fluid.max_speed = " + to_text(speed) +
         " m/s at fluid.lattice_velocity = 0.1, or fluid.dt; " + to_text(top / 0.1) +
         "x the gas steps; in a jet mill keep jet_mill.nozzles.source_speed at the old max_speed, "
         "or the jets' sources shrink), or slower inflows";
}

}  // namespace lbdem::scenarios
