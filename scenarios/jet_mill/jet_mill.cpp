#include "scenarios/jet_mill/jet_mill.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "core/error.hpp"
#include "scenarios/jet_mill/chamber_stl.hpp"

namespace lbdem::scenarios {

JetMillScenario::JetMillScenario(const Config& cfg) : box_(cfg) {
  if (!box_.gas())
    throw InputError("fluid", "", "a jet mill needs its gas",
                     "add a [fluid] table (see scenarios/jet_mill/presets/gas.toml)");
  // The chamber's walls are the particles' walls: the DEM gets the cylinder and the top plate with
  // the vortex finder's hole from [jet_mill], the floor from the box's z_lo face. Particles enter
  // through [inflow] (the feed) only, inside the chamber.
  for (const char* key : {"fill", "particle", "walls"})
    if (cfg.has(key))
      throw InputError(
          key, "",
          "the jet mill's particles come from its feed and its walls from "
          "[jet_mill]",
          key == std::string("walls") ? "remove [[walls]]" : "feed the particles through [inflow]");
  const FluidConfig& f = box_.fluid();
  // The chamber (jet_mill_geometry.cpp) is built on the gas grid, its floor the box's z_lo face:
  // a grid centred on edges that are not whole cells would part the two by up to dx/4.
  for (int a = 0; a < 3; ++a)
    if (f.wall_offset(a) != 0) {
      const double l = f.box_hi[a] - f.box_lo[a];
      throw InputError("fluid.dx", to_text(f.dx),
                       "the jet mill's box edge along " + std::string(1, char('x' + a)) + " (" +
                           to_text(l) + " m) is " + to_text(l / f.dx) +
                           " cells; its chamber is built on the gas cells, so every edge must be "
                           "a whole number of them",
                       "choose dx = L/n, e.g. " +
                           to_text(l / std::max(1.0, std::floor(l / f.dx)), 12) + " or " +
                           to_text(l / std::ceil(l / f.dx), 12) + " m");
    }
  static const char* kFaces[6] = {"x_lo", "x_hi", "y_lo", "y_hi", "z_lo", "z_hi"};
  for (int a = 0; a < 6; ++a)
    if (f.faces[std::size_t(a)].kind != "wall")
      throw InputError(std::string("fluid.faces.") + kFaces[a],
                       "\"" + f.faces[std::size_t(a)].kind + "\"",
                       "the jet mill's chamber is closed: the plates are walls, the side is the "
                       "chamber's cylinder, the outlet is cut into the top plate",
                       "leave fluid.faces out (all walls)");
  geometry_ = read_jet_mill(cfg.section("jet_mill"), f);
  const bool particles = cfg.section("inflow").get_bool("enabled", false);
  if (particles) add_chamber_walls(cfg);
  // The chamber and the jets shape the gas; the box then builds the exchange's kernel, which must
  // see the chamber's solid cells.
  box_.shape_gas([&](lbm::LbmSolver& gas) {
    outlet_ = build_chamber(gas, f, geometry_);
    if (particles && geometry_.meshed()) check_feed_in_gas(cfg);
    sources_ = jet_sources(gas, f, geometry_);
    gas.set_mass_sources(sources_.mass);
    gas.enable_force_field();
    gas.set_force_field(sources_.force);
  });
  if (box_.coupler()) box_.coupler()->set_gas_source(sources_.force);
  const lbm::LbmSolver& gas = *box_.gas();
  {
    const lbm::Grid& g = gas.grid();
    ring_level_.assign(std::size_t(g.cells()), 0);
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x) {
          const Vec3 c = f.cell_centre(x, y, z) - geometry_.axis;
          const int k = int(std::hypot(c.x(), c.y()) / f.dx);
          ring_level_[std::size_t(g.compact_index(x, y, z))] = k;
          ring_levels_ = std::max(ring_levels_, k + 1);
        }
  }

  box_.extend(this);
}

std::vector<std::string> JetMillScenario::row_columns() const {
  return {"jet_mass_flow_kg_s",           "outlet_mass_flow_kg_s", "gas_tangential_speed_mid_m_s",
          "gas_radial_speed_mid_m_s",     "gas_max_speed_m_s",     "gas_angular_momentum_z_Nms",
          "gas_radial_mass_flow_mid_kg_s"};
}

void JetMillScenario::on_row(const run::Instant& /*now*/, std::vector<double>& row) const {
  std::vector<Vec3> u;
  std::vector<double> rho;
  box_.gas()->velocity(u);
  box_.gas()->density(rho);
  const auto ring = ring_velocity(u, 0.5 * geometry_.radius);
  double umax = 0;
  for (const Vec3& v : u) umax = std::max(umax, v.norm());
  row.insert(row.end(), {jet_mass_flow(), outlet_mass_flow(), ring[0], ring[1],
                         box_.fluid().units().velocity_to_si(umax), angular_momentum(u, rho),
                         radial_mass_flow()[mid_ring()]});
}

