// Probe 2: the whole pair evaluation (geometry from particle arrays by index, Hertz-Mindlin law
// without rolling or cohesion, booking into a tally) per contact: lbdem's scalar pair_kernel shape
// (Eigen, AoS history and tally) against a branch-free lane form (SoA pair arrays, omp simd).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>
#include <cmath>
#include <algorithm>
#include <Eigen/Geometry>
#include "dem/contact/contact_law.hpp"
#include "dem/pair_list.hpp"
using namespace lbdem;
using namespace lbdem::dem;
using Law = ContactLaw<HertzMindlin, NoRolling, NoCohesion>;

// The tally (ContactTally) as it was when this probe was timed (2026-12-02: 13 doubles;
// dem/pair_list.hpp split the last five into ContactRecord on 2026-12-04), kept here so the probe
// builds as timed.
struct ProbeTally {
  double e_normal_damping = 0, e_tangential_damping = 0;
  double p_normal_damping = 0, p_tangential_damping = 0;
  double e_sliding = 0, e_rolling = 0, e_stiffness = 0, u_elastic = 0;
  double t_start = 0, vn_impact = 0, vt_impact = 0, max_overlap = 0, max_force = 0;
};

struct Parts {
  std::vector<Vec3> x, v, w, vp, wp;
  std::vector<double> r, m;
};
struct Pairs {
  std::vector<uint32_t> i, j, slot;
  std::vector<ContactHistory> h;
  std::vector<ProbeTally> t;
  std::vector<uint8_t> st;
  std::vector<Vec3> jf, jt, fi, ti;
};
struct PairsSoa {
  std::vector<double> xx, xy, xz, kt, end, etd, pnd, ptd, esl, est, uel, vni, vti, tst;
};

[[gnu::noinline, gnu::flatten]] void scalar(const Law::Params& prm, const Parts& p, Pairs& pl,
                                            double dt, double time) {
  for (size_t k = 0; k < pl.i.size(); ++k) {
    const uint32_t i = pl.i[k], j = pl.j[k];
    const Vec3 d = p.x[j] - p.x[i];
    const double dist = d.norm(), rs = p.r[i] + p.r[j];
    ContactGeometry g;
    g.n = d / dist;
    g.delta = rs - dist;
    g.r_star = p.r[i] * p.r[j] / rs;
    g.m_star = p.m[i] * p.m[j] / (p.m[i] + p.m[j]);
    g.i_star = 0;
    const double half = 0.5 * std::max(g.delta, 0.0), ai = p.r[i] - half, aj = p.r[j] - half;
    g.v_rel = p.vp[i] - p.vp[j] + (ai * p.wp[i] + aj * p.wp[j]).cross(g.n);
    g.w_rel = p.wp[i] - p.wp[j];
    g.v_half = p.v[i] - p.v[j] + (ai * p.w[i] + aj * p.w[j]).cross(g.n);
    g.w_half = p.w[i] - p.w[j];
    const ContactForce c = Law::evaluate(prm, g, pl.h[k], dt);
    const Vec3 tc = g.n.cross(c.ft);
    pl.jf[pl.slot[k]] = -c.force;
    pl.jt[pl.slot[k]] = aj * tc;
    ProbeTally& t = pl.t[k];
    if (!(pl.st[k] & kTouching)) {
      const double vn = g.v_rel.dot(g.n);
      t = ProbeTally{};
      t.t_start = time;
      t.vn_impact = vn;
      t.vt_impact = (g.v_rel - vn * g.n).norm();
    }
    t.e_normal_damping += 0.5 * dt * (t.p_normal_damping + c.p_normal_damping);
    t.e_tangential_damping += 0.5 * dt * (t.p_tangential_damping + c.p_tangential_damping);
    t.p_normal_damping = c.p_normal_damping;
    t.p_tangential_damping = c.p_tangential_damping;
    t.e_sliding += c.e_sliding;
    t.e_stiffness += c.e_stiffness;
    t.u_elastic = c.u_elastic;
    pl.st[k] = kTouching | kInteracting;
    pl.fi[k] = c.force;
    pl.ti[k] = ai * tc;
  }
}

