#include "lbm/boundary/wall_function.hpp"

#include "core/deterministic_sum.hpp"
#include "lbm/d3q19.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <vector>

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

// Wall cells per block of the load's sum: a general cell costs about three cell collisions, and
// the jet mill's default chamber has about 4,600 wall cells (with blocks of 4,096 the wall
// function took 1.86 s on 1 and 2 threads alike).
constexpr std::size_t kWallCellBlock = 256;

// A flat-face cell: five links, all with the same nonzero component along one axis.
bool flat_face(const BounceBackLinks& links, std::size_t k0, std::size_t k1) {
  if (k1 - k0 != 5) return false;
  const int* c[3] = {kCx.data(), kCy.data(), kCz.data()};
  for (int a = 0; a < 3; ++a) {
    const int s = c[a][links.dir[k0]];
    bool all = s != 0;
    for (std::size_t k = k0 + 1; k < k1 && all; ++k) all = c[a][links.dir[k]] == s;
    if (all) return true;
  }
  return false;
}

// Cell i continues a flat run that cell i - 1 is in: its storage neighbour, with the same links
// to the same offsets (a periodic wrap or another body's cell ends the run).
bool continues_run(const WallFunctionCells& c, const BounceBackLinks& links, std::size_t i) {
  if (c.cell[i] != c.cell[i - 1] + 1) return false;
  const std::size_t k = c.first[i], kp = c.first[i - 1];
  for (std::size_t m = 0; m < 5; ++m)
    if (links.dir[k + m] != links.dir[kp + m] ||
        links.solid[k + m] - links.fluid[k + m] != links.solid[kp + m] - links.fluid[kp + m])
      return false;
  return true;
}

void group_units(WallFunctionCells& c, const BounceBackLinks& links, bool flat_runs) {
  std::vector<bool> flat(c.size());
  for (std::size_t i = 0; i < c.size(); ++i)
    flat[i] = flat_runs && c.area[i] > 0 && flat_face(links, c.first[i], c.first[i + 1]);
  std::size_t cells_in_block = 0;
  c.block_first.push_back(0);
  for (std::size_t i = 0; i < c.size();) {
    std::size_t end = i + 1;
    if (flat[i])
      while (end < c.size() && flat[end] && continues_run(c, links, end)) ++end;
    if (cells_in_block >= kWallCellBlock) {
      c.block_first.push_back(std::uint32_t(c.unit_first.size()));
      cells_in_block = 0;
    }
    c.unit_first.push_back(std::uint32_t(i));
    c.unit_flat.push_back(flat[i] ? 1 : 0);
    cells_in_block += end - i;
    i = end;
  }
  c.unit_first.push_back(std::uint32_t(c.size()));
  c.block_first.push_back(std::uint32_t(c.unit_flat.size()));
}

}  // namespace

WallFunctionCells build_wall_function_cells(const BounceBackLinks& links, bool flat_runs) {
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
  group_units(c, links, flat_runs);
  return c;
}

