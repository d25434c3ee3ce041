// A round jet at Re = U d / nu0 = 1e4 with the regularized LES operator
// (lbm/collision/regularized_les.hpp): it stays bounded over 10 flow-through times, the mass
// balance closes, the eddy viscosity carries the shear layer, and the centreline near the nozzle
// keeps the nozzle velocity (potential core). BGK, TRT and regularized BGK without eddy viscosity
// blow up on the same case (second test).
//
// Set-up (lattice units): a 24 x 24 x 40 box, axis along z. z_lo is a wall with a circular nozzle
// of radius 4 (d = 8; the 52 ghost cells of z_lo whose centres lie within 4 of the axis, i.e. an
// area-equivalent diameter 8.1) made of velocity-inlet cells at U = 0.095 e_z (lattice Mach
// U / c_s = 0.165), plus four travelling azimuthal modes of 1 % each. nu0 = U d / Re = 7.6e-5, so
// tau0 - 1/2 = 2.3e-4. z_hi is a density outlet (rho = 1) behind an 8-layer sponge; the side faces
// are periodic. 10 flow-through times = 10 x 430 steps (430 >= L / U = 421).
//
// Why periodic sides and a sponge. The anti-bounce-back outlet (open_boundary.hpp) fixes only the
// density: where the jet's vortices and the return flow cross it at tau -> 1/2, it grows unstable.
// Measured on this case without a sponge (W = 32, L = 48, U = 0.08): side outlets blow up at step
// 1620 at the edge between two side outlets, periodic sides at step 1560 at the z_hi outlet, both
// when the starting vortex ring reaches the boundary (front speed ~ U/2). The standard cure is an
// absorbing layer ahead of the outflow (Colonius 2004, Annu. Rev. Fluid Mech. 36, 315; Mani 2012,
// J. Comput. Phys. 231, 704), here a Darcy drag (forcing/porous.hpp, eps = 1) ramped
// quadratically to alpha = 0.05 / step over the last 8 layers: a smooth ramp reflects little, and
// a fluctuation crossing the layer at ~ U/2 spends ~ 170 steps in it, about 3 e-folds of the mean
// rate alpha / 3. With the sponge both side choices survive; side outlets (with a 4-cell side
// sponge) give the same centreline and eddy viscosity within 2 % but cost 27 % more time (the
// outlet velocity sampling and links), so the sides are periodic: a square array of jets at pitch 3
// d whose entrainment is fed by the return flow through the top, as in a confined jet
// (Craya-Curtet), and whose mass budget is the nozzle in, the top out.
//
// Measured (Release, one thread, about 14 s): E(k)/E(5) over flow-through times 6-10 from 1.006
// to 1.031; mass budget closed to 2.3e-13 of the total mass; nozzle inflow 0.99988 of U x 52
// cells per step; effective tau - 1/2 (molecular 2.28e-4) 1.20e-3 in the shear layer, 5.1e-3 at
// most; centreline u_c / U between 0.972 and 1.075 for z <= 2 d.
//
// Without eddy viscosity (the second test; same case and tau0; the watchdog looks every 0.1
// flow-through time): BGK (Bgk::from_tau(tau0)) is caught at step 301 (0.7
// flow-through times) at the nozzle lip, rho 1.107; TRT (Lambda = 3/16) at the first check, step
// 43, at the lip, |u| = 0.55 = 5.8 U; regularized BGK without eddy viscosity (C_s = 0) lives
// longer, its energy rising (E = 5.1, 6.6, 5.6, 6.0, 7.8 at flow-through times 1-5 against the
// LES's 4.9, 6.5, 5.6, 5.7, 5.7), and is caught at step 2236 (5.2 flow-through times) on the z_lo
// wall, rho 0.87. The regularization alone delays the blow-up; the eddy viscosity prevents it.
#include <catch2/catch.hpp>

#include "lbm/aa_pattern.hpp"
#include "lbm/geometry/cylinder.hpp"
#include "lbm/geometry/lattice_frame.hpp"
#include "lbm/lbm_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <optional>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

using namespace lbdem;
using namespace lbdem::lbm;

