#include "scenarios/jet_mill/jet_mill.hpp"

#include <cmath>
#include <string_view>

#include "core/error.hpp"

namespace lbdem::scenarios {

JetMillScenario::JetMillScenario(const Config& cfg) : box_(cfg) {
  if (!box_.gas())
    throw InputError("fluid", "", "a jet mill needs its gas",
                     "add a [fluid] table (see scenarios/jet_mill/presets/default.toml)");
  // Particles come with the next step of issue 11: the DEM's chamber walls, the feed, the outlet's
  // removal, and a coupler built after the chamber's cells (its kernel masks solids when built).
  // [inflow] and [outlet] are the box's particle streams; the resolved config of a run (read back
  // by --resume) holds them switched off.
  for (const char* key : {"coupling", "fill", "particle", "inflow", "outlet", "walls", "materials"})
    if (cfg.has(key) &&
        !((std::string_view(key) == "inflow" || std::string_view(key) == "outlet") &&
          !cfg.section(key).get_bool("enabled", true)))
      throw InputError(key, "", "the jet mill runs its gas only so far (particles: next step)",
                       "remove [" + std::string(key) + "]");
  const FluidConfig& f = box_.fluid();
  static const char* kFaces[6] = {"x_lo", "x_hi", "y_lo", "y_hi", "z_lo", "z_hi"};
  for (int a = 0; a < 6; ++a)
    if (f.faces[std::size_t(a)].kind != "wall")
      throw InputError(std::string("fluid.faces.") + kFaces[a],
                       "\"" + f.faces[std::size_t(a)].kind + "\"",
                       "the jet mill's chamber is closed: the plates are walls, the side is the "
                       "chamber's cylinder, the outlet is cut into the top plate",
                       "leave fluid.faces out (all walls)");
  geometry_ = read_jet_mill(cfg.section("jet_mill"), f);
  lbm::LbmSolver& gas = *box_.gas();
  outlet_ = build_chamber(gas, f, geometry_);
  sources_ = jet_sources(gas, f, geometry_);
  gas.set_mass_sources(sources_.mass);
  gas.enable_force_field();
  gas.set_force_field(sources_.force);
  if (box_.coupler()) box_.coupler()->set_gas_source(sources_.force);

  BoxScenario::Extra extra;
  extra.columns = {
      "jet_mass_flow_kg_s",       "outlet_mass_flow_kg_s", "gas_tangential_speed_mid_m_s",
      "gas_radial_speed_mid_m_s", "gas_max_speed_m_s",     "gas_angular_momentum_z_Nms"};
  extra.values = [this](const dem::DemSolver&) {
    std::vector<Vec3> u;
    std::vector<double> rho;
    box_.gas()->velocity(u);
    box_.gas()->density(rho);
    const auto ring = ring_velocity(u, 0.5 * geometry_.radius);
    double umax = 0;
    for (const Vec3& v : u) umax = std::max(umax, v.norm());
    return std::vector<double>{jet_mass_flow(),
                               outlet_mass_flow(),
                               ring[0],
                               ring[1],
                               box_.fluid().units().velocity_to_si(umax),
                               angular_momentum(u, rho)};
  };
  extra.banner = [this](Log& log) { mill_banner(log); };
  box_.set_extra(std::move(extra));
}

double JetMillScenario::outlet_mass_flow() const {
  // mass_flow: what the body passed to the fluid (negative when leaving).
  return -box_.fluid().units().mass_flow_to_si(box_.gas()->mass_flow(outlet_));
}

double JetMillScenario::jet_mass_flow() const {
  return box_.fluid().units().mass_flow_to_si(box_.gas()->mass_source_rate());
}

double JetMillScenario::angular_momentum(const std::vector<Vec3>& u,
                                         const std::vector<double>& rho) const {
  const FluidConfig& f = box_.fluid();
  const lbm::LbmSolver& gas = *box_.gas();
  const lbm::Grid& g = gas.grid();
  const lbm::LatticeUnits units = f.units();
  double l = 0;  // serial, in cell order: the same sum for any thread count
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        if (!gas.flags().fluid(g.index(x, y, z))) continue;
        const std::size_t c = std::size_t(g.compact_index(x, y, z));
        const Vec3 r = f.cell_centre(x, y, z) - geometry_.axis;
        l += rho[c] * (r.x() * u[c].y() - r.y() * u[c].x());
      }
  return l * units.rho * units.velocity_to_si(1.0) * f.dx * f.dx * f.dx;
}

std::array<double, 2> JetMillScenario::ring_velocity(const std::vector<Vec3>& u, double r) const {
  const FluidConfig& f = box_.fluid();
  const lbm::LbmSolver& gas = *box_.gas();
  const lbm::Grid& g = gas.grid();
  double ut = 0, ur = 0;
  long n = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        if (!gas.flags().fluid(g.index(x, y, z))) continue;
        const Vec3 c = f.cell_centre(x, y, z) - geometry_.axis;
        const double rc = std::hypot(c.x(), c.y());
        if (std::abs(rc - r) >= f.dx || rc <= 0) continue;
        const Vec3& v = u[std::size_t(g.compact_index(x, y, z))];
        ur += (v.x() * c.x() + v.y() * c.y()) / rc;
        ut += (-v.x() * c.y() + v.y() * c.x()) / rc;
        ++n;
      }
  const double to_si = f.units().velocity_to_si(1.0);
  return n ? std::array<double, 2>{to_si * ut / double(n), to_si * ur / double(n)}
           : std::array<double, 2>{0.0, 0.0};
}

void JetMillScenario::mill_banner(Log& log) const {
  const FluidConfig& f = box_.fluid();
  const JetMillGeometry& g = geometry_;
  log.line("jet mill derived numbers:");
  log.derived("chamber diameter", 2 * g.radius, "m",
              "(" + to_text(2 * g.radius / f.dx) + " cells)");
  log.derived("chamber height", g.height, "m", "(" + to_text(g.height / f.dx) + " cells)");
  log.derived("outlet (vortex finder) radius", g.outlet_radius, "m",
              "(" + to_text(g.outlet_radius / f.dx) + " cells)");
  if (g.nozzles.empty()) return;
  const Nozzle& q = g.nozzles.front();
  const double nu = f.nu();
  log.derived(
      "nozzles", double(g.nozzles.size()), "",
      "(diameter " + to_text(q.diameter) + " m = " + to_text(q.diameter / f.dx) + " cells)");
  log.derived("jet exit speed U", q.speed, "m/s",
              "(lattice " + to_text(f.units().velocity_to_lattice(q.speed)) + ", Mach " +
                  to_text(f.units().velocity_to_lattice(q.speed) * std::sqrt(3.0)) + ")");
  log.derived("jet Reynolds number U d / nu", q.speed * q.diameter / nu, "");
  log.derived("mass flow per nozzle", q.mass_flow, "kg/s",
              "(total " + to_text(q.mass_flow * double(g.nozzles.size())) + " kg/s)");
  log.derived("momentum flux per nozzle J", q.momentum_flux(), "N", "(mdot U)");
  log.derived("notional source radius r_s", q.source_radius, "m",
              "(" + to_text(q.source_radius / f.dx) + " cells; speed at r_s about " +
                  to_text(std::sqrt(q.momentum_flux() /
                                    (kPi * f.density * q.source_radius * q.source_radius))) +
                  " m/s)");
  log.derived("source cells per nozzle", double(sources_.cells_per_nozzle.front()), "",
              "(mass and momentum exact on any grid: jet_mill_geometry.hpp)");
}

}  // namespace lbdem::scenarios
