// Probe: cost per contact of the Hertz-Mindlin law (no rolling, no cohesion) evaluated by the
// scalar Law::evaluate on AoS inputs, against a branch-free lane form over SoA arrays (omp simd).
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <random>
#include <vector>
#include "dem/contact/contact_law.hpp"
using namespace lbdem;
using namespace lbdem::dem;
using Law = ContactLaw<HertzMindlin, NoRolling, NoCohesion>;

struct Soa {
  std::vector<double> nx, ny, nz, delta, rs, ms, vx, vy, vz, hx, hy, hz;    // geometry
  std::vector<double> xx, xy, xz, kt;                                       // history
  std::vector<double> fx, fy, fz, tx, ty, tz, pnd, ptd, esl, est, uel, fn;  // outputs
  void resize(size_t n) {
    for (auto* v : {&nx, &ny, &nz, &delta, &rs, &ms, &vx, &vy, &vz,  &hx,  &hy,  &hz,  &xx,  &xy,
                    &xz, &kt, &fx, &fy,    &fz, &tx, &ty, &tz, &pnd, &ptd, &esl, &est, &uel, &fn})
      v->resize(n);
  }
};

[[gnu::noinline]] void lanes(const Law::Params& p, Soa& s, size_t n, double dt) {
  const double E = p.normal.e_star, G = p.normal.g_star, cd = p.normal.c_damp,
               tr = p.normal.t_ratio, mu = p.friction;
  const bool td = p.tangential_damping;
  double* __restrict xx = s.xx.data();
  double* __restrict xy = s.xy.data();
  double* __restrict xz = s.xz.data();
  double* __restrict kt = s.kt.data();
#pragma omp simd
  for (size_t k = 0; k < n; ++k) {
    const double nx = s.nx[k], ny = s.ny[k], nz = s.nz[k], d = s.delta[k];
    const double a = std::sqrt(s.rs[k] * d);
    const double kn = 4.0 / 3.0 * E * a, fel = kn * d, ktn = 8.0 * G * a;
    const double vn = s.vx[k] * nx + s.vy[k] * ny + s.vz[k] * nz;
    const double gam = cd * std::sqrt(s.ms[k] * kn);
    const double fn = fel + gam * vn;
    const double vtx = s.vx[k] - vn * nx, vty = s.vy[k] - vn * ny, vtz = s.vz[k] - vn * nz;
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
    const double hn = s.hx[k] * nx + s.hy[k] * ny + s.hz[k] * nz;
    x0 += (s.hx[k] - hn * nx) * dt;
    x1 += (s.hy[k] - hn * ny) * dt;
    x2v += (s.hz[k] - hn * nz) * dt;
    const double gt = td ? gam * tr : 0.0;
    const double cap = mu * std::max(fn, 0.0);
    const double f0 = -ktn * x0, f1 = -ktn * x1, f2 = -ktn * x2v;
    const double fs2 = f0 * f0 + f1 * f1 + f2 * f2;
    const bool slide = fs2 > cap * cap;
    const double r = cap / std::sqrt(slide ? fs2 : 1.0);
    // sliding branch
    const double sf0 = f0 * r, sf1 = f1 * r, sf2 = f2 * r;
    const double nx0 = -sf0 / ktn, nx1 = -sf1 / ktn, nx2 = -sf2 / ktn;
    const double esl =
        0.5 * ((kto * s0 + ktn * nx0) * (x0 - nx0) + (kto * s1 + ktn * nx1) * (x1 - nx1) +
               (kto * s2 + ktn * nx2) * (x2v - nx2));
    // sticking branch
    double d0 = f0 - gt * vtx, d1 = f1 - gt * vty, d2 = f2 - gt * vtz;
    const double dd = d0 * d0 + d1 * d1 + d2 * d2;
    const double lim = dd > cap * cap ? cap / std::sqrt(dd) : 1.0;
    d0 *= lim, d1 *= lim, d2 *= lim;
    const double ptd = -((d0 - f0) * vtx + (d1 - f1) * vty + (d2 - f2) * vtz);
    const double ft0 = slide ? sf0 : d0, ft1 = slide ? sf1 : d1, ft2 = slide ? sf2 : d2;
    x0 = slide ? nx0 : x0, x1 = slide ? nx1 : x1, x2v = slide ? nx2 : x2v;
    s.esl[k] = slide ? esl : 0.0;
    s.ptd[k] = slide ? 0.0 : ptd;
    s.est[k] = 0.5 * (ktn - kto) * (s0 * x0 + s1 * x1 + s2 * x2v);
    s.uel[k] = 0.4 * fel * d + 0.5 * ktn * (x0 * x0 + x1 * x1 + x2v * x2v);
    s.pnd[k] = gam * vn * vn;
    s.fn[k] = fn;
    s.fx[k] = -fn * nx + ft0, s.fy[k] = -fn * ny + ft1, s.fz[k] = -fn * nz + ft2;
    s.tx[k] = ny * ft2 - nz * ft1, s.ty[k] = nz * ft0 - nx * ft2, s.tz[k] = nx * ft1 - ny * ft0;
    xx[k] = x0, xy[k] = x1, xz[k] = x2v, kt[k] = ktn;
  }
}