namespace {

// The cells of a flat run, in chunks whose per-cell results stay on the stack: the first loop has
// no reductions and no branches (selects only, every lane's arithmetic safe), so that it
// vectorises; the sums follow in cell order. Same formulas as the general kernel with n a face
// axis, A = 1 and the pseudo-inverse 3 I, so the two differ at round-off (tested).
constexpr std::size_t kFlatChunk = 64;

// The run's kernel on the slots as stored: from[m][j] holds slot f_q* of link m of cell j, to[m][j]
// receives the reflected value. S: the slots' precision, in which it computes; M: the stored
// moments' (the lattice's). Double slots hold f_q. Float slots hold f_q - w_q (pdf_field.hpp), and
// since w_q = w_qbar the reflection f_q* + corr_q is the same sum on the shifted value. Over a
// face's five links sum_q w_q c_q is along the normal only, so the tangential momentum (all the
// slip uses) is the same sum on shifted slots, and each cell's force is the shifted sum plus the
// constant 2 sum_q w_q c_q, added in double. Not inlined: inlined into a mixed-precision caller,
// GCC 12 left its cell loop scalar.
template <class S, class M>
[[gnu::noinline]] WallLoad flat_run_kernel(const S* const (&from)[5], S* const (&to)[5],
                                           BounceBackLinks& links, const WallFunctionCells& cells,
                                           std::size_t u, const WernerWengleCell& law,
                                           const MomentFields<M>& moments, double rho_w,
                                           const Vec3& origin) {
  using R = S;
  constexpr bool kShiftedSlots = std::is_same_v<S, float>;
  const std::size_t i0 = cells.unit_first[u], n = cells.unit_first[u + 1] - i0;
  const std::size_t k0 = cells.first[i0];
  const std::size_t c0 = std::size_t(cells.cell[i0]);
  R cx[5], cy[5], cz[5], wc[5];     // c_q and Ladd's factor: corr_q = wc_q c_q . u_s
  Vec3 shift_force = Vec3::Zero();  // 2 sum_q w_q c_q, the shifted slots' missing force
  for (std::size_t m = 0; m < 5; ++m) {
    const int q = links.dir[k0 + m];
    cx[m] = R(kCx[q]);
    cy[m] = R(kCy[q]);
    cz[m] = R(kCz[q]);
    wc[m] = R(-2.0 * kW[q] * rho_w / kCs2);
    shift_force += 2.0 * kW[q] * Vec3(kCx[q], kCy[q], kCz[q]);
  }
  // Tangential mask: 0 along the face normal, 1 across; multiplying by it is exact.
  const Vec3& nrm = cells.normal[i0];
  const R tx = nrm.x() == 0 ? R(1) : R(0), ty = nrm.y() == 0 ? R(1) : R(0),
          tz = nrm.z() == 0 ? R(1) : R(0);
  const R pinv = R(3.0 / rho_w);  // (M_t / rho_w)^-1 = 3 I on a flat face, over rho_w
  const R tiny = kShiftedSlots ? R(1e-30) : R(1e-300);
  const R law_c0 = R(law.c0), law_c1 = R(law.c1), law_linear = R(law.linear),
          law_switch = R(law.switch_speed);
  const M* rho = moments.rho + c0;
  const M *ux = moments.u[0] + c0, *uy = moments.u[1] + c0, *uz = moments.u[2] + c0;

  Vec3 force_sum = Vec3::Zero(), torque_sum = Vec3::Zero();
  Vec3 force_run = Vec3::Zero(), moment_run = Vec3::Zero();  // shifted slots: sum f, e_x x sum j f
  double mass_sum = 0.0;
  for (std::size_t j0 = 0; j0 < n; j0 += kFlatChunk) {
    const std::size_t len = std::min(kFlatChunk, n - j0);
    R fx[kFlatChunk], fy[kFlatChunk], fz[kFlatChunk], dm[kFlatChunk], corr[5][kFlatChunk];
#pragma omp simd
    for (std::size_t jj = 0; jj < len; ++jj) {
      const std::size_t j = j0 + jj;
      R post[5];
      R px = 0, py = 0, pz = 0;
      for (std::size_t m = 0; m < 5; ++m) {
        post[m] = from[m][j];
        px += post[m] * cx[m];
        py += post[m] * cy[m];
        pz += post[m] * cz[m];
      }
      const R utx = tx * R(ux[j]), uty = ty * R(uy[j]), utz = tz * R(uz[j]);
      const R speed = std::sqrt(utx * utx + uty * uty + utz * utz);
      const R safe = std::max(speed, tiny);
      const R x = law_c0 + law_c1 * speed;
      const R tau = speed <= law_switch ? law_linear * speed : x * std::sqrt(x * std::sqrt(x));
      const R g = R(rho[j]) * tau / safe;  // target = g u_t, the law's stress along the flow
      R sx = pinv * tx * (R(2) * px - g * utx), sy = pinv * ty * (R(2) * py - g * uty),
        sz = pinv * tz * (R(2) * pz - g * utz);
      // The general kernel's bounds: along the flow between 0 and the speed, across at most it.
      const R ex = utx / safe, ey = uty / safe, ez = utz / safe;
      const R d = sx * ex + sy * ey + sz * ez;
      const R along = std::min(std::max(d, R(0)), speed);
      R ax = sx - d * ex, ay = sy - d * ey, az = sz - d * ez;
      const R an = std::sqrt(ax * ax + ay * ay + az * az);
      const R scale = an > speed ? speed / std::max(an, tiny) : R(1);
      const R on = speed > 0 ? R(1) : R(0);
      sx = on * (along * ex + scale * ax);
      sy = on * (along * ey + scale * ay);
      sz = on * (along * ez + scale * az);
      R fxj = 0, fyj = 0, fzj = 0, dmj = 0;
      for (std::size_t m = 0; m < 5; ++m) {
        const R cm = wc[m] * (cx[m] * sx + cy[m] * sy + cz[m] * sz);
        corr[m][jj] = cm;
        to[m][j] = post[m] + cm;
        const R out = R(2) * post[m] + cm;
        fxj += out * cx[m];
        fyj += out * cy[m];
        fzj += out * cz[m];
        dmj += cm;
      }
      fx[jj] = fxj;
      fy[jj] = fyj;
      fz[jj] = fzj;
      dm[jj] = dmj;
    }
    if constexpr (kShiftedSlots) {
      // The run's cells are x neighbours with five links each: centre_j = centre_0 + j e_x and
      // link m of cell j is k0 + 5 j + m. Sums of f and of j f give force and torque.
      double sx = 0, sy = 0, sz = 0, jy = 0, jz = 0, sm = 0;
#pragma omp simd reduction(+ : sx, sy, sz, jy, jz, sm)
      for (std::size_t jj = 0; jj < len; ++jj) {
        const double j = double(j0 + jj);
        sx += double(fx[jj]);
        sy += double(fy[jj]);
        sz += double(fz[jj]);
        jy += j * (double(fy[jj]) + shift_force.y());
        jz += j * (double(fz[jj]) + shift_force.z());
        sm += double(dm[jj]);
      }
      for (std::size_t jj = 0; jj < len; ++jj)
        for (std::size_t m = 0; m < 5; ++m)
          links.correction[k0 + 5 * (j0 + jj) + m] = double(corr[m][jj]);
      force_run += Vec3(sx, sy, sz) + double(len) * shift_force;
      moment_run += Vec3(0.0, -jz, jy);  // e_x x sum_j j f_j
      mass_sum += sm;
    } else {
      for (std::size_t jj = 0; jj < len; ++jj) {
        const std::size_t i = i0 + j0 + jj;
        const Vec3 f(fx[jj], fy[jj], fz[jj]);
        force_sum += f;
        torque_sum += (cells.centre[i] - origin).cross(f);
        mass_sum += dm[jj];
        for (std::size_t m = 0; m < 5; ++m) links.correction[cells.first[i] + m] = corr[m][jj];
      }
    }
  }
  if constexpr (kShiftedSlots) {
    force_sum = force_run;
    torque_sum = (cells.centre[i0] - origin).cross(force_run) + moment_run;
  }
  WallLoad load;
  load.force = force_sum;
  load.torque = torque_sum;
  load.mass = mass_sum;
  return load;
}

/// Points the kernel at the run's slots, which along a flat run are consecutive per link.
template <class T>
WallLoad apply_flat_run(PdfField<T>& pdf, AaState now, BounceBackLinks& links,
                        const WallFunctionCells& cells, std::size_t u, const WernerWengleCell& law,
                        const MomentFields<T>& moments, double rho_w, const Vec3& origin) {
  const std::size_t k0 = cells.first[cells.unit_first[u]];
  const T* from[5];
  T* to[5];
  for (std::size_t m = 0; m < 5; ++m) {
    const auto slots = link_slots(pdf, now, links, k0 + m);
    from[m] = slots.from.p;
    to[m] = slots.to.p;
  }
  return flat_run_kernel(from, to, links, cells, u, law, moments, rho_w, origin);
}

// General (staircase) cells on float slots, kGeneralChunk consecutive cells at a time in three
// passes: their links' momentum is gathered cell by cell, the slip of every cell is computed in
// one vectorised loop (the latency-bound part: roots, divisions and the bounds), and the links
// are written back cell by cell. The formulas are the general kernel's (apply_wall_function) on
// shifted slots: sum_q w_q c_q = -(A / 6) n lies along the normal, so the tangential momentum the
// slip needs is the same sum on f_q - w_q, and each cell's force is the shifted sum plus the
// constant 2 sum_q w_q c_q = -(A / 3) n.
constexpr std::size_t kGeneralChunk = 64;  // a multiple of 16
constexpr std::size_t kShortRun = 16;

WallLoad general_chunk(PdfField<float>& pdf, AaState now, BounceBackLinks& links,
                       const WallFunctionCells& cells, const std::size_t (&idx)[kGeneralChunk],
                       std::size_t count, const WernerWengleCell& law,
                       const MomentFields<float>& moments, double rho_w, const Vec3& origin) {
  float px[kGeneralChunk], py[kGeneralChunk], pz[kGeneralChunk];
  float ux[kGeneralChunk], uy[kGeneralChunk], uz[kGeneralChunk], rho[kGeneralChunk];
  float nx[kGeneralChunk], ny[kGeneralChunk], nz[kGeneralChunk], area[kGeneralChunk];
  float e1[3][kGeneralChunk], e2[3][kGeneralChunk], mp[3][kGeneralChunk];
  for (std::size_t j = 0; j < count; ++j) {
    const std::size_t i = idx[j];
    float sx = 0, sy = 0, sz = 0;
    for (std::size_t k = cells.first[i]; k < cells.first[i + 1]; ++k) {
      const int q = links.dir[k];
      const float post = *link_slots(pdf, now, links, k).from.p;
      sx += post * float(kCx[q]);
      sy += post * float(kCy[q]);
      sz += post * float(kCz[q]);
    }
    px[j] = sx;
    py[j] = sy;
    pz[j] = sz;
    const std::size_t c = std::size_t(cells.cell[i]);
    rho[j] = moments.rho[c];
    ux[j] = moments.u[0][c];
    uy[j] = moments.u[1][c];
    uz[j] = moments.u[2][c];
    nx[j] = float(cells.normal[i].x());
    ny[j] = float(cells.normal[i].y());
    nz[j] = float(cells.normal[i].z());
    area[j] = float(cells.area[i]);
    for (int a = 0; a < 3; ++a) {
      e1[a][j] = float(cells.e1[i][a]);
      e2[a][j] = float(cells.e2[i][a]);
      mp[a][j] = float(cells.m_pinv[i][std::size_t(a)]);
    }
  }
  // Whole vectors: the padding lanes are zero (no area, no slip).
  const std::size_t padded = (count + 15) / 16 * 16;
  for (std::size_t j = count; j < padded; ++j) {
    px[j] = py[j] = pz[j] = ux[j] = uy[j] = uz[j] = rho[j] = 0;
    nx[j] = ny[j] = nz[j] = area[j] = 0;
    for (int a = 0; a < 3; ++a) e1[a][j] = e2[a][j] = mp[a][j] = 0;
  }
  const float law_c0 = float(law.c0), law_c1 = float(law.c1), law_linear = float(law.linear),
              law_switch = float(law.switch_speed), inv_rho_w = float(1.0 / rho_w), tiny = 1e-30f;
  float slip[3][kGeneralChunk];
#pragma omp simd
  for (std::size_t j = 0; j < padded; ++j) {
    const float un = ux[j] * nx[j] + uy[j] * ny[j] + uz[j] * nz[j];
    const float tx = ux[j] - un * nx[j], ty = uy[j] - un * ny[j], tz = uz[j] - un * nz[j];
    const float speed = std::sqrt(tx * tx + ty * ty + tz * tz);
    const float safe = std::max(speed, tiny);
    const float x = law_c0 + law_c1 * speed;
    const float tau = speed <= law_switch ? law_linear * speed : x * std::sqrt(x * std::sqrt(x));
    const float g = rho[j] * tau * area[j] / safe;  // target = g u_t
    const float rx = 2.0f * px[j] - g * tx, ry = 2.0f * py[j] - g * ty, rz = 2.0f * pz[j] - g * tz;
    const float r1 = e1[0][j] * rx + e1[1][j] * ry + e1[2][j] * rz;
    const float r2 = e2[0][j] * rx + e2[1][j] * ry + e2[2][j] * rz;
    const float a1 = (mp[0][j] * r1 + mp[1][j] * r2) * inv_rho_w;
    const float a2 = (mp[1][j] * r1 + mp[2][j] * r2) * inv_rho_w;
    float sx = a1 * e1[0][j] + a2 * e2[0][j], sy = a1 * e1[1][j] + a2 * e2[1][j],
          sz = a1 * e1[2][j] + a2 * e2[2][j];
    // The bounds of the general kernel: along the flow between 0 and the speed, across at most it.
    const float ex = tx / safe, ey = ty / safe, ez = tz / safe;
    const float d = sx * ex + sy * ey + sz * ez;
    const float along = std::min(std::max(d, 0.0f), speed);
    const float cx = sx - d * ex, cy = sy - d * ey, cz = sz - d * ez;
    const float cn = std::sqrt(cx * cx + cy * cy + cz * cz);
    const float scale = cn > speed ? speed / std::max(cn, tiny) : 1.0f;
    const float on = speed > 0 && area[j] > 0 ? 1.0f : 0.0f;
    slip[0][j] = on * (along * ex + scale * cx);
    slip[1][j] = on * (along * ey + scale * cy);
    slip[2][j] = on * (along * ez + scale * cz);
  }
  WallLoad load;
  for (std::size_t j = 0; j < count; ++j) {
    const std::size_t i = idx[j];
    float fx = 0, fy = 0, fz = 0, mass = 0;
    for (std::size_t k = cells.first[i]; k < cells.first[i + 1]; ++k) {
      const int q = links.dir[k];
      const float cxq = float(kCx[q]), cyq = float(kCy[q]), czq = float(kCz[q]);
      const float corr = float(-2.0 * kW[q] * rho_w / kCs2) *
                         (cxq * slip[0][j] + cyq * slip[1][j] + czq * slip[2][j]);
      const auto slots = link_slots(pdf, now, links, k);
      const float post = *slots.from.p;
      *slots.to.p = post + corr;
      const float out = 2.0f * post + corr;
      fx += out * cxq;
      fy += out * cyq;
      fz += out * czq;
      mass += corr;
      links.correction[k] = double(corr);
    }
    const Vec3 f = Vec3(fx, fy, fz) - cells.area[i] / 3.0 * cells.normal[i];
    load.force += f;
    load.torque += (cells.centre[i] - origin).cross(f);
    load.mass += double(mass);
  }
  return load;
}

}  // namespace