template <int W>
[[gnu::noinline]] void lanes(const Law::Params& prm, const Parts& p, Pairs& pl, PairsSoa& s,
                             double dt, double time) {
  const double E = prm.normal.e_star, G = prm.normal.g_star, cd = prm.normal.c_damp,
               tr = prm.normal.t_ratio, mu = prm.friction;
  const size_t m = pl.i.size();
  const double* X = p.x.data()->data();
  const double* V = p.v.data()->data();
  const double* Wv = p.w.data()->data();
  const double* VP = p.vp.data()->data();
  const double* WP = p.wp.data()->data();
  const double* R = p.r.data();
  const double* M = p.m.data();
  double* JF = pl.jf.data()->data();
  double* JT = pl.jt.data()->data();
  double* FI = pl.fi.data()->data();
  double* TI = pl.ti.data()->data();
  const uint32_t* I = pl.i.data();
  const uint32_t* J = pl.j.data();
  const uint32_t* SL = pl.slot.data();
  double* __restrict xx = s.xx.data();
  double* __restrict xy = s.xy.data();
  double* __restrict xz = s.xz.data();
  double* __restrict kt = s.kt.data();
#pragma omp simd
  for (size_t k = 0; k < m; ++k) {
    const int a = 3 * int(I[k]), b = 3 * int(J[k]);
    const double dx = X[b] - X[a], dy = X[b + 1] - X[a + 1], dz = X[b + 2] - X[a + 2];
    const double dist = std::sqrt(dx * dx + dy * dy + dz * dz), inv = 1.0 / dist;
    const double ri = R[a / 3], rj = R[b / 3], rs = ri + rj;
    const double nx = dx * inv, ny = dy * inv, nz = dz * inv, d = rs - dist;
    const double rst = ri * rj / rs, mst = M[a / 3] * M[b / 3] / (M[a / 3] + M[b / 3]);
    const double half = 0.5 * std::max(d, 0.0), ai = ri - half, aj = rj - half;
    // v_rel = vp_i - vp_j + (ai wp_i + aj wp_j) x n ; v_half likewise
    const double cx = ai * WP[a] + aj * WP[b], cy = ai * WP[a + 1] + aj * WP[b + 1],
                 cz = ai * WP[a + 2] + aj * WP[b + 2];
    const double vx = VP[a] - VP[b] + cy * nz - cz * ny,
                 vy = VP[a + 1] - VP[b + 1] + cz * nx - cx * nz,
                 vz = VP[a + 2] - VP[b + 2] + cx * ny - cy * nx;
    const double ex = ai * Wv[a] + aj * Wv[b], ey = ai * Wv[a + 1] + aj * Wv[b + 1],
                 ez = ai * Wv[a + 2] + aj * Wv[b + 2];
    const double hx = V[a] - V[b] + ey * nz - ez * ny, hy = V[a + 1] - V[b + 1] + ez * nx - ex * nz,
                 hz = V[a + 2] - V[b + 2] + ex * ny - ey * nx;
    const double sa = std::sqrt(rst * d);
    const double kn = 4.0 / 3.0 * E * sa, fel = kn * d, ktn = 8.0 * G * sa;
    const double vn = vx * nx + vy * ny + vz * nz;
    const double gam = cd * std::sqrt(mst * kn);
    const double fn = fel + gam * vn;
    const double vtx = vx - vn * nx, vty = vy - vn * ny, vtz = vz - vn * nz;
    double x0 = xx[k], x1 = xy[k], x2v = xz[k];
    const double x2 = x0 * x0 + x1 * x1 + x2v * x2v;
    const double sn = x0 * nx + x1 * ny + x2v * nz;
    const double t0 = x0 - sn * nx, t1 = x1 - sn * ny, t2v = x2v - sn * nz;
    const double t2 = t0 * t0 + t1 * t1 + t2v * t2v;
    const double sc = (x2 > 0 && t2 > 0) ? std::sqrt(x2 / t2) : 0.0;
    x0 = x2 > 0 ? t0 * sc : x0;
    x1 = x2 > 0 ? t1 * sc : x1;
    x2v = x2 > 0 ? t2v * sc : x2v;
    const double s0 = x0, s1 = x1, s2 = x2v, kto = kt[k];
    const double hn = hx * nx + hy * ny + hz * nz;
    x0 += (hx - hn * nx) * dt;
    x1 += (hy - hn * ny) * dt;
    x2v += (hz - hn * nz) * dt;
    const double gt = gam * tr;
    const double cap = mu * std::max(fn, 0.0);
    const double f0 = -ktn * x0, f1 = -ktn * x1, f2 = -ktn * x2v;
    const double fs2 = f0 * f0 + f1 * f1 + f2 * f2;
    const bool slide = fs2 > cap * cap;
    const double r = cap / std::sqrt(slide ? fs2 : 1.0);
    const double sf0 = f0 * r, sf1 = f1 * r, sf2 = f2 * r;
    const double ik = 1.0 / ktn;
    const double nx0 = -sf0 * ik, nx1 = -sf1 * ik, nx2 = -sf2 * ik;
    const double esl =
        0.5 * ((kto * s0 + ktn * nx0) * (x0 - nx0) + (kto * s1 + ktn * nx1) * (x1 - nx1) +
               (kto * s2 + ktn * nx2) * (x2v - nx2));
    double d0 = f0 - gt * vtx, d1 = f1 - gt * vty, d2 = f2 - gt * vtz;
    const double dd = d0 * d0 + d1 * d1 + d2 * d2;
    const double lim = dd > cap * cap ? cap / std::sqrt(dd) : 1.0;
    d0 *= lim, d1 *= lim, d2 *= lim;
    const double ptd = slide ? 0.0 : -((d0 - f0) * vtx + (d1 - f1) * vty + (d2 - f2) * vtz);
    const double ft0 = slide ? sf0 : d0, ft1 = slide ? sf1 : d1, ft2 = slide ? sf2 : d2;
    x0 = slide ? nx0 : x0, x1 = slide ? nx1 : x1, x2v = slide ? nx2 : x2v;
    const double pnd = gam * vn * vn;
    // booking (SoA tally), start of contact by select
    const bool start = s.tst[k] < 0;
    const double vt = std::sqrt(vtx * vtx + vty * vty + vtz * vtz);
    s.tst[k] = start ? time : s.tst[k];
    s.vni[k] = start ? vn : s.vni[k];
    s.vti[k] = start ? vt : s.vti[k];
    const double pnd0 = start ? 0.0 : s.pnd[k], ptd0 = start ? 0.0 : s.ptd[k];
    s.end[k] = (start ? 0.0 : s.end[k]) + 0.5 * dt * (pnd0 + pnd);
    s.etd[k] = (start ? 0.0 : s.etd[k]) + 0.5 * dt * (ptd0 + ptd);
    s.pnd[k] = pnd, s.ptd[k] = ptd;
    s.esl[k] = (start ? 0.0 : s.esl[k]) + (slide ? esl : 0.0);
    s.est[k] += 0.5 * (ktn - kto) * (s0 * x0 + s1 * x1 + s2 * x2v);
    s.uel[k] = 0.4 * fel * d + 0.5 * ktn * (x0 * x0 + x1 * x1 + x2v * x2v);
    const double Fx = -fn * nx + ft0, Fy = -fn * ny + ft1, Fz = -fn * nz + ft2;
    const double tx = ny * ft2 - nz * ft1, ty = nz * ft0 - nx * ft2, tz = nx * ft1 - ny * ft0;
    const int q = 3 * int(SL[k]);
    JF[q] = -Fx, JF[q + 1] = -Fy, JF[q + 2] = -Fz;
    JT[q] = aj * tx, JT[q + 1] = aj * ty, JT[q + 2] = aj * tz;
    FI[3 * k] = Fx, FI[3 * k + 1] = Fy, FI[3 * k + 2] = Fz;
    TI[3 * k] = ai * tx, TI[3 * k + 1] = ai * ty, TI[3 * k + 2] = ai * tz;
    xx[k] = x0, xy[k] = x1, xz[k] = x2v, kt[k] = ktn;
  }
}

