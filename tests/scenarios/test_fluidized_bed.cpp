// The fluidized bed through the real executable (scenarios/fluidized_bed): a bed of parcels
// (l = 4 of 100 um originals, cohesionless, periodic sides) poured through still air, then the
// inflow ramped slowly to about 3 U_mf. Against references: once fluidized, the pressure drop and
// the distributor plate together carry the bed's weight per area less buoyancy (plus the gas's
// own head) within 3 %, and so does the pressure drop alone (see below); and the
// minimum fluidization velocity read from the ramp (the fixed-bed line of dp against U meeting the
// weight) lies within 15 % of the Ergun balance at the bed's own measured voidage (the issue's
// tolerances). Both come from one run of 0.37 s.
// The voidage is the bulk one an experiment measures, eps_mf = 1 - M / (rho_p A H), with the
// surface height H from bed_height_m (95 % of the particle volume below): for centres spread
// evenly over [r, H - r], h95 = r + 0.95 (H - 2 r). Ergun's U_mf goes as eps^3 / (1 - eps), 9 %
// per 0.01 of eps, so a voidage read as the kernel's eps inside the bed (bed_voidage, 0.413 here)
// would compare a different quantity: the drag law there sees the kernel-sampled eps, whose
// fluctuations (4.7 % in the solid fraction at sigma = 2 D, kernel.hpp) open easier paths and lower
// the pressure drop of a random bed of parcels below Ergun at its mean eps.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "core/h5.hpp"
#include "helpers/cli.hpp"
#include "helpers/csv_table.hpp"
#include "helpers/resume_check.hpp"

namespace {

using lbdem::test::cli;
using lbdem::test::tmpdir;

// 2 x 2 mm, 5 parcels across (the kernel, 2 cells, smooths the rest), 5 mm static height, a
// 16.8 mm column; U ramps from 0 at 0.08 s to 25 mm/s at 0.23 s (about 3 U_mf) and holds.
const char* kBed = R"(scenario = "fluidized_bed"
[run]
end_time = 0.5
seed = 3
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.002, 0.002, 0.0168]
x_lo = "periodic"
x_hi = "periodic"
y_lo = "periodic"
y_hi = "periodic"
z_lo = "wall"
z_hi = "wall"
[[materials]]
name = "powder"
density = 1500
stiffness = 10
restitution = 0.9
friction = 0.3
[contact]
normal = "linear"
[coarse_grain]
size_factor = 4
rule = "linear_similarity"
[dem]
impact_speed = 0.3
steps_per_contact = 20
[[fill]]
lo = [0.0, 0.0, 0.0]
hi = [0.002, 0.002, 0.0145]
mass = 1.8e-5
material = "powder"
radius = { kind = "fixed", radius = 5e-5 }
[fluid]
density = 1.2
viscosity = 1.8e-5
dx = 4e-4
lattice_velocity = 0.1
max_speed = 0.5
pressure_difference = 50.0
gravity = true
[fluid.faces]
x_lo = "periodic"
x_hi = "periodic"
y_lo = "periodic"
y_hi = "periodic"
z_lo = { kind = "inlet", velocity = [0.0, 0.0, 0.025], ramp_start = 0.08, ramp_time = 0.15 }
z_hi = { kind = "outlet", pressure = 0.0 }
[coupling]
drag = "gidaspow"
exchange_every = 10
[output]
interval = 0.005
snapshot_interval = 0.5
checkpoint_interval = 0.5
)";

using Table = lbdem::test::CsvTable;
using lbdem::test::read_csv;

// What the bed run measured against its references (see the test).
struct BedResult {
  double dp = 0, plate = 0, weight = 0, u_mf = 0, u_ergun = 0, eps_mf = 0;
};

// The run's timing: the gas starts at ramp_start [s], dp is averaged from fluidized [s].
struct BedTimes {
  double ramp_start = 0.08, fluidized = 0.27;
};

