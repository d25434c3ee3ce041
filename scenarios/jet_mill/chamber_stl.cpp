#include "scenarios/jet_mill/chamber_stl.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scenarios/common/fluid_config.hpp"

namespace lbdem::scenarios {

namespace {
// Distance in the x-y plane from point c to the projection of triangle t (0 inside it; a
// vertical facet projects to a segment).
double xy_distance(const Triangle& t, const Vec3& c) {
  using V2 = Eigen::Vector2d;
  const V2 p(c.x(), c.y());
  const V2 a(t[0].x(), t[0].y()), b(t[1].x(), t[1].y()), d(t[2].x(), t[2].y());
  const auto cross = [](const V2& u, const V2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double s0 = cross(b - a, p - a), s1 = cross(d - b, p - b), s2 = cross(a - d, p - d);
  if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) {
    if (std::abs(cross(b - a, d - a)) > 0) return 0;  // a proper triangle holds p
  }
  const auto seg = [&](const V2& u, const V2& v) {
    const V2 e = v - u;
    const double l2 = e.squaredNorm();
    const double t0 = l2 > 0 ? std::clamp((p - u).dot(e) / l2, 0.0, 1.0) : 0.0;
    return (u + t0 * e - p).norm();
  };
  return std::min({seg(a, b), seg(b, d), seg(d, a)});
}
}  // namespace

std::vector<Triangle> JetMillGeometry::side_facets() const {
  const double tol = plate_tol, z0 = axis.z(), z1 = axis.z() + height;
  std::vector<Triangle> side;
  for (const Triangle& t : chamber_mesh) {
    bool floor = true, roof = true;
    for (const Vec3& v : t) {
      floor = floor && std::abs(v.z() - z0) <= tol;
      roof = roof && std::abs(v.z() - z1) <= tol;
    }
    if (!floor && !roof) side.push_back(t);
  }
  return side;
}

void read_chamber_stl(const Config& section, const FluidConfig& f, const Vec3& hi,
                      JetMillGeometry& g) {
  if (section.has("chamber_stl")) {
    // A user's chamber: any closed surface inside the box (the box stays the bounding box that
    // sets the nominal radius, the plates and the outlet's plane).
    g.chamber_key = section.path("chamber_stl");
    const std::string file = section.get_string("chamber_stl", "");
    const double scale = section.get("chamber_stl_scale", 1.0,
                                     Range::positive("give the factor to metres, e.g. 1e-3 for a "
                                                     "file in mm"));
    g.chamber_mesh = read_stl(file, scale, g.chamber_key);
    g.plate_tol = 1e-3 * f.dx;
    const double tol = g.plate_tol;
    for (const Triangle& t : g.chamber_mesh)
      for (const Vec3& v : t)
        for (int a = 0; a < 3; ++a)
          if (v[a] < f.lo[a] - tol || v[a] > hi[a] + tol)
            throw InputError(g.chamber_key, file,
                             "a corner (" + to_text(v.x()) + ", " + to_text(v.y()) + ", " +
                                 to_text(v.z()) + " m) lies outside the box " + to_text(f.lo.x()) +
                                 " - " + to_text(hi.x()) + ", " + to_text(f.lo.y()) + " - " +
                                 to_text(hi.y()) + ", " + to_text(f.lo.z()) + " - " +
                                 to_text(hi.z()) + " m",
                             "give box.lo and box.hi that hold the chamber (and check "
                             "jet_mill.chamber_stl_scale: 1e-3 for a file in mm)");
    const std::vector<Triangle> side = g.side_facets();
    if (side.empty())
      throw InputError(g.chamber_key, file, "every facet lies in the floor's or the roof's plane",
                       "give a closed surface around the chamber's gas, its side included");
    // A lid under the vortex finder within the top cell layer leaves gas under the outlet (the
    // gas check of build_chamber passes) but would be a wall closing it to the particles; one
    // lower down closes it to the gas too, which build_chamber reports.
    for (const Triangle& t : side) {
      const bool high = std::min({t[0].z(), t[1].z(), t[2].z()}) > hi.z() - 1.5 * f.dx;
      if (high && xy_distance(t, g.axis) < g.outlet_radius - tol)
        throw InputError(g.chamber_key, file,
                         "a facet below the top plate, within 1.5 cells of it, covers the vortex "
                         "finder (radius " +
                             to_text(g.outlet_radius) + " m): it would close it to the particles",
                         "put the chamber's roof in the box's top plane (box.hi z) or remove the "
                         "facet");
    }
    if (section.has("classifier"))
      throw InputError(section.path("classifier"), "", "given with jet_mill.chamber_stl",
                       "model the classifier ring in the chamber's STL, or drop chamber_stl");
  } else if (section.has("chamber_stl_scale")) {
    throw InputError(section.path("chamber_stl_scale"),
                     to_text(section.get("chamber_stl_scale", 1.0, Range::positive(""))),
                     "it scales jet_mill.chamber_stl, which is not given",
                     "give jet_mill.chamber_stl or remove chamber_stl_scale");
  }
}

void check_source_in_stl(const lbm::LbmSolver& gas, const FluidConfig& f, const JetMillGeometry& g,
                         std::size_t k, double s0) {
  const Nozzle& q = g.nozzles[k];
  const lbm::Grid& grid = gas.grid();
  const double rs = q.source_radius, len = 2 * rs, reach = rs + 1.5 * f.dx;
  const auto cell_of = [&](double coordinate, int a) {
    return int(std::floor((coordinate - f.lo[a]) / f.dx));
  };
  const auto gas_at = [&](int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < grid.nx() && y < grid.ny() && z < grid.nz() &&
           gas.flags().fluid(grid.index(x, y, z));
  };
  const std::string nozzle = q.feed ? "the feed" : "nozzle " + std::to_string(k + 1);
  const std::string move = q.feed ? "move the feed (jet_mill.feed.position_deg, height)"
                                  : "move the nozzles (jet_mill.nozzles.first_deg, height)";
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    const double b0 = q.exit[a] + s0 * q.dir[a], b1 = b0 + len * q.dir[a];
    lo[a] = cell_of(std::min(b0, b1) - reach, a) - 1;
    hi[a] = cell_of(std::max(b0, b1) + reach, a) + 1;
  }
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) {
        const Vec3 r = f.cell_centre(x, y, z) - q.exit;
        const double s = r.dot(q.dir);
        if (s < s0 || s > s0 + len || (r - s * q.dir).norm() > reach || gas_at(x, y, z)) continue;
        throw InputError(g.chamber_key, nozzle,
                         "the STL's wall (or floor or roof) comes within 1.5 cells of the jet's "
                         "notional source (radius " +
                             to_text(rs) + " m), at the cell centred at " +
                             to_text(r.x() + q.exit.x()) + ", " + to_text(r.y() + q.exit.y()) +
                             ", " + to_text(r.z() + q.exit.z()) + " m",
                         "make the STL's wall meet the nozzles' circle of radius " +
                             to_text(g.radius) + " m (half the box's width) there, or " + move);
      }
  Vec3 out = q.exit - g.axis;
  out.z() = 0;
  const Vec3 behind = q.exit + 0.75 * f.dx * out.normalized();
  if (gas_at(cell_of(behind.x(), 0), cell_of(behind.y(), 1), cell_of(behind.z(), 2)))
    throw InputError(g.chamber_key, nozzle,
                     "the STL's wall at the nozzle lies outside the nozzles' circle of radius " +
                         to_text(g.radius) + " m (gas 0.75 cells behind the exit)",
                     "make the STL's wall meet the nozzles' circle there, or " + move);
}

bool triangle_meets_box(const Triangle& t, const Vec3& lo, const Vec3& hi) {
  const Vec3 c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
  const Vec3 v[3] = {t[0] - c, t[1] - c, t[2] - c};
  const auto separated = [&](const Vec3& ax) {
    if (ax.squaredNorm() == 0) return false;
    const double p0 = v[0].dot(ax), p1 = v[1].dot(ax), p2 = v[2].dot(ax);
    const double r = h.x() * std::abs(ax.x()) + h.y() * std::abs(ax.y()) + h.z() * std::abs(ax.z());
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
  };
  const Vec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  for (int a = 0; a < 3; ++a)
    if (separated(Vec3::Unit(a))) return false;
  if (separated(e[0].cross(e[1]))) return false;
  for (const Vec3& ei : e)
    for (int a = 0; a < 3; ++a)
      if (separated(Vec3::Unit(a).cross(ei))) return false;
  return true;
}

}  // namespace lbdem::scenarios