namespace {

constexpr int kWidth = 24;       // W = 3 d: the near-field shear layer (< 2 d wide) stays clear
constexpr int kLength = 40;      // L = 5 d, the last 8 cells sponge
constexpr int kSponge = 8;       // sponge layers ahead of z_hi
constexpr double kAlpha = 0.05;  // Darcy rate at z_hi [1/step]
constexpr double kRadius = 4;    // nozzle radius [cells]
constexpr double kDiameter = 2 * kRadius;
constexpr double kU = 0.095;   // nozzle velocity
constexpr double kRe = 1e4;    // U d / nu0
constexpr double kAmp = 0.01;  // inlet perturbation per azimuthal mode, fraction of U
constexpr double kCentre = 0.5 * (kWidth - 1);  // nozzle axis, lattice coordinates
constexpr long kCheck = 43;                 // steps between watchdog checks: 1/10 flow-through time
constexpr long kFlowThrough = 10 * kCheck;  // >= L / U = 421 steps
constexpr int kCoreEnd = int(2 * kDiameter);  // potential-core check over z <= 2 d

double molecular_tau() {
  return tau_from_viscosity(kU * kDiameter / kRe);
}

// The watchdog's range. Density: the jet's dynamic pressure is rho U^2 / 2, a density change of
// U^2 / (2 c_s^2) = 1.4 %; with the start-up pulse and the sponge's pressure drop the measured
// extreme over all checks is 5.3 %. 10 % is twice that, and a run that leaves the weakly
// compressible range crosses it within a few checks. Speed: no cell of a jet from a nozzle at U
// should exceed U by much (measured max 1.21 U); 2.5 U = 0.24 is caught before the lattice Mach
// of 0.4, where the second-order equilibrium fails.
constexpr double kRhoMin = 0.9, kRhoMax = 1.1, kSpeedMax = 2.5 * kU;

/// The inflow: a top-hat U e_z times 1 + sum_m a cos(m theta - omega_m t + phi_m), m = 0..3,
/// a = 1 %, each mode at a Strouhal number St = f d / U drawn from [0.3, 0.6] (the jet column's
/// preferred mode, St ~ 0.3-0.5: Crow & Champagne 1971, J. Fluid Mech. 48, 547) with a random
/// phase. mt19937's raw output is fixed by the standard, so the draw is the same on any platform.
class InletPerturbation {
 public:
  InletPerturbation() {
    std::mt19937 gen(20240611u);
    const auto uniform = [&] { return double(gen()) / 4294967296.0; };
    for (std::size_t m = 0; m < omega_.size(); ++m) {
      omega_[m] = 2 * M_PI * (0.3 + 0.3 * uniform()) * kU / kDiameter;
      phase_[m] = 2 * M_PI * uniform();
    }
  }
  WallVelocity at(long t) const {
    return [this, t](const Vec3& x) {
      const double theta = std::atan2(x.y() - kCentre, x.x() - kCentre);
      double a = 1;
      for (std::size_t m = 0; m < omega_.size(); ++m)
        a += kAmp * std::cos(double(m) * theta - omega_[m] * double(t) + phase_[m]);
      return Vec3(0, 0, kU * a);
    };
  }

