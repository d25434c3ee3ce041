#include "tools/src/mill_map_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/config.hpp"
#include "core/h5.hpp"
#include "tools/src/window_stats.hpp"

namespace lbdem::tools {

namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

// Snapshot times come from step counts times a step that is itself a rounded quotient: a snapshot
// meant for 0.13 s can sit at 0.1300000000001 s. Window edges are compared with this slack, far
// below any snapshot interval.
constexpr double kTimeSlack = 1e-9;  // [s]

// Indices of the snapshot times in [from, to]; and the last one at or before `to`.
std::vector<std::size_t> in_window(const std::vector<double>& t, double from, double to) {
  std::vector<std::size_t> k;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= from - kTimeSlack && t[i] <= to + kTimeSlack) k.push_back(i);
  return k;
}

std::size_t last_before(const std::vector<double>& t, double to, const std::string& what) {
  std::size_t k = t.size();
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] <= to + kTimeSlack) k = i;
  if (k == t.size()) throw ToolError("no " + what + " snapshot at or before " + num(to) + " s");
  return k;
}

std::string snapshot(const std::string& dir, const char* kind, std::size_t k) {
  char name[64];
  std::snprintf(name, sizeof name, "/snapshots/%s_%06zu.h5", kind, k);
  return dir + name;
}

}  // namespace

