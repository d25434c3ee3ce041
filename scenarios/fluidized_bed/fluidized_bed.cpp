#include "scenarios/fluidized_bed/fluidized_bed.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace lbdem::scenarios {

FluidizedBedScenario::FluidizedBedScenario(const Config& cfg) : box_(cfg) {
  const FluidConfig& f = box_.fluid();
  if (!box_.gas() || !box_.coupler())
    throw InputError(box_.gas() ? "coupling" : "fluid", "", "a fluidized bed needs a coupled gas",
                     "add the [fluid] and [coupling] tables (see the fluidized_bed presets)");
  if (f.faces[4].kind != "inlet")
    throw InputError("fluid.faces.z_lo", "\"" + f.faces[4].kind + "\"",
                     "the gas enters a fluidized bed through the bottom face",
                     "set fluid.faces.z_lo = {kind = \"inlet\", velocity = [0, 0, U]}");
  if (f.faces[5].kind != "outlet")
    throw InputError("fluid.faces.z_hi", "\"" + f.faces[5].kind + "\"",
                     "the gas leaves a fluidized bed through the top face",
                     "set fluid.faces.z_hi = {kind = \"outlet\", pressure = 0.0}");
  u_in_ = f.faces[4].velocity.z();
  const Config bed = cfg.section("bed");
  const double z_lo = f.lo.z(), z_hi = f.hi().z();
  fraction_ = bed.get("height_fraction", 0.95,
                      {0, 1, true, false, "give the particle volume fraction, e.g. 0.95"});
  // Default: the distributor and the outlet, so that the drop carries all of the bed's weight
  // (the kernel spreads the lowest particles' forces into the first cells). A tap at or beyond a
  // gas face reads that face (plane_pressure), so the particles' floor and roof are taps too where
  // the gas grid is shorter than the box (fluid_config.cpp centres it on the box).
  const std::vector<double> def = {z_lo, z_hi};
  std::vector<double> taps = bed.get_list("pressure_taps", def);
  const double lowest = std::min(z_lo, f.box_lo.z()), highest = std::max(z_hi, f.box_hi.z());
  if (taps.size() != 2 || !(taps[0] < taps[1]) || taps[0] < lowest || taps[1] > highest)
    throw InputError(
        bed.path("pressure_taps"), list_text(taps), "two heights inside the column, lower first",
        "give [z_low, z_high] in m within [" + to_text(lowest) + ", " + to_text(highest) + "]");
  taps_ = {taps[0], taps[1]};
  const auto mats = cfg.table_array("materials");
  hamaker_original_ = mats.empty() ? 0.0 : mats.front().get("hamaker", 0.0);
  h_min_ = box_.solver().settings().contact.h_min;

  box_.extend(this);
}

void FluidizedBedScenario::banner(Log& log) const {
  box_.banner(log);
  bed_banner(log);
}

std::vector<std::string> FluidizedBedScenario::row_columns() const {
  return {"bed_height_m", "pressure_drop_Pa", "bed_voidage"};
}

void FluidizedBedScenario::on_row(const run::Instant& /*now*/, std::vector<double>& row) const {
  const double h = bed_height();
  row.insert(row.end(), {h, pressure_drop(), bed_voidage(h)});
}

double FluidizedBedScenario::bed_height() const {
  const auto& p = box_.solver().particles();
  const std::size_t n = p.size();
  if (n == 0) return 0;
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  // Sorted by height, ties by id: the same answer whatever order the particles are stored in.
  std::sort(order.begin(), order.end(), [&](auto a, auto b) {
    return p.x[a].z() != p.x[b].z() ? p.x[a].z() < p.x[b].z() : p.id[a] < p.id[b];
  });
  double total = 0;
  for (std::size_t k = 0; k < n; ++k) total += p.radius[k] * p.radius[k] * p.radius[k];
  double sum = 0;
  for (const auto k : order) {
    sum += p.radius[k] * p.radius[k] * p.radius[k];
    if (sum >= fraction_ * total) return p.x[k].z() - box_.fluid().box_lo.z();
  }
  return p.x[order.back()].z() - box_.fluid().box_lo.z();
}

