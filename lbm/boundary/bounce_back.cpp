#include "lbm/boundary/bounce_back.hpp"

#include "core/deterministic_sum.hpp"
#include "lbm/d3q19.hpp"

#include <Eigen/Geometry>

namespace lbdem::lbm {

std::vector<BounceBackLinks> build_links(const FlagField& flags, int n_bodies) {
  std::vector<BounceBackLinks> links(static_cast<std::size_t>(n_bodies));
  const Grid& g = flags.grid();
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        const Index n = g.index(x, y, z);
        if (!flags.fluid(n)) continue;
        for (int q = 1; q < kQ; ++q) {
          const Index s = g.neighbor(x, y, z, q);
          const CellFlag body = flags.at(s);
          if (body == kFluid || body > n_bodies) continue;
          auto& l = links[body - 1u];
          l.fluid.push_back(n);
          l.solid.push_back(s);
          l.dir.push_back(std::uint8_t(q));
          l.correction.push_back(0.0);
          l.point.push_back(Vec3(x + 0.5 * kCx[q], y + 0.5 * kCy[q], z + 0.5 * kCz[q]));
        }
      }
  return links;
}

void set_wall_velocity(BounceBackLinks& links, const Grid& g, const WallVelocity& u, double rho_w) {
  for (std::size_t k = 0; k < links.size(); ++k) {
    const int q = links.dir[k];
    if (!u) {
      links.correction[k] = 0.0;
      continue;
    }
    const auto [ix, iy, iz] = g.coordinates(links.fluid[k]);
    const Vec3 x(ix, iy, iz);
    const Vec3 c(kCx[q], kCy[q], kCz[q]);
    links.correction[k] = -2.0 * kW[q] * rho_w * c.dot(u(x + 0.5 * c)) / kCs2;
  }
}

template <class T>
WallLoad apply_bounce_back(PdfField<T>& pdf, AaState now, const BounceBackLinks& links,
                           const Vec3& origin) {
  // The summand applies its link as a side effect: deterministic_sum calls it once per k.
  return deterministic_sum(
      links.size(),
      [&](std::size_t k) -> WallLoad {
        const int q = links.dir[k];
        auto [from, to] = link_slots(pdf, now, links, k);
        const double post = from;  // f_q*(x, t)
        to = post + links.correction[k];
        const double m = 2.0 * post + links.correction[k];
        const Vec3 f(kCx[q] * m, kCy[q] * m, kCz[q] * m);
        return {f, (links.point[k] - origin).cross(f), links.correction[k]};
      },
      WallLoad{});
}

template WallLoad apply_bounce_back(PdfField<double>&, AaState, const BounceBackLinks&,
                                    const Vec3&);
template WallLoad apply_bounce_back(PdfField<float>&, AaState, const BounceBackLinks&, const Vec3&);

}  // namespace lbdem::lbm