template <class T>
WallLoad apply_wall_function(PdfField<T>& pdf, AaState now, BounceBackLinks& links,
                             const WallFunctionCells& cells, const WernerWengle& law,
                             const MomentFields<T>& moments, double rho_w, const Vec3& origin) {
  const WernerWengleCell cell_law(law);
  // Each summand applies its links as a side effect: deterministic_sum calls it once per block.
  if constexpr (std::is_same_v<T, float>) {
    return deterministic_sum(
        cells.block_first.size() - 1,
        [&](std::size_t b) {
          WallLoad load;
          std::size_t idx[kGeneralChunk];
          std::size_t count = 0;
          const auto flush = [&] {
            if (count > 0)
              load += general_chunk(pdf, now, links, cells, idx, count, cell_law, moments, rho_w,
                                    origin);
            count = 0;
          };
          // Flat runs shorter than a vector go with the general cells: the staircase of the
          // jet mill's cylinder holds hundreds of flat runs of one or two cells, for which the
          // run kernel's set-up costs more than the general formulas, computed in lanes.
          for (std::size_t u = cells.block_first[b]; u < cells.block_first[b + 1]; ++u) {
            const std::size_t i0 = cells.unit_first[u], i1 = cells.unit_first[u + 1];
            if (cells.unit_flat[u] && i1 - i0 >= kShortRun) {
              flush();
              load += apply_flat_run(pdf, now, links, cells, u, cell_law, moments, rho_w, origin);
              continue;
            }
            for (std::size_t i = i0; i < i1; ++i) {
              if (count == kGeneralChunk) flush();
              idx[count++] = i;
            }
          }
          flush();
          return load;
        },
        WallLoad{}, 1);
  } else {
    // Double: one cell at a time, any staircase shape (single takes general_chunk above).
    using Codec = PopulationCodec<T>;
    const auto general = [&](std::size_t i) -> WallLoad {
      const std::size_t k0 = cells.first[i], k1 = cells.first[i + 1];
      // The links' slots are found once: f_q* is read here and the reflected value written
      // below (a cell has at most kQ - 1 links).
      double post[kQ - 1];
      T* to[kQ - 1];
      Vec3 p = Vec3::Zero();  // momentum the links carry into the wall
      for (std::size_t k = k0; k < k1; ++k) {
        const int q = links.dir[k];
        const auto slots = link_slots(pdf, now, links, k);
        post[k - k0] = slots.from;
        to[k - k0] = slots.to.p;
        p += post[k - k0] * Vec3(kCx[q], kCy[q], kCz[q]);
      }
      Vec3 slip = Vec3::Zero();
      if (cells.area[i] > 0) {
        // The cell's density and velocity as its collision this step saw them.
        const std::size_t c = std::size_t(cells.cell[i]);
        const double rho = moments.rho[c];
        const Vec3 u(double(moments.u[0][c]), double(moments.u[1][c]), double(moments.u[2][c]));
        const Vec3& n = cells.normal[i];
        const Vec3 ut = u - u.dot(n) * n;
        const double speed = ut.norm();
        Vec3 target = Vec3::Zero();
        if (speed > 0) target = rho * cell_law.kinematic_stress(speed) * cells.area[i] / speed * ut;
        const Vec3 r = 2.0 * p - target;
        const double r1 = cells.e1[i].dot(r), r2 = cells.e2[i].dot(r);
        const auto& mi = cells.m_pinv[i];
        slip = ((mi[0] * r1 + mi[1] * r2) * cells.e1[i] + (mi[1] * r1 + mi[2] * r2) * cells.e2[i]) /
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
        *to[k - k0] = Codec::store(post[k - k0] + corr, q);
        force += (2.0 * post[k - k0] + corr) * cq;
        mass += corr;
      }
      WallLoad load;
      load.force = force;
      load.torque = (cells.centre[i] - origin).cross(force);
      load.mass = mass;
      return load;
    };
    return deterministic_sum(
        cells.block_first.size() - 1,
        [&](std::size_t b) {
          WallLoad load;
          for (std::size_t u = cells.block_first[b]; u < cells.block_first[b + 1]; ++u)
            if (cells.unit_flat[u])
              load += apply_flat_run(pdf, now, links, cells, u, cell_law, moments, rho_w, origin);
            else
              load += general(cells.unit_first[u]);
          return load;
        },
        WallLoad{}, 1);
  }
}

template WallLoad apply_wall_function(PdfField<double>&, AaState, BounceBackLinks&,
                                      const WallFunctionCells&, const WernerWengle&,
                                      const MomentFields<double>&, double, const Vec3&);
template WallLoad apply_wall_function(PdfField<float>&, AaState, BounceBackLinks&,
                                      const WallFunctionCells&, const WernerWengle&,
                                      const MomentFields<float>&, double, const Vec3&);

}  // namespace lbdem::lbm