// Runs kBed with `args` added and checks dp and U_mf against their references.
BedResult fluidized_bed(const std::string& name, const std::string& args, BedTimes times = {},
                        int threads = 2) {
  const std::string dir = tmpdir(name);
  std::filesystem::create_directories(dir + "_cfg");
  const std::string cfg = dir + "_cfg/bed.toml";
  std::ofstream(cfg) << kBed;
  const auto r = cli("run fluidized_bed --config " + cfg + " --out " + dir + " --threads " +
                     std::to_string(threads) + args);
  REQUIRE(r.code == 0);
  const Table t = read_csv(dir + "/timeseries.csv");
  const int it = t.col("time_s"), idp = t.col("pressure_drop_Pa");
  const int iu = t.col("gas_mass_flow_z_lo_kg_s");

  const double rho_p = 1500, rho_f = 1.2, mu = 1.8e-5, g = 9.81, d = 100e-6;
  const double area = 0.002 * 0.002, column = 0.0168;
  // The bed's mass from its parcels (radius 4 x 50 um, all alike) as the final checkpoint holds
  // them: the fill stops at the first parcel that reaches the 1.8e-5 kg asked, so it overshoots by
  // up to one parcel (5.0e-8 kg, 0.28 %); nothing leaves the closed column.
  const auto radii = lbdem::H5In(dir + "/checkpoint.h5").doubles("/dem/radius");
  double mass = 0;
  for (double rp : radii) mass += rho_p * 4.0 / 3.0 * M_PI * rp * rp * rp;
  const double parcel = rho_p * 4.0 / 3.0 * M_PI * std::pow(4 * 50e-6, 3);
  CHECK(mass >= 1.8e-5);
  CHECK(mass < 1.8e-5 + parcel * (1 + 1e-12));
  const double weight = mass * g * (1 - rho_f / rho_p) / area + rho_f * g * column;

  // (1) Fluidized: mean over 0.27 - 0.37 s, the inflow held at 25 mm/s from 0.23 s. Over time the
  // gas (dp A) and the distributor plate (its contact force) carry the weight; the window's ends
  // add the bed's momentum change over it, M dv / T: the bed oscillates at about 0.01 m/s, so up
  // to 1.8e-5 kg x 0.02 m/s / 0.1 s / 4e-6 m^2 = 0.9 Pa (2 % of 44 Pa), and the 21 samples of dp
  // (1.2 Pa rms, correlated over the 0.05 s period, two periods in the window) add about 1 %: 3 %,
  // the issue's bound for both. The bed still expands just after the ramp (a window from 0.25 s
  // read dp 2 % low). This bed, 5 parcels wide, slugs and falls back onto the plate, which
  // carries about 1 % of the weight (measured over 0.33 - 0.5 s of a 0.5 s run: dp alone -1.0 %,
  // dp + plate +0.1 %), so dp alone has the smaller margin; the wider study beds give dp + plate
  // within 0.5 % of the weight.
  const int iw = t.col("wall_z_lo_force_z_N");
  double dp = 0, plate = 0;
  int n = 0;
  for (const auto& row : t.rows)
    if (row[it] >= times.fluidized) dp += row[idp], plate -= row[iw] / area, ++n;
  dp /= n;
  plate /= n;
  CAPTURE(dp, plate, weight);
  CHECK(dp + plate == Approx(weight).epsilon(0.03));
  CHECK(dp == Approx(weight).epsilon(0.03));

  // (2) U_mf: the fixed-bed part of the ramp (dp below 60 % of the weight, U above 5 % of the
  // final speed: the start of the ramp carries the settling gas's transient) is the Darcy line
  // dp = a U, through the origin by least squares; U_mf = weight / a, where that line meets the
  // fluidized plateau. Ergun's inertial term adds 0.3 % at Re = 0.04 and is left out of the fit.
  // The bed's voidage is read over the same rows as the fit: the bed the Darcy line measures.
  // A bed poured through gas is still consolidating when the ramp begins (its gas has to leave
  // through it: coupling.displaced_gas), so its height at 0.08 s is not the fixed bed's.
  double suu = 0, sup = 0, h95 = 0, h0 = 0;
  int nh = 0;
  const int ih = t.col("bed_height_m");
  for (const auto& row : t.rows) {
    const double u = row[iu] / (rho_f * area);             // superficial inflow [m/s]
    if (row[it] <= times.ramp_start + 1e-9) h0 = row[ih];  // before the gas starts
    if (row[it] > times.ramp_start && u > 0.05 * 0.025 && row[idp] < 0.6 * weight)
      suu += u * u, sup += u * row[idp], h95 += row[ih], ++nh;
  }
  REQUIRE(suu > 0);
  h95 /= nh;
  const double u_mf = weight / (sup / suu);
  const double r_p = 4 * 50e-6, height = (h95 - r_p) / 0.95 + 2 * r_p;
  const double eps_mf = 1 - mass / (rho_p * area * height);
  // Ergun balance at eps_mf: 150 mu (1-e)^2 U / (e^3 d^2) + 1.75 rho_f (1-e) U^2 / (e^3 d) =
  // (1-e) (rho_p - rho_f) g, for U.
  const double e = eps_mf, e3 = e * e * e;
  const double a2 = 1.75 * rho_f * (1 - e) / (e3 * d),
               a1 = 150 * mu * (1 - e) * (1 - e) / (e3 * d * d);
  const double c = (1 - e) * (rho_p - rho_f) * g;
  const double u_ergun = (-a1 + std::sqrt(a1 * a1 + 4 * a2 * c)) / (2 * a2);
  CAPTURE(u_mf, u_ergun, eps_mf, h95, h0);
  WARN("fluidized bed: dp " << dp << " Pa + plate " << plate << " Pa against " << weight
                            << " Pa; U_mf " << u_mf << " m/s from the ramp, Ergun at eps_mf = "
                            << eps_mf << ": " << u_ergun << " m/s (bed height " << h95
                            << " m over the fit, " << h0 << " m at 0.08 s)");
  CHECK(eps_mf > 0.35);
  CHECK(eps_mf < 0.5);
  CHECK(u_mf == Approx(u_ergun).epsilon(0.15));
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(dir + "_cfg");
  return {dp, plate, weight, u_mf, u_ergun, eps_mf};
}

}  // namespace

