// The gas's mass ledger (LbmSolver::initial_mass, exchanged_mass): the mass at initialize() plus
// what every body's links, the mass sources and cells turned solid or fluid gave the fluid equals
// total_mass() to round-off, step by step, in a channel with a velocity inlet, a pressure outlet,
// no-slip and free-slip walls, a mass source, and cells carved out after initialize() (as the jet
// mill builds its chamber), for both population storages.
#include <catch2/catch.hpp>

#include "lbm/lbm_solver.hpp"

#include <cmath>

using namespace lbdem;
using namespace lbdem::lbm;

TEST_CASE("LBM mass ledger closes with inlets, outlets, sources and cells carved after start",
          "[lbm]") {
  for (const Precision storage : {Precision::float64, Precision::float32}) {
    LbmSettings s;
    s.nx = 8, s.ny = 6, s.nz = 16;
    s.faces[0].kind = s.faces[1].kind = FaceKind::wall;
    s.faces[2].kind = s.faces[3].kind = FaceKind::wall;
    s.faces[2].slip = s.faces[3].slip = 1.0;
    s.faces[4].kind = FaceKind::inlet;
    s.faces[4].wall_velocity = Vec3(0, 0, 0.02);
    s.faces[5].kind = FaceKind::outlet;
    s.faces[5].density = 0.999;
    s.collision = Trt::from_tau(0.6, 3.0 / 16);
    s.precision = storage;
    LbmSolver g(s);
    const double m0 = g.total_mass();
    CHECK(g.initial_mass() == m0);
    CHECK(g.exchanged_mass() == 0);
    // A block turned solid after the start (its mass leaves the fluid), then one cell of it back.
    const int body = g.add_body("block");
    for (int z = 6; z < 9; ++z)
      for (int x = 2; x < 5; ++x) g.set_cell(x, 3, z, body);
    g.set_cell(3, 3, 7, 0);
    g.set_mass_sources({{1, 1, 12, 1e-4}, {6, 4, 3, -5e-5}});
    double scale = m0;
    for (int k = 0; k < 301; ++k) {
      g.step();
      const double err = g.total_mass() - g.initial_mass() - g.exchanged_mass();
      scale += std::abs(g.mass_flow(g.face_body(4))) + std::abs(g.mass_flow(g.face_body(5)));
      // Sums of a few hundred link terms per step at 1e-16 each (float storage: its rounding of
      // each population, 6e-8 relative): far below any real leak.
      CHECK(std::abs(err) < (storage == Precision::float64 ? 1e-13 : 1e-5) * scale);
    }
    // The block's mass really left the ledger: without the booking the error would be its mass.
    CHECK(g.exchanged_mass() != 0);
  }
}