std::vector<run::SnapshotArray> JetMillScenario::snapshot_arrays() const {
  std::vector<double> ring_radius(std::size_t(ring_levels_), 0.0);
  for (int k = 0; k < ring_levels_; ++k) ring_radius[std::size_t(k)] = k * box_.fluid().dx;
  return {{"radial_mass_flow_radius_m", ring_radius},
          {"radial_mass_flow_kg_per_s", radial_mass_flow()}};
}

void JetMillScenario::add_chamber_walls(const Config& cfg) {
  const Config box = cfg.section("box");
  // The box's own DEM faces: the floor only. Planes at the cylinder's bounding box would touch it
  // at four lines and double the contact force there; a top face would close the vortex finder.
  for (const char* face : {"x_lo", "x_hi", "y_lo", "y_hi", "z_hi"}) {
    const std::string kind = box.get_string(face, face == std::string("z_hi") ? "open" : "wall");
    if (kind != "open")
      throw InputError(box.path(face), "\"" + kind + "\"",
                       "the chamber's cylinder and top plate are the particles' walls",
                       "set box." + std::string(face) + " = \"open\"");
  }
  if (box.get_string("z_lo", "wall") != "wall")
    throw InputError(box.path("z_lo"), "\"" + box.get_string("z_lo", "wall") + "\"",
                     "the box's z_lo face is the chamber's floor", "set box.z_lo = \"wall\"");
  // The feed region lies inside the chamber (random fills keep spheres inside their region).
  const Config inflow = cfg.section("inflow");
  const Vec3 lo = inflow.require_vec3("lo"), hi = inflow.require_vec3("hi");
  const JetMillGeometry& g = geometry_;
  // (An STL chamber is checked on the gas's cells once they exist: check_feed_in_gas.)
  for (const Vec3& c : {lo, hi, Vec3(lo.x(), hi.y(), lo.z()), Vec3(hi.x(), lo.y(), hi.z())})
    if ((!g.meshed() && std::hypot(c.x() - g.axis.x(), c.y() - g.axis.y()) > g.radius) ||
        c.z() < g.axis.z() || c.z() > g.axis.z() + g.height)
      throw InputError(
          inflow.path(c == hi ? "hi" : "lo"), vec_text(c),
          "a corner of the feed region lies outside the chamber",
          g.meshed() ? "keep inflow.lo - inflow.hi between the floor and the top plate (0 - " +
                           to_text(g.height) + " m above box.lo)"
                     : "keep inflow.lo - inflow.hi inside the cylinder of radius " +
                           to_text(g.radius) + " m and height " + to_text(g.height) + " m");
  if (g.classifier_height > 0) {
    // The feed region must not reach into the classifier ring: radial range of the region's x-y
    // rectangle against the ring's band, where their heights overlap.
    const double cx = std::clamp(g.axis.x(), lo.x(), hi.x()),
                 cy = std::clamp(g.axis.y(), lo.y(), hi.y());
    const double r_min = std::hypot(cx - g.axis.x(), cy - g.axis.y());
    double r_max = 0;
    for (double x : {lo.x(), hi.x()})
      for (double y : {lo.y(), hi.y()})
        r_max = std::max(r_max, std::hypot(x - g.axis.x(), y - g.axis.y()));
    const double r_in = g.classifier_radius - 0.5 * g.classifier_thickness;
    const double r_out = g.classifier_radius + 0.5 * g.classifier_thickness;
    if (r_max >= r_in && r_min <= r_out && hi.z() >= g.axis.z() + g.height - g.classifier_height)
      throw InputError(inflow.path("lo"), vec_text(lo),
                       "the feed region reaches into the classifier ring (radii " + to_text(r_in) +
                           " - " + to_text(r_out) + " m)",
                       "move inflow.lo - inflow.hi inside or outside the ring, or below it");
  }
  dem::DemSolver& s = box_.solver();
  int material = 0;
  for (const dem::Wall& w : s.walls())
    if (w.name == "z_lo") material = w.material;
  dem::Wall side;
  side.name = "chamber";
  side.material = material;
  if (g.meshed()) {
    // The same facets the gas's cells came from, less those in the plates' planes (the floor is
    // the box's face and the roof the plane with the outlet's hole below: two walls in one plane
    // would double the force). Vertices merged as the STL reader merges them.
    const std::vector<Triangle> facets = g.side_facets();
    Vec3 lo_v = facets.front()[0], hi_v = lo_v;
    for (const Triangle& t : facets)
      for (const Vec3& v : t) lo_v = lo_v.cwiseMin(v), hi_v = hi_v.cwiseMax(v);
    dem::MeshWall m;
    m.mesh = dem::TriangleMesh::from_triangles(facets, 1e-9 * (hi_v - lo_v).norm());
    side.shape = std::move(m);
  } else {
    dem::CylinderWall c;
    c.origin = g.axis;
    c.radius = g.radius;
    c.inside = true;
    side.shape = c;
  }
  side.torque_origin = g.axis;
  box_.add_wall(std::move(side));
  dem::Wall top;
  top.name = "top_plate";
  top.material = material;
  dem::PlaneWall p;
  p.point = g.axis + g.height * Vec3::UnitZ();
  p.normal = -Vec3::UnitZ();
  p.hole_radius = g.outlet_radius;
  p.hole_centre = p.point;
  top.shape = p;
  top.torque_origin = p.point;
  box_.add_wall(std::move(top));
  if (g.classifier_height > 0) {
    // The solid tube, met from inside, outside and below (dem/walls/tube_wall.hpp).
    dem::Wall ring;
    ring.name = "classifier";
    ring.material = material;
    dem::TubeWall tube;
    tube.axis = g.axis;
    tube.r_in = g.classifier_radius - 0.5 * g.classifier_thickness;
    tube.r_out = g.classifier_radius + 0.5 * g.classifier_thickness;
    tube.z_hi = g.axis.z() + g.height;
    tube.z_lo = tube.z_hi - g.classifier_height;
    ring.shape = tube;
    ring.torque_origin = g.axis;
    box_.add_wall(std::move(ring));
  }
}

