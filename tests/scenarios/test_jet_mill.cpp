// The spiral jet mill's gas (scenarios/jet_mill) through the real executable, on the gas-only
// preset's chamber (50 mm across, 5 mm high, four 0.8 mm nozzles at 40 degrees to the wall tangent,
// 120 m/s jets, LES) with coarse grids. Against references: the jets' torque 4 J R cos(40 deg)
// (the only torque on the gas about the axis before wall friction builds up: pressure on the
// cylinder and plates is radial or axial), the same on two grids; the outlet's mass flow against
// the jets' sum (steady mass balance); a vortex (tangential speed at mid-radius against the radial
// one).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/config.hpp"
#include "core/h5.hpp"
#include "dem/walls/cuboid_mesh.hpp"
#include "dem/walls/triangle_mesh.hpp"
#include "helpers/cli.hpp"
#include "helpers/csv_table.hpp"
#include "helpers/meshes.hpp"
#include "helpers/resume_check.hpp"
#include "scenarios/jet_mill/jet_mill.hpp"
#include "tools/src/run_folder.hpp"

namespace {

using lbdem::test::cli;
using lbdem::test::tmpdir;

const std::string kPreset =
    " --config " + std::string(LBDEM_SOURCE_DIR) + "/scenarios/jet_mill/presets/gas.toml";
const std::string kFeedPreset =
    " --config " + std::string(LBDEM_SOURCE_DIR) + "/scenarios/jet_mill/presets/default.toml";

using Table = lbdem::test::CsvTable;
using lbdem::test::read_csv;

constexpr double kPi = 3.14159265358979323846;

}  // namespace

namespace {
// The gas-only preset's text with its 0.5 mm cells replaced by dx.
std::string gas_preset(double dx) {
  std::ifstream in(std::string(LBDEM_SOURCE_DIR) + "/scenarios/jet_mill/presets/gas.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string cfg = text.str();
  cfg.replace(cfg.find("dx = 5e-4"), 9, "dx = " + std::to_string(dx));
  return cfg;
}

const double kRho = 1.2, kU = 120, kD = 8e-4, kRadius = 0.025;
const double kMassFlow = kRho * kU * kPi * kD * kD / 4;  // per nozzle [kg/s]
// The jets' torque about the axis: a force J = mdot U along a nozzle axis through the exit point on
// the wall has the moment J R cos(angle to the tangent).
const double kTorque = 4 * kMassFlow * kU * kRadius * std::cos(40 * kPi / 180);
}  // namespace

TEST_CASE("jet mill: the nozzles' sources hold mdot, J and the jets' torque on any grid",
          "[scenarios][jet_mill]") {
  for (const double dx : {1e-3, 5e-4, 2.5e-4}) {
    const std::string cfg = gas_preset(dx);
    lbdem::scenarios::JetMillScenario mill(lbdem::Config::from_string(cfg));
    const auto& f = mill.box().fluid();
    const auto src = lbdem::scenarios::jet_sources(*mill.box().gas(), f, mill.geometry());
    double mass = 0;  // per step [lattice]
    for (const auto& m : src.mass) mass += m.mass;
    const double cell = f.dx * f.dx * f.dx, to_si = cell / f.units().force_density_to_lattice(1.0);
    lbdem::Vec3 force = lbdem::Vec3::Zero();
    double torque = 0, abs_force = 0;
    const auto& g = mill.box().gas()->grid();
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x) {
          const lbdem::Vec3 fc = to_si * src.force[std::size_t(g.compact_index(x, y, z))];
          const lbdem::Vec3 r = f.cell_centre(x, y, z) - mill.geometry().axis;
          force += fc;
          abs_force += fc.norm();
          torque += r.x() * fc.y() - r.y() * fc.x();
        }
    INFO("dx = " << dx << " m, " << src.mass.size() << " source cells, torque " << torque
                 << " N m against " << kTorque);
    // Mass and momentum are normalised per nozzle: exact to round-off (sums of a few hundred
    // terms).
    CHECK(mass * kRho * cell / f.dt == Approx(4 * kMassFlow).epsilon(1e-12));
    CHECK(abs_force == Approx(4 * kMassFlow * kU).epsilon(1e-12));
    CHECK(force.norm() < 1e-12 * abs_force);  // four jets, 90 degrees apart
    // The torque needs the force's centroid on the nozzle axis; the weights put it at cell centres,
    // so it may sit up to dx / 2 off the axis, 2.6 % of the lever arm R cos(40 deg) at 1 mm cells,
    // but the sampled overlaps balance about the axis: measured 0.001 - 0.014 % on 1, 0.5 and
    // 0.25 mm cells. Bound 1 %.
    CHECK(torque == Approx(kTorque).epsilon(0.01));
  }
}

