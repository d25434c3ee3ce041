// The two-way gas-particle exchange (coupling/coupler.hpp) against references: the Schiller-Naumann
// terminal velocity of a settling sphere (one-way, originals and coarse-grained parcels), momentum
// of gas + particles to round-off (periodic, and against the fluxes of walls, an inlet and an
// outlet), the self-induced slip error against the kernel width
// (two-way), and the Ergun pressure drop of a fixed packed bed with the Gidaspow law.
#include <catch2/catch.hpp>

#include "coupling/coupler.hpp"
#include "dem/dem_solver.hpp"
#include "helpers/dem_setup.hpp"
#include "lbm/collision/trt.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <random>

using namespace lbdem;
using namespace lbdem::coupling;

namespace {

constexpr double kRhoGas = 1.2, kMuGas = 1.8e-5;  // air at 20 C [kg/m^3], [Pa s]

// Gas + particles + coupler in an n^3 (or nx ny nz) box whose lower corner is the SI origin.
struct Rig {
  lbm::LatticeUnits units;
  lbm::LatticeFrame frame;
  std::unique_ptr<lbm::LbmSolver> gas;
  std::unique_ptr<dem::DemSolver> dem;
  std::unique_ptr<Coupler> coupler;
  int dem_per_interval = 1, gas_per_interval = 1;