 private:
  std::array<double, 4> omega_{}, phase_{};
};

struct JetResult {
  long steps = 0;                    // steps run
  std::optional<UnhealthyCell> bad;  // first watchdog hit
  long bad_step = -1;                // the step at which it was found
  std::vector<double> energy;        // kinetic energy at the end of each flow-through time
  double m0 = 0, mass_change = 0;    // total mass at the start, its change over the run
  double mass_flowed = 0;            // sum over steps and bodies of mass_flow
  double inflow = 0;                 // sum over steps of the nozzle's mass_flow
  long nozzle_cells = 0;             // inlet ghost cells
  std::vector<double> centreline;    // time-mean u_z / U on the axis, z = 0 .. 2 d
  // Effective tau - 1/2 (LES only) over the last flow-through time, outside the sponge: its
  // minimum and maximum, and its mean in the shear layer (|r - R| <= 1, d/2 <= z <= 2 d).
  double tau_min = 1e300, tau_max = 0, tau_shear = 0;
};

/// Effective-tau statistics of one snapshot (the sponge is left out: its Darcy force shifts u).
void sample_effective_tau(const LbmSolver& lbm, const RegularizedLes& les, JetResult& r,
                          double& shear_sum, long& shear_n) {
  for (int z = 0; z < kLength - kSponge; ++z)
    for (int y = 0; y < kWidth; ++y)
      for (int x = 0; x < kWidth; ++x) {
        double f[kQ];
        lbm.cell_populations(x, y, z, f);
        const double tau = les.effective_tau(f, cell_moments<false>(f, {})) - 0.5;
        r.tau_min = std::min(r.tau_min, tau);
        r.tau_max = std::max(r.tau_max, tau);
        if (z >= kRadius && z <= kCoreEnd &&
            std::abs(std::hypot(x - kCentre, y - kCentre) - kRadius) <= 1.0) {
          shear_sum += tau;
          ++shear_n;
        }
      }
}

JetResult run_jet(const CollisionModel& op, int flow_throughs,
                  Precision precision = Precision::float64) {
  LbmSettings s;
  s.precision = precision;
  s.nx = s.ny = kWidth;
  s.nz = kLength;
  s.faces[4].kind = FaceKind::wall;
  s.faces[5].kind = FaceKind::outlet;
  s.faces[5].density = 1.0;
  s.collision = op;
  LbmSolver lbm(s);
  const InletPerturbation perturbation;
  const int nozzle = lbm.add_inlet("nozzle", perturbation.at(0));
  Cylinder disk;  // z = -1 only
  disk.axis_point = Vec3(kCentre, kCentre, 0);
  disk.radius = kRadius;
  disk.start = -1.5;
  disk.end = -0.5;
  JetResult r;
  r.nozzle_cells =
      mark_cylinder(lbm, LatticeFrame::lattice_units(), disk, SolidSide::inside, nozzle);
  lbm.enable_porosity();
  for (int z = kLength - kSponge; z < kLength; ++z) {
    const double depth = double(z - (kLength - kSponge) + 1) / kSponge;
    for (int y = 0; y < kWidth; ++y)
      for (int x = 0; x < kWidth; ++x) lbm.set_cell_porosity(x, y, z, 1.0, kAlpha * depth * depth);
  }

  const auto* les = std::get_if<RegularizedLes>(&op);
  const long total = kFlowThrough * flow_throughs, mean_from = total / 2;
  const int axis = kWidth / 2 - 1;  // the four cells around the axis: axis, axis + 1
  r.centreline.assign(std::size_t(kCoreEnd + 1), 0.0);
  long samples = 0, shear_n = 0;
  double shear_sum = 0;
  r.m0 = lbm.total_mass();
  std::vector<Vec3> u;
  std::vector<double> rho;
  for (long t = 1; t <= total; ++t) {
    lbm.set_wall_velocity(nozzle, perturbation.at(t - 1));
    lbm.step();
    for (int b = 1; b <= lbm.body_count(); ++b) r.mass_flowed += lbm.mass_flow(b);
    r.inflow += lbm.mass_flow(nozzle);
    r.steps = t;
    if (t % kCheck != 0) continue;
    if (auto bad = lbm.find_unhealthy(kRhoMin, kRhoMax, kSpeedMax)) {
      r.bad = bad;
      r.bad_step = t;
      break;
    }
    if (t > mean_from) {
      for (int z = 0; z <= kCoreEnd; ++z) {
        double uz = 0;
        for (int y = axis; y <= axis + 1; ++y)
          for (int x = axis; x <= axis + 1; ++x) uz += lbm.moments(x, y, z).uz;
        r.centreline[std::size_t(z)] += uz / 4;
      }
      ++samples;
    }
    if (les && t > total - kFlowThrough) sample_effective_tau(lbm, *les, r, shear_sum, shear_n);
    if (t % kFlowThrough == 0) {
      lbm.velocity(u);
      lbm.density(rho);
      double e = 0;
      for (std::size_t c = 0; c < u.size(); ++c) e += 0.5 * rho[c] * u[c].squaredNorm();
      r.energy.push_back(e);
    }
  }
  r.mass_change = lbm.total_mass() - r.m0;
  for (double& c : r.centreline) c /= double(std::max(samples, 1L)) * kU;
  r.tau_shear = shear_sum / double(std::max(shear_n, 1L));
  return r;
}

/// The LES jet's checks over 10 flow-through times; mass_tolerance bounds the mass balance
/// relative to the total mass (round-off: 1e-12 in double, see the single-precision test).
void check_les_jet(Precision precision, double mass_tolerance) {
  const double tau0 = molecular_tau();
  const JetResult r = run_jet(RegularizedLes::from_tau(tau0), 10, precision);
  INFO(to_string(precision) << ": tau0 - 1/2 = " << tau0 - 0.5 << ", nozzle cells "
                            << r.nozzle_cells << ", steps " << r.steps);

  // Finite and sane at every check (kRhoMin, kRhoMax, kSpeedMax).
  if (r.bad)
    FAIL_CHECK("watchdog at step " << r.bad_step << ": cell (" << r.bad->x << ", " << r.bad->y
                                   << ", " << r.bad->z << ") rho " << r.bad->rho << " |u| "
                                   << r.bad->speed);
  REQUIRE(!r.bad);
  REQUIRE(r.energy.size() == 10);

  // Kinetic energy. The jet is established after ~2 flow-through times (front speed ~ U/2);
  // afterwards its energy is statistically steady (measured within +3.1 % of flow-through 5).
  // Over the last five flow-through times it must neither grow beyond 15 % above the level of
  // flow-through 5 (the energy of regularized BGK at C_s = 0 rises 30 % in one flow-through time
  // before it blows up, file header) nor fall below 85 % (the jet dying out).
  const double e5 = r.energy[4];
  std::ostringstream energies;
  for (double e : r.energy) energies << ' ' << e / e5;
  INFO("E(k) / E(5), k = 1..10:" << energies.str());
  for (std::size_t k = 5; k < 10; ++k) {
    CHECK(r.energy[k] < 1.15 * e5);
    CHECK(r.energy[k] > 0.85 * e5);
  }

  // Mass balance. Each link's reported mass is what it writes minus what it takes, and collision
  // and the Darcy drag conserve each cell's mass, so the change of total mass equals the summed
  // flows up to the rounding of the stored populations and of the sums. That rounding need not
  // average out: it drifts by up to ~1e-16 of the total mass per step (measured 5e-17 here,
  // 7e-17 in test_open_boundaries.cpp), so 4300 steps allow ~5e-13: in double 1e-12 (measured
  // 2.3e-13), which is still 1e-12 of the 2e4 that passed the nozzle; in single
  // mass_tolerance is float's (see its test case).
  INFO("mass change " << std::setprecision(15) << r.mass_change << ", summed flows "
                      << r.mass_flowed << ", inflow " << r.inflow);
  INFO("mass balance error / total mass " << (r.mass_change - r.mass_flowed) / r.m0);
  CHECK(std::abs(r.mass_change - r.mass_flowed) < mass_tolerance * r.m0);
  // The nozzle passes rho_w U per inlet ghost cell and step (bounce_back.hpp: the five links
  // into a face cell), times the perturbation, whose m >= 1 modes integrate to ~0 over the disk
  // and whose m = 0 mode to at most a / (omega T) ~ 1e-4 over the run: 1e-3.
  CHECK(r.inflow == Approx(kU * double(r.nozzle_cells * r.steps)).epsilon(1e-3));

  // The LES carries the shear layer: at the nozzle lip the strain is U / delta_omega with a
  // vorticity thickness of ~ 3 cells at this resolution (spreading 0.18 z, Brown & Roshko 1974,
  // J. Fluid Mech. 64, 775, but not below ~ 2-3 dx), so nu_t = (C_s dx)^2 |S| ~ 3e-4 and
  // tau - 1/2 ~ 3 (nu0 + nu_t) ~ 1.1e-3, five times tau0 - 1/2. Ask for at least 2.5 times in
  // the mean over the shear layer and the last flow-through time, and for the molecular value
  // as the floor (tau = tau0 exactly at zero stress). Measured 5.3 times. Somewhere the eddy
  // part must dominate: the sharpest strain, U over ~ 1 cell at the lip, gives
  // tau - 1/2 ~ 3 (C_s dx)^2 U ~ 3e-3, 13 times tau0 - 1/2: ask for 5 (measured 22).
  INFO("effective tau - 1/2: min " << r.tau_min << ", max " << r.tau_max << ", shear layer "
                                   << r.tau_shear << "; molecular " << tau0 - 0.5);
  CHECK(r.tau_shear > 2.5 * (tau0 - 0.5));
  CHECK(r.tau_max > 5 * (tau0 - 0.5));

  // Potential core: up to ~ 4-5 d from the nozzle the centreline keeps the nozzle velocity
  // (Crow & Champagne 1971; Pope 2000, Turbulent Flows, sec. 5.1). Here the time mean over the
  // last five flow-through times on the four cells around the axis, z <= 2 d. 15 %: the shear
  // layer, 2-3 cells thick on an 8-cell nozzle, displaces the core flow and accelerates it
  // (measured up to +8 % at z = 2 d); a core eaten by a spurious or over-dissipated shear layer
  // falls below.
  for (std::size_t z = 0; z < r.centreline.size(); ++z) {
    INFO("z = " << z << ": u_c / U = " << r.centreline[z]);
    CHECK(std::abs(r.centreline[z] - 1.0) < 0.15);
  }
}

}  // namespace