void JetMillScenario::check_feed_in_gas(const Config& cfg) const {
  // The feed region lies in an STL chamber if no facet of its side meets the region (the
  // insertion keeps spheres inside the region) and the region's centre is in a gas cell.
  const Config inflow = cfg.section("inflow");
  const Vec3 lo = inflow.require_vec3("lo"), hi = inflow.require_vec3("hi");
  const std::string where = "lo " + vec_text(lo) + "; hi " + vec_text(hi);
  for (const Triangle& t : geometry_.side_facets())
    if (triangle_meets_box(t, lo, hi))
      throw InputError(inflow.path("lo"), where,
                       "the feed region meets the wall of the chamber's STL",
                       "keep inflow.lo - inflow.hi inside the chamber");
  const FluidConfig& f = box_.fluid();
  const lbm::LbmSolver& gas = *box_.gas();
  const lbm::Grid& grid = gas.grid();
  const Vec3 m = 0.5 * (lo + hi);
  int c[3];
  for (int a = 0; a < 3; ++a) c[a] = int(std::floor((m[a] - f.lo[a]) / f.dx));
  const bool inside = c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < grid.nx() && c[1] < grid.ny() &&
                      c[2] < grid.nz() && gas.flags().fluid(grid.index(c[0], c[1], c[2]));
  if (!inside)
    throw InputError(inflow.path("lo"), where, "the feed region lies outside the chamber's STL",
                     "keep inflow.lo - inflow.hi inside the chamber");
}

double JetMillScenario::outlet_mass_flow() const {
  // mass_flow: what the body passed to the fluid (negative when leaving).
  return -box_.fluid().units().mass_flow_to_si(box_.gas()->mass_flow(outlet_));
}

double JetMillScenario::jet_mass_flow() const {
  return box_.fluid().units().mass_flow_to_si(box_.gas()->mass_source_rate());
}

double JetMillScenario::angular_momentum(const std::vector<Vec3>& u,
                                         const std::vector<double>& rho) const {
  const FluidConfig& f = box_.fluid();
  const lbm::LbmSolver& gas = *box_.gas();
  const lbm::Grid& g = gas.grid();
  const lbm::LatticeUnits units = f.units();
  double l = 0;  // serial, in cell order: the same sum for any thread count
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        if (!gas.flags().fluid(g.index(x, y, z))) continue;
        const std::size_t c = std::size_t(g.compact_index(x, y, z));
        const Vec3 r = f.cell_centre(x, y, z) - geometry_.axis;
        l += rho[c] * (r.x() * u[c].y() - r.y() * u[c].x());
      }
  return l * units.rho * units.velocity_to_si(1.0) * f.dx * f.dx * f.dx;
}

std::vector<double> JetMillScenario::radial_mass_flow() const {
  std::vector<double> flow = box_.gas()->level_flux(ring_level_, ring_levels_);
  for (double& m : flow) m = box_.fluid().units().mass_flow_to_si(m);
  return flow;
}

std::size_t JetMillScenario::mid_ring() const {
  return std::min(std::size_t(ring_levels_ - 1),
                  std::size_t(std::lround(0.5 * geometry_.radius / box_.fluid().dx)));
}