double FluidizedBedScenario::plane_pressure(double z, const std::vector<double>& p) const {
  const FluidConfig& f = box_.fluid();
  // At the distributor or the outlet: the gas's push on that face (its momentum-exchange force)
  // per area, what a tap in the plate reads, rather than an extrapolation of the cell planes over
  // the half cell next to it, where the bed's lowest forces sit. That push is the absolute
  // lattice pressure rho c_s^2 (plus the momentum flux rho u^2 through an inlet or outlet, about
  // 1 Pa at 1 m/s), so the reference rho_ref c_s^2 is taken off, as the cell planes' gauge
  // pressure (rho - rho_ref) c_s^2 has it: a tap inside the gas and one at a face then read on
  // one scale (with one of each the drop was off by rho_ref c_s^2, tens of kPa).
  // The gas's cross-section: the pressure acts over the grid, whose walls may lie up to dx/4
  // outside or inside the particles' (fluid_config.cpp).
  const double z_hi = f.hi().z();
  const double area = f.cells[0] * f.dx * f.cells[1] * f.dx;
  if (z <= f.lo.z() || z >= z_hi) {
    const lbm::LbmSolver& gas = *box_.gas();
    // Over the last two steps: one step carries half of the period-2 oscillation of a gas near
    // tau = 1/2 (lbm/lbm_solver.hpp, wall_force_mean2).
    const double fz =
        f.units().force_to_si(gas.wall_force_mean2(gas.face_body(z <= f.lo.z() ? 4 : 5)).z());
    return (z <= f.lo.z() ? -fz : fz) / area - f.units().pressure_to_si(lbm::kCs2);
  }
  // Linear between the cell-centre planes, extrapolated over the half cell next to a face.
  const double s = (z - f.lo.z()) / f.dx - 0.5;  // cell-centre coordinate
  const int k0 = std::clamp(int(std::floor(s)), 0, f.cells[2] - 2);
  const double w = s - k0;
  const auto plane = [&](int k) {
    double sum = 0, cells = 0;
    const auto& g = box_.gas()->grid();
    const auto& flags = box_.gas()->flags();
    for (int y = 0; y < f.cells[1]; ++y)
      for (int x = 0; x < f.cells[0]; ++x)
        if (flags.at(x, y, k) == lbm::kFluid)
          sum += p[std::size_t(g.compact_index(x, y, k))], cells += 1;
    return cells > 0 ? sum / cells : 0.0;
  };
  return (1 - w) * plane(k0) + w * plane(k0 + 1);
}

double FluidizedBedScenario::bed_voidage(double height) const {
  const FluidConfig& f = box_.fluid();
  const auto& eps = box_.coupler()->eps();
  const auto& g = box_.gas()->grid();
  const auto& flags = box_.gas()->flags();
  // Cell planes whose centres lie below the bed height (above the particles' floor) less two
  // kernel widths (the smeared top).
  const double top = f.box_lo.z() + height - 2 * box_.coupler()->settings().kernel_width;
  double sum = 0, cells = 0;
  for (int z = 0; z < f.cells[2] && f.lo.z() + (z + 0.5) * f.dx < top; ++z)
    for (int y = 0; y < f.cells[1]; ++y)
      for (int x = 0; x < f.cells[0]; ++x)
        if (flags.at(x, y, z) == lbm::kFluid)
          sum += eps[std::size_t(g.compact_index(x, y, z))], cells += 1;
  return cells > 0 ? sum / cells : 1.0;
}

double FluidizedBedScenario::pressure_drop() const {
  std::vector<double> p;
  box_.coupler()->pressure(p);
  return plane_pressure(taps_[0], p) - plane_pressure(taps_[1], p);
}