  Rig(std::array<int, 3> cells, double dx, double dt_gas, lbm::BoxFaces faces, dem::DemSettings ds,
      dem::Material mat, lbm::Precision precision = lbm::Precision::float64) {
    units = {dx, dt_gas, kRhoGas};
    frame = {Vec3::Zero(), dx};
    lbm::LbmSettings ls;
    ls.nx = cells[0], ls.ny = cells[1], ls.nz = cells[2];
    ls.faces = faces;
    ls.precision = precision;
    const double nu_lat = units.viscosity_to_lattice(kMuGas / kRhoGas);
    ls.collision = lbm::Trt::from_tau(0.5 + 3 * nu_lat);
    gas = std::make_unique<lbm::LbmSolver>(ls);
    gas->initialize([](int, int, int, double& rho, Vec3& u) { rho = 1, u = Vec3::Zero(); });
    ds.domain.lo = Vec3::Zero();
    ds.domain.hi = Vec3(cells[0], cells[1], cells[2]) * dx;
    dem = std::make_unique<dem::DemSolver>(ds, std::vector<dem::Material>{mat});
  }
  void couple(CouplerSettings cs) {
    cs.viscosity = kMuGas;
    coupler = std::make_unique<Coupler>(*gas, frame, units, cs);
    dem->track_external_work();
  }
  // One exchange interval: the gas steps first, then the DEM (scenarios do the same);
  // `after_gas_step` runs after each gas step (to read the boundaries' loads).
  ExchangeReport interval(const std::function<void()>& after_gas_step = {}) {
    coupler->begin_interval(dem->particles(), gas_per_interval);
    for (int k = 0; k < gas_per_interval; ++k) {
      coupler->before_gas_step();
      gas->step();
      if (after_gas_step) after_gas_step();
    }
    const ExchangeReport report = coupler->end_interval(dem->particles());
    for (int k = 0; k < dem_per_interval; ++k) dem->step();
    return report;
  }
  // Momentum of gas and particles at the half step (see the momentum test).
  Vec3 momentum() const {
    const auto& p = dem->particles();
    const double h = 0.5 * dem->settings().dt;
    Vec3 m = coupler->gas_momentum();
    for (std::size_t k = 0; k < p.size(); ++k) m += p.mass[k] * p.v[k] + h * p.force[k];
    return m;
  }
};

dem::Material powder(double density) {
  dem::Material m = test::glass();
  m.density = density;
  m.stiffness = 1e-2;
  return m;
}

// Schiller-Naumann terminal velocity, written out here from the correlation (Schiller & Naumann
// 1933; Clift, Grace & Weber 1978, Table 5.2): 3 pi mu d v (1 + 0.15 Re^0.687) = F, by bisection.
double sn_terminal_velocity(double d, double force) {
  double lo = 0, hi = force / (3 * kPi * kMuGas * d);  // the Stokes value bounds it from above
  for (int it = 0; it < 200; ++it) {
    const double v = 0.5 * (lo + hi), re = kRhoGas * v * d / kMuGas;
    (3 * kPi * kMuGas * d * v * (1 + 0.15 * std::pow(re, 0.687)) < force ? lo : hi) = v;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("one-way settling reaches the Schiller-Naumann terminal velocity, parcels too",
          "[coupling][physics]") {
  // A sphere in a gas at rest (no gas weight, so no buoyancy: the balance is m g = F_d). Steady
  // state is a fixed point of the exchange, so the only errors are the remaining transient
  // (20 response times: e^-20) and round-off; 0.5 % is the tolerance. A parcel of l^3
  // originals (diameter l d) is dragged as l^3 originals, so it settles at the original's speed.
  struct Case {
    double re, d, dx, dt;
  };
  const Case cases[] = {{0.1, 50e-6, 1e-4, 1.1e-4}, {10, 300e-6, 1e-3, 2e-3}};
  for (const Case& c : cases) {
    // The particle density that gives Re at terminal velocity (Schiller-Naumann, g = 9.81).
    const double v_target = c.re * kMuGas / (kRhoGas * c.d);
    const double drag = 3 * kPi * kMuGas * c.d * v_target * (1 + 0.15 * std::pow(c.re, 0.687));
    const double g = 9.81, vol = kPi * c.d * c.d * c.d / 6, rho_p = drag / (vol * g);
    const double v_t = sn_terminal_velocity(c.d, rho_p * vol * g);
    const double tau_p = v_t / g;  // response time of the drag law at terminal velocity (upper)
    for (int l = 1; l <= 3; ++l) {
      CAPTURE(c.re, l, v_t);
      auto ds = test::settings(c.dt, Vec3(0, 0, -g));
      ds.domain.periodic = {true, true, true};
      ds.skin = c.d;
      Rig rig({8, 8, 8}, c.dx, c.dt, lbm::BoxFaces::all_periodic(), ds, powder(rho_p));
      CouplerSettings cs;
      cs.two_way = false;
      cs.drag = SchillerNaumann{};
      cs.size_factor = l;
      cs.kernel_width = default_kernel_width(c.dx, l * c.d);
      rig.couple(cs);
      rig.dem->add_particle(Vec3(4, 4, 4) * c.dx, Vec3::Zero(), 0.5 * l * c.d, 0);
      const int steps = int(std::ceil(20 * tau_p / c.dt));
      for (int k = 0; k < steps; ++k) rig.interval();
      const double v = -rig.dem->particles().v[0].z();
      CHECK(v == Approx(v_t).epsilon(0.005));
      CHECK(std::abs(v / v_t - 1) < 1e-6);  // what the fixed point gives: e^-20 and round-off
    }
  }
}

namespace {

// What a momentum budget measured: the residual, the scale it is measured against, and the
// figures that show the balance is not trivial.
struct Budget {
  double residual = 0, scale = 0;
  Vec3 p0 = Vec3::Zero(), p1 = Vec3::Zero();
  double gas = 0, drag = 0, impulse_z = 0;
  // What float rounding acts on, summed over the gas steps [N s]: each cell's |rho - 1| c + |rho u|
  // (sum of components; lattice c = 1) and each particle's |F| dt (the exchange, drag and
  // pressure-gradient force, which the gas receives as its force field and implicit drag).
  double rounded = 0;
};

// Adds one gas step's sum over cells of |rho - 1| + |rho u|_1, in SI [N s].
void add_rounded(const Rig& rig, Budget& b) {
  std::vector<double> rho;
  std::vector<Vec3> u;
  rig.gas->raw_moments(rho, u);
  const double per = kRhoGas * std::pow(rig.units.dx, 4) / rig.units.dt;
  double s = 0;
  for (std::size_t c = 0; c < rho.size(); ++c)
    s += std::abs(rho[c] - 1) + (rho[c] * u[c]).lpNorm<1>();
  b.rounded += per * s;
}

// Adds one interval's sum over particles of |F|_1 dt_interval [N s].
void add_exchange(const Rig& rig, Budget& b) {
  const auto& p = rig.dem->particles();
  double s = 0;
  for (std::size_t k = 0; k < p.size(); ++k) s += p.external[k].lpNorm<1>();
  b.rounded += s * rig.gas_per_interval * rig.units.dt;
}

// Periodic gas at rest, 40 particles moving at random, no gravity (see the test below).
Budget periodic_budget(lbm::Precision precision) {
  const double dx = 1e-4, dt_gas = 2e-5;
  auto ds = test::settings(dt_gas / 4);
  ds.domain.periodic = {true, true, true};
  ds.skin = 2e-5;
  Rig rig({12, 12, 12}, dx, dt_gas, lbm::BoxFaces::all_periodic(), ds, powder(1500), precision);
  rig.dem_per_interval = 8;
  rig.gas_per_interval = 2;
  CouplerSettings cs;
  cs.drag = Gidaspow{};
  cs.kernel_width = default_kernel_width(dx, 100e-6);
  rig.couple(cs);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Budget b;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 2; ++k) {
        const Vec3 x = Vec3(0.15 + 0.25 * i, 0.1 + 0.2 * j, 0.25 + 0.5 * k) * 12 * dx;
        const Vec3 v = 0.05 * Vec3(u(rng), u(rng), u(rng));
        rig.dem->add_particle(x + 0.05 * dx * Vec3(u(rng), u(rng), u(rng)), v, 50e-6, 0);
      }
  for (std::size_t k = 0; k < rig.dem->particles().size(); ++k)
    b.scale += rig.dem->particles().mass[k] * rig.dem->particles().v[k].norm();
  b.p0 = rig.momentum();
  for (int n = 0; n < 50; ++n) {
    b.drag += rig.interval([&] { add_rounded(rig, b); }).drag.norm();
    add_exchange(rig, b);
  }
  b.p1 = rig.momentum();
  b.residual = (b.p1 - b.p0).norm();
  b.gas = rig.coupler->gas_momentum().norm();
  return b;
}

// Gas through an inlet and an outlet between no-slip walls with 30 particles in it (see the test
// below): P(t) - P(0) + the boundaries' impulse.
Budget open_budget(lbm::Precision precision) {
  const double dx = 1e-4, dt_gas = 2e-5;
  auto ds = test::settings(dt_gas / 4);
  ds.domain.periodic = {false, true, false};
  ds.skin = 2e-5;
  lbm::BoxFaces faces;
  faces[0].kind = faces[1].kind = lbm::FaceKind::wall;
  faces[4].kind = lbm::FaceKind::inlet;
  faces[4].wall_velocity = Vec3(0, 0, 0.02);
  faces[5].kind = lbm::FaceKind::outlet;
  Rig rig({12, 12, 16}, dx, dt_gas, faces, ds, powder(1500), precision);
  rig.dem_per_interval = 8;
  rig.gas_per_interval = 2;
  CouplerSettings cs;
  cs.drag = Gidaspow{};
  cs.kernel_width = default_kernel_width(dx, 100e-6);
  rig.couple(cs);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 2; ++k) {
        const Vec3 x = Vec3((3.0 + 3 * i) / 12, (0.5 + j) / 5, (5.0 + 6 * k) / 16);
        const Vec3 v = 0.05 * Vec3(u(rng), u(rng), u(rng));
        rig.dem->add_particle(x.cwiseProduct(Vec3(12, 12, 16)) * dx, v, 50e-6, 0);
      }
  const double per = kRhoGas * std::pow(dx, 4) / dt_gas;  // lattice momentum per step -> N s
  Budget b;
  b.p0 = rig.momentum();
  Vec3 impulse = Vec3::Zero();
  b.scale = b.p0.norm();
  const auto add_loads = [&] {
    for (int body = 1; body <= rig.gas->body_count(); ++body) {
      impulse += per * rig.gas->wall_force(body);
      b.scale += per * rig.gas->wall_force(body).norm();
    }
    add_rounded(rig, b);
  };
  for (int n = 0; n < 50; ++n) {
    b.drag += rig.interval(add_loads).drag.norm();
    add_exchange(rig, b);
  }
  b.p1 = rig.momentum();
  b.residual = (b.p1 - b.p0 + impulse).norm();
  b.impulse_z = impulse.z();
  b.gas = rig.coupler->gas_momentum().norm();
  return b;
}

}  // namespace

TEST_CASE("two-way exchange conserves gas + particle momentum to round-off",
          "[coupling][physics]") {
  // Periodic gas at rest, 40 particles moving at random, no gravity: nothing outside acts, so
  // the momentum of gas and particles stays what it was. Measured at the half step on both sides:
  // particles sum m v + dt/2 F (velocity Verlet), gas sum c f (before Guo's half-force shift);
  // each step adds exactly dt F to either, and the exchange gives them opposite impulses. The
  // test sub-cycles 4 DEM steps per gas step and exchanges every 2 gas steps (8 DEM steps), with
  // the pressure-gradient force on, so every path of the exchange is crossed. Tolerance 1e-12 of
  // the particles' momentum scale: a few hundred steps of sums of O(50) terms at 1e-16 each.
  const Budget b = periodic_budget(lbm::Precision::float64);
  CAPTURE(b.p0.transpose(), b.p1.transpose(), b.scale);
  CHECK(b.residual < 1e-12 * b.scale);
  // And the exchange did something: over 2 ms, 4 % of the particles' response time
  // rho_p d^2 / (18 mu) = 46 ms, the gas takes about 4 % of their momentum.
  CHECK(b.gas > 0.02 * b.p0.norm());
}

namespace {
/// The single-precision budget's bound (derived in the test below): the residual within one float
/// rounding, u_f = 2^-24, of the summed magnitudes S the float collision and fields act on.
void check_single_budget(const char* name, const Budget& b, const Budget& d) {
  WARN("momentum budget, " << name << ": residual / scale " << b.residual / b.scale
                           << " in single, " << d.residual / d.scale
                           << " in double; single residual / (u_f S) "
                           << b.residual / (0x1p-24 * b.rounded) << ", S / scale "
                           << b.rounded / b.scale);
  CAPTURE(b.p0.transpose(), b.p1.transpose(), b.impulse_z, b.scale, b.drag, b.residual, b.rounded);
  CHECK(b.residual < 0x1p-24 * b.rounded);
}
}  // namespace

TEST_CASE("two-way exchange conserves gas + particle momentum in single precision",
          "[coupling][physics]") {
  // The budget above with the gas in single precision (lbm/cell.hpp): populations f - w, the
  // force field, 1/eps, alpha and the velocity sums in float, the collision in float. The
  // particles still receive, in double, the interval's mean of what the gas lost, but the gas
  // loses it in float, so the budget closes only to what float rounding moves. A population
  // stored as f - w is rounded to u_f = 2^-24 = 6e-8 of itself, and f_q - w_q = w_q (drho +
  // 3 c_q.u + ...), so one rounding of a cell's populations misplaces at most about u_f (|drho|
  // + |rho u|_1) of its momentum (lattice c = 1); the force field and alpha are rounded once per
  // interval (u_f of the force a cell receives), the velocity sums once per step (u_f of the drag
  // the particles then get). The bound is one such rounding per gas step, all of one sign:
  //   |residual| < u_f S,  S = sum over gas steps of (sum over cells (|rho - 1| + |rho u|_1)
  //                                                   + sum over particles |F|_1 dt),
  // S computed along the run (0.75 of the particles' momentum scale here). The float
  // equilibrium's momentum bias, (1 + d_w) rho u with d_w = 7.45e-9 (tests/lbm), is 0.12 u_f per
  // collision, inside it. Signs vary between cells and steps, so the residual sits well below
  // (measured 0.043 u_f S = 1.9e-9 of the scale; double 3.6e-16).
  const Budget b = periodic_budget(lbm::Precision::float32);
  const Budget d = periodic_budget(lbm::Precision::float64);
  check_single_budget("periodic", b, d);
  // Not a trivial bound: S stays of the order of the momentum scale (u_f S is 4.5e-8 of it), and
  // the gas takes the same share of the particles' momentum as in double (4 %).
  CHECK(b.rounded < 10 * b.scale);
  CHECK(b.gas > 0.02 * b.p0.norm());
  CHECK(b.gas == Approx(d.gas).epsilon(1e-4));
}

TEST_CASE("two-way exchange with walls, an inlet and an outlet balances the boundary fluxes",
          "[coupling][physics]") {
  // The budget: gas + particles change their momentum by exactly what the boundaries
  // give them. Gas enters through a velocity inlet (z_lo) and leaves through a pressure outlet
  // (z_hi) between no-slip walls (x faces), y periodic, with 30 particles moving at random in it,
  // no gravity. Every boundary link's momentum exchange is the momentum it takes from the gas
  // (Ladd's and the anti-bounce-back link forces, c_q (f_q* + f_qbar)), which includes the
  // inflow's and outflow's momentum flux and the pressure on the open faces, so
  //   P(t) - P(0) + sum over gas steps of sum over bodies F_b = 0
  // to round-off. Its scale is the sum of |F_b| over the steps (the pressure on every face,
  // rho c_s^2 per face cell and step, dominates it and cancels between opposite faces); sums of
  // about 3,300 link terms per step over 100 steps at 1e-16 each: 1e-12 of that scale.
  const Budget b = open_budget(lbm::Precision::float64);
  CAPTURE(b.p0.transpose(), b.p1.transpose(), b.impulse_z, b.scale, b.drag, b.residual);
  CHECK(b.residual < 1e-12 * b.scale);  // measured: 2e-24 N s of a 1.3e-7 N s scale
  // Not a trivial balance: the inflow gave the box upward momentum a thousand times the
  // tolerance (measured: 2.6e-3 of the scale), and the particles exchanged momentum with the gas.
  CHECK(std::abs(b.p1.z() - b.p0.z()) > 1e3 * 1e-12 * b.scale);
  CHECK(b.drag > 0);
}

TEST_CASE(
    "single precision: two-way exchange with walls and open faces balances the boundary fluxes",
    "[coupling][physics]") {
  // The budget above with the gas in single precision. The boundaries still compute in double
  // through the codec (pdf_field.hpp) and their link forces are summed in double, so what float
  // adds is the collision's and the fields' rounding, bounded as in the periodic single test by
  // u_f S (S summed along the run: 0.39 of this test's scale, the boundaries' pressure loads).
  // Measured 0.036 u_f S = 8.3e-10 of the scale (double 6.2e-17).
  const Budget b = open_budget(lbm::Precision::float32);
  const Budget d = open_budget(lbm::Precision::float64);
  check_single_budget("with walls, inlet and outlet", b, d);
  // Not trivial: the inflow's momentum is 1e5 times the bound, and the particles felt the gas.
  CHECK(std::abs(b.p1.z() - b.p0.z()) > 1e3 * 0x1p-24 * b.rounded);
  CHECK(b.drag > 0);
}

namespace {

// Two-way settling of one particle or parcel in a periodic box; a uniform upward force on the gas
// carries the particle's weight, so nothing outside acts and the gas far away stays at its
// (small) mean velocity. The particle's own reaction drags the gas where it sits along with it,
// so the drag law, which sees that local gas, lets it fall faster than the Schiller-Naumann speed
// against the gas far away. In Stokes flow the force F, spread by a kernel of width sigma, moves
// the gas at its centre by about 0.28 d / sigma of the single sphere's own terminal speed (force
// coupling, Maxey & Patel 2001; kernel.hpp); a parcel of l^3 originals carries l^3 times an
// original's force, so 0.28 l^3 d / sigma (d the original's diameter). The periodic images hinder
// it by Hasimoto's 1.7601 c^(1/3) (1959, simple cubic array at volume fraction c), i.e.
// 2.837 a / L for c = (4 pi / 3) a^3 / L^3, a = l^3 d / 2 the radius whose Stokes drag is the
// parcel's.
struct TwoWaySettling {
  double re;       // the original's Reynolds number at terminal velocity
  int l;           // size factor: the parcel holds l^3 originals, its diameter is l d
  double d_cells;  // the parcel's diameter in cells
  double nu_lat;   // lattice viscosity (sets the time step)
  std::array<int, 3> cells;
};

struct SlipError {
  double error;     // slip / v_t - 1 against the gas's mean velocity
  double self;      // error + periodic-image hindrance
  double estimate;  // 0.28 l^3 d / sigma
};

SlipError settle_two_way(const TwoWaySettling& c, double sigma_over_dp,
                         lbm::Precision precision = lbm::Precision::float64) {
  const double dx = 50e-6, d_p = c.d_cells * dx, d = d_p / c.l;
  const double dt = c.nu_lat * dx * dx / (kMuGas / kRhoGas);
  const double v_t = c.re * kMuGas / (kRhoGas * d), sn = 1 + 0.15 * std::pow(c.re, 0.687);
  // The parcel's response time is the original's: 100 gas steps.
  const double tau_p = 100 * dt, g = v_t / tau_p * sn;
  const double vol = kPi * d * d * d / 6;
  const double rho_p = 3 * kPi * kMuGas * d * v_t * sn / (vol * g);
  auto ds = test::settings(dt, Vec3(0, 0, -g));
  ds.domain.periodic = {true, true, true};
  ds.skin = d_p;
  Rig rig(c.cells, dx, dt, lbm::BoxFaces::all_periodic(), ds, powder(rho_p), precision);
  CouplerSettings cs;
  cs.drag = SchillerNaumann{};
  cs.size_factor = c.l;
  cs.kernel_width = sigma_over_dp * d_p;
  rig.couple(cs);
  rig.dem->add_particle(Vec3(c.cells[0] / 2.0, c.cells[1] / 2.0, c.cells[2] / 2.0) * dx,
                        Vec3::Zero(), d_p / 2, 0);
  const double m = rig.dem->particles().mass[0];
  const double box = double(c.cells[0]) * c.cells[1] * c.cells[2] * dx * dx * dx;
  rig.gas->set_body_force(Vec3(0, 0, rig.units.force_density_to_lattice(m * g / box)));
  // 15 response times; the last 3 are averaged.
  const int steps = 1500;
  double slip = 0;
  int samples = 0;
  for (int k = 0; k < steps; ++k) {
    rig.interval();
    if (k >= steps - 300) {
      const Vec3 u_mean = rig.coupler->gas_momentum() / (kRhoGas * box);
      slip += u_mean.z() - rig.dem->particles().v[0].z();
      ++samples;
    }
  }
  slip /= samples;
  const double l3 = double(c.l) * c.l * c.l;
  const double error = slip / v_t - 1, image = 2.837 * l3 * (d / 2) / (c.cells[0] * dx);
  const double estimate = 0.28 * l3 * d / (sigma_over_dp * d_p);
  WARN("two-way settling (" << lbm::to_string(precision) << "), Re " << c.re << ", l = " << c.l
                            << ", sigma/d_p = " << sigma_over_dp << ": slip " << slip << " m/s, "
                            << 100 * error << " % above Schiller-Naumann; self-induced part "
                            << 100 * (error + image) << " % (force coupling: " << 100 * estimate
                            << " %)");
  return {error, error + image, estimate};
}

}  // namespace

TEST_CASE("two-way settling: the self-induced slip error falls as the kernel widens",
          "[coupling][physics][slow]") {
  // No fixed tolerance holds for the error (the issue); the test asks that it falls as sigma / d
  // grows, and in Stokes flow (Re 0.1) that the self-induced part (error + image term) is the
  // force-coupling estimate within a factor 1.5, for an original and for parcels of l = 2 and 3
  // (each parcel one cell across, so the original is 1/l of a cell: the coupling sees only the
  // parcel). tau = 1. Measured: self-induced part / estimate 0.92-1.03 for sigma <= 2 d_p, and
  // 1.32 at sigma = 4 d_p = L / 4, where the kernel (reaching 3 sigma) overlaps its own periodic
  // images, which the point-force image term does not know.
  const double widths[] = {1, 2, 4};  // sigma / d_p
  for (int l = 1; l <= 3; ++l) {
    const TwoWaySettling c{0.1, l, 1.0, 1.0 / 6, {16, 16, 16}};
    double previous = 1e300;
    // At l = 3 and sigma = d_p the gas at the parcel would move at 2.5 v_t (lattice 0.13, Mach
    // 0.22): outside the weakly compressible range, so l = 3 starts at sigma = 2 d_p.
    for (double w : widths) {
      if (l == 3 && w < 2) continue;
      CAPTURE(l, w);
      const SlipError e = settle_two_way(c, w);
      CHECK(std::abs(e.error) < previous);
      CHECK(e.self / e.estimate > 1 / 1.5);
      CHECK(e.self / e.estimate < 1.5);
      previous = std::abs(e.error);
    }
  }
}

TEST_CASE("two-way settling at Re 10: the self-induced error falls as the kernel widens",
          "[coupling][physics][slow]") {
  // Re 10 at 0.05 lattice speed needs tau = 0.515 for a sphere of one cell. The Stokes estimate
  // no longer holds: the particle outruns its own disturbance (the Oseen length nu / v_t is d /
  // 10), so the gas it drags along is less than in Stokes flow. The test asks that the error falls
  // as the kernel widens and stays below the Stokes estimate (Hasimoto's image term, a Stokes
  // result, is left out here); it reports the figures (5.5, 1.6 and 0.16 % for sigma = 1, 2, 4 d).
  // The box is 64 cells tall; the particle falls 75 cells in the run and so crosses its own wake
  // through the periodic top during the averaging: a 24 x 24 x 96 box with a two-cell sphere gave
  // 5.3, 1.1 and 0.01 %, so the wake adds at most half a point.
  const TwoWaySettling c{10, 1, 1.0, 0.005, {16, 16, 64}};
  double previous = 1e300;
  for (double w : {1.0, 2.0, 4.0}) {
    CAPTURE(w);
    const SlipError e = settle_two_way(c, w);
    CHECK(std::abs(e.error) < previous);
    CHECK(e.error < e.estimate);
    previous = std::abs(e.error);
  }
}

TEST_CASE("two-way settling in single precision: the self-induced slip error as in double",
          "[coupling][physics]") {
  // The Stokes case of the test above (Re 0.1, tau = 1) with the gas in single precision,
  // against the same references: the self-induced part of the slip error (error + Hasimoto's
  // image term) is the force-coupling estimate 0.28 l^3 d / sigma within a factor 1.5, and the
  // error falls as the kernel widens. The double tolerance is kept: the model (a point-force
  // estimate, its image term) dominates it, float moves the slip by far less. The gas the drag
  // sees moves at 0.1 - 1.1 v_t at the particle; float resolves it to u_f = 6e-8 per rounding
  // (populations f - w, the velocity sum of the interval's one gas step, the fields 1/eps, alpha
  // and force rounded once per interval), and the steady slip relaxes such errors within the
  // particle's response time (100 of the 1500 steps), so they do not add up: a few tens of
  // roundings of 6e-8 of at most 1.1 v_t, < 1e-5 of v_t. The float equilibrium's momentum bias
  // (d_w = 7.45e-9 per collision, tests/lbm) drifts the gas as a whole, which the slip, taken
  // against the gas's mean velocity, does not see. So besides the references the single slip
  // error must be the double one within 1e-5 of v_t (measured 1e-8 to 3.5e-7); l = 1 and 2 at
  // sigma = d_p and 2 d_p, single and double (about 1 s each).
  for (int l = 1; l <= 2; ++l) {
    const TwoWaySettling c{0.1, l, 1.0, 1.0 / 6, {16, 16, 16}};
    double previous = 1e300;
    for (double w : {1.0, 2.0}) {
      CAPTURE(l, w);
      const SlipError e = settle_two_way(c, w, lbm::Precision::float32);
      CHECK(std::abs(e.error) < previous);
      CHECK(e.self / e.estimate > 1 / 1.5);
      CHECK(e.self / e.estimate < 1.5);
      previous = std::abs(e.error);
      const SlipError d = settle_two_way(c, w, lbm::Precision::float64);
      CAPTURE(e.error, d.error);
      WARN("slip error single - double: " << e.error - d.error);
      CHECK(std::abs(e.error - d.error) < 1e-5);
    }
  }
}

TEST_CASE("fixed packed bed with the Gidaspow law gives the Ergun pressure drop",
          "[coupling][physics][slow]") {
  // Spheres on a body-centred cubic lattice (solid fraction 0.6, eps = 0.4; nearest neighbours
  // 1.04 d apart) held in place, gas entering at U through the bottom and leaving at the top,
  // periodic sides. Below eps = 0.8 the Gidaspow law is Ergun's equation per particle, so the
  // drop across the bed interior must be Ergun's, dp/L = 150 mu (1-eps)^2 U / (eps^3 d^2) +
  // 1.75 rho (1-eps) U^2 / (eps^3 d) (Ergun 1952), through the set II split (drag = eps x the
  // total force, coupler.hpp). Tolerance 5 % (the issue's): the kernel smooths the lattice of
  // spheres to eps within about 1 % in the interior, and the pressure gradient is read over a
  // section 2 kernel widths inside the bed. (Wen-Yu alone would sit about 10 % below Ergun at
  // eps = 0.4: its voidage function is fitted to expanded beds.)
  // BCC cell a holds 2 spheres: 2 pi d^3 / 6 = 0.6 a^3.
  const double a = 120e-6, dx = a / 3, d = a * std::cbrt(1.8 / kPi);
  const double eps = 0.4, u_in = 0.05, dt = 5e-8;
  const int nxy = 6, nz = 90, bed_cells = 20;  // bed: 20 BCC cells high, from z = 15 dx
  lbm::BoxFaces faces;
  faces[4].kind = lbm::FaceKind::inlet;
  faces[4].wall_velocity = Vec3(0, 0, u_in * dt / dx);
  faces[5].kind = lbm::FaceKind::outlet;
  auto ds = test::settings(dt);
  ds.domain.periodic = {true, true, false};
  ds.skin = 0.1 * d;
  Rig rig({nxy, nxy, nz}, dx, dt, faces, ds, powder(1500));
  CouplerSettings cs;
  cs.drag = Gidaspow{};
  cs.kernel_width = d;  // narrower than the default 2 d: a bed 20 diameters high keeps an interior
  rig.couple(cs);
  const double z0 = 15 * dx;
  for (int k = 0; k < bed_cells; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const Vec3 corner(i * a, j * a, z0 + k * a);
        rig.dem->add_particle(corner + Vec3(0.25, 0.25, 0.25) * a, Vec3::Zero(), d / 2, 0);
        rig.dem->add_particle(corner + Vec3(0.75, 0.75, 0.75) * a, Vec3::Zero(), d / 2, 0);
      }
  // The particles stay put: only the exchange and the gas run. The pressure settles diffusively
  // (Darcy flow: diffusivity c_s^2 rho eps / A = 13 cells^2 per step here), 3000 steps are about
  // ten diffusion times of the 60-cell bed; the test checks the mass flow is steady.
  for (int k = 0; k < 3000; ++k) {
    rig.coupler->begin_interval(rig.dem->particles(), 1);
    rig.coupler->before_gas_step();
    rig.gas->step();
    rig.coupler->end_interval(rig.dem->particles());
  }
  std::vector<double> p;
  rig.coupler->pressure(p);
  const auto plane = [&](int z, const std::vector<double>& f) {
    double s = 0;
    for (int y = 0; y < nxy; ++y)
      for (int x = 0; x < nxy; ++x) s += f[std::size_t(rig.gas->grid().compact_index(x, y, z))];
    return s / (nxy * nxy);
  };
  // The triweight reaches 3 sigma (kernel.hpp): planes farther than that from the bed's faces see
  // only interior particles.
  const int margin = int(std::ceil(rig.coupler->kernel().support_radius() / dx)) + 1;
  const int za = 15 + margin, zb = 15 + bed_cells * 3 - margin;
  REQUIRE(zb - za >= 10);
  const double grad = (plane(za, p) - plane(zb, p)) / ((zb - za) * dx);
  const double ergun = 150 * kMuGas * (1 - eps) * (1 - eps) * u_in / (eps * eps * eps * d * d) +
                       1.75 * kRhoGas * (1 - eps) * u_in * u_in / (eps * eps * eps * d);
  double eps_bed = 0;
  for (int z = za; z <= zb; ++z) eps_bed += plane(z, rig.coupler->eps()) / (zb - za + 1);
  std::vector<Vec3> u;
  std::vector<double> rho, flux(p.size());
  rig.gas->velocity(u);
  rig.gas->density(rho);
  for (std::size_t c = 0; c < flux.size(); ++c) flux[c] = rho[c] * u[c].z() * dx / dt;
  CAPTURE(grad, ergun, eps_bed, d, za, zb);
  // Steady: the superficial mass flux in the bed and above it is the inflow rho U (0.1 %).
  CHECK(plane(za, flux) == Approx(u_in).epsilon(1e-3));
  CHECK(plane(nz - 2, flux) == Approx(u_in).epsilon(1e-3));
  CHECK(eps_bed == Approx(eps).epsilon(0.01));
  CHECK(grad == Approx(ergun).epsilon(0.05));
}

TEST_CASE("coarse-grained drag: a dilute cloud relaxes and settles alike as originals and as CG-8",
          "[coupling][physics]") {
  // The jet mill's powder (rho 1500 kg/m^3, original radius uniform in 75-100 um, Morsi-Alexander
  // drag) launched at 20 m/s along x into gas at rest, gravity along -z: a uniform stream seen
  // from the gas, with gravity across it. One-way, so the gas stays at rest and the
  // only difference between the clouds is the parcels' drag: l^3 times one original's, with the
  // original's diameter and Reynolds number (coarse_grain_drag.hpp). CG-1: 128 originals; CG-8
  // (l = 2): 16 parcels of 8, radii drawn from the same distribution. Each particle has a lane of
  // its own across y (no force acts along y), wider than a parcel, so none ever touches another
  // (checked): collisions would spread the velocities and, through the nonlinear drag, shift the
  // mean (by 4 % with 512 originals in a 32 mm box). The mass-weighted mean velocities must agree
  // within three standard errors of the radius sampling (from the velocity spread among the
  // particles at that time) over the whole relaxation (Re_p from about 230 down to the terminal
  // value, about 10). At 0.6 s the cloud falls at the mass-weighted mean of its originals'
  // Morsi-Alexander terminal velocities within 1 % (measured: the transient, slowed at first by
  // the large slip along x, is within 0.1 % of its end by then; 5 % short at 0.3 s).
  const double g = 9.81, dt = 1e-4, dx = 4e-3, rho_p = 1500, r_lo = 75e-6, r_hi = 100e-6;
  const int n_cells = 8;
  const double box = n_cells * dx;
  const std::vector<double> times = {0.0025, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.6};
  struct Cloud {
    std::vector<Vec3> mean, err;
    double terminal = 0;  // sum m v_z / sum m v_t at the end, v_t each original's
    std::int64_t collisions = 0;
  };
  const auto run = [&](int l, int count, unsigned seed) {
    auto ds = test::settings(dt, Vec3(0, 0, -g));
    ds.domain.periodic = {true, true, true};
    ds.skin = 2e-3;  // a coarse neighbour grid: the particles fly fast and never meet
    Rig rig({n_cells, n_cells, n_cells}, dx, dt, lbm::BoxFaces::all_periodic(), ds, powder(rho_p));
    CouplerSettings cs;
    cs.two_way = false;
    cs.drag = MorsiAlexander{};
    cs.size_factor = l;
    cs.kernel_width = default_kernel_width(dx, l * 2 * r_hi);
    rig.couple(cs);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> radius(r_lo, r_hi), at(0.0, box);
    for (int k = 0; k < count; ++k) {
      const Vec3 x(at(rng), (k + 0.5) * box / count, at(rng));
      rig.dem->add_particle(x, Vec3(20, 0, 0), l * radius(rng), 0);
    }
    Cloud c;
    long step = 0;
    for (double t : times) {
      for (; double(step) * dt < t - 0.5 * dt; ++step) rig.interval();
      const auto& p = rig.dem->particles();
      // The mass-weighted mean and its standard error: var = n / (n - 1) sum w^2 (v - m)^2 /
      // (sum w)^2, the weights being the masses, which the velocities depend on.
      double w = 0;
      Vec3 m = Vec3::Zero(), s2 = Vec3::Zero();
      for (std::size_t k = 0; k < p.size(); ++k) w += p.mass[k], m += p.mass[k] * p.v[k];
      m /= w;
      for (std::size_t k = 0; k < p.size(); ++k) {
        const Vec3 d = p.v[k] - m;
        s2 += p.mass[k] * p.mass[k] * d.cwiseProduct(d);
      }
      const double n = double(p.size());
      c.mean.push_back(m);
      c.err.push_back((s2 * n / (n - 1)).cwiseSqrt() / w);
    }
    const auto& p = rig.dem->particles();
    double fall = 0, ref = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      // The original's terminal velocity: m g = 3 pi mu d v f_MA(Re), by bisection.
      const double d = 2 * p.radius[k] / l, weight = rho_p * kPi * d * d * d / 6 * g;
      double lo = 0, hi = weight / (3 * kPi * kMuGas * d);
      for (int it = 0; it < 200; ++it) {
        const double v = 0.5 * (lo + hi), re = kRhoGas * v * d / kMuGas;
        (3 * kPi * kMuGas * d * v * morsi_alexander_factor(re) < weight ? lo : hi) = v;
      }
      fall -= p.mass[k] * p.v[k].z();
      ref += p.mass[k] * 0.5 * (lo + hi);
    }
    c.terminal = fall / ref;
    c.collisions = rig.dem->collisions().started_pp();
    return c;
  };
  const Cloud one = run(1, 128, 11), eight = run(2, 16, 12);
  REQUIRE(one.collisions == 0);
  REQUIRE(eight.collisions == 0);
  for (std::size_t s = 0; s < times.size(); ++s)
    for (int a : {0, 2}) {
      const double diff = one.mean[s][a] - eight.mean[s][a];
      const double err = std::hypot(one.err[s][a], eight.err[s][a]);
      CAPTURE(times[s], a, one.mean[s][a], eight.mean[s][a], err);
      CHECK(std::abs(diff) <= 3 * err + 1e-12);
    }
  WARN("cloud mean velocity at 0.01 s: CG-1 "
       << one.mean[2].transpose() << ", CG-8 " << eight.mean[2].transpose()
       << " m/s; fall at 0.6 s over terminal: " << one.terminal << " / " << eight.terminal);
  CHECK(one.terminal == Approx(1).epsilon(0.01));
  CHECK(eight.terminal == Approx(1).epsilon(0.01));
}