int main() {
  const size_t np = std::getenv("N") ? std::atoi(std::getenv("N")) : 20000;
  const size_t npairs = size_t(2.18 * np);
  const int reps = std::max<int>(3, 40000000 / npairs);
  MaterialPair mp{};
  mp.e_star = 5e6 / (2 * (1 - 0.09));
  mp.g_star = mp.e_star * 0.4;
  mp.restitution = 0.5;
  Law::Params prm{HertzMindlin::from(mp), 0.5, true, {}, {}};
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  Parts p;
  p.x.resize(np);
  p.v.resize(np);
  p.w.resize(np);
  p.vp.resize(np);
  p.wp.resize(np);
  p.r.assign(np, 5e-4);
  p.m.assign(np, 6.5e-7);
  for (size_t k = 0; k < np; ++k) {
    p.x[k] = Vec3(k * 1e-3, 0, 0);
    p.v[k] = Vec3(u(rng), u(rng), u(rng)) * 1e-3;
    p.w[k] = Vec3(u(rng), u(rng), u(rng));
    p.vp[k] = p.v[k];
    p.wp[k] = p.w[k];
  }
  Pairs pl;
  PairsSoa s;
  for (size_t k = 0; k < npairs; ++k) {
    const uint32_t i = uint32_t(k / 2.18);
    uint32_t j = std::min<uint32_t>(np - 1, i + 1 + uint32_t(std::abs(u(rng)) * 40));
    if (j == i) continue;
    pl.i.push_back(i);
    pl.j.push_back(j);
  }
  const size_t m = pl.i.size();
  // contact geometry: put j at 0.999 d from i along a random direction (the arrays hold one x per
  // particle, so geometry is approximated by moving x; the arithmetic path is what is timed)
  for (size_t k = 0; k < m; ++k) {
    Vec3 n(u(rng), u(rng), u(rng));
    n.normalize();
    p.x[pl.j[k]] = p.x[pl.i[k]] + 0.9995e-3 * n;
  }
  for (size_t k = 0; k < m; ++k)
    if ((p.x[pl.j[k]] - p.x[pl.i[k]]).norm() > 0.9999e-3) {
      pl.j[k] = pl.i[k] + 1 < np ? pl.i[k] + 1 : pl.i[k] - 1;
      p.x[pl.j[k]] = p.x[pl.i[k]] + Vec3(0.9995e-3, 0, 0);
    }
  size_t bad = 0;
  for (size_t k = 0; k < m; ++k) {
    const double d = (p.x[pl.j[k]] - p.x[pl.i[k]]).norm();
    if (d >= 1e-3) {
      ++bad;
    }
  }
  std::printf("apart: %zu of %zu\n", bad, m);
  std::vector<uint32_t> perm(m);
  for (size_t k = 0; k < m; ++k) perm[k] = k;
  std::shuffle(perm.begin(), perm.end(), rng);
  pl.slot = perm;
  pl.h.assign(m, ContactHistory{});
  pl.t.assign(m, ProbeTally{});
  pl.st.assign(m, 0);
  pl.jf.assign(m, Vec3::Zero());
  pl.jt = pl.jf;
  pl.fi = pl.jf;
  pl.ti = pl.jf;
  for (auto* v : {&s.xx, &s.xy, &s.xz, &s.kt, &s.end, &s.etd, &s.pnd, &s.ptd, &s.esl, &s.est,
                  &s.uel, &s.vni, &s.vti, &s.tst})
    v->assign(m, 0.0);
  auto st0 = pl.st;
  for (int pass = 0; pass < 3; ++pass) {
    pl.st = st0;
    auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < reps; ++r) scalar(prm, p, pl, 1e-6, r * 1e-6);
    auto t1 = std::chrono::steady_clock::now();
    pl.st = st0;
    for (int r = 0; r < reps; ++r) lanes<8>(prm, p, pl, s, 1e-6, r * 1e-6);
    auto t2 = std::chrono::steady_clock::now();
    std::printf("N=%zu pairs=%zu: scalar %.2f ns/contact, lanes %.2f ns/contact\n", np, m,
                std::chrono::duration<double, std::nano>(t1 - t0).count() / (m * reps),
                std::chrono::duration<double, std::nano>(t2 - t1).count() / (m * reps));
  }
  // agreement of the last forces on j
  double md = 0;
  for (size_t k = 0; k < m; ++k) md = std::max(md, std::abs(pl.fi[k][0]));
  std::printf("max |F_i,x| %.3g N\n", md);
}