TEST_CASE("jet mill: the feed inlet adds its own mass flow and momentum, apart from the jets",
          "[scenarios][jet_mill]") {
  // A 1.5 mm feed injector at 20 m/s, halfway between the first two nozzles (45 deg), at 30
  // degrees to the wall tangent: the four jets' forces cancel (90 degrees apart), so the sources'
  // net force is the feed's J along its axis, and their mass the jets' plus the feed's
  // rho U pi d^2 / 4; both exact to round-off, as for the jets (sums of a few hundred terms).
  std::string cfg = gas_preset(1e-3);
  cfg += "\n[jet_mill.feed]\ndiameter = 1.5e-3\nspeed = 20.0\nangle_deg = 30.0\n";
  lbdem::scenarios::JetMillScenario mill(lbdem::Config::from_string(cfg));
  const auto& g = mill.geometry();
  REQUIRE(g.nozzles.size() == 5);
  const auto& feed = g.nozzles.back();
  CHECK(feed.feed);
  CHECK(!g.nozzles.front().feed);
  const double feed_mdot = kRho * 20.0 * kPi * 1.5e-3 * 1.5e-3 / 4, feed_j = feed_mdot * 20.0;
  // At 45 degrees on the wall, pointing 30 degrees inwards from the counter-clockwise tangent.
  const double th = kPi / 4, a = kPi / 6;
  const lbdem::Vec3 dir = std::cos(a) * lbdem::Vec3(-std::sin(th), std::cos(th), 0) -
                          std::sin(a) * lbdem::Vec3(std::cos(th), std::sin(th), 0);
  CHECK((feed.dir - dir).norm() < 1e-14);
  CHECK((feed.exit - g.axis - lbdem::Vec3(kRadius * std::cos(th), kRadius * std::sin(th), 2.5e-3))
            .norm() < 1e-15);
  const auto& f = mill.box().fluid();
  const auto src = lbdem::scenarios::jet_sources(*mill.box().gas(), f, g);
  double mass = 0;
  for (const auto& m : src.mass) mass += m.mass;
  const double cell = f.dx * f.dx * f.dx, to_si = cell / f.units().force_density_to_lattice(1.0);
  lbdem::Vec3 force = lbdem::Vec3::Zero();
  for (const auto& fc : src.force) force += to_si * fc;
  CHECK(mass * kRho * cell / f.dt == Approx(4 * kMassFlow + feed_mdot).epsilon(1e-12));
  CHECK((force - feed_j * dir).norm() < 1e-10 * 4 * kMassFlow * kU);

  // The feed's notional source is sized for the grinding nozzles' source_speed unless it gives its
  // own: r_s = (d / 2) U / U_cap where that exceeds d / 2. Nozzles sized for 60 m/s: 0.8 mm; a
  // 0.5 mm feed at 110 m/s: 0.458 mm, at its own 100 m/s 0.275 mm.
  std::string slow = gas_preset(1e-3);
  slow.replace(slow.find("\nspeed = 120.0"), 1, "\nsource_speed = 60.0\n");
  for (const double own : {0.0, 100.0}) {
    std::string c = slow + "\n[jet_mill.feed]\ndiameter = 5e-4\nspeed = 110.0\n";
    if (own > 0) c += "source_speed = 100.0\n";
    lbdem::scenarios::JetMillScenario m(lbdem::Config::from_string(c));
    INFO("feed source_speed " << own);
    CHECK(m.geometry().nozzles.front().source_radius == Approx(4e-4 * 120 / 60).epsilon(1e-12));
    CHECK(m.geometry().nozzles.back().source_radius ==
          Approx(2.5e-4 * 110 / (own > 0 ? own : 60.0)).epsilon(1e-12));
  }
}

TEST_CASE("jet mill: a supply pressure feeds the jets a choked nozzle's mass flow and thrust",
          "[scenarios][jet_mill]") {
  // 5 bar absolute through the 0.8 mm nozzles: 0.0404 A p0 / sqrt(T0) = 0.593 g/s each, and
  // J = mdot u* + A (p* - p_a) = 1.2679 A p0 - A p_a = 0.268 N (nozzle_flow.hpp; hand values,
  // tests/scenarios/test_nozzle_flow.cpp checks the formulas). The sources must carry exactly that
  // into the gas; the lattice is set for 300 m/s so that the notional source fits the chamber.
  std::string cfg = gas_preset(1e-3);
  cfg.replace(cfg.find("max_speed = 120.0"), 17, "max_speed = 300.0");
  cfg.replace(cfg.find("speed = 120.0 "), 14, "supply_pressure = 5e5 ");
  lbdem::scenarios::JetMillScenario mill(lbdem::Config::from_string(cfg));
  const auto& f = mill.box().fluid();
  const auto src = lbdem::scenarios::jet_sources(*mill.box().gas(), f, mill.geometry());
  double mass = 0;
  for (const auto& m : src.mass) mass += m.mass;
  const double cell = f.dx * f.dx * f.dx, to_si = cell / f.units().force_density_to_lattice(1.0);
  double abs_force = 0;
  for (const auto& fc : src.force) abs_force += to_si * fc.norm();
  // The choked mass flux and vacuum thrust coefficient of air (gamma = 1.4, R = 287.05 J/(kg K)),
  // sqrt(gamma / R) (2 / (gamma + 1))^3 and (gamma + 1) (2 / (gamma + 1))^(gamma / (gamma - 1)):
  // the sources carry them to round-off.
  const double area = lbdem::kPi * 4e-4 * 4e-4, k = std::sqrt(1.4 / 287.05) * std::pow(2 / 2.4, 3);
  const double mdot = k * area * 5e5 / std::sqrt(293.15), cf = 2.4 * std::pow(2 / 2.4, 3.5);
  CHECK(mass * kRho * cell / f.dt == Approx(4 * mdot).epsilon(1e-10));
  CHECK(abs_force == Approx(4 * (cf * area * 5e5 - area * 101325)).epsilon(1e-10));
  CHECK(mill.geometry().nozzles.front().supply_pressure == 5e5);
  // The notional source carries J at the speed it is sized for, sqrt(J / (pi rho r_s^2)): the gas
  // step's 300 m/s by default, or a lower jet_mill.nozzles.source_speed (the p5bar presets keep the
  // source of 300 m/s on a step set for 450 m/s). The sources' sums stay exact either way.
  const double thrust = cf * area * 5e5 - area * 101325;
  const auto core_speed = [&](const lbdem::scenarios::JetMillScenario& m) {
    const double rs = m.geometry().nozzles.front().source_radius;
    return std::sqrt(thrust / (lbdem::kPi * kRho * rs * rs));
  };
  CHECK(core_speed(mill) == Approx(300).epsilon(1e-12));
  std::string wide = cfg;
  wide.replace(wide.find("max_speed = 300.0"), 17, "max_speed = 450.0");
  wide.replace(wide.find("supply_pressure = 5e5 "), 22,
               "supply_pressure = 5e5\nsource_speed = 300.0 ");
  lbdem::scenarios::JetMillScenario mill450(lbdem::Config::from_string(wide));
  CHECK(core_speed(mill450) == Approx(300).epsilon(1e-12));
  CHECK(mill450.box().fluid().dt == Approx(f.dt * 300 / 450).epsilon(1e-12));
  const auto src450 = lbdem::scenarios::jet_sources(*mill450.box().gas(), mill450.box().fluid(),
                                                    mill450.geometry());
  double abs450 = 0;
  const double to_si450 = cell / mill450.box().fluid().units().force_density_to_lattice(1.0);
  for (const auto& fc : src450.force) abs450 += to_si450 * fc.norm();
  CHECK(abs450 == Approx(4 * thrust).epsilon(1e-10));
}

