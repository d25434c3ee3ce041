#include "scenarios/jet_mill/jet_mill_geometry.hpp"
#include "scenarios/jet_mill/nozzle_flow.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "lbm/geometry/cylinder.hpp"
#include "lbm/geometry/lattice_frame.hpp"
#include "lbm/geometry/mesh_voxelizer.hpp"
#include "scenarios/jet_mill/chamber_stl.hpp"
#include "scenarios/common/fluid_config.hpp"

namespace lbdem::scenarios {

namespace {
constexpr int kSamples = 4;  // per cell and axis, for the source weights

double start_offset(const Nozzle& q, const Vec3& axis, double dx) {
  // Far enough along the axis that the whole source disc clears the wall by 1.5 cells: the disc's
  // edge nearest the wall lies s sin(a) - r_s cos(a) from it, a the angle to the tangent (for a
  // flat wall; the chamber's curves towards the jet by t^2 / 2R over a tangential run t, about a
  // tenth of a cell here).
  Vec3 radial = q.exit - axis;
  radial.z() = 0;
  const double sin_a = std::abs(q.dir.dot(radial.normalized()));
  const double cos_a = std::sqrt(std::max(0.0, 1 - sin_a * sin_a));
  return (q.source_radius * cos_a + 1.5 * dx) / std::max(sin_a, 1e-3);
}

// A nozzle on the chamber wall at `at_deg` (counter-clockwise from +x) from its config section:
// angle to the wall tangent, axis height, diameter, and the jet from a supply pressure
// (nozzle_flow.hpp: a choked nozzle's mass flow and the speed that carries its momentum flux) or
// given as exit speed and mass flow.
Nozzle read_nozzle(const Config& n, const JetMillGeometry& g, const FluidConfig& f, double at_deg,
                   double source_default) {
  const double angle =
      n.get("angle_deg", 40.0,
            Range::closed(5, 90, "give the angle to the wall tangent in degrees, 5 - 90"));
  const double z = n.get("height", 0.5 * g.height,
                         Range::closed(0, g.height, "give the axis height above the floor in m"));
  const double d = n.require("diameter", Range::positive("give the nozzle diameter in m"));
  if (d >= g.height)
    throw InputError(n.path("diameter"), to_text(d), "the nozzle is as tall as the chamber",
                     "give a diameter below the chamber height " + to_text(g.height) + " m");
  double u = 0, mdot = 0, p0 = 0;
  if (!n.has("supply_pressure"))
    for (const char* key : {"ambient_pressure", "supply_temperature"})
      if (n.has(key))
        throw InputError(n.path(key), "", "it belongs to a nozzle fed from a supply pressure",
                         "give " + n.path("supply_pressure") +
                             " (in place of speed and mass_flow), or remove " + std::string(key));
  if (n.has("supply_pressure")) {
    for (const char* key : {"speed", "mass_flow"})
      if (n.has(key))
        throw InputError(n.path(key), "given with supply_pressure",
                         "the supply pressure sets the jet's speed and mass flow",
                         "give either supply_pressure or speed (and mass_flow), not both");
    const double pa = n.get("ambient_pressure", 101325.0,
                            Range::positive("give the chamber's absolute pressure in Pa"));
    p0 = n.require("supply_pressure",
                   Range{pa, Range::kInf, true, false,
                         "give the absolute supply pressure in Pa, above ambient_pressure"});
    const double t0 = n.get("supply_temperature", 293.15,
                            Range::closed(150, 1000, "give the supply temperature in K"));
    const NozzleFlow nf = nozzle_flow(p0, t0, pa, kPi * d * d / 4);
    u = nf.speed;
    mdot = nf.mass_flow;
  } else {
    u = n.require("speed", Range::positive("give the jet exit speed in m/s"));
    mdot = n.get("mass_flow", f.density * u * kPi * d * d / 4,
                 Range::positive("give the mass flow per nozzle in kg/s"));
  }
  const double th = at_deg * kPi / 180.0;
  const Vec3 radial(std::cos(th), std::sin(th), 0.0);
  const Vec3 tangent(-std::sin(th), std::cos(th), 0.0);  // counter-clockwise from +z
  Nozzle q;
  q.exit = g.axis + g.radius * radial + z * Vec3::UnitZ();
  q.dir = std::cos(angle * kPi / 180.0) * tangent - std::sin(angle * kPi / 180.0) * radial;
  q.diameter = d;
  q.speed = u;
  q.mass_flow = mdot;
  q.supply_pressure = p0;
  // The speed the notional source is sized for: by default the one the gas step was set for; a
  // lower one widens the source (the same J at a lower core speed) so that a step set for a
  // faster gas keeps the same jet on every grid.
  const std::string cap_fix = "give the notional source's speed in m/s, at most fluid.max_speed (" +
                              to_text(f.max_speed) + " m/s), which sets the gas step";
  const double u_cap =
      n.get("source_speed", source_default, Range{0, f.max_speed, true, false, cap_fix});
  q.source_radius =
      std::max(0.5 * d, std::sqrt(q.momentum_flux() / (kPi * f.density * u_cap * u_cap)));
  return q;
}

// The notional source must lie in the gas, clear of every wall by 1.5 cells (on the wall's cells
// bounce-back takes a large part of its momentum; jet_mill_geometry.hpp). Errors name the keys of
// the nozzle's section `n`.
void check_source_fits(const Config& n, const Nozzle& q, const JetMillGeometry& g,
                       const FluidConfig& f, const Config& section) {
  const double rs = q.source_radius, clear = 1.5 * f.dx;
  const double z = q.exit.z() - g.axis.z();
  if (2 * (rs + clear) > g.height)  // no height fits: the source is too wide for the chamber
    throw InputError(n.has("supply_pressure") ? n.path("supply_pressure") : n.path("speed"),
                     n.has("supply_pressure") ? to_text(q.supply_pressure) : to_text(q.speed),
                     std::string(q.feed ? "the feed's" : "the jets'") +
                         " notional source (radius " + to_text(rs) +
                         " m) does not fit the chamber height " + to_text(g.height) +
                         " m with 1.5 cells to floor and roof",
                     "lower the speed, pressure or diameter, or raise fluid.max_speed (now " +
                         to_text(f.max_speed) +
                         " m/s; it sets the gas step) so that the source may be narrower");
  if (z < rs + clear || z > g.height - rs - clear)
    throw InputError(
        n.path("height"), to_text(z),
        std::string(q.feed ? "the feed's" : "the jets'") + " notional source (radius " +
            to_text(rs) + " m) comes within 1.5 cells of the floor or roof",
        "give a height in [" + to_text(rs + clear) + ", " + to_text(g.height - rs - clear) +
            "] m, a smaller diameter, or a finer fluid.dx");
  Vec3 radial = q.exit - g.axis;
  radial.z() = 0;
  const double sin_a = std::abs(q.dir.dot(radial.normalized()));
  const double chord = 2 * g.radius * sin_a;
  if (start_offset(q, g.axis, f.dx) + 2 * rs > chord - clear)
    throw InputError(n.path("angle_deg"), to_text(n.get("angle_deg", 40.0)),
                     std::string(q.feed ? "the feed's" : "the jets'") +
                         " notional source does not fit on the chord the jet crosses (" +
                         to_text(chord) + " m)",
                     "give a larger angle to the wall tangent, a smaller diameter, or a finer "
                     "fluid.dx");
  if (g.classifier_height > 0) {
    // The sources must clear the ring as they clear the other walls (1.5 cells), where the ring
    // reaches down to the sources' height: sampled along the source's axis.
    const double r_in = g.classifier_radius - 0.5 * g.classifier_thickness;
    const double r_out = g.classifier_radius + 0.5 * g.classifier_thickness;
    const double s0 = start_offset(q, g.axis, f.dx);
    const bool reaches = z + rs + clear > g.height - g.classifier_height;
    for (int k = 0; k <= 16 && reaches; ++k) {
      const Vec3 p = q.exit + (s0 + 2 * rs * k / 16.0) * q.dir;
      const double r = std::hypot(p.x() - g.axis.x(), p.y() - g.axis.y());
      if (r > r_in - rs - clear && r < r_out + rs + clear)
        throw InputError(section.section("classifier").path("radius"), to_text(g.classifier_radius),
                         std::string(q.feed ? "the feed's" : "the jets'") +
                             " notional source comes within 1.5 cells of the classifier ring",
                         "move the ring inwards, shorten it (classifier.height) or lower the "
                         "nozzles");
    }
  }
}
}  // namespace

bool JetMillGeometry::in_classifier(const Vec3& x) const {
  if (classifier_height <= 0) return false;
  const double r = std::hypot(x.x() - axis.x(), x.y() - axis.y());
  return std::abs(r - classifier_radius) <= 0.5 * classifier_thickness &&
         x.z() >= axis.z() + height - classifier_height;
}

bool JetMillGeometry::inside(const Vec3& x) const {
  const double dx = x.x() - axis.x(), dy = x.y() - axis.y();
  return dx * dx + dy * dy <= radius * radius && !in_classifier(x);
}

JetMillGeometry read_jet_mill(const Config& section, const FluidConfig& f) {
  JetMillGeometry g;
  const Vec3 hi = f.lo + f.dx * Vec3(f.cells[0], f.cells[1], f.cells[2]);
  const double wx = hi.x() - f.lo.x(), wy = hi.y() - f.lo.y();
  if (std::abs(wx - wy) > 0.5 * f.dx)
    throw InputError("box.hi", "[" + to_text(hi.x()) + ", " + to_text(hi.y()) + ", ...]",
                     "the jet mill's box is the chamber's bounding box, square in x and y",
                     "give box.lo = [-R, -R, 0] and box.hi = [R, R, H]");
  g.radius = 0.5 * wx;
  g.height = hi.z() - f.lo.z();
  g.axis = Vec3(0.5 * (f.lo.x() + hi.x()), 0.5 * (f.lo.y() + hi.y()), f.lo.z());
  g.outlet_radius = section.get("outlet_radius", 0.2 * g.radius,
                                Range::closed(f.dx, 0.9 * g.radius,
                                              "give the vortex finder's radius in m, at least "
                                              "one cell and below the chamber radius"));
  read_chamber_stl(section, f, hi, g);
  if (section.has("classifier")) {
    // A ring between the outlet and the grinding zone. At least sqrt(2) cells thick: the longest
    // D3Q19 link is sqrt(2) dx and the radius changes along it by at most its length, so no link
    // joins gas cells on both sides (a 1-cell ring leaked along the diagonals at 45 degrees).
    // Clear of the outlet's rim by a cell and of the wall by two (a gas cell between two walls
    // would have no meaningful wall normal).
    const Config c = section.section("classifier");
    g.classifier_radius = c.require(
        "radius", Range::closed(g.outlet_radius + f.dx, g.radius - 2 * f.dx,
                                "give the ring's mean radius in m, between the outlet's rim and "
                                "the chamber wall"));
    const double min_t = std::sqrt(2.0) * f.dx;
    g.classifier_thickness = c.get("thickness", 1.5 * f.dx, Range::positive("give the wall in m"));
    if (g.classifier_thickness < min_t * (1 - 1e-9))
      throw InputError(c.path("thickness"), to_text(g.classifier_thickness),
                       "the ring is thinner than sqrt(2) gas cells: diagonal links would cross it",
                       "give a thickness of at least " + to_text(min_t) + " m (sqrt(2) fluid.dx)");
    const double r_in = g.classifier_radius - 0.5 * g.classifier_thickness;
    const double r_out = g.classifier_radius + 0.5 * g.classifier_thickness;
    if (r_in < g.outlet_radius + f.dx || r_out > g.radius - 2 * f.dx)
      throw InputError(c.path("thickness"), to_text(g.classifier_thickness),
                       "the ring (radii " + to_text(r_in) + " - " + to_text(r_out) +
                           " m) comes within a cell of the outlet's rim or two of the wall",
                       "a thinner ring or another radius");
    g.classifier_height = c.require(
        "height", Range::closed(f.dx, g.height - 2 * f.dx,
                                "give how far the ring reaches below the top plate in m, leaving "
                                "at least two cells above the floor"));
  }
  const Config n = section.section("nozzles");
  const int count = int(n.get_int("count", 4, Range::closed(1, 64)));
  const double first = n.get("first_deg", 0.0, Range::closed(-360, 360));
  for (int k = 0; k < count; ++k) {
    const Nozzle q = read_nozzle(n, g, f, first + 360.0 * k / count, f.max_speed);
    g.nozzles.push_back(q);
    if (k == 0) check_source_fits(n, q, g, f, section);
  }
  if (section.has("feed")) {
    // The feed injector's gas: one more nozzle on the wall, its own position, angle and flow.
    const Config c = section.section("feed");
    const double at = c.get("position_deg", first + 180.0 / count,
                            Range::closed(-360, 360,
                                          "give where on the wall the feed enters, in degrees "
                                          "counter-clockwise from +x"));
    // The feed's source is sized as the grinding nozzles' unless it says otherwise.
    Nozzle q = read_nozzle(c, g, f, at, n.get("source_speed", f.max_speed));
    q.feed = true;
    check_source_fits(c, q, g, f, section);
    g.nozzles.push_back(q);
  }
  return g;
}

int build_chamber(lbm::LbmSolver& gas, const FluidConfig& f, const JetMillGeometry& g) {
  const lbm::LatticeFrame frame{f.lo, f.dx};
  const int chamber = gas.add_body("chamber");
  if (g.meshed()) {
    lbm::mark_mesh(gas, frame, g.chamber_mesh, lbm::SolidSide::outside, chamber, g.chamber_key);
  } else {
    lbm::Cylinder wall;
    wall.axis_point = g.axis;
    wall.radius = g.radius;
    lbm::mark_cylinder(gas, frame, wall, lbm::SolidSide::outside, chamber);
  }
  // The classifier ring: cells whose centre lies in its solid belong to the chamber's body (the
  // same wall treatment, wall function included).
  const lbm::Grid& cells = gas.grid();
  if (g.classifier_height > 0)
    for (int z = 0; z < cells.nz(); ++z)
      for (int y = 0; y < cells.ny(); ++y)
        for (int x = 0; x < cells.nx(); ++x)
          if (g.in_classifier(f.cell_centre(x, y, z))) gas.set_cell(x, y, z, chamber);
  if (f.wall_function) gas.set_wall_function(chamber, true);
  // The vortex finder: the top plate's ghost cells over r < outlet_radius, at the reference
  // pressure (density 1: the gauge pressure of the outlet is zero).
  const int outlet = gas.add_outlet("outlet", 1.0);
  // The vortex crosses the outlet at several times the through-flow speed: the half-way velocity
  // is the cell's (lbm/boundary/open_boundary.hpp), the extrapolated one diverged at 16 ms.
  gas.set_outlet_extrapolation(outlet, false);
  // The vortex's low-pressure core draws gas in through a fixed-pressure outlet, and the inflow
  // feeds the core: shut, as a real vortex finder's swirl would not let it in (open_boundary.hpp).
  gas.set_outlet_backflow(outlet, false);
  const lbm::Grid& grid = gas.grid();
  const int top = grid.nz();
  for (int y = -1; y <= grid.ny(); ++y)
    for (int x = -1; x <= grid.nx(); ++x) {
      const Vec3 c = f.cell_centre(x, y, top);
      const double rx = c.x() - g.axis.x(), ry = c.y() - g.axis.y();
      if (rx * rx + ry * ry < g.outlet_radius * g.outlet_radius) gas.set_cell(x, y, top, outlet);
    }
  // The gas must reach the vortex finder (a chamber STL may close it).
  bool open = false;
  for (int y = 0; y < grid.ny() && !open; ++y)
    for (int x = 0; x < grid.nx() && !open; ++x) {
      const Vec3 c = f.cell_centre(x, y, top - 1);
      const double rx = c.x() - g.axis.x(), ry = c.y() - g.axis.y();
      open = rx * rx + ry * ry < g.outlet_radius * g.outlet_radius &&
             gas.flags().fluid(grid.index(x, y, top - 1));
    }
  if (!open)
    throw InputError(g.meshed() ? g.chamber_key : "jet_mill.outlet_radius",
                     g.meshed() ? "the chamber's STL" : to_text(g.outlet_radius),
                     "no gas cell lies under the vortex finder (radius " +
                         to_text(g.outlet_radius) + " m at the top plate's centre)",
                     "open the chamber to the roof over the outlet, or widen "
                     "jet_mill.outlet_radius");
  return outlet;
}

JetSources jet_sources(const lbm::LbmSolver& gas, const FluidConfig& f, const JetMillGeometry& g) {
  const lbm::Grid& grid = gas.grid();
  const lbm::LatticeUnits units = f.units();
  JetSources out;
  out.force.assign(std::size_t(grid.nx()) * grid.ny() * grid.nz(), Vec3::Zero());
  const double cell_volume = f.dx * f.dx * f.dx;
  for (std::size_t k = 0; k < g.nozzles.size(); ++k) {
    const Nozzle& q = g.nozzles[k];
    const double rs = q.source_radius, len = 2 * rs;
    const double s0 = start_offset(q, g.axis, f.dx);
    // Cells whose box meets the source's bounding box.
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      const double b0 = q.exit[a] + s0 * q.dir[a], b1 = b0 + len * q.dir[a];
      const double a0 = std::min(b0, b1) - rs, a1 = std::max(b0, b1) + rs;
      lo[a] = std::max(0, int(std::floor((a0 - f.lo[a]) / f.dx)));
      hi[a] = std::min(f.cells[std::size_t(a)] - 1, int(std::floor((a1 - f.lo[a]) / f.dx)));
    }
    struct Weighted {
      int x, y, z;
      double w;
    };
    std::vector<Weighted> cells;
    double total = 0;
    long samples_all = 0, samples_gas = 0;
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const bool fluid = gas.flags().fluid(grid.index(x, y, z));
          int in = 0;
          for (int sz = 0; sz < kSamples; ++sz)
            for (int sy = 0; sy < kSamples; ++sy)
              for (int sx = 0; sx < kSamples; ++sx) {
                const Vec3 p =
                    f.lo + f.dx * Vec3(x + (sx + 0.5) / kSamples, y + (sy + 0.5) / kSamples,
                                       z + (sz + 0.5) / kSamples);
                const Vec3 r = p - q.exit;
                const double s = r.dot(q.dir);
                if (s < s0 || s > s0 + len || (r - s * q.dir).squaredNorm() > rs * rs) continue;
                ++samples_all;
                // In an STL chamber the gas cells are the chamber; the cylinder is nominal.
                if (fluid && (g.meshed() ? !g.in_classifier(p) : g.inside(p))) ++in;
              }
          samples_gas += in;
          if (in == 0) continue;
          const double w = double(in) / (kSamples * kSamples * kSamples);
          cells.push_back({x, y, z, w});
          total += w;
        }
    out.gas_fraction.push_back(double(samples_gas) / double(std::max(samples_all, 1L)));
    if (g.meshed()) check_source_in_stl(gas, f, g, k, s0);
    if (total <= 0)
      throw InputError(q.feed ? "jet_mill.feed" : "jet_mill.nozzles",
                       q.feed ? "the feed" : "nozzle " + std::to_string(k + 1),
                       "its notional source holds no fluid cell",
                       q.feed ? "refine fluid.dx or move the feed (jet_mill.feed.height)"
                              : "refine fluid.dx or move the nozzle (jet_mill.nozzles.height)");
    const double mass_per_step = q.mass_flow * f.dt / (f.density * cell_volume);  // lattice
    const Vec3 force_si = q.momentum_flux() * q.dir / cell_volume;                // N/m^3 per w
    for (const Weighted& c : cells) {
      const double share = c.w / total;
      out.mass.push_back({c.x, c.y, c.z, mass_per_step * share});
      Vec3& fc = out.force[std::size_t(grid.compact_index(c.x, c.y, c.z))];
      for (int a = 0; a < 3; ++a) fc[a] += units.force_density_to_lattice(force_si[a] * share);
    }
    out.cells_per_nozzle.push_back(int(cells.size()));
  }
  return out;
}

}  // namespace lbdem::scenarios