TEST_CASE("fluidized bed: dp = weight / area once fluidized, U_mf from a ramp against Ergun",
          "[scenarios][fluidized_bed][physics][slow]") {
  // Measured: dp -1.64 % (dp + plate -0.52 %), U_mf +7.9 % of Ergun.
  fluidized_bed("fluidized_bed", " --no-plots --set run.end_time=0.37", {}, 1);
}

TEST_CASE("fluidized bed in single precision: dp = weight / area and U_mf against Ergun",
          "[scenarios][fluidized_bed][physics][slow]") {
  // The test above with the gas in single precision (about 20 s on a busy core). Same references
  // (W/A less buoyancy plus the gas's head; Ergun at the bed's measured voidage) and the double
  // tolerances, 3 % and 15 %, kept because the model and the sampling dominate them while float
  // moves dp and U_mf by far less: dp is the gas's density difference times c_s^2, and a float
  // population f - w resolves a density deviation to u_f = 2^-24 = 6e-8 of w_q (dp is about 1e-2 of
  // the lattice pressure rho c_s^2 here: 6e-6 of dp); the exchange's float fields (alpha, 1/eps,
  // force: 6e-8 of each, rounded once per 10-step interval) and the velocity sums (10 float adds
  // per interval, at most 10 u_f of the sum) move each parcel's drag by < 1e-6. A granular bed is
  // chaotic, so such a difference grows into another realisation of the same random bed (single and
  // double part during the pour), as another seed would: the checks read averages over the bed (dp
  // over 0.1 s, the Darcy slope of the ramp), whose scatter between realisations the tolerances are
  // for. Measured: single dp -1.52 % (dp + plate -0.84 %), U_mf +6.2 % of Ergun; double dp -1.64 %
  // (-0.52 %), U_mf +7.9 %.
  const BedResult s =
      fluidized_bed("fluidized_bed_single",
                    " --no-plots --set run.end_time=0.37 --set fluid.precision=single", {}, 1);
  WARN("fluidized bed in single precision: dp / weight - 1 = "
       << s.dp / s.weight - 1 << ", (dp + plate) / weight - 1 = " << (s.dp + s.plate) / s.weight - 1
       << ", U_mf / Ergun - 1 = " << s.u_mf / s.u_ergun - 1);
}

TEST_CASE("a resumed coupled bed equals an uninterrupted one, on any thread count",
          "[scenarios][fluidized_bed]") {
  // The default preset with the inflow ramping from t = 0, so that gas, drag, porosity and the
  // pressure-gradient force all act: 0.002 s (55 exchanges) on 1 thread against 0.001 s on 2
  // threads resumed to 0.002 s on 2 threads, with a row every 1 ms (kept short: 0.004 s took 27 s
  // under the sanitizers). The exchange is recomputed at every interval from the populations and
  // the particles alone, so nothing of it needs a checkpoint.
  const std::string full = tmpdir("fb_full"), part = tmpdir("fb_part");
  const std::string ramp = " --set fluid.faces.z_lo.ramp_start=0.0 --set output.interval=0.001";
  REQUIRE(cli("run fluidized_bed --threads 1 --set run.end_time=0.002 --out " + full + ramp).code ==
          0);
  REQUIRE(cli("run fluidized_bed --threads 2 --set run.end_time=0.001 --out " + part + ramp).code ==
          0);
  REQUIRE(cli("run --resume " + part + " --threads 2 --set run.end_time=0.002").code == 0);
  lbdem::test::check_same_runs(full, part,
                               {"/fluid/populations", "/dem/x", "/dem/v", "/dem/external"});
  std::filesystem::remove_all(full);
  std::filesystem::remove_all(part);
}

