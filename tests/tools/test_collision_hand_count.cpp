// lbdem-collision-stats on a constructed run against hand counts: two beads meet
// head-on and a third hits the floor, once each, without gravity; the tool's collision counts,
// frequencies and dissipated energy against what one computes on paper.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "helpers/cli.hpp"

namespace {

using lbdem::test::cli;
using lbdem::test::tmpdir;

// Beads of r = 1 mm, rho = 2500 kg/m^3 (m = 1.0472e-5 kg), linear spring k = 10 N/m (contact
// time about 2.3 ms for the pair's reduced mass m/2, 3.2 ms against the floor), e = 0.5, no
// friction, no gravity, in a closed 10 mm box; a step of 50 us (t_c/45 and t_c/64), so that the
// time-series rows, every 5 ms, fall on whole steps (100). A and B approach at 0.1 m/s each across
// a 2 mm gap and touch at 10 ms; C falls at 0.1 m/s onto the floor from 1 mm and touches at 10 ms.
// By 50 ms A and B (0.05 m/s each after the collision) are more than 1 mm from the x walls, C 5 mm
// from the top.
const char* kCase = R"(scenario = "box"
[run]
end_time = 0.05
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.01, 0.01, 0.01]
z_hi = "wall"
[physics]
gravity = [0.0, 0.0, 0.0]
[[materials]]
name = "bead"
density = 2500
stiffness = 10.0
restitution = 0.5
friction = 0.0
[contact]
normal = "linear"
[dem]
dt = 5e-5
[[particle]]
position = [0.003, 0.005, 0.005]
velocity = [0.1, 0.0, 0.0]
radius = 1e-3
[[particle]]
position = [0.007, 0.005, 0.005]
velocity = [-0.1, 0.0, 0.0]
radius = 1e-3
[[particle]]
position = [0.002, 0.002, 0.002]
velocity = [0.0, 0.0, -0.1]
radius = 1e-3
[output]
interval = 0.005
)";

std::map<std::string, std::string> first_row(const std::string& path) {
  std::ifstream f(path);
  std::string head, row;
  std::getline(f, head);
  std::getline(f, row);
  std::map<std::string, std::string> out;
  std::stringstream hs(head), rs(row);
  for (std::string h, v; std::getline(hs, h, ',') && std::getline(rs, v, ',');) out[h] = v;
  return out;
}

}  // namespace

TEST_CASE("collision-stats counts and dissipation equal hand counts on a constructed run",
          "[tools][collisions]") {
  const std::string dir = tmpdir("coll_hand"), cfg = dir + ".toml";
  std::ofstream(cfg) << kCase;
  const auto run = cli("run box --config " + cfg + " --out " + dir + " --threads 1");
  INFO(run.err);
  REQUIRE(run.code == 0);
  const std::string tool =
      (std::filesystem::path(LBDEM_CLI).parent_path() / "lbdem-collision-stats").string();
  const std::string csv = dir + "_coll.csv";
  // The window 0 - 47.5 ms ends half-way between two rows, so the rows it holds are those at 0,
  // 5, ..., 45 ms whatever their times round to.
  REQUIRE(std::system(
              (tool + " " + dir + " --from 0 --to 0.0475 --csv " + csv + " > /dev/null").c_str()) ==
          0);
  const auto r = first_row(csv);
  const auto num = [&](const char* k) { return std::stod(r.at(k)); };
  CHECK(num("collisions_pp") == 1);
  CHECK(num("collisions_pw") == 1);
  // The tool's span is that of the window's first and last time-series rows: 0 and 45 ms (900
  // steps of 50 us; the CSV holds 9 digits).
  CHECK(num("t_from_s") == 0);
  CHECK(num("t_to_s") == Approx(0.045).epsilon(1e-8));
  // Per parcel over T = 45 ms among 3 parcels: 2 x 1 / (3 T) particle-particle (two parcels take
  // part in each) and 1 / (3 T) particle-wall; l = 1, so per original the same. Both contacts
  // (10 - 13 ms) lie inside the window. 1e-8: the CSV's 9 digits.
  const double T = 0.045;
  CHECK(num("freq_pp_per_parcel_per_s") == Approx(2.0 / (3 * T)).epsilon(1e-8));
  CHECK(num("freq_pw_per_parcel_per_s") == Approx(1.0 / (3 * T)).epsilon(1e-8));
  CHECK(num("freq_pp_per_original_per_s") == Approx(2.0 / (3 * T)).epsilon(1e-8));
  // Dissipated: (1 - e^2) of the kinetic energy of the relative motion, 1/2 (m/2) (0.2 m/s)^2 for
  // the pair and 1/2 m (0.1 m/s)^2 against the (infinitely heavy) floor: 7.854e-8 + 3.927e-8 J,
  // all by normal damping. The linear spring-dashpot's restitution is exact for the continuous
  // contact; the velocity-Verlet step (t_c/45 or shorter) leaves an error of order (dt/t_c)^2 in
  // the rebound speed: 1 % covers it with room.
  const double m = 2500 * 4.0 / 3.0 * M_PI * 1e-9;
  const double pair = 0.75 * 0.5 * (m / 2) * 0.04, wall = 0.75 * 0.5 * m * 0.01;
  CHECK(num("dissipated_J") == Approx(pair + wall).epsilon(0.01));
  CHECK(num("dissipated_normal_damping_J") == Approx(pair + wall).epsilon(0.01));
  CHECK(std::abs(num("dissipated_sliding_J")) < 1e-3 * (pair + wall));
  CHECK(num("dissipated_per_collision_J") == Approx((pair + wall) / 2).epsilon(0.01));

  // A folder of a run's kept small outputs (results/) has timeseries.csv but neither
  // collisions.h5 nor particles.h5: the counts and energies, which come from the time series,
  // stand (the same hand counts); the impact speeds and the powder mass are unknown, NaN, not 0
  // (its three particles were placed, not fed, so the inflow ledger does not give the mass).
  std::filesystem::remove(dir + "/collisions.h5");
  std::filesystem::remove(dir + "/particles.h5");
  const std::string err = dir + "_coll_err.txt";
  REQUIRE(std::system(
              (tool + " " + dir + " --from 0 --to 0.0475 --csv " + csv + " > /dev/null 2> " + err)
                  .c_str()) == 0);
  CHECK(lbdem::test::read_text(err).find("no collisions.h5") != std::string::npos);
  std::filesystem::remove(err);
  const auto k = first_row(csv);
  CHECK(std::stod(k.at("collisions_pp")) == 1);
  CHECK(std::stod(k.at("collisions_pw")) == 1);
  CHECK(std::stod(k.at("dissipated_J")) == Approx(pair + wall).epsilon(0.01));
  CHECK(k.at("impact_source") == "none (no collisions.h5)");
  CHECK(std::isnan(std::stod(k.at("impacts_pp"))));
  CHECK(std::isnan(std::stod(k.at("powder_mass_kg"))));
  std::filesystem::remove_all(dir);
  std::filesystem::remove(cfg);
  std::filesystem::remove(csv);
  std::filesystem::remove(dir + "_coll_impact_speed.csv");
}