TEST_CASE("LES round jet at Re = 1e4 stays bounded over 10 flow-through times",
          "[lbm][les][les_jet][slow]") {
  check_les_jet(Precision::float64, 1e-12);
}

TEST_CASE("LES round jet at Re = 1e4 in single precision stays bounded over 10 flow-through times",
          "[lbm][les][les_jet][slow]") {
  // The same jet with float populations f - w and float arithmetic, under the same checks: the
  // energy band (15 %), the nozzle inflow (1e-3), the eddy viscosity (factors 2.5 and 5) and the
  // potential core (15 %) are set by the flow, and float round-off (2^-24 of deviations f - w of
  // at most w (3 U + 4.5 U^2) = 0.33 w) is orders of magnitude below each. The mass balance was a
  // round-off bound in double. In float, rounding to nearest mostly cancels, and the bias of the
  // equilibrium's float weights (sum_q float(w_q) = 1 + 2 d_w, sum_q float(w_q) c_qx^2 =
  // (1 + d_w) / 3, d_w = 7.45e-9: d_w (2 drho - 1.5 u^2) of a cell's mass per collision, the same
  // sign every step) is removed by setting the rest population from the mass (cell.hpp). Left is
  // the rounding of the stored deviations, about 2^-24 x 0.33 w sqrt(19) = 4e-10 of a cell's mass
  // per step with no sign of its own, which over 4300 steps and thousands of cells averages to
  // ~1e-10 of the total. Bound 1e-8; the bias, had it stayed, gives up to 7.45e-9 x 0.035 x 4300
  // = 1.1e-6 (with |drho| and u^2 at most 0.01 on the box average; measured 1.6e-7 with it,
  // 1.1e-10 without). A wrong link or a leaking outlet shows at O(U) per face cell and step, 1e-2
  // of the total mass over the run and more.
  check_les_jet(Precision::float32, 1e-8);
}

