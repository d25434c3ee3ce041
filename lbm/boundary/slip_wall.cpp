#include "lbm/boundary/slip_wall.hpp"

#include "core/deterministic_sum.hpp"
#include "lbm/d3q19.hpp"

#include <Eigen/Geometry>

#include <array>
#include <stdexcept>
#include <string>

namespace lbdem::lbm {

namespace {

/// The q with c_q = c; -1 if none.
int direction_of(const std::array<int, 3>& c) {
  for (int q = 0; q < kQ; ++q)
    if (kCx[q] == c[0] && kCy[q] == c[1] && kCz[q] == c[2]) return q;
  return -1;
}

/// The slot that holds f_q*(x, t) of link (fluid, q) into `solid` in state `now` (bounce_back.hpp).
template <class T>
SlotRef<T> outgoing_slot(PdfField<T>& pdf, AaState now, Index fluid, Index solid, int q) {
  if (now == AaState::swapped) return {pdf.dir(opposite(q)) + fluid, q};
  return {pdf.dir(q) + solid, q};
}

/// The slot the next step reads f_qbar(x, t+1) from.
template <class T>
SlotRef<T> incoming_slot(PdfField<T>& pdf, AaState now, Index fluid, Index solid, int q) {
  if (now == AaState::swapped) return {pdf.dir(q) + solid, q};
  return {pdf.dir(opposite(q)) + fluid, q};
}

}  // namespace

SlipLinks split_slip_links(BounceBackLinks& links, const FlagField& flags, CellFlag body, int axis,
                           int sign, double slip) {
  if (!(slip > 0 && slip <= 1))
    throw std::invalid_argument("slip links need a slip fraction in (0, 1], got " +
                                std::to_string(slip));
  if (axis < 0 || axis > 2 || (sign != 1 && sign != -1))
    throw std::invalid_argument("slip links need an axis-aligned wall normal");
  const Grid& g = flags.grid();
  SlipLinks s;
  s.slip = slip;
  s.axis = axis;
  BounceBackLinks rest;
  for (std::size_t k = 0; k < links.size(); ++k) {
    const int q = links.dir[k];
    const std::array<int, 3> c = {kCx[q], kCy[q], kCz[q]};
    int r = -1;
    Index partner = -1, partner_solid = -1;
    if (c[std::size_t(axis)] * sign < 0) {  // into the face, not into an interior solid
      // Partner: cell y + c_qt (wrapped), direction c_r = c_qn - c_qt.
      auto [x, y, z] = g.coordinates(links.fluid[k]);
      int p[3] = {x, y, z};
      std::array<int, 3> cr{};
      for (int a = 0; a < 3; ++a) {
        if (a == axis) {
          cr[std::size_t(a)] = c[std::size_t(a)];
          continue;
        }
        p[a] = g.shift(a, p[a], c[std::size_t(a)]);
        cr[std::size_t(a)] = -c[std::size_t(a)];
      }
      const bool inside = p[0] >= -1 && p[0] <= g.nx() && p[1] >= -1 && p[1] <= g.ny() &&
                          p[2] >= -1 && p[2] <= g.nz();
      if (inside && flags.fluid(g.index(p[0], p[1], p[2]))) {
        r = direction_of(cr);
        const Index target = g.neighbor(p[0], p[1], p[2], r);
        if (flags.at(target) == body) {
          partner = g.index(p[0], p[1], p[2]);
          partner_solid = target;
        }
      }
    }
    if (partner < 0) {  // stays bounce-back
      rest.fluid.push_back(links.fluid[k]);
      rest.solid.push_back(links.solid[k]);
      rest.dir.push_back(links.dir[k]);
      rest.correction.push_back(links.correction[k]);
      rest.point.push_back(links.point[k]);
      continue;
    }
    s.fluid.push_back(links.fluid[k]);
    s.solid.push_back(links.solid[k]);
    s.dir.push_back(links.dir[k]);
    s.point.push_back(links.point[k]);
    s.partner_fluid.push_back(partner);
    s.partner_solid.push_back(partner_solid);
    s.partner_dir.push_back(std::uint8_t(r));
  }
  links = std::move(rest);
  return s;
}

template <class T>
WallLoad apply_slip_links(PdfField<T>& pdf, AaState now, const SlipLinks& links,
                          const Vec3& origin) {
  const double s = links.slip;
  const bool specular = s == 1.0;
  const double keep = 1.0 - s;  // share of the tangential momentum the wall takes
  const int axis = links.axis;
  // Each link writes its own incoming slot and reads two outgoing slots, which no link writes
  // (header comment): the summand applies its link as a side effect, in any order.
  return deterministic_sum(
      links.size(),
      [&](std::size_t k) -> WallLoad {
        const int q = links.dir[k];
        const double a = outgoing_slot(pdf, now, links.fluid[k], links.solid[k], q);
        const double b = outgoing_slot(pdf, now, links.partner_fluid[k], links.partner_solid[k],
                                       links.partner_dir[k]);
        incoming_slot(pdf, now, links.fluid[k], links.solid[k], q) = specular ? b : a + s * (b - a);
        const double m = 2.0 * a;
        Vec3 f(kCx[q] * m, kCy[q] * m, kCz[q] * m);
        for (int d = 0; d < 3; ++d)
          if (d != axis) f[d] *= keep;
        return {f, (links.point[k] - origin).cross(f), 0.0};
      },
      WallLoad{});
}

template WallLoad apply_slip_links(PdfField<double>&, AaState, const SlipLinks&, const Vec3&);
template WallLoad apply_slip_links(PdfField<float>&, AaState, const SlipLinks&, const Vec3&);

}  // namespace lbdem::lbm
