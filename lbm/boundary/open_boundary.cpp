#include "lbm/boundary/open_boundary.hpp"

#include "core/deterministic_sum.hpp"
#include "lbm/d3q19.hpp"

#include <Eigen/Geometry>
#include <unordered_map>

namespace lbdem::lbm {

PressureOutlet build_outlet(const BounceBackLinks& links, const FlagField& flags, double density,
                            bool extrapolate, bool backflow) {
  const Grid& g = flags.grid();
  PressureOutlet o;
  o.density = density;
  o.extrapolate = extrapolate;
  o.backflow = backflow;
  std::unordered_map<Index, std::uint32_t> position;
  auto cell_of = [&](Index n) {
    const auto [it, added] = position.try_emplace(n, std::uint32_t(o.cells.size()));
    if (added) o.cells.push_back(g.coordinates(n));
    return it->second;
  };
  o.near_cell.reserve(links.size());
  o.inward_cell.reserve(links.size());
  for (std::size_t k = 0; k < links.size(); ++k) {
    const std::uint32_t near = cell_of(links.fluid[k]);
    const auto [x, y, z] = g.coordinates(links.fluid[k]);
    const Index inward = g.neighbor(x, y, z, opposite(links.dir[k]));  // x - c_q, wrapped
    o.near_cell.push_back(near);
    o.inward_cell.push_back(extrapolate && flags.fluid(inward) ? cell_of(inward) : near);
  }
  o.velocity.assign(o.cells.size(), Vec3::Zero());
  o.normal.assign(o.cells.size(), Vec3::Zero());
  for (std::size_t k = 0; k < links.size(); ++k) {
    const int q = links.dir[k];
    o.normal[o.near_cell[k]] += kW[q] * Vec3(kCx[q], kCy[q], kCz[q]);
  }
  for (Vec3& n : o.normal)
    if (n.norm() > 0) n.normalize();
  return o;
}

template <class T>
WallLoad apply_anti_bounce_back(PdfField<T>& pdf, AaState now, const BounceBackLinks& links,
                                const PressureOutlet& outlet, const Vec3& origin) {
  const double rho = outlet.density;
  // The summand applies its link as a side effect: deterministic_sum calls it once per k. Slots
  // as in apply_bounce_back (bounce_back.hpp).
  return deterministic_sum(
      links.size(),
      [&](std::size_t k) -> WallLoad {
        const int q = links.dir[k];
        auto [from, to] = link_slots(pdf, now, links, k);
        const Vec3& u = outlet.velocity[outlet.near_cell[k]];
        const Vec3& u_in = outlet.velocity[outlet.inward_cell[k]];
        const Vec3 uw = u + 0.5 * (u - u_in);  // exactly u(x) without an inward cell (or option)
        const double cu = kCx[q] * uw.x() + kCy[q] * uw.y() + kCz[q] * uw.z();
        // 1/(2 c_s^4) = 4.5 and 1/(2 c_s^2) = 1.5 for c_s^2 = 1/3.
        const double even = 2.0 * kW[q] * rho * (1.0 + 4.5 * cu * cu - 1.5 * uw.squaredNorm());
        const double post = from;  // f_q*(x, t)
        if (!outlet.backflow &&
            (even > 2.0 * post || u.dot(outlet.normal[outlet.near_cell[k]]) < 0)) {
          // Inflow here (the link would add mass, or the cell moves inwards): a wall at rest for
          // this step (header).
          to = post;
          const Vec3 f(2 * kCx[q] * post, 2 * kCy[q] * post, 2 * kCz[q] * post);
          return {f, (links.point[k] - origin).cross(f), 0.0};
        }
        const double back = even - post;
        to = back;
        const double m = post + back;
        const Vec3 f(kCx[q] * m, kCy[q] * m, kCz[q] * m);
        return {f, (links.point[k] - origin).cross(f), back - post};
      },
      WallLoad{});
}

template WallLoad apply_anti_bounce_back(PdfField<double>&, AaState, const BounceBackLinks&,
                                         const PressureOutlet&, const Vec3&);
template WallLoad apply_anti_bounce_back(PdfField<float>&, AaState, const BounceBackLinks&,
                                         const PressureOutlet&, const Vec3&);

}  // namespace lbdem::lbm