TEST_CASE("jet mill: the jets spin the gas up at their torque 4 J R cos(40 deg) on two grids",
          "[scenarios][jet_mill][physics]") {
  // Measured on the gas itself: its angular momentum about the axis over the first 0.2 ms, before
  // the jets cross the chamber (24 mm at 120 m/s against a 32 mm chord) and wall shear builds up.
  // The only other torque is the staircase walls': bounce-back on a voxelised cylinder pushes along
  // the lattice axes, not along the radius, as the jets' mass raises the pressure; it is of first
  // order in dx (measured: +3.0 % at 1 mm, +1.6 % at 0.5 mm). Bounds: 5 % at 1 mm, 2.5 % at
  // 0.5 mm, and the two grids within 2 % of each other (the grid-independence bound).
  // No-slip walls: the staircase torque of the wall function's slip terms does not converge as
  // cleanly (measured -2.8 % at 1 mm, +1.1 % at 0.5 mm; README, open defects), and this test is
  // about the jets' source.
  const double torque = kTorque;
  std::vector<double> slopes;
  for (const char* dx : {"1e-3", "5e-4"}) {
    const std::string out = tmpdir(std::string("jet_mill_torque_") + dx);
    const auto r =
        cli("run jet_mill" + kPreset + " --out " + out + " --threads 1 --set fluid.dx=" + dx +
            " --set run.end_time=2e-4 --set output.interval=2e-5 --set fluid.wall_function=false");
    REQUIRE(r.code == 0);
    const Table t = read_csv(out + "/timeseries.csv");
    const int it = t.col("time_s"), il = t.col("gas_angular_momentum_z_Nms");
    // Least-squares slope through the origin (the gas starts at rest).
    double lt = 0, tt = 0;
    for (const auto& row : t.rows) lt += row[il] * row[it], tt += row[it] * row[it];
    const double slope = lt / tt;
    INFO("dx = " << dx << " m: dL/dt = " << slope << " N m, jets' torque " << torque << " N m");
    // One-sided below: the staircase's torque adds to the jets' here (measured), and any loss of
    // the injected momentum would show as a slope under the torque.
    CHECK(slope > 0.99 * torque);
    CHECK(slope < (std::string(dx) == "1e-3" ? 1.05 : 1.025) * torque);
    slopes.push_back(slope);
  }
  CHECK(slopes[0] == Approx(slopes[1]).epsilon(0.02));
}