TEST_CASE(
    "a resumed coupled bed in single precision equals an uninterrupted one on 1 2 and 4 "
    "threads",
    "[scenarios][fluidized_bed]") {
  // The test above with the gas in single precision (fluid.precision = "single": float
  // populations f - w, float force, 1/eps, alpha and velocity sums, a float collision). No
  // tolerance: the float arithmetic runs in a fixed order per cell whatever the threads (the
  // kernel's per-cell update, the exchange's deterministic sums), and a checkpoint keeps the float
  // slots widened to double, which narrow back exactly, so any difference is a defect. The same
  // 0.002 s (55 exchanges) on 1 thread and on 4 threads must agree to the bit, and 0.001 s on 4
  // threads resumed to 0.002 s on 2 threads must agree with both.
  const std::string full = tmpdir("fb_single_full"), four = tmpdir("fb_single_four"),
                    part = tmpdir("fb_single_part");
  const std::string args =
      " --set fluid.precision=single --set fluid.faces.z_lo.ramp_start=0.0"
      " --set output.interval=0.001";
  REQUIRE(cli("run fluidized_bed --threads 1 --set run.end_time=0.002 --out " + full + args).code ==
          0);
  REQUIRE(cli("run fluidized_bed --threads 4 --set run.end_time=0.002 --out " + four + args).code ==
          0);
  REQUIRE(cli("run fluidized_bed --threads 4 --set run.end_time=0.001 --out " + part + args).code ==
          0);
  REQUIRE(cli("run --resume " + part + " --threads 2 --set run.end_time=0.002").code == 0);
  CHECK(lbdem::H5In(full + "/checkpoint.h5").attr_string("precision", "/fluid") == "single");
  CHECK(lbdem::H5In(part + "/checkpoint.h5").attr_string("precision", "/fluid") == "single");
  lbdem::test::check_same_runs(full, four,
                               {"/fluid/populations", "/dem/x", "/dem/v", "/dem/external"});
  lbdem::test::check_same_runs(full, part,
                               {"/fluid/populations", "/dem/x", "/dem/v", "/dem/external"});
  // Not a trivial agreement: the gas moved and the particles felt it.
  const auto external = lbdem::H5In(full + "/checkpoint.h5").doubles("/dem/external");
  double largest = 0;
  for (double f : external) largest = std::max(largest, std::abs(f));
  CHECK(largest > 0);
  std::filesystem::remove_all(full);
  std::filesystem::remove_all(four);
  std::filesystem::remove_all(part);
}

TEST_CASE("a coupled bed stopped by a signal resumes to the uninterrupted run",
          "[scenarios][fluidized_bed][checkpoint][slow]") {
  // A stop lands anywhere in an exchange interval (20 DEM steps here); the run steps on to the
  // interval's end before it writes the checkpoint, so that the resumed run equals one that never
  // stopped (a checkpoint inside an interval could not resume: the gas had run ahead). The signal
  // comes after 2 s of a run of about 4 s on 1 thread.
  const std::string full = tmpdir("fb_sig_full"), part = tmpdir("fb_sig_part");
  const std::string args =
      " --threads 1 --set run.end_time=0.03 --set output.checkpoint_interval=0.03"
      " --set fluid.faces.z_lo.ramp_start=0.0";
  REQUIRE(cli("run fluidized_bed --out " + full + args).code == 0);
  const std::string cmd = std::string(LBDEM_CLI) + " run fluidized_bed --out " + part + args +
                          " --no-plots > /dev/null 2>&1 & pid=$!; sleep 2; kill -TERM $pid; "
                          "wait $pid; exit $?";
  const int rc = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(rc));
  REQUIRE(WEXITSTATUS(rc) == 130);
  REQUIRE(cli("run --resume " + part + " --threads 1").code == 0);
  lbdem::test::check_same_runs(full, part,
                               {"/fluid/populations", "/dem/x", "/dem/v", "/dem/external"});
  std::filesystem::remove_all(full);
  std::filesystem::remove_all(part);
}
