// The mass source field (the coupling's displaced gas): the collision of the next step adds a
// step's sources as it loads the populations (lbm/forcing/mass_source.hpp), unless something
// reads the populations first, which adds them in a pass of its own. Both must give the same
// bits, or a run would change with its output and checkpoint intervals.
#include <catch2/catch.hpp>

#include "lbm/lbm_solver.hpp"

#include <cmath>
#include <cstring>
#include <vector>

using namespace lbdem;
using namespace lbdem::lbm;

namespace {

// A porous channel with a velocity inlet and a pressure outlet, as the coupling runs it: porous
// form with the velocity sums (the policy whose collision adds the sources), sources in most
// cells, the outlet's and the walls' included, some cells without.
LbmSolver channel(Precision storage) {
  LbmSettings s;
  s.nx = 8, s.ny = 6, s.nz = 14;
  s.faces[0].kind = s.faces[1].kind = FaceKind::wall;
  s.faces[2].kind = s.faces[3].kind = FaceKind::wall;
  s.faces[4].kind = FaceKind::inlet;
  s.faces[4].wall_velocity = Vec3(0, 0, 0.02);
  s.faces[5].kind = FaceKind::outlet;
  s.faces[5].density = 0.999;
  s.collision = Trt::from_tau(0.6, 3.0 / 16);
  s.precision = storage;
  LbmSolver g(s);
  g.enable_porosity();
  g.enable_velocity_sum();
  const std::size_t cells = std::size_t(s.nx * s.ny * s.nz);
  std::vector<double> eps(cells), alpha(cells, 0.02);
  for (std::size_t c = 0; c < cells; ++c) eps[c] = 0.6 + 0.4 * std::abs(std::sin(0.37 * double(c)));
  g.set_porosity_field(eps, alpha);
  g.initialize([](int, int, int z, double& rho, Vec3& u) {
    rho = 1.0 + 0.001 * z;
    u = Vec3(0, 0, 0.02);
  });
  return g;
}

// Per cell: a source or sink of up to 1e-5 a step (the displaced gas of a moving bed is of this
// order at the coupling's scales), none in every seventh cell.
std::vector<double> field(std::size_t cells, double phase) {
  std::vector<double> m(cells);
  for (std::size_t c = 0; c < cells; ++c)
    m[c] = c % 7 == 3 ? 0.0 : 1e-5 * std::sin(phase + 0.91 * double(c));
  return m;
}

}  // namespace

TEST_CASE("mass source field: the collision adds it as a separate pass does, bit for bit",
          "[lbm]") {
  for (const Precision storage : {Precision::float64, Precision::float32}) {
    LbmSolver fused = channel(storage), read = channel(storage);
    const std::size_t cells = 8 * 6 * 14;
    double outflow_fused = 0, outflow_read = 0;
    for (int k = 0; k < 120; ++k) {
      // A new field every 40 steps, as the coupling sets one per exchange: the step pending from
      // the old field goes in first.
      if (k % 40 == 0) {
        fused.set_mass_source_field(field(cells, 0.1 * k));
        read.set_mass_source_field(field(cells, 0.1 * k));
      }
      fused.step();
      read.step();
      read.total_mass();  // a reader between steps: the sources go in by the pass
      outflow_fused += fused.mass_flow(fused.face_body(5));
      outflow_read += read.mass_flow(read.face_body(5));
    }
    // The outlet's velocity samples saw the pending sources too (its flow is the same).
    CHECK(outflow_fused == outflow_read);
    const std::vector<double> a = fused.stored_slots(), b = read.stored_slots();
    REQUIRE(a.size() == b.size());
    CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
    // The ledger: the sources' mass is in the populations (the same bound as the ledger test's:
    // float storage rounds each population to 6e-8 of itself).
    const double err = fused.total_mass() - fused.initial_mass() - fused.exchanged_mass();
    CHECK(std::abs(err) < (storage == Precision::float64 ? 1e-13 : 1e-5) * fused.initial_mass());
  }
}
