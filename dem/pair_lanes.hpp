#pragma once
// The Hertz-Mindlin and linear laws, with any rolling model (none, constant torque, EPSD) and with
// or without van der Waals cohesion, evaluated over a block's touching pairs in SIMD lanes
// (docs/performance.md has the measurements); pairs apart but within the cohesion's reach take the
// scalar law. The scalar law (contact_law.hpp) is bound by its dependency chain, three
// roots and two divisions in series per contact; here each lane takes one contact, branch-free:
// both sides of the sliding test are computed and selected. The arithmetic is the scalar law's,
// term by term (contact_law.hpp gives the physics and the energy bookkeeping), so the results agree
// to round-off (tested against it in tests/dem/test_pair_lanes.cpp). Private to dem_passes.hpp.
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "dem/contact/contact_law.hpp"
#include "dem/particles.hpp"

namespace lbdem::dem {

/// The touching pairs of a block, gathered by the distance loop, and what the lanes return.
struct LaneBuffer {
  std::vector<std::int32_t> k, i, j;  // pair index, its row (particle i), its partner j
  std::vector<double> dx, dy, dz;     // x_j - x_i (minimum image)
  std::vector<double> dist;           // |x_j - x_i| as the distance test took it
  // Results: force on i, n x F_t (the torque per lever arm), the lever arms, the law's energies,
  // the normal force, the normal and tangential relative speeds (impact record) and the overlap.
  std::vector<double> fx, fy, fz, cx, cy, cz, ai, aj;
  std::vector<double> p_nd, p_td, e_sl, e_st, u_el, fn, vn, vt, delta;
  std::vector<double> mx, my, mz, e_ro;  // rolling torque on i and its loss