std::string write_mill_maps(const MillMapOptions& o) {
  const std::string& dir = o.dir;
  const std::string& prefix = o.prefix;
  const double from = o.from, to = o.to, bin = o.bin, wall_bin = o.wall_bin;
  if (!(bin > 0) || !(wall_bin > 0))
    throw ToolError("--bin and --wall-bin must be positive lengths in m");
  if (!(from < to)) throw ToolError("empty window: --from " + num(from) + " --to " + num(to));
  const RunFolder run = RunFolder::open(dir);
  const lbdem::Config cfg = lbdem::Config::from_string(run.config_text, dir + "/config.toml");
  const auto lo = cfg.section("box").get_list("lo", {}), hi = cfg.section("box").get_list("hi", {});
  if (lo.size() != 3 || hi.size() != 3) throw ToolError(dir + "/config.toml has no box.lo/hi");
  const MillAxis axis{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (hi[0] - lo[0])};
  const std::vector<JetRegion>& regions = o.jets;

  // Particles: every sample of the window's snapshots (none in a run without particles).
  const std::string pmaster = dir + "/particles.h5";
  const bool particles = fs::is_regular_file(pmaster);
  if (!particles && !fs::is_regular_file(dir + "/fluid.h5"))
    throw ToolError("no " + pmaster + " and no fluid.h5 in " + dir);
  std::vector<double> ptimes;
  std::vector<std::size_t> window;
  double all = 0, all_n = 0, jet = 0, jet_n = 0;
  std::string csv;
  if (particles) {
    ptimes = lbdem::H5In(pmaster).doubles("/time_s");
    window = in_window(ptimes, from, to);
    if (window.empty())
      throw ToolError("no particle snapshot in [" + num(from) + ", " + num(to) + "] s of " + dir +
                      " (set output.snapshot_interval)");
    const std::size_t n = std::size_t(std::ceil(2 * axis.radius / bin));
    Bins2D map(axis.cx - axis.radius, axis.cy - axis.radius, bin, n);
    Bins1D wall(0.0, wall_bin, std::size_t(std::ceil(axis.radius / wall_bin)));
    for (std::size_t k : window) {
      const lbdem::H5In s(snapshot(dir, "particles", k));
      const auto x = s.vec3s("/position_m"), v = s.vec3s("/velocity_m_per_s");
      for (std::size_t p = 0; p < x.size(); ++p) {
        const double speed = v[p].norm();
        map.add(x[p].x(), x[p].y(), speed);
        wall.add(axis.wall_distance(x[p]), speed);
        all += speed, all_n += 1;
        if (std::any_of(regions.begin(), regions.end(),
                        [&](const JetRegion& j) { return j.contains(x[p]); }))
          jet += speed, jet_n += 1;
      }
    }
    csv = "x_m,y_m,mean_speed_m_per_s,samples\n";
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i)
        if (map.samples(i, j) > 0)
          csv += num(map.x(i)) + "," + num(map.y(j)) + "," + num(map.mean(i, j)) + "," +
                 num(map.samples(i, j)) + "\n";
    lbdem::write_file_atomic(prefix + "_speed_map.csv", csv);
    csv = "wall_distance_m,mean_speed_m_per_s,samples\n";
    for (std::size_t k = 0; k < wall.size(); ++k)
      if (wall.samples(k) > 0)
        csv += num(wall.centre(k)) + "," + num(wall.mean(k)) + "," + num(wall.samples(k)) + "\n";
    lbdem::write_file_atomic(prefix + "_wall_profile.csv", csv);
    {
      const std::size_t k = last_before(ptimes, to, "particle");
      const lbdem::H5In s(snapshot(dir, "particles", k));
      const auto x = s.vec3s("/position_m"), v = s.vec3s("/velocity_m_per_s");
      const auto r = s.doubles("/radius_m");
      csv = "x_m,y_m,z_m,radius_m,speed_m_per_s\n";
      for (std::size_t p = 0; p < x.size(); ++p)
        csv += num(x[p].x()) + "," + num(x[p].y()) + "," + num(x[p].z()) + "," + num(r[p]) + "," +
               num(v[p].norm()) + "\n";
      lbdem::write_file_atomic(prefix + "_positions.csv", csv);
    }
  }

  // Gas: the last snapshot of the window.
  double gas_t = kNaN;
  const std::string gmaster = dir + "/fluid.h5";
  if (fs::is_regular_file(gmaster)) {
    const lbdem::H5In g(gmaster);
    const auto gt = g.doubles("/time_s");
    const std::size_t k = last_before(gt, to, "gas");
    gas_t = gt[k];
    const auto o = g.doubles("/grid/origin_m");
    const double dx = g.doubles("/grid/spacing_m").at(0);
    const auto c = g.int32s("/grid/cells");
    const std::array<int, 3> cells = {c.at(0), c.at(1), c.at(2)};
    const lbdem::H5In s(snapshot(dir, "fluid", k));
    const auto u = s.doubles("/velocity_m_per_s"), eps = s.doubles("/porosity");
    const GasProfile prof =
        gas_profile(u, eps, cells, Vec3(o.at(0), o.at(1), o.at(2)), dx, axis, bin, 0, cells[2]);
    csv = "radius_m,u_theta_m_per_s,u_r_m_per_s,cells\n";
    for (std::size_t i = 0; i < prof.radius.size(); ++i)
      csv += num(prof.radius[i]) + "," + num(prof.u_theta[i]) + "," + num(prof.u_r[i]) + "," +
             num(prof.cells[i]) + "\n";
    lbdem::write_file_atomic(prefix + "_gas_profile.csv", csv);
    const int mid = std::min(cells[2] - 1, cells[2] / 2);  // the layer holding mid-height
    const auto sp = layer_speed(u, eps, cells, mid);
    csv = "x_m,y_m,speed_m_per_s\n";
    for (int y = 0; y < cells[1]; ++y)
      for (int x = 0; x < cells[0]; ++x) {
        const double v = sp[std::size_t(y) * std::size_t(cells[0]) + std::size_t(x)];
        if (std::isfinite(v))
          csv += num(o[0] + x * dx) + "," + num(o[1] + y * dx) + "," + num(v) + "\n";
      }
    lbdem::write_file_atomic(prefix + "_gas_midplane.csv", csv);

    // The gas crossing each cylinder, counted link by link by the run (one gas step before each
    // snapshot), averaged over the window's snapshots; runs before 2026-11-24 lack it.
    std::vector<double> radius;
    std::vector<std::vector<double>> samples;  // per snapshot: the flow through each cylinder
    for (std::size_t i : in_window(gt, from, to)) {
      const lbdem::H5In f(snapshot(dir, "fluid", i));
      if (!f.has("/radial_mass_flow_kg_per_s")) continue;
      samples.push_back(f.doubles("/radial_mass_flow_kg_per_s"));
      if (samples.size() == 1) radius = f.doubles("/radial_mass_flow_radius_m");
      if (samples.back().size() != radius.size())
        throw ToolError("radial mass flow of " + snapshot(dir, "fluid", i) + " changes size");
    }
    if (!samples.empty()) {
      // u_r that carries the flux through the cylinder's whole height at the gas's reference
      // density: the radial velocity of the mass balance. The snapshots are taken as
      // independent samples (2.5 ms apart in the presets).
      const double rho = g.attr_double("pressure_reference_density_kg_m3");
      const double height = hi[2] - lo[2], n = double(samples.size());
      csv = "radius_m,mass_flow_kg_per_s,std_err_kg_per_s,snapshots,u_r_m_per_s\n";
      std::vector<double> column(samples.size());
      for (std::size_t r = 0; r < radius.size(); ++r) {
        for (std::size_t i = 0; i < samples.size(); ++i) column[i] = samples[i][r];
        const Moments m = moments(column);
        const double ur = radius[r] > 0 ? m.mean / (2 * M_PI * radius[r] * height * rho) : kNaN;
        csv += num(radius[r]) + "," + num(m.mean) + "," + num(m.std / std::sqrt(n)) + "," + num(n) +
               "," + num(ur) + "\n";
      }
      lbdem::write_file_atomic(prefix + "_gas_radial_flow.csv", csv);
    }
  }

  csv =
      "run_dir,from_s,to_s,particle_snapshots,samples,mean_speed_m_per_s,jet_samples,"
      "jet_mean_speed_m_per_s,gas_snapshot_s\n";
  const double first = particles ? ptimes[window.front()] : kNaN;
  const double last = particles ? ptimes[window.back()] : kNaN;
  csv += run.dir + "," + num(first) + "," + num(last) + "," + num(double(window.size())) + "," +
         num(all_n) + "," + num(all_n > 0 ? all / all_n : kNaN) + "," + num(jet_n) + "," +
         num(jet_n > 0 ? jet / jet_n : kNaN) + "," + num(gas_t) + "\n";
  lbdem::write_file_atomic(prefix + "_summary.csv", csv);
  char line[512];
  std::snprintf(line, sizeof line,
                "%s: %zu particle snapshots in %s-%s s, mean speed %.4g m/s, in the jets %.4g m/s "
                "(%g samples); gas at %s s\n",
                run.name.c_str(), window.size(), num(first).c_str(), num(last).c_str(),
                all_n > 0 ? all / all_n : kNaN, jet_n > 0 ? jet / jet_n : kNaN, jet_n,
                num(gas_t).c_str());
  return line;
}

}  // namespace lbdem::tools