TEST_CASE(
    "jet mill gas: outlet balances the jets, a vortex forms, the radial flow carries the mass",
    "[scenarios][jet_mill][physics][slow]") {
  // 1 mm cells (50 x 50 x 5), the preset's wall function, 12 ms: the outflow settles within about
  // 5 ms (acoustic and spin-up transients; measured). Over 6 - 12 ms:
  //  - the outlet's mass flow equals the jets' sum within 0.5 % (the bound; the gas mass is
  //    then steady, so the only error left is the outflow's residual ripple),
  //  - the gas crossing the cylinder r = 13 mm (the multiple of dx nearest R/2), counted link by
  //    link, carries that mass inwards within the same 0.5 % (measured: 0.001 %; one sample's
  //    ripple is 0.14 %),
  //  - the tangential speed there is several (> 3) times the radial velocity that carries this
  //    mass, mdot / (2 pi r H rho) = 0.59 m/s: a vortex.
  // The ring's mean cell velocity u_r is not a measure of that flux next to the wall function's
  // walls: it reads -0.776 m/s, 26 % more inflow (-0.612 with no slip), because a wall cell's
  // velocity also counts the populations the wall sent back into it, which cross no face.
  const std::string out = tmpdir("jet_mill_gas");
  const auto r = cli("run jet_mill" + kPreset + " --out " + out +
                     " --threads 1 --set fluid.dx=1e-3 --set run.end_time=0.012"
                     " --set output.interval=5e-4");
  REQUIRE(r.code == 0);
  const Table t = read_csv(out + "/timeseries.csv");
  const int it = t.col("time_s"), ij = t.col("jet_mass_flow_kg_s");
  const int io = t.col("outlet_mass_flow_kg_s"), iut = t.col("gas_tangential_speed_mid_m_s");
  const int iq = t.col("gas_radial_mass_flow_mid_kg_s");
  double jets = 0, outlet = 0, ut = 0, radial = 0;
  int n = 0;
  for (const auto& row : t.rows)
    if (row[it] >= 0.006 - 1e-9) {
      jets += row[ij], outlet += row[io], ut += row[iut], radial += row[iq];
      ++n;
    }
  REQUIRE(n >= 10);
  jets /= n, outlet /= n, ut /= n, radial /= n;
  INFO("jets " << jets << " kg/s, outlet " << outlet << " kg/s, through r = 13 mm " << radial
               << " kg/s, u_theta " << ut << " m/s");
  CHECK(jets == Approx(4 * kMassFlow).epsilon(1e-9));  // the CSV holds 10 digits
  CHECK(outlet == Approx(jets).epsilon(0.005));
  CHECK(-radial == Approx(outlet).epsilon(0.005));
  const double ur = radial / (2 * kPi * 0.013 * 0.005 * kRho);
  CHECK(ut > 3 * std::abs(ur));

  // The snapshot at 10 ms holds the profile: the same inflow through every cylinder between the
  // outlet's hole (r < 5 mm) and the jets' sources (r > 22 mm; measured 0.03 % apart).
  const lbdem::H5In snap(out + "/snapshots/fluid_000002.h5");
  REQUIRE(snap.attr_double("time_s") == Approx(0.01));
  const std::vector<double> radius = snap.doubles("/radial_mass_flow_radius_m"),
                            flow = snap.doubles("/radial_mass_flow_kg_per_s");
  REQUIRE(radius.size() == flow.size());
  REQUIRE(radius.size() >= 26);
  for (std::size_t k = 0; k < radius.size(); ++k) {
    INFO("r = " << radius[k] << " m: " << flow[k] << " kg/s");
    CHECK(radius[k] == Approx(1e-3 * double(k)));
    if (radius[k] > 0.0055 && radius[k] < 0.0215) CHECK(-flow[k] == Approx(outlet).epsilon(0.005));
  }

  // lbdem-jet-mill-maps averages it over the window's gas snapshots (here those at 10 and 12 ms)
  // and turns it into the radial velocity of the mass balance, mdot / (2 pi r H rho).
  const std::string maps =
      (std::filesystem::path(LBDEM_CLI).parent_path() / "lbdem-jet-mill-maps").string() + " " +
      out + " --from 0.008 --to 0.012 --out " + out + "/mill > /dev/null";
  REQUIRE(std::system(maps.c_str()) == 0);
  const std::vector<double> last =
      lbdem::H5In(out + "/snapshots/fluid_000003.h5").doubles("/radial_mass_flow_kg_per_s");
  const Table q = read_csv(out + "/mill_gas_radial_flow.csv");
  REQUIRE(q.rows.size() == flow.size());
  for (std::size_t k = 1; k < flow.size(); ++k) {
    const auto& row = q.rows[k];
    const double mean = 0.5 * (flow[k] + last[k]);
    CHECK(row[std::size_t(q.col("snapshots"))] == 2);
    CHECK(row[std::size_t(q.col("mass_flow_kg_per_s"))] == Approx(mean).margin(1e-15));
    CHECK(row[std::size_t(q.col("std_err_kg_per_s"))] ==
          Approx(0.5 * std::abs(flow[k] - last[k])).margin(1e-15));
    CHECK(row[std::size_t(q.col("u_r_m_per_s"))] ==
          Approx(mean / (2 * kPi * radius[k] * 0.005 * kRho)).epsilon(1e-8));
  }
}

TEST_CASE("jet mill gas: LES stays stable where TRT diverges, and the watchdog says so",
          "[scenarios][jet_mill][slow]") {
  // A 10 mm chamber at 0.25 mm cells, tau - 1/2 = 1.5e-4: the 120 m/s jets (Re 6400, 3.2 cells
  // across) are far from resolved. TRT passes the input checks (tau margin 1e-4, Mach 0.17) and
  // blows up within 0.2 ms (measured); the LES operator runs the same set-up (0.5 ms).
  const std::string small =
      " --set fluid.dx=2.5e-4 --set 'box.lo=[-0.005,-0.005,0.0]'"
      " --set 'box.hi=[0.005,0.005,0.005]' --set jet_mill.outlet_radius=0.001"
      " --set run.end_time=5e-4 --set output.interval=1e-4 --set output.checkpoint_interval=1e-4 "
      "--threads 1";
  const std::string cfg_dir = tmpdir("jet_mill_trt_cfg");
  std::filesystem::create_directories(cfg_dir);
  {
    std::ifstream in(std::string(LBDEM_SOURCE_DIR) + "/scenarios/jet_mill/presets/gas.toml");
    std::ofstream o(cfg_dir + "/trt.toml");
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("smagorinsky", 0) == 0) continue;
      if (line.rfind("collision", 0) == 0) line = "collision = \"trt\"";
      o << line << "\n";
    }
  }
  const std::string out = tmpdir("jet_mill_trt");
  const auto bad = cli("run jet_mill --config " + cfg_dir + "/trt.toml --out " + out + small);
  const auto at = bad.err.find("lbdem:");
  const std::string line = at == std::string::npos ? std::string() : bad.err.substr(at);
  INFO(bad.err);
  CHECK(bad.code == 3);
  CHECK(line.rfind("lbdem: error: gas diverged at t = ", 0) == 0);
  CHECK(std::count(line.begin(), line.end(), '\n') == 1);
  CHECK(line.find("les") != std::string::npos);
  const auto good = cli("run jet_mill" + kPreset + " --out " + tmpdir("jet_mill_les") + small);
  CHECK(good.code == 0);
}