TEST_CASE("BGK, TRT and regularized BGK without eddy viscosity blow up on the LES round jet",
          "[lbm][les][les_jet][slow]") {
  // The other half of the LES test above: on the same case and tau0 (tau0 - 1/2 = 2.3e-4, the
  // shear layer resolved by 2-3 cells at Re = 1e4) an operator without eddy viscosity has nothing
  // to carry the energy of the unresolved scales away, so the watchdog must catch it within the 10
  // flow-through times the LES survives; were it to survive, the LES test would show nothing the
  // molecular viscosity does not already give. BGK and TRT (Lambda = 3/16) fail at the nozzle lip
  // within the first flow-through time (measured: steps 301 and 43); regularization alone, which
  // filters the non-hydrodynamic moments (Latt & Chopard 2006), delays the blow-up (measured: step
  // 2236, 5.2 flow-through times) but does not prevent it. Each run stops at the watchdog:
  // about 7 s in all in Release.
  const double tau0 = molecular_tau();
  const std::array<std::pair<const char*, CollisionModel>, 3> ops = {{
      {"BGK", Bgk::from_tau(tau0)},
      {"TRT", Trt::from_tau(tau0)},
      {"regularized BGK, C_s = 0", RegularizedLes::from_tau(tau0, 0.0)},
  }};
  std::array<long, 3> caught{};
  for (std::size_t k = 0; k < ops.size(); ++k) {
    const auto& [name, op] = ops[k];
    const JetResult r = run_jet(op, 10);
    std::ostringstream msg;
    msg << name;
    if (r.bad)
      msg << ": watchdog at step " << r.bad_step << " ("
          << double(r.bad_step) / double(kFlowThrough) << " flow-through times), cell (" << r.bad->x
          << ", " << r.bad->y << ", " << r.bad->z << ") rho " << r.bad->rho << " |u| "
          << r.bad->speed;
    else
      msg << " survived";
    msg << "; E per flow-through time:";
    for (double e : r.energy) msg << ' ' << e;
    INFO(msg.str());
    CHECK(r.bad.has_value());
    caught[k] = r.bad ? r.bad_step : 10 * kFlowThrough + 1;
  }
  // BGK and TRT within 2 flow-through times (measured 0.7 and 0.1); the regularized operator
  // later than both. This records why fluid.collision = "les" exists for the jets: a change that
  // kept BGK or TRT bounded here would fail the test, and should then revise it (and the
  // jet mill's choice of operator), not be undone.
  CHECK(caught[0] <= 2 * kFlowThrough);
  CHECK(caught[1] <= 2 * kFlowThrough);
  CHECK(caught[2] > std::max(caught[0], caught[1]));
}
