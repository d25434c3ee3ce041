#include "lbm/boundary/wall_function.hpp"

#include "core/deterministic_sum.hpp"
#include "lbm/d3q19.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lbdem::lbm {

double WernerWengle::kinematic_stress(double u, double dz) const {
  return WernerWengleCell(*this, dz).kinematic_stress(u);
}

WernerWengleCell::WernerWengleCell(const WernerWengle& law, double dz) {
  const double a = WernerWengle::kA, b = WernerWengle::kB;
  const double nu_dz = law.nu / dz;
  switch_speed = 0.5 * nu_dz * std::pow(a, 2.0 / (1.0 - b));
  linear = 2.0 * nu_dz;
  c0 = 0.5 * (1.0 - b) * std::pow(a, (1.0 + b) / (1.0 - b)) * std::pow(nu_dz, 1.0 + b);
  c1 = (1.0 + b) / a * std::pow(nu_dz, b);
}

namespace {

// A unit vector normal to n, chosen from the axis least aligned with it (deterministic).
Vec3 first_tangent(const Vec3& n) {
  const Vec3 a = std::abs(n.x()) <= std::abs(n.y()) && std::abs(n.x()) <= std::abs(n.z())
                     ? Vec3::UnitX()
                     : (std::abs(n.y()) <= std::abs(n.z()) ? Vec3::UnitY() : Vec3::UnitZ());
  return (a - a.dot(n) * n).normalized();
}

}  // namespace

WallFunctionCells build_wall_function_cells(const BounceBackLinks& links) {
  WallFunctionCells c;
  std::size_t k = 0;
  while (k < links.size()) {
    const Index cell = links.fluid[k];
    std::size_t end = k;
    Vec3 s = Vec3::Zero();
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    for (; end < links.size() && links.fluid[end] == cell; ++end) {
      const int q = links.dir[end];
      const Vec3 cq(kCx[q], kCy[q], kCz[q]);
      s += kW[q] * cq;
      m += 6.0 * kW[q] * cq * cq.transpose();
    }
    if (end - k > std::size_t(kQ - 1))  // apply_wall_function keeps a cell's links on the stack
      throw std::logic_error("wall function: a cell lists more links than directions");
    // A cell whose links cancel (a one-cell gap) has no wall direction: it keeps no-slip links.
    const double len = s.norm();
    Vec3 n = Vec3::Zero(), e1 = Vec3::Zero(), e2 = Vec3::Zero();
    Eigen::Matrix2d pinv = Eigen::Matrix2d::Zero();
    if (len > 1e-12) {
      n = -s / len;
      e1 = first_tangent(n);
      e2 = n.cross(e1);
      Eigen::Matrix2d mt;
      mt << e1.dot(m * e1), e1.dot(m * e2), e2.dot(m * e1), e2.dot(m * e2);
      // Pseudo-inverse: eigenvalues far below a flat face's 1/3 belong to directions no link
      // reaches (a link along n), which the slip cannot change.
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es;
      es.computeDirect(mt);  // closed form for 2 x 2
      for (int i = 0; i < 2; ++i)
        if (es.eigenvalues()(i) > 1e-9)
          pinv +=
              es.eigenvectors().col(i) * es.eigenvectors().col(i).transpose() / es.eigenvalues()(i);
    }
    c.cell.push_back(cell);
    c.first.push_back(std::uint32_t(k));
    c.normal.push_back(n);
    c.e1.push_back(e1);
    c.e2.push_back(e2);
    c.area.push_back(len > 1e-12 ? 6.0 * len : 0.0);
    c.m_pinv.push_back({pinv(0, 0), pinv(0, 1), pinv(1, 1)});
    const int q0 = links.dir[k];
    c.centre.push_back(links.point[k] - 0.5 * Vec3(kCx[q0], kCy[q0], kCz[q0]));
    k = end;
  }
  c.first.push_back(std::uint32_t(links.size()));
  return c;
}