TEST_CASE("two-way intervals without particles skip their grid passes and change no bit",
          "[coupling]") {
  // An interval without particles after another one sets nothing in the gas (coupler.hpp): its
  // fields are already eps = 1, no drag and the source. Against a coupler built afresh for every
  // interval (which never skips): empty intervals, a source that changes between two of them,
  // particles fed in, all removed, and fed in again. The gas's density and velocity and the
  // particles' state must be bitwise the same (no tolerance: the same arithmetic in the same order,
  // or a defect).
  const double dx = 1e-4, dt_gas = 2e-5;
  auto ds = test::settings(dt_gas / 2);
  ds.domain.periodic = {true, true, true};
  ds.skin = 2e-5;
  ds.gravity = Vec3(0, 0, -9.81);
  CouplerSettings cs;
  cs.drag = Gidaspow{};
  cs.kernel_width = default_kernel_width(dx, 100e-6);
  cs.gas_weight = Vec3(0, 0, -9.81 * kRhoGas);
  Rig kept({8, 8, 8}, dx, dt_gas, lbm::BoxFaces::all_periodic(), ds, powder(1500));
  Rig fresh({8, 8, 8}, dx, dt_gas, lbm::BoxFaces::all_periodic(), ds, powder(1500));
  for (Rig* r : {&kept, &fresh}) r->dem_per_interval = 2, r->gas_per_interval = 3;
  kept.couple(cs);
  const auto source = [](double fx) {
    std::vector<Vec3> f(512, Vec3::Zero());
    for (std::size_t c = 0; c < f.size(); c += 3) f[c] = Vec3(fx, 0, -0.5 * fx);
    return f;
  };
  std::vector<Vec3> src = source(1e-6);
  kept.coupler->set_gas_source(src);
  for (int n = 0; n < 16; ++n) {
    if (n == 4) {  // a new source between two empty intervals
      src = source(-2e-6);
      kept.coupler->set_gas_source(src);
    }
    if (n == 7 || n == 13)  // particles arrive
      for (Rig* r : {&kept, &fresh})
        for (int i = 0; i < 6; ++i)
          r->dem->add_particle(Vec3(0.2 + 0.1 * i, 0.5, 0.3 + 0.05 * i) * 8 * dx,
                               Vec3(0.01, 0, -0.02), 50e-6, 0);
    if (n == 10)  // and leave: the first empty interval after them must set the fields again
      for (Rig* r : {&kept, &fresh}) r->dem->remove_particles({0, 1, 2, 3, 4, 5});
    fresh.couple(cs);
    fresh.coupler->set_gas_source(src);
    kept.interval();
    fresh.interval();
  }
  std::vector<double> rk, rf;
  std::vector<Vec3> uk, uf;
  kept.gas->density(rk), fresh.gas->density(rf);
  kept.gas->raw_velocity(uk), fresh.gas->raw_velocity(uf);
  CHECK(rk == rf);
  CHECK(uk == uf);
  const auto &pk = kept.dem->particles(), &pf = fresh.dem->particles();
  REQUIRE(pk.size() == 6);
  CHECK(pk.x == pf.x);
  CHECK(pk.v == pf.v);
  // (Checked by mutation: without the reset in set_gas_source the densities differ.)
}
