#include "scenarios/common/coupling_config.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "coupling/drag/coarse_grain_drag.hpp"

namespace lbdem::scenarios {

CouplingConfig read_coupling(const Config& c, const FluidConfig& fluid, double d_min, double d_max,
                             double l, double rho_p, bool gas_weighs, const Vec3& gravity) {
  CouplingConfig out;
  auto& s = out.settings;
  out.parcel_diameter_min = d_min;
  out.parcel_diameter_max = d_max;
  out.particle_density = rho_p;
  s.two_way = c.get_bool("two_way", true);
  std::vector<std::string> laws;
  for (const auto& m : coupling::kDragModels) laws.emplace_back(coupling::name_of(m));
  s.drag = coupling::make_drag_model(c.get_choice("drag", "gidaspow", laws));
  s.size_factor = l;
  s.viscosity = fluid.viscosity;
  const double sigma_default = coupling::default_kernel_width(fluid.dx, d_max);
  s.kernel_width = c.get("kernel_width", sigma_default,
                         Range::positive("give the kernel width sigma in m, at least fluid.dx"));
  if (s.kernel_width < fluid.dx * (1 - 1e-12))
    throw InputError(c.path("kernel_width"), to_text(s.kernel_width),
                     "narrower than one cell (fluid.dx = " + to_text(fluid.dx) + " m)",
                     "give kernel_width >= fluid.dx, e.g. " + to_text(sigma_default));
  s.eps_min = c.get("eps_min", coupling::kDefaultEpsMin,
                    {0, 1, true, true, "give the lower bound of the gas fraction, e.g. 0.3"});
  s.pressure_gradient = c.get_bool("pressure_gradient", true);
  s.displaced_gas = c.get_bool("displaced_gas", true);
  s.gas_weight = gas_weighs ? Vec3(fluid.density * gravity) : Vec3(Vec3::Zero());
  // The kernel's outer cells stand for the part of the particles' box they hold (a grid centred on
  // an edge that is not whole cells, fluid_config.cpp); an edge of whole cells is the grid's,
  // exactly (fluid_config.cpp takes an edge within 1e-9 relative of whole cells for whole).
  coupling::ParticleBox box{fluid.lo, fluid.hi()};
  for (int a = 0; a < 3; ++a)
    if (fluid.wall_offset(a) != 0) box.lo[a] = fluid.box_lo[a], box.hi[a] = fluid.box_hi[a];
  s.particle_box = box;
  out.exchange_every = int(c.get_int(
      "exchange_every", 1, Range::closed(1, 1e6, "give the coupling cycles per exchange, >= 1")));
  return out;
}

void coupling_banner(Log& log, const CouplingConfig& c, const FluidConfig& fluid,
                     const SubCycle& sub, std::size_t particles, double fluid_cells) {
  const auto& s = c.settings;
  const double l = s.size_factor, dmax = c.parcel_diameter_max, dmin = c.parcel_diameter_min;
  const double d_o = dmax / l;  // largest original diameter
  const double mu = fluid.viscosity, rho_f = fluid.density;
  const double vp = kPi * dmax * dmax * dmax / 6;
  log.line("coupling derived numbers:");
  log.line(std::string("  formulation                        ") +
           (s.two_way ? "two-way" : "one-way (the gas does not feel the particles)") +
           ", Zhou et al. 2010 set II on the Guo-Zhao LBM; drag law " +
           std::string(coupling::name_of(s.drag)) +
           (s.pressure_gradient ? " + pressure-gradient force" : "") +
           (s.two_way && s.displaced_gas ? "; d(eps)/dt in the gas continuity" : ""));
  // Single-particle terminal velocity of one original (Schiller-Naumann, no buoyancy), the
  // speed scale of a settling or fluidized particle, by bisection.
  const double g = 9.81, m_o = c.particle_density * kPi * d_o * d_o * d_o / 6;
  double lo = 0, hi = m_o * g / (3 * kPi * mu * d_o);
  for (int it = 0; it < 200; ++it) {
    const double v = 0.5 * (lo + hi), re = rho_f * v * d_o / mu;
    (3 * kPi * mu * d_o * v * (1 + 0.15 * std::pow(re, 0.687)) < m_o * g ? lo : hi) = v;
  }
  const double v_t = 0.5 * (lo + hi);
  const double tau_p = c.particle_density * d_o * d_o / (18 * mu);
  log.derived("original diameter (largest)", d_o, "m", "(parcels l = " + to_text(l) + ")");
  log.derived("terminal velocity of an original", v_t, "m/s", "(Schiller-Naumann, |g| = 9.81)");
  log.derived("particle Reynolds number Re_p", rho_f * v_t * d_o / mu, "",
              "(at the terminal velocity; " + to_text(rho_f * fluid.max_speed * d_o / mu) +
                  " at max_speed)");
  log.derived("Stokes response time tau_p", tau_p, "s", "(rho_p d^2 / 18 mu, shared by parcels)");
  log.derived("Stokes number tau_p U / d", tau_p * fluid.max_speed / d_o, "",
              "(U = max_speed " + to_text(fluid.max_speed) + " m/s)");
  log.derived("cells per parcel diameter", dmax / fluid.dx, "",
              "(smallest parcel " + to_text(dmin / fluid.dx) + ")");
  log.derived("parcels per cell", fluid_cells > 0 ? double(particles) / fluid_cells : 0.0, "",
              "(mean; " + to_text(0.6 * std::pow(fluid.dx, 3) / vp) + " at solid fraction 0.6)");
  log.derived("kernel width sigma", s.kernel_width, "m",
              "(" + to_text(s.kernel_width / dmax) + " parcel diameters, " +
                  to_text(s.kernel_width / fluid.dx) + " cells)");
  // Maxey & Patel: the parcel's own reaction slows the gas at it by about 0.28 D / sigma of the
  // slip, l^3 times more for a parcel of l^3 originals (docs/physics.md, Coupling kernel).
  log.derived("self-induced slip error", 0.28 * l * l * l * d_o / s.kernel_width, "",
              "(dilute limit 0.28 l^3 d / sigma, two-way; screened in a dense bed)");
  const ExchangeInterval e = exchange_interval(sub, c.exchange_every);
  log.derived("gas step", fluid.dt, "s");
  log.derived("DEM step", sub.dem_dt, "s",
              "(ratio gas/DEM " + to_text(fluid.dt / sub.dem_dt) + ")");
  log.derived("exchange interval", double(e.dem_steps) * sub.dem_dt, "s",
              "(" + std::to_string(e.dem_steps) + " DEM steps, " + std::to_string(e.gas_steps) +
                  " gas steps)");
  // The particle side is explicit: the drag relaxes a particle by beta dt / m per interval.
  const double interval = double(e.dem_steps) * sub.dem_dt;
  log.derived("particle drag per interval dt/tau_p", interval / tau_p, "",
              "(isolated Stokes particle; a dense bed is stiffer by about 10)");
  if (interval / tau_p * 10 > 0.5)
    log.line(
        "warning: coupling: the exchange interval is " + to_text(interval / tau_p) +
        " tau_p; a dense bed's drag may overshoot: lower coupling.exchange_every or the steps");
}

}  // namespace lbdem::scenarios
