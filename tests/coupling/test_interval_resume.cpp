// An exchange interval stopped part-way and taken up again (Coupler::interval_state and
// resume_interval, what a stop on SIGTERM inside a long interval checkpoints): the rest of the
// interval and its exchange must be what they would have been without the stop, to the bit — the
// reference is the same interval run through, so any difference is an error, not round-off. In
// double and in single precision: single keeps the interval's velocity sums in float
// (lbm/lattice_fields.hpp), which IntervalState holds widened to double and set_velocity_sum
// narrows back, exactly, so the bound stays zero.
#include <catch2/catch.hpp>

#include "coupling/coupler.hpp"
#include "dem/dem_solver.hpp"
#include "helpers/dem_setup.hpp"
#include "lbm/collision/trt.hpp"

#include <random>
#include <vector>

using namespace lbdem;
using namespace lbdem::coupling;

namespace {

void stop_and_resume(lbm::Precision precision) {
  const double dx = 1e-4, dt = 2e-7, d = 1.2e-4;
  const int n = 8, steps = 20, stop_after = 7;
  lbm::LatticeUnits units{dx, dt, 1.2};
  lbm::LbmSettings ls;
  ls.nx = ls.ny = n, ls.nz = 2 * n;
  lbm::BoxFaces faces;  // walls on z, periodic x and y
  faces[4].kind = faces[5].kind = lbm::FaceKind::wall;
  ls.faces = faces;
  ls.collision = lbm::Trt::from_tau(0.5 + 3 * units.viscosity_to_lattice(1.8e-5 / 1.2));
  ls.precision = precision;
  auto ds = test::settings(dt);
  ds.domain.lo = Vec3::Zero();
  ds.domain.hi = Vec3(n, n, 2 * n) * dx;
  ds.domain.periodic = {true, true, false};
  dem::DemSolver dem(ds, std::vector<dem::Material>{test::glass()});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 60; ++k)
    dem.add_particle(Vec3(u(rng) * n, u(rng) * n, (2 + u(rng) * 12)) * dx,
                     Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) * 0.1, d / 2, 0);
  // A gas in motion, so that the slip, grad p and the sums all matter.
  const auto start = [&](lbm::LbmSolver& gas) {
    gas.initialize([&](int x, int y, int z, double& rho, Vec3& v) {
      rho = 1 + 1e-3 * std::sin(0.7 * x + 0.3 * z);
      v = Vec3(0.01 * std::sin(0.5 * z), 0.005 * std::cos(0.4 * x + y), 0.002);
    });
  };
  for (const bool two_way : {true, false}) {
    CAPTURE(two_way);
    CouplerSettings cs;
    cs.drag = Beetstra{};
    cs.kernel_width = 2 * dx;
    cs.viscosity = 1.8e-5;
    cs.two_way = two_way;
    // Run through.
    lbm::LbmSolver ga(ls);
    start(ga);
    Coupler ca(ga, lbm::LatticeFrame{Vec3::Zero(), dx}, units, cs);
    dem::ParticleArrays pa = dem.particles();
    ca.begin_interval(pa, steps);
    for (int k = 0; k < steps; ++k) ca.before_gas_step(), ga.step();
    const ExchangeReport ra = ca.end_interval(pa);
    // Stopped after 7 steps: what a checkpoint keeps, then a new gas and coupler from it.
    lbm::LbmSolver gb(ls);
    start(gb);
    Coupler cb(gb, lbm::LatticeFrame{Vec3::Zero(), dx}, units, cs);
    dem::ParticleArrays pb = dem.particles();
    cb.begin_interval(pb, steps);
    for (int k = 0; k < stop_after; ++k) cb.before_gas_step(), gb.step();
    CHECK(cb.steps_left() == steps - stop_after);
    const IntervalState st = cb.interval_state();
    lbm::LbmSolver gc(ls);
    gc.load_state(gb.stored_slots(), gb.state(), gb.steps());
    Coupler cc(gc, lbm::LatticeFrame{Vec3::Zero(), dx}, units, cs);
    cc.resume_interval(pb, st);
    REQUIRE(cc.steps_left() == steps - stop_after);
    while (cc.steps_left() > 0) cc.before_gas_step(), gc.step();
    const ExchangeReport& r = cc.end_interval(pb);
    CHECK(cc.steps_left() == 0);
    for (std::size_t k = 0; k < pa.size(); ++k) REQUIRE(pb.external[k] == pa.external[k]);
    CHECK(gc.stored_slots() == ga.stored_slots());
    CHECK(r.drag == ra.drag);
    CHECK(r.pressure_force == ra.pressure_force);
    CHECK(r.mean_eps_particles == ra.mean_eps_particles);
    CHECK(r.max_particle_rate == ra.max_particle_rate);
    // A state that does not fit the particles is refused.
    IntervalState short_one = st;
    short_one.beta.pop_back();
    CHECK_THROWS_AS(cc.resume_interval(pb, short_one), std::invalid_argument);
  }
}

}  // namespace

TEST_CASE("an exchange interval stopped part-way and resumed equals one run through",
          "[coupling][checkpoint]") {
  stop_and_resume(lbm::Precision::float64);
}

TEST_CASE(
    "an exchange interval stopped part-way and resumed equals one run through in single "
    "precision",
    "[coupling][checkpoint]") {
  stop_and_resume(lbm::Precision::float32);
}