void FluidizedBedScenario::bed_banner(Log& log) const {
  const FluidConfig& f = box_.fluid();
  const BoxScenario& box = box_;
  const auto& p = box.solver().particles();
  const auto& mats = box.solver().materials();
  const Vec3 g = box.solver().settings().gravity;
  // The gas's cross-section carries the bed's weight; the particles' holds the bed.
  const double area = f.cells[0] * f.dx * f.cells[1] * f.dx;
  const Vec3 edge = f.box_hi - f.box_lo;
  double mass = 0, vol = 0, d_parcel = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    mass += p.mass[k];
    vol += 4.0 / 3.0 * kPi * std::pow(p.radius[k], 3);
    d_parcel = std::max(d_parcel, 2 * p.radius[k]);
  }
  const double rho_p = mats.front().density, rho_f = f.density, mu = f.viscosity;
  const double l = box.coupler()->settings().size_factor, d_o = d_parcel / l;
  log.line("fluidized bed derived numbers:");
  log.derived("bed weight per area, less buoyancy", mass * g.norm() * (1 - rho_f / rho_p) / area,
              "Pa", "(the fluidized pressure drop)");
  // Wen & Yu (1966): Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7; Ergun at eps_mf = 0.4:
  // 150 (1-e)/e^3 Re + 1.75/e^3 Re^2 = Ar.
  const double ar = rho_f * (rho_p - rho_f) * g.norm() * d_o * d_o * d_o / (mu * mu);
  const double re_wy = std::sqrt(33.7 * 33.7 + 0.0408 * ar) - 33.7;
  const double e = 0.4, a = 1.75 / (e * e * e), b = 150 * (1 - e) / (e * e * e);
  const double re_er = (-b + std::sqrt(b * b + 4 * a * ar)) / (2 * a);
  const double umf = re_wy * mu / (rho_f * d_o);
  log.derived("U_mf (Wen-Yu)", umf, "m/s",
              "(Ergun at eps_mf = 0.4: " + to_text(re_er * mu / (rho_f * d_o)) + " m/s)");
  log.derived("inflow U / U_mf", u_in_ / umf, "",
              "(U = " + to_text(u_in_) + " m/s, from " + to_text(f.faces[4].ramp_from.norm()) +
                  " m/s at t = " + to_text(f.faces[4].ramp_start) + " s over " +
                  to_text(f.faces[4].ramp_time) + " s)");
  const double h_static = vol / (0.6 * edge.x() * edge.y());
  log.derived("static bed height at solid fraction 0.6", h_static, "m",
              "(" + to_text(h_static / d_parcel) + " parcels high)");
  log.derived("parcels across the bed", edge.x() / d_parcel, "",
              "x " + to_text(edge.y() / d_parcel) + " (width / parcel diameter)");
  if (hamaker_original_ > 0) {
    // Bond number F_vdW(h_min) / (m g), equal spheres: F = A d / (24 h_min^2) (docs/physics.md, Van
    // der Waals cohesion).
    const double m_o = rho_p * kPi * d_o * d_o * d_o / 6;
    const double bo = hamaker_original_ * d_o / (24 * h_min_ * h_min_) / (m_o * g.norm());
    const double m_p = rho_p * kPi * d_parcel * d_parcel * d_parcel / 6;
    const double bo_p = mats.front().hamaker * d_parcel / (24 * h_min_ * h_min_) / (m_p * g.norm());
    log.derived("Bond number of an original", bo, "",
                "(A = " + to_text(hamaker_original_) + " J, h_min = " + to_text(h_min_) + " m)");
    log.derived("Bond number of a parcel", bo_p, "", "(its cohesion over its own weight)");
  }
  log.derived("pressure taps", taps_[0], "m", "and " + to_text(taps_[1]) + " m");
  log.derived("bed height definition", fraction_, "", "(of the particle volume lies below)");
}

}  // namespace lbdem::scenarios