// Wall cells per block of the load's sum: each costs about three cell collisions, and the jet
// mill's default chamber has about 4,600 of them, one full block of the default 4,096 and a small
// one (measured: the wall function took 1.86 s on 1 and 2 threads alike).
constexpr std::size_t kWallCellBlock = 256;

WallLoad apply_wall_function(PdfField& pdf, AaState now, BounceBackLinks& links,
                             const WallFunctionCells& cells, const WernerWengle& law,
                             const MomentFields& moments, double rho_w, const Vec3& origin) {
  const WernerWengleCell cell_law(law);
  // The summand applies its cell's links as a side effect: deterministic_sum calls it once per i.
  return deterministic_sum(
      cells.size(),
      [&](std::size_t i) -> WallLoad {
        const std::size_t k0 = cells.first[i], k1 = cells.first[i + 1];
        // The links' slots are found once: f_q* is read here and the reflected value written
        // below (a cell has at most kQ - 1 links).
        double post[kQ - 1];
        double* to[kQ - 1];
        Vec3 p = Vec3::Zero();  // momentum the links carry into the wall
        for (std::size_t k = k0; k < k1; ++k) {
          const int q = links.dir[k];
          auto slots = link_slots(pdf, now, links, k);
          post[k - k0] = slots.from;
          to[k - k0] = &slots.to;
          p += slots.from * Vec3(kCx[q], kCy[q], kCz[q]);
        }
        Vec3 slip = Vec3::Zero();
        if (cells.area[i] > 0) {
          // The cell's density and velocity as its collision this step saw them.
          const std::size_t c = std::size_t(cells.cell[i]);
          const double rho = moments.rho[c];
          const Vec3 u(moments.u[0][c], moments.u[1][c], moments.u[2][c]);
          const Vec3& n = cells.normal[i];
          const Vec3 ut = u - u.dot(n) * n;
          const double speed = ut.norm();
          Vec3 target = Vec3::Zero();
          if (speed > 0)
            target = rho * cell_law.kinematic_stress(speed) * cells.area[i] / speed * ut;
          const Vec3 r = 2.0 * p - target;
          const double r1 = cells.e1[i].dot(r), r2 = cells.e2[i].dot(r);
          const auto& mi = cells.m_pinv[i];
          slip =
              ((mi[0] * r1 + mi[1] * r2) * cells.e1[i] + (mi[1] * r1 + mi[2] * r2) * cells.e2[i]) /
              rho_w;
          // Stability: the wall may slip along the flow, between no slip and the cell's own speed,
          // never against it or past it. The bounds are inactive where the layer is in
          // equilibrium (slip ~ u_t - 3 tau_w / rho_w, with tau_w between 0 and no slip's) and
          // catch the transients in which the explicit slip would drive the wall cell.
          if (speed > 0) {
            const Vec3 t = ut / speed;
            const double along = std::clamp(slip.dot(t), 0.0, speed);
            Vec3 across = slip - slip.dot(t) * t;
            if (across.norm() > speed) across *= speed / across.norm();
            slip = along * t + across;
          } else {
            slip = Vec3::Zero();
          }
        }
        // Sums in locals: accumulated in the returned struct they went through memory, a
        // store-to-load chain per link (9 % of this function in perf).
        Vec3 force = Vec3::Zero();
        double mass = 0.0;
        for (std::size_t k = k0; k < k1; ++k) {
          const int q = links.dir[k];
          const Vec3 cq(kCx[q], kCy[q], kCz[q]);
          const double corr = -2.0 * kW[q] * rho_w * cq.dot(slip) / kCs2;
          links.correction[k] = corr;
          *to[k - k0] = post[k - k0] + corr;
          force += (2.0 * post[k - k0] + corr) * cq;
          mass += corr;
        }
        WallLoad load;
        load.force = force;
        load.torque = (cells.centre[i] - origin).cross(force);
        load.mass = mass;
        return load;
      },
      WallLoad{}, kWallCellBlock);
}

}  // namespace lbdem::lbm