  void clear() {
    k.clear(), i.clear(), j.clear(), dx.clear(), dy.clear(), dz.clear(), dist.clear();
  }
  void push(std::size_t pair, std::size_t row, std::uint32_t partner, const Vec3& d, double r) {
    k.push_back(std::int32_t(pair)), i.push_back(std::int32_t(row)),
        j.push_back(std::int32_t(partner));
    dx.push_back(d.x()), dy.push_back(d.y()), dz.push_back(d.z()), dist.push_back(r);
  }
  void size_results() {
    const std::size_t n = k.size();
    for (auto* v : {&fx,   &fy,   &fz, &cx, &cy, &cz,    &ai, &aj, &p_nd, &p_td, &e_sl,
                    &e_st, &u_el, &fn, &vn, &vt, &delta, &mx, &my, &mz,   &e_ro})
      v->resize(n);
  }
};

/// Whether contact_lanes has the law's form: the normal, rolling and cohesion models it spells out
/// below. A law without it (a new model) takes the scalar kernel, which every law has.
template <class T, class... Of>
inline constexpr bool kOneOf = (std::is_same_v<T, Of> || ...);
template <class Law>
constexpr bool has_lane_form() {
  const bool normal = kOneOf<typename Law::Normal, HertzMindlin, LinearSpringDashpot>;
  const bool rolling = kOneOf<typename Law::Rolling, NoRolling, ConstantTorqueRolling, EpsdRolling>;
  const bool cohesion = kOneOf<typename Law::Cohesion, NoCohesion, VanDerWaals>;
  return normal && rolling && cohesion;
}

/// Turns a spring (x0, x1, x2) into the plane normal to n, keeping its length; one at right
/// angles to the plane becomes zero (as the scalar law does). Branch-free, for the lanes.
inline void into_tangent_plane(double& x0, double& x1, double& x2, double nx, double ny,
                               double nz) {
  const double xx = x0 * x0 + x1 * x1 + x2 * x2;
  const double xn = x0 * nx + x1 * ny + x2 * nz;
  const double t0 = x0 - xn * nx, t1 = x1 - xn * ny, t2 = x2 - xn * nz;
  const double tt = t0 * t0 + t1 * t1 + t2 * t2;
  const double sq = std::sqrt(xx / (tt > 0 ? tt : 1.0));  // unconditional: no branch in lanes
  const double sc = tt > 0 ? sq : 0.0;
  x0 = xx > 0 ? t0 * sc : x0;
  x1 = xx > 0 ? t1 * sc : x1;
  x2 = xx > 0 ? t2 * sc : x2;
}

/// Evaluates every pair of `b` (touching: delta > 0) with the parameters `prm` of one material
/// pair, updating the tangential springs in `history` (and the rolling springs in `rolling` for
/// EPSD) and writing the results into `b`. Normal: HertzMindlin or LinearSpringDashpot; Rolling:
/// NoRolling, ConstantTorqueRolling or EpsdRolling (rolling_resistance.hpp); Cohesion: NoCohesion
/// or VanDerWaals (van_der_waals.hpp).
template <class Normal, class Rolling, class Cohesion>
void contact_lanes(const typename ContactLaw<Normal, Rolling, Cohesion>::Params& prm,
                   const ParticleArrays& p, const std::vector<Vec3>& v_pred,
                   const std::vector<Vec3>& w_pred, SpringHistory* history, RollingHistory* rolling,
                   double dt, LaneBuffer& b) {
  constexpr bool kHertz = std::is_same_v<Normal, HertzMindlin>;
  static_assert(kHertz || std::is_same_v<Normal, LinearSpringDashpot>);
  constexpr bool kTorque = std::is_same_v<Rolling, ConstantTorqueRolling>;
  constexpr bool kEpsd = std::is_same_v<Rolling, EpsdRolling>;
  static_assert(kTorque || kEpsd || std::is_same_v<Rolling, NoRolling>);
  constexpr bool kVdw = std::is_same_v<Cohesion, VanDerWaals>;
  static_assert(kVdw || std::is_same_v<Cohesion, NoCohesion>);
  b.size_results();
  double mu_r = 0, arm = 0;
  if constexpr (kTorque || kEpsd) mu_r = prm.rolling.mu_r, arm = prm.rolling.arm_factor;
  // Van der Waals in contact: the gap is clamped to h_min (van_der_waals.hpp).
  double hamaker = 0, h_min = 0, h_max = 0;
  if constexpr (kVdw)
    hamaker = prm.cohesion.hamaker, h_min = prm.cohesion.h_min, h_max = prm.cohesion.h_max;
  double* __restrict RH = reinterpret_cast<double*>(rolling);  // theta (3) and kr per contact
  const double* IN = p.inertia.data();
  double* __restrict MX = b.mx.data();
  double* __restrict MY = b.my.data();
  double* __restrict MZ = b.mz.data();
  double* __restrict ERO = b.e_ro.data();
  // Hertz: E*, G*; linear: k, k_t / k_n and an absolute damping coefficient if set.
  double E = 0, G = 0, k_lin = 0, kt_ratio = 0, gamma_abs = 0;
  if constexpr (kHertz) {
    E = prm.normal.e_star, G = prm.normal.g_star;
  } else {
    k_lin = prm.normal.k, kt_ratio = prm.normal.kt_ratio, gamma_abs = prm.normal.gamma_abs;
  }
  const double cd = prm.normal.c_damp;
  const double tr = prm.tangential_damping ? prm.normal.t_ratio : 0.0, mu = prm.friction;
  const double* R = p.radius.data();
  const double* M = p.mass.data();
  const double* V = p.v.data()->data();
  const double* W = p.omega.data()->data();
  const double* VP = v_pred.data()->data();
  const double* WP = w_pred.data()->data();
  const std::int32_t* K = b.k.data();
  const std::int32_t* I = b.i.data();
  const std::int32_t* J = b.j.data();
  double* __restrict H = reinterpret_cast<double*>(history);  // xi (3) and kt per contact
  const double* DX = b.dx.data();
  const double* DY = b.dy.data();
  const double* DZ = b.dz.data();
  const double* DS = b.dist.data();
  double* __restrict FX = b.fx.data();
  double* __restrict FY = b.fy.data();
  double* __restrict FZ = b.fz.data();
  double* __restrict CX = b.cx.data();
  double* __restrict CY = b.cy.data();
  double* __restrict CZ = b.cz.data();
  double* __restrict AI = b.ai.data();
  double* __restrict AJ = b.aj.data();
  double* __restrict PND = b.p_nd.data();
  double* __restrict PTD = b.p_td.data();
  double* __restrict ESL = b.e_sl.data();
  double* __restrict EST = b.e_st.data();
  double* __restrict UEL = b.u_el.data();
  double* __restrict FN = b.fn.data();
  double* __restrict VN = b.vn.data();
  double* __restrict VT = b.vt.data();
  double* __restrict DL = b.delta.data();
  const std::size_t n = b.k.size();
#pragma omp simd
  for (std::size_t q = 0; q < n; ++q) {
    // int indices: GCC 12 gathers with 32-bit offsets (a 64-bit index left the loop scalar).
    const int i = I[q], j = J[q], hk = 4 * K[q];
    const int a3 = 3 * i, b3 = 3 * j;
    const double dx = DX[q], dy = DY[q], dz = DZ[q], dist = DS[q];
    const double ri = R[i], rj = R[j], rs = ri + rj;
    const double nx = dx / dist, ny = dy / dist, nz = dz / dist;
    const double delta = rs - dist;
    const double r_star = ri * rj / rs, m_star = M[i] * M[j] / (M[i] + M[j]);
    const double half = 0.5 * delta, ai = ri - half, aj = rj - half;
    // v_rel = vp_i - vp_j + (ai wp_i + aj wp_j) x n; v_half likewise from v and omega.
    const double ex = ai * WP[a3] + aj * WP[b3], ey = ai * WP[a3 + 1] + aj * WP[b3 + 1],
                 ez = ai * WP[a3 + 2] + aj * WP[b3 + 2];
    const double vx = VP[a3] - VP[b3] + (ey * nz - ez * ny),
                 vy = VP[a3 + 1] - VP[b3 + 1] + (ez * nx - ex * nz),
                 vz = VP[a3 + 2] - VP[b3 + 2] + (ex * ny - ey * nx);
    const double hx_ = ai * W[a3] + aj * W[b3], hy_ = ai * W[a3 + 1] + aj * W[b3 + 1],
                 hz_ = ai * W[a3 + 2] + aj * W[b3 + 2];
    const double ux = V[a3] - V[b3] + (hy_ * nz - hz_ * ny),
                 uy = V[a3 + 1] - V[b3 + 1] + (hz_ * nx - hx_ * nz),
                 uz = V[a3 + 2] - V[b3 + 2] + (hx_ * ny - hy_ * nx);
    // Cohesion in contact (the gap -delta < 0 <= h_max): the pull at h = max(gap, h_min), its
    // potential continued linearly below h_min.
    double f_coh = 0, u_coh = 0;
    if constexpr (kVdw) {
      const double gap = -delta, h = gap > h_min ? gap : h_min;
      const double c = hamaker * r_star / 6.0, f = c / (h * h);
      const double u = -c * (1.0 / h - 1.0 / h_max) - (gap < h_min ? f * (h_min - gap) : 0.0);
      f_coh = hamaker > 0 ? f : 0.0;
      u_coh = hamaker > 0 ? u : 0.0;
    }
    // Hertz normal force with Tsuji damping; Mindlin's k_t.
    double kn, f_el, kt, u_n;
    if constexpr (kHertz) {
      const double a = std::sqrt(r_star * delta);
      kn = 4.0 / 3.0 * E * a, f_el = kn * delta, kt = 8.0 * G * a, u_n = 0.4 * f_el * delta;
    } else {
      kn = k_lin, f_el = k_lin * delta, kt = kt_ratio * k_lin, u_n = 0.5 * k_lin * delta * delta;
    }
    const double vn = vx * nx + vy * ny + vz * nz;
    double gam = cd * std::sqrt(m_star * kn);
    if constexpr (!kHertz) gam = gamma_abs > 0 ? gamma_abs : gam;
    const double fnv = f_el + gam * vn;
    const double vtx = vx - vn * nx, vty = vy - vn * ny, vtz = vz - vn * nz;
    // The spring turned into the tangent plane, its length kept.
    double x0 = H[hk], x1 = H[hk + 1], x2 = H[hk + 2];
    const double kt_old = H[hk + 3];
    into_tangent_plane(x0, x1, x2, nx, ny, nz);
    const double s0 = x0, s1 = x1, s2 = x2;
    // Grown by the relative displacement of the step (mid-step velocity).
    const double un = ux * nx + uy * ny + uz * nz;
    x0 += (ux - un * nx) * dt;
    x1 += (uy - un * ny) * dt;
    x2 += (uz - un * nz) * dt;
    const double gt = gam * tr;
    const double cap = mu * (fnv > 0 ? fnv : 0.0);
    const double f0 = -kt * x0, f1 = -kt * x1, f2 = -kt * x2;
    const double ff = f0 * f0 + f1 * f1 + f2 * f2;
    const bool slide = ff > cap * cap;
    // Sliding: the spring cut back to the cap, no dashpot.
    const double r_cut = cap / std::sqrt(slide ? ff : 1.0);
    const double g0 = f0 * r_cut, g1 = f1 * r_cut, g2 = f2 * r_cut;
    const double y0 = -g0 / kt, y1 = -g1 / kt, y2 = -g2 / kt;
    const double esl =
        0.5 * ((kt_old * s0 + kt * y0) * (x0 - y0) + (kt_old * s1 + kt * y1) * (x1 - y1) +
               (kt_old * s2 + kt * y2) * (x2 - y2));
    // Sticking: spring + dashpot, the dashpot limited so that |F_t| <= cap.
    double d0 = f0 - gt * vtx, d1 = f1 - gt * vty, d2 = f2 - gt * vtz;
    const double dd = d0 * d0 + d1 * d1 + d2 * d2;
    const double root = std::sqrt(dd > 0 ? dd : 1.0);
    const double lim = dd > cap * cap ? cap / root : 1.0;
    d0 *= lim, d1 *= lim, d2 *= lim;
    const double ptd = -((d0 - f0) * vtx + (d1 - f1) * vty + (d2 - f2) * vtz);
    const double ft0 = slide ? g0 : d0, ft1 = slide ? g1 : d1, ft2 = slide ? g2 : d2;
    x0 = slide ? y0 : x0, x1 = slide ? y1 : x1, x2 = slide ? y2 : x2;
    H[hk] = x0, H[hk + 1] = x1, H[hk + 2] = x2, H[hk + 3] = kt;
    const double fnet = f_coh - fnv;
    FX[q] = fnet * nx + ft0, FY[q] = fnet * ny + ft1, FZ[q] = fnet * nz + ft2;
    CX[q] = ny * ft2 - nz * ft1, CY[q] = nz * ft0 - nx * ft2, CZ[q] = nx * ft1 - ny * ft0;
    AI[q] = ai, AJ[q] = aj;
    PND[q] = gam * vn * vn;
    PTD[q] = slide ? 0.0 : ptd;
    ESL[q] = slide ? esl : 0.0;
    double est = 0.5 * (kt - kt_old) * (s0 * x0 + s1 * x1 + s2 * x2);
    double uel = u_coh + u_n + 0.5 * kt * (x0 * x0 + x1 * x1 + x2 * x2);
    FN[q] = fnv;
    VN[q] = vn;
    VT[q] = std::sqrt(vtx * vtx + vty * vty + vtz * vtz);
    DL[q] = delta;
    if constexpr (kTorque) {
      // Constant directional torque on the relative rolling rate (end of step), limited to what
      // stops it within the step; none without a normal load or a rolling rate.
      const double wx = WP[a3] - WP[b3], wy = WP[a3 + 1] - WP[b3 + 1], wz = WP[a3 + 2] - WP[b3 + 2];
      const double wn = wx * nx + wy * ny + wz * nz;
      const double rx = wx - wn * nx, ry = wy - wn * ny, rz = wz - wn * nz;
      const double w = std::sqrt(rx * rx + ry * ry + rz * rz);
      const double i_star = IN[i] * IN[j] / (IN[i] + IN[j]);
      const double m_cap = mu_r * arm * r_star * fnv, m_stop = i_star * w / dt;
      const double m = m_cap < m_stop ? m_cap : m_stop;
      const bool on = w > 0 && fnv > 0;
      const double per = on ? m / (w > 0 ? w : 1.0) : 0.0;
      MX[q] = -per * rx, MY[q] = -per * ry, MZ[q] = -per * rz;
      ERO[q] = on ? m * w * dt : 0.0;
    }
    if constexpr (kEpsd) {
      // Elastic-plastic rolling spring: theta turned into the tangent plane (length kept), grown by
      // the step's relative rotation (mid-step rate, tangential part), k_r = 2.25 k_n mu_r^2 r_a^2,
      // the torque capped at mu_r r_a F_n with the plastic rotation's loss.
      const int hr = 4 * K[q];
      const double ra = arm * r_star, kr = 2.25 * kn * mu_r * mu_r * ra * ra;
      double h0 = RH[hr], h1 = RH[hr + 1], h2 = RH[hr + 2];
      const double kr_old = RH[hr + 3];
      into_tangent_plane(h0, h1, h2, nx, ny, nz);
      const double q0 = h0, q1 = h1, q2 = h2;
      const double m_start = kr_old * std::sqrt(h0 * h0 + h1 * h1 + h2 * h2);
      const double wx = W[a3] - W[b3], wy = W[a3 + 1] - W[b3 + 1], wz = W[a3 + 2] - W[b3 + 2];
      const double wn = wx * nx + wy * ny + wz * nz;
      h0 += (wx - wn * nx) * dt;
      h1 += (wy - wn * ny) * dt;
      h2 += (wz - wn * nz) * dt;
      double m0 = -kr * h0, m1 = -kr * h1, m2 = -kr * h2;
      const double mcap = mu_r * ra * (fnv > 0 ? fnv : 0.0);
      const double mm = std::sqrt(m0 * m0 + m1 * m1 + m2 * m2);
      const bool plastic = mm > mcap;
      const double mr = mcap / (plastic ? mm : 1.0);
      m0 = plastic ? m0 * mr : m0, m1 = plastic ? m1 * mr : m1, m2 = plastic ? m2 * mr : m2;
      const double ikr = 1.0 / (kr > 0 ? kr : 1.0);
      const double c0 = kr > 0 ? -m0 * ikr : 0.0, c1 = kr > 0 ? -m1 * ikr : 0.0,
                   c2 = kr > 0 ? -m2 * ikr : 0.0;
      const double l0 = h0 - c0, l1 = h1 - c1, l2 = h2 - c2;
      const double slip = std::sqrt(l0 * l0 + l1 * l1 + l2 * l2);
      ERO[q] = plastic ? 0.5 * (m_start + mcap) * slip : 0.0;
      h0 = plastic ? c0 : h0, h1 = plastic ? c1 : h1, h2 = plastic ? c2 : h2;
      RH[hr] = h0, RH[hr + 1] = h1, RH[hr + 2] = h2, RH[hr + 3] = kr;
      est += 0.5 * (kr - kr_old) * (q0 * h0 + q1 * h1 + q2 * h2);
      uel += 0.5 * kr * (h0 * h0 + h1 * h1 + h2 * h2);
      MX[q] = m0, MY[q] = m1, MZ[q] = m2;
    }
    EST[q] = est;
    UEL[q] = uel;
  }
}

}  // namespace lbdem::dem