std::array<double, 2> JetMillScenario::ring_velocity(const std::vector<Vec3>& u, double r) const {
  const FluidConfig& f = box_.fluid();
  const lbm::LbmSolver& gas = *box_.gas();
  const lbm::Grid& g = gas.grid();
  double ut = 0, ur = 0;
  long n = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        if (!gas.flags().fluid(g.index(x, y, z))) continue;
        const Vec3 c = f.cell_centre(x, y, z) - geometry_.axis;
        const double rc = std::hypot(c.x(), c.y());
        if (std::abs(rc - r) >= f.dx || rc <= 0) continue;
        const Vec3& v = u[std::size_t(g.compact_index(x, y, z))];
        ur += (v.x() * c.x() + v.y() * c.y()) / rc;
        ut += (-v.x() * c.y() + v.y() * c.x()) / rc;
        ++n;
      }
  const double to_si = f.units().velocity_to_si(1.0);
  return n ? std::array<double, 2>{to_si * ut / double(n), to_si * ur / double(n)}
           : std::array<double, 2>{0.0, 0.0};
}

void JetMillScenario::mill_banner(Log& log) const {
  const FluidConfig& f = box_.fluid();
  const JetMillGeometry& g = geometry_;
  log.line("jet mill derived numbers:");
  log.derived("chamber diameter", 2 * g.radius, "m",
              "(" + to_text(2 * g.radius / f.dx) + " cells)");
  log.derived("chamber height", g.height, "m", "(" + to_text(g.height / f.dx) + " cells)");
  log.derived("outlet (vortex finder) radius", g.outlet_radius, "m",
              "(" + to_text(g.outlet_radius / f.dx) + " cells)");
  if (g.meshed())
    log.derived(
        "chamber from STL", double(g.chamber_mesh.size()), "facets",
        "(" + std::to_string(g.side_facets().size()) +
            " side facets are the particles' wall; nozzles on the nominal radius, source "
            "gas fraction " +
            to_text(*std::min_element(sources_.gas_fraction.begin(), sources_.gas_fraction.end())) +
            " at least)");
  if (g.classifier_height > 0)
    log.derived("classifier ring radius", g.classifier_radius, "m",
                "(wall " + to_text(g.classifier_thickness / f.dx) + " cells thick, reaching " +
                    to_text(g.classifier_height / f.dx) + " cells below the top plate)");
  if (g.nozzles.empty()) return;
  const Nozzle& q = g.nozzles.front();
  const double nu = f.nu();
  const auto grinding = double(
      std::count_if(g.nozzles.begin(), g.nozzles.end(), [](const Nozzle& n) { return !n.feed; }));
  log.derived(
      "nozzles", grinding, "",
      "(diameter " + to_text(q.diameter) + " m = " + to_text(q.diameter / f.dx) + " cells)");
  if (q.supply_pressure > 0)
    log.derived("nozzle supply pressure p0", q.supply_pressure, "Pa",
                "(absolute; air through an ideal convergent nozzle, choked above 1.89 x ambient: "
                "mdot and the momentum-conserving speed J / mdot below)");
  log.derived("jet exit speed U", q.speed, "m/s",
              "(lattice " + to_text(f.units().velocity_to_lattice(q.speed)) + ", Mach " +
                  to_text(f.units().velocity_to_lattice(q.speed) * std::sqrt(3.0)) + ")");
  log.derived("jet Reynolds number U d / nu", q.speed * q.diameter / nu, "");
  log.derived("mass flow per nozzle", q.mass_flow, "kg/s",
              "(total " + to_text(q.mass_flow * grinding) + " kg/s)");
  log.derived("momentum flux per nozzle J", q.momentum_flux(), "N", "(mdot U)");
  log.derived("notional source radius r_s", q.source_radius, "m",
              "(" + to_text(q.source_radius / f.dx) + " cells; speed at r_s about " +
                  to_text(std::sqrt(q.momentum_flux() /
                                    (kPi * f.density * q.source_radius * q.source_radius))) +
                  " m/s)");
  log.derived("source cells per nozzle", double(sources_.cells_per_nozzle.front()), "",
              "(mass and momentum exact on any grid: jet_mill_geometry.hpp)");
  const Nozzle& feed = g.nozzles.back();
  if (!feed.feed) return;
  const Vec3 at = feed.exit - g.axis;
  log.derived("feed inlet gas", feed.mass_flow, "kg/s",
              "(at " + to_text(std::atan2(at.y(), at.x()) * 180 / kPi) + " deg, diameter " +
                  to_text(feed.diameter) + " m, " + to_text(feed.speed) + " m/s, J " +
                  to_text(feed.momentum_flux()) + " N, source radius " +
                  to_text(feed.source_radius / f.dx) + " cells)");
}

}  // namespace lbdem::scenarios