TEST_CASE("jet mill: bad input stops with one line naming the key", "[scenarios][jet_mill]") {
  struct Case {
    std::string set, key;
  };
  const std::vector<Case> cases = {
      {"jet_mill.nozzles.angle_deg=2.0", "jet_mill.nozzles.angle_deg"},
      {"jet_mill.nozzles.height=0.0004", "jet_mill.nozzles.height"},
      {"jet_mill.nozzles.diameter=0.006", "jet_mill.nozzles.diameter"},
      {"jet_mill.outlet_radius=0.03", "jet_mill.outlet_radius"},
      {"'fluid.faces.z_lo={kind=\"inlet\",velocity=[0.0,0.0,1.0]}'", "fluid.faces.z_lo"},
      {"coupling.drag=\"gidaspow\"", "coupling"},
      // The preset gives speed: a supply pressure besides it is refused, naming speed.
      {"jet_mill.nozzles.supply_pressure=5e5", "jet_mill.nozzles.speed"},
      // ... and a supply temperature without a supply pressure, naming the temperature.
      {"jet_mill.nozzles.supply_temperature=300.0", "jet_mill.nozzles.supply_temperature"},
      // A source sized for more than the gas step allows (the preset's max_speed is 120 m/s).
      {"jet_mill.nozzles.source_speed=200.0", "jet_mill.nozzles.source_speed"},
  };
  for (const Case& c : cases) {
    const std::string out = tmpdir("jet_mill_bad");
    const auto r = cli("run jet_mill" + kPreset + " --out " + out + " --set " + c.set);
    INFO(c.set << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("'" + c.key) != std::string::npos);
    CHECK(r.err.find("fix:") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

TEST_CASE("jet mill gas: a resumed run equals one that never stopped", "[scenarios][jet_mill]") {
  // The resolved config.toml of a run holds the box's particle streams switched off ([inflow],
  // [outlet]); --resume reads it back, so the jet mill must accept them. 1 mm cells, 0.4 ms on
  // 1 thread against 0.2 ms on 2 threads resumed to 0.4 ms on 2: bitwise the same gas and time
  // series (the wall function, the jets' sources and the outlet all carry over).
  const std::string full = tmpdir("jm_full"), part = tmpdir("jm_part");
  const std::string args = kPreset +
                           " --set fluid.dx=1e-3 --set output.interval=1e-4"
                           " --set output.checkpoint_interval=2e-4";
  REQUIRE(cli("run jet_mill" + args + " --threads 1 --set run.end_time=4e-4 --out " + full).code ==
          0);
  REQUIRE(cli("run jet_mill" + args + " --threads 2 --set run.end_time=2e-4 --out " + part).code ==
          0);
  const auto resumed = cli("run --resume " + part + " --threads 2 --set run.end_time=4e-4");
  INFO(resumed.err);
  REQUIRE(resumed.code == 0);
  lbdem::test::check_same_runs(full, part, {"/fluid/populations"});
  std::filesystem::remove_all(full);
  std::filesystem::remove_all(part);
}

TEST_CASE("jet mill with particles: the feed delivers its mass into the chamber, which holds it",
          "[scenarios][jet_mill]") {
  // The default preset (CG-10 parcels fed at 0.1 kg/s, two-way coupled, 1 mm cells) for 0.25 ms
  // (0.5 s in Release). The DEM takes the gas step, 0.1 x 1 mm / 120 m/s = 0.83 us, so the feed
  // inserts every 0.1 ms (120 steps) what its rate asks by then, and the run's 300 steps are a
  // whole number of 5-step exchanges (the maps' window ends on the last one): the last insertion,
  // at 0.2 ms, brings the total to 0.1 kg/s x 0.2 ms, past it by less than one parcel (a fill stops
  // at the particle that reaches its mass; the largest parcel, r = 215 um, has 6.3e-8 kg), and no
  // warning that the region is full. The run ends half-way between two insertions, so which step is
  // the last one does not hang on how the end time rounds. The chamber's walls (cylinder, floor,
  // top plate) keep every centre inside it; through the vortex finder none has left yet (the feed
  // region's nearest point is 3 mm outside the outlet's edge, and the feed moves along +y, away
  // from it).
  const std::string out = tmpdir("jet_mill_feed");
  const auto r = cli("run jet_mill" + kFeedPreset + " --out " + out +
                     " --threads 2 --set fluid.dx=1e-3 --set run.end_time=2.5e-4"
                     " --set output.interval=1.25e-4 --set output.checkpoint_interval=2.5e-4");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const Table t = read_csv(out + "/timeseries.csv");
  const auto& last = t.rows.back();
  const double inserted = last[std::size_t(t.col("mass_inserted_kg"))];
  CHECK(inserted >= 0.1 * 0.0002 * (1 - 1e-12));  // round-off of the insertion's time only
  CHECK(inserted < 0.1 * 0.0002 + 6.3e-8);
  CHECK(lbdem::test::read_text(out + "/log.txt").find("warning: inflow") == std::string::npos);
  CHECK(last[std::size_t(t.col("mass_removed_kg"))] == 0.0);
  const lbdem::H5In cp(out + "/checkpoint.h5");
  const auto x = cp.doubles("/dem/x");
  // 2e-5 kg in parcels of 4.3e-8 kg on average (10 originals, radius uniform in 75-100 um):
  // about 465 parcels, 3 coordinates each.
  REQUIRE(x.size() > 1200);
  std::size_t outside = 0;
  for (std::size_t k = 0; k + 2 < x.size(); k += 3)
    if (std::hypot(x[k], x[k + 1]) > kRadius || x[k + 2] < 0 || x[k + 2] > 0.005) ++outside;
  CHECK(outside == 0);
  // lbdem-jet-mill-maps on this run folder: the window 0-0.25 ms holds the snapshots at 0 (no
  // particles yet) and at the end, so every parcel of the last one is one sample; all lie inside
  // the chamber, so each falls in one x-y bin and one wall-distance bin, and the positions file
  // lists each once.
  const std::string maps =
      (std::filesystem::path(LBDEM_CLI).parent_path() / "lbdem-jet-mill-maps").string() + " " +
      out + " --from 0 --to 2.5e-4 --out " + out + "/mill > /dev/null";
  REQUIRE(std::system(maps.c_str()) == 0);
  const double parcels = double(x.size() / 3);
  const auto samples = [](const Table& m) {
    double n = 0;
    for (const auto& row : m.rows) n += row[std::size_t(m.col("samples"))];
    return n;
  };
  CHECK(samples(read_csv(out + "/mill_speed_map.csv")) == parcels);
  CHECK(samples(read_csv(out + "/mill_wall_profile.csv")) == parcels);
  CHECK(double(read_csv(out + "/mill_positions.csv").rows.size()) == parcels);
  CHECK_FALSE(read_csv(out + "/mill_gas_profile.csv").rows.empty());
  // The powder mass two ways: the last snapshot's radii and density, and the run's ledger
  // (inserted less removed, nothing removed yet), which a folder of kept outputs without
  // snapshots falls back on. The ledger is read from timeseries.csv's 10 significant digits
  // (rounding: at most 5e-10 of the value; the sums' round-off over some 465 parcels is far
  // smaller): tolerance 1e-9, twice the rounding.
  const auto run = lbdem::tools::RunFolder::open(out);
  CHECK(lbdem::tools::ledger_mass(run, 2.5e-4) ==
        Approx(lbdem::tools::snapshot_mass(run, 2.5e-4)).epsilon(1e-9));
  std::filesystem::remove_all(out);
}

TEST_CASE("jet mill with particles: bad input names the key", "[scenarios][jet_mill]") {
  struct Case {
    std::string set, key;
  };
  const std::vector<Case> cases = {
      {"box.x_lo=\"wall\"", "box.x_lo"},                  // a plane tangent to the cylinder
      {"box.z_hi=\"wall\"", "box.z_hi"},                  // would close the vortex finder
      {"'inflow.hi=[0.03,0.0015,0.0045]'", "inflow.hi"},  // the feed outside the chamber
  };
  for (const Case& c : cases) {
    const std::string out = tmpdir("jet_mill_feed_bad");
    const auto r = cli("run jet_mill" + kFeedPreset + " --out " + out + " --set " + c.set);
    INFO(c.set << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("'" + c.key) != std::string::npos);
    CHECK(r.err.find("fix:") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

TEST_CASE("jet mill study: bad input names the option", "[scenarios][jet_mill]") {
  // An unknown case (CG-3 is not in the seed study's series), --quick where a study has none, and
  // bad windows: exit 2, one line naming the option and the fix, and no study folder.
  const std::string out = tmpdir("jm_study_bad");
  const auto unknown = cli("study jet_mill --cases cg3 --out " + out);
  CHECK(unknown.code == 2);
  CHECK(unknown.err.find("'--cases' = cg3") != std::string::npos);
  CHECK(unknown.err.find("fix:") != std::string::npos);
  const auto quick = cli("study fluidized_bed --quick --out " + out);
  CHECK(quick.code == 2);
  CHECK(quick.err.find("'--quick'") != std::string::npos);
  const auto both = cli("study jet_mill --quick --end-time 0.01 --out " + out);
  CHECK(both.code == 2);
  CHECK(both.err.find("'--end-time'") != std::string::npos);
  // A statistics window where the study has the seed's fixed one, and one that ends first.
  const auto window = cli("study jet_mill --from 0.05 --out " + out);
  CHECK(window.code == 2);
  CHECK(window.err.find("'--from'") != std::string::npos);
  const auto reversed = cli("study fluidized_bed --from 0.3 --to 0.2 --out " + out);
  CHECK(reversed.code == 2);
  CHECK(reversed.err.find("'--to'") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("jet mill classifier ring: solid for the gas where it stands, a wall for the particles",
          "[scenarios][jet_mill]") {
  // A ring of mean radius 7 mm, 1.5 mm thick (the least is sqrt(2) cells), reaching 3 mm below
  // the 5 mm roof, in the default preset on 1 mm cells. In the first gas snapshot, every cell
  // whose centre lies in the ring's solid is solid (porosity 0) and every other cell inside the
  // chamber is gas, the cells under the ring included; no D3Q19 link joins a gas cell inside the
  // ring to one outside it at the ring's height (a 1-cell ring leaked along the diagonals); the
  // particles get the wall "classifier" (its load columns), and the banner describes it.
  const std::string out = tmpdir("jet_mill_ring");
  const std::string ring =
      " --set jet_mill.classifier.radius=0.007 --set jet_mill.classifier.thickness=1.5e-3"
      " --set jet_mill.classifier.height=0.003";
  const auto r = cli("run jet_mill" + kFeedPreset + " --out " + out + ring +
                     " --threads 1 --set run.end_time=1e-5");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const lbdem::H5In grid(out + "/fluid.h5");
  const auto o = grid.doubles("/grid/origin_m");
  const double dx = grid.doubles("/grid/spacing_m").at(0);
  const auto n = grid.int32s("/grid/cells");
  const auto eps = lbdem::H5In(out + "/snapshots/fluid_000000.h5").doubles("/porosity");
  REQUIRE(eps.size() == std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]));
  int ring_cells = 0, wrong = 0;
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const double px = o[0] + x * dx, py = o[1] + y * dx, pz = o[2] + z * dx;
        const double rc = std::hypot(px, py);
        if (rc > kRadius) continue;  // outside the chamber: solid anyway
        const bool in_ring = std::abs(rc - 0.007) <= 0.75e-3 && pz >= 0.002;
        const double e =
            eps[(std::size_t(z) * std::size_t(n[1]) + std::size_t(y)) * std::size_t(n[0]) +
                std::size_t(x)];
        ring_cells += in_ring;
        if (in_ring != (e == 0.0)) ++wrong;
      }
  CHECK(ring_cells > 150);  // about 2 pi 7 mm x 1.5 mm x 3 mm / 1 mm^3 = 198
  CHECK(wrong == 0);
  const auto gas_at = [&](int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < n[0] && y < n[1] && z < n[2] &&
           eps[(std::size_t(z) * std::size_t(n[1]) + std::size_t(y)) * std::size_t(n[0]) +
               std::size_t(x)] > 0;
  };
  int leaks = 0;
  for (int z = 2; z < n[2]; ++z)  // cell centres from 2.5 mm: the ring's height
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        if (!gas_at(x, y, z) || std::hypot(o[0] + x * dx, o[1] + y * dx) > 0.007) continue;
        for (int cz = -1; cz <= 1; ++cz)
          for (int cy = -1; cy <= 1; ++cy)
            for (int cx = -1; cx <= 1; ++cx) {
              if (std::abs(cx) + std::abs(cy) + std::abs(cz) > 2) continue;  // D3Q19
              const int X = x + cx, Y = y + cy, Z = z + cz;
              if (Z >= 2 && gas_at(X, Y, Z) && std::hypot(o[0] + X * dx, o[1] + Y * dx) > 0.007)
                ++leaks;
            }
      }
  CHECK(leaks == 0);
  const std::string log = lbdem::test::read_text(out + "/log.txt");
  CHECK(log.find("classifier ring radius") != std::string::npos);
  CHECK(lbdem::test::read_text(out + "/timeseries.csv").find("wall_classifier_force_z_N") !=
        std::string::npos);
  std::filesystem::remove_all(out);
  // Bad input: a ring thinner than a cell (holes in the staircase), and one across the feed.
  struct Case {
    std::string set, key;
  };
  const std::vector<Case> bad = {
      {" --set jet_mill.classifier.thickness=5e-4", "jet_mill.classifier.thickness"},
      {" --set jet_mill.classifier.radius=0.012", "inflow.lo"},
  };
  for (const Case& c : bad) {
    const auto b = cli("run jet_mill" + kFeedPreset + " --out " + out + ring + c.set);
    INFO(c.set << ": " << b.err);
    CHECK(b.code == 2);
    CHECK(b.err.find("'" + c.key) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

TEST_CASE("jet mill chamber from an STL: a faceted copy of the cylinder gives its cells and walls",
          "[scenarios][jet_mill]") {
  // The default preset on 1 mm cells for 0.5 ms, with the analytic cylinder and with a closed
  // 256-sided prism inscribed in it, written in mm (jet_mill.chamber_stl_scale = 1e-3).
  // - Solid cells: the same, exactly. Cell centres at (i + 1/2, j + 1/2) mm have r^2 = an integer
  //   + 1/2 mm^2, at least 0.5 mm^2 from R^2 = 625 mm^2, so |r - R| >= 0.01 mm: beyond the
  //   facets' sagitta R (1 - cos(pi / 256)) = 1.9 um, float32 storage and the voxelizer's rounding
  //   (2^-13 cells).
  // - The jets: the same mass flow, and all of each notional source in gas (the banner's
  //   fraction is 1).
  // - The particles: the prism's 512 side facets are their wall (the 512 cap facets are left to
  //   the plates), and every centre stays inside the circle and between the plates.
  const std::string dir = tmpdir("jet_mill_stl");
  std::filesystem::create_directories(dir);
  const auto write = [&](const std::string& name, double r_mm, double h_mm) {
    const std::string path = dir + "/" + name;
    lbdem::dem::TriangleMesh::from_triangles(
        lbdem::test::prism(lbdem::Vec3::Zero(), lbdem::Vec3::UnitZ(), r_mm, 0, h_mm, 256))
        .write_stl_binary(path);
    return path;
  };
  const std::string chamber = write("chamber.stl", 25, 5);
  const std::string run =
      " --threads 1 --set fluid.dx=1e-3 --set run.end_time=5e-4"
      " --set output.interval=2.5e-4 --set output.checkpoint_interval=5e-4";
  const std::string stl =
      " --set 'jet_mill.chamber_stl=\"" + chamber + "\"' --set jet_mill.chamber_stl_scale=1e-3";
  const auto a = cli("run jet_mill" + kFeedPreset + " --out " + dir + "/cyl" + run);
  const auto m = cli("run jet_mill" + kFeedPreset + " --out " + dir + "/stl" + run + stl);
  INFO(a.err << m.err);
  REQUIRE(a.code == 0);
  REQUIRE(m.code == 0);
  const auto eps_a = lbdem::H5In(dir + "/cyl/snapshots/fluid_000000.h5").doubles("/porosity");
  const auto eps_m = lbdem::H5In(dir + "/stl/snapshots/fluid_000000.h5").doubles("/porosity");
  REQUIRE(eps_a.size() == eps_m.size());
  std::size_t solid = 0, differ = 0;
  for (std::size_t k = 0; k < eps_a.size(); ++k) {
    solid += eps_a[k] == 0.0;
    differ += (eps_a[k] == 0.0) != (eps_m[k] == 0.0);
  }
  CHECK(solid > 500);  // 50 x 50 cells less the circle's 1,976, on 5 layers: 2,620
  CHECK(differ == 0);
  const std::string log = lbdem::test::read_text(dir + "/stl/log.txt");
  CHECK(log.find("512 side facets") != std::string::npos);
  CHECK(log.find("source gas fraction 1 ") != std::string::npos);
  {
    // The particles' side wall is the mesh, without the caps; the jets' sources (cells, mass,
    // force) are the cylinder's exactly: every sample of a source lies 1.5 cells or more from the
    // wall, so both chambers count the same samples.
    std::ifstream in(std::string(LBDEM_SOURCE_DIR) + "/scenarios/jet_mill/presets/default.toml");
    std::stringstream text;
    text << in.rdbuf();
    const std::string cyl_cfg = text.str();
    std::string cfg = cyl_cfg;
    cfg.replace(cfg.find("\n[jet_mill]\n"), 12,
                "\n[jet_mill]\nchamber_stl = \"" + chamber + "\"\nchamber_stl_scale = 1e-3\n");
    lbdem::scenarios::JetMillScenario mill(lbdem::Config::from_string(cfg));
    lbdem::scenarios::JetMillScenario cyl(lbdem::Config::from_string(cyl_cfg));
    const lbdem::dem::MeshWall* side = nullptr;
    for (const auto& w : mill.box().solver().walls())
      if (w.name == "chamber") side = std::get_if<lbdem::dem::MeshWall>(&w.shape);
    REQUIRE(side != nullptr);
    CHECK(side->mesh.size() == 512);
    const auto &sm = mill.sources(), &sc = cyl.sources();
    REQUIRE(sm.mass.size() == sc.mass.size());
    bool same = sm.force == sc.force;
    for (std::size_t k = 0; k < sm.mass.size(); ++k)
      same = same && sm.mass[k].x == sc.mass[k].x && sm.mass[k].y == sc.mass[k].y &&
             sm.mass[k].z == sc.mass[k].z && sm.mass[k].mass == sc.mass[k].mass;
    CHECK(same);
  }
  const auto x = lbdem::H5In(dir + "/stl/checkpoint.h5").doubles("/dem/x");
  REQUIRE(x.size() > 2400);  // about 930 parcels (the feed test above)
  std::size_t outside = 0;
  for (std::size_t k = 0; k + 2 < x.size(); k += 3)
    if (std::hypot(x[k], x[k + 1]) > kRadius || x[k + 2] < 0 || x[k + 2] > 0.005) ++outside;
  CHECK(outside == 0);

  // Bad input: exit 2, the key and the reason named, no run folder.
  struct Case {
    std::string set, key, why;
  };
  const std::string mm = "' --set jet_mill.chamber_stl_scale=1e-3";
  const auto stl_at = [&](const std::string& path) {
    return " --set 'jet_mill.chamber_stl=\"" + path + "\"";
  };
  // A square chamber filling the box: at 45 degrees its wall lies outside the nozzles' circle.
  const std::string square = dir + "/square.stl";
  lbdem::dem::cuboid_mesh(lbdem::Vec3(0, 0, 2.5),
                          {lbdem::Vec3::UnitX(), lbdem::Vec3::UnitY(), lbdem::Vec3::UnitZ()},
                          lbdem::Vec3(25, 25, 2.5))
      .write_stl_binary(square);
  const std::vector<Case> bad = {
      {stl_at(dir + "/none.stl") + "'", "jet_mill.chamber_stl", ""},
      {" --set jet_mill.chamber_stl_scale=1e-3", "jet_mill.chamber_stl_scale", "not given"},
      // The file in mm read as metres: 25 m across, outside the box.
      {stl_at(chamber) + "'", "jet_mill.chamber_stl", "outside the box"},
      // A wall 3 mm inside the nozzles' circle: their sources would sit in solid.
      {stl_at(write("narrow.stl", 22, 5)) + mm, "jet_mill.chamber_stl", "within 1.5 cells"},
      {stl_at(square) + mm + " --set jet_mill.nozzles.first_deg=45.0", "jet_mill.chamber_stl",
       "outside the nozzles' circle"},
      // A roof 2 mm below the top plate: no gas reaches the vortex finder.
      {stl_at(write("low.stl", 25, 3)) + mm, "jet_mill.chamber_stl", "no gas cell"},
      // A roof 0.1 mm below it: gas passes, but the roof would close the outlet to particles
      // (within 1.5 cells of the plate: so would one 1 mm below it, on these 1 mm cells).
      {stl_at(write("lid.stl", 25, 4.9)) + mm, "jet_mill.chamber_stl", "covers the vortex"},
      {stl_at(chamber) + mm + " --set jet_mill.classifier.radius=0.007" +
           " --set jet_mill.classifier.height=0.003",
       "jet_mill.classifier", "in the chamber's STL"},
      // The feed (r up to 20 mm) reaching past an 18 mm wall.
      {stl_at(write("small.stl", 18, 5)) + mm, "inflow.lo", "meets the wall"},
  };
  for (const Case& c : bad) {
    const auto b = cli("run jet_mill" + kFeedPreset + " --out " + dir + "/bad" + c.set);
    INFO(c.set << ": " << b.err);
    CHECK(b.code == 2);
    CHECK(b.err.find("'" + c.key + "'") != std::string::npos);
    CHECK(b.err.find(c.why) != std::string::npos);
    CHECK(b.err.find("fix:") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir + "/bad"));
  }
  std::filesystem::remove_all(dir);
}