[[gnu::noinline, gnu::flatten]] void scalar(const Law::Params& p,
                                            const std::vector<ContactGeometry>& g,
                                            std::vector<ContactHistory>& h,
                                            std::vector<ContactForce>& out, double dt) {
  for (size_t k = 0; k < g.size(); ++k) out[k] = Law::evaluate(p, g[k], h[k], dt);
}

int main() {
  const size_t n = std::getenv("N") ? std::atoi(std::getenv("N")) : 50000;
  const int reps = 20000000 / n;
  MaterialPair m{};
  m.e_star = 5e6 / (2 * (1 - 0.09));
  m.g_star = m.e_star * 0.4;
  m.restitution = 0.5;
  Law::Params p{HertzMindlin::from(m), 0.5, true, {}, {}};
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<ContactGeometry> g(n);
  std::vector<ContactHistory> h(n);
  std::vector<ContactForce> out(n);
  Soa s;
  s.resize(n);
  for (size_t k = 0; k < n; ++k) {
    Vec3 nn(u(rng), u(rng), u(rng));
    nn.normalize();
    g[k].n = nn;
    g[k].delta = 1e-6 * (1 + u(rng));
    g[k].r_star = 2.5e-4;
    g[k].m_star = 2.6e-7;
    g[k].v_rel = Vec3(u(rng), u(rng), u(rng)) * 1e-3;
    g[k].v_half = g[k].v_rel;
    h[k].xi = Vec3(u(rng), u(rng), u(rng)) * 1e-8;
    h[k].kt = 1e3;
    s.nx[k] = nn[0], s.ny[k] = nn[1], s.nz[k] = nn[2], s.delta[k] = g[k].delta, s.rs[k] = 2.5e-4,
    s.ms[k] = 2.6e-7;
    s.vx[k] = g[k].v_rel[0], s.vy[k] = g[k].v_rel[1], s.vz[k] = g[k].v_rel[2];
    s.hx[k] = s.vx[k], s.hy[k] = s.vy[k], s.hz[k] = s.vz[k];
    s.xx[k] = h[k].xi[0], s.xy[k] = h[k].xi[1], s.xz[k] = h[k].xi[2], s.kt[k] = 1e3;
  }
  // one evaluation each, compared
  auto h0 = h;
  auto s0 = s;
  scalar(p, g, h, out, 1e-6);
  lanes(p, s, n, 1e-6);
  double md = 0;
  int nsl = 0;
  for (size_t k = 0; k < n; ++k) {
    md = std::max(md, std::abs(out[k].force[0] - s.fx[k]) / (std::abs(out[k].fn) + 1e-30));
    nsl += out[k].e_sliding > 0;
  }
  std::printf("max |dFx|/Fn = %.3g, sliding %d of %zu\n", md, nsl, n);
  for (int pass = 0; pass < 3; ++pass) {
    h = h0;
    s = s0;
    auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < reps; ++r) scalar(p, g, h, out, 1e-6);
    auto t1 = std::chrono::steady_clock::now();
    for (int r = 0; r < reps; ++r) lanes(p, s, n, 1e-6);
    auto t2 = std::chrono::steady_clock::now();
    std::printf("scalar %.2f ns/contact, lanes %.2f ns/contact\n",
                std::chrono::duration<double, std::nano>(t1 - t0).count() / (n * reps),
                std::chrono::duration<double, std::nano>(t2 - t1).count() / (n * reps));
  }
}
