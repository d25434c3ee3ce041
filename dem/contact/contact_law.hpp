#pragma once
// A contact law composed of small members (docs/architecture.md): a normal law (elastic + damping),
// the tangential spring with Coulomb cap, a rolling model and a cohesion model. One templated loop
// is instantiated per combination and chosen once per run with std::visit
// (dem/contact/registry.hpp).
#include <algorithm>
#include <cmath>

#include "dem/contact/geometry.hpp"
#include "dem/contact/hertz_mindlin.hpp"
#include "dem/contact/linear_spring_dashpot.hpp"
#include "dem/contact/rolling_resistance.hpp"
#include "dem/contact/van_der_waals.hpp"

namespace lbdem::dem {

template <class NormalT, class RollingT, class CohesionT>
struct ContactLaw {
  using Normal = NormalT;
  using Rolling = RollingT;
  using Cohesion = CohesionT;

  struct Params {
    typename Normal::Params normal;
    double friction;          // Coulomb mu [-]
    bool tangential_damping;  // dashpot on the tangential spring
    typename Rolling::Params rolling;
    typename Cohesion::Params cohesion;
  };

  /// Distance beyond touch over which the law still acts [m].
  static double range(const Params& p) {
    if constexpr (Cohesion::active) return Cohesion::range(p.cohesion);
    return 0.0;
  }

  /// The cohesive pull at g (0 without cohesion); books its potential into out.u_elastic.
  static double cohesion(const Params& p, const ContactGeometry& g, ContactForce& out) {
    if constexpr (Cohesion::active) {
      const auto c = Cohesion::eval(p.cohesion, g.delta, g.r_star);
      out.u_elastic = c.u;
      return c.f;
    }
    return 0.0;
  }

  /// Force on i from j apart (delta <= 0): cohesion only, and the springs released. It reads only
  /// g.n, g.delta and g.r_star, so a caller may leave the kinematics unset (about half the listed
  /// pairs of a cohesive bed are in this state, measured on the Bo 10 original: 149,500 of 303,221
  /// interacting pairs).
  static ContactForce evaluate_apart(const Params& p, const ContactGeometry& g, HistoryRef h) {
    ContactForce out;
    const double f_coh = cohesion(p, g, out);
    out.e_stiffness = -0.5 * h.spring.kt * h.spring.xi.squaredNorm();
    h.spring = SpringHistory{};
    if constexpr (Rolling::active) {
      out.e_stiffness -= 0.5 * h.rolling.kr * h.rolling.theta.squaredNorm();
      h.rolling = RollingHistory{};
    }
    out.force = f_coh * g.n;
    return out;
  }

  /// Force on i from j (or a wall) for the geometry g; updates the history.
  ///
  /// Tangential spring (Cundall & Strack 1979; Luding 2008): xi is kept in the tangent plane by
  /// projection with its length preserved, grows by v_t dt, gives F_t = -k_t xi - gamma_t v_t and
  /// is capped at mu max(F_n, 0), F_n the normal contact force (elastic + damping, cohesion
  /// excluded). Energy is booked so that the budget closes at the order of velocity Verlet: every
  /// term below is the exact counterpart of the trapezoidal work of the step. Sliding starts when
  /// the spring alone exceeds the cap: the spring is cut back to it, the dashpot is off, and the
  /// sliding dissipation is the spring force, averaged over the step as velocity Verlet averages
  /// the work, times the slip xi_trial - xi (zero for mu = 0; exactly the work minus the change of
  /// spring energy). Below that, spring + dashpot is limited to the cap by limiting the dashpot,
  /// which dissipates -(F_t - F_spring) . v_t. So no account turns negative and the budget closes
  /// at second order. When k_t changes with the overlap (Mindlin), 0.5 (k_t,new - k_t,old) |xi|^2
  /// enters the spring without work: it is booked as e_stiffness so that the energy budget closes
  /// (1/2 (k_{n+1} - k_n) xi_n . xi_{n+1}); at separation the spring's energy leaves the same way.
  static ContactForce evaluate(const Params& p, const ContactGeometry& g, HistoryRef hr,
                               double dt) {
    if (g.delta <= 0) return evaluate_apart(p, g, hr);
    SpringHistory& h = hr.spring;
    ContactForce out;
    const double f_coh = cohesion(p, g, out);
    const auto s = Normal::elastic(p.normal, g.delta, g.r_star);
    const double vn = g.v_rel.dot(g.n);
    const double gam = Normal::gamma(p.normal, s, g.m_star);
    const double fn = s.f_el + gam * vn;
    out.fn = fn;
    out.u_elastic += s.u_el;
    out.p_normal_damping = gam * vn * vn;

    const Vec3 vt = g.v_rel - vn * g.n;
    const double x2 = h.xi.squaredNorm();
    if (x2 > 0) {
      const Vec3 t = h.xi - h.xi.dot(g.n) * g.n;
      const double t2 = t.squaredNorm();
      h.xi = t2 > 0 ? Vec3(t * std::sqrt(x2 / t2)) : Vec3::Zero();
    }
    const Vec3 xi_start = h.xi;
    const double kt_old = h.kt;
    h.kt = s.k_t;
    // The elongation grows by the relative displacement of the step (mid-step velocity, as the
    // positions moved); the end-of-step velocity would make the spring energy drift at first order.
    const Vec3 vh = g.v_half - g.v_half.dot(g.n) * g.n;
    h.xi += vh * dt;
    const double gt = p.tangential_damping ? gam * Normal::tangential_damping_ratio(p.normal) : 0.0;
    const double cap = p.friction * std::max(fn, 0.0);
    const Vec3 fs = -s.k_t * h.xi;  // spring
    Vec3 ft;
    if (fs.squaredNorm() > cap * cap) {  // sliding: the spring is cut back to the cap, no dashpot
      const double fsn = fs.norm();
      ft = fs * (cap / fsn);
      const Vec3 xi_trial = h.xi;
      h.xi = -ft / s.k_t;
      out.e_sliding = 0.5 * (kt_old * xi_start + s.k_t * h.xi).dot(xi_trial - h.xi);
    } else {
      ft = fs - gt * vt;
      const double f2 = ft.squaredNorm();
      if (f2 > cap * cap) ft *= cap / std::sqrt(f2);  // the dashpot is limited so that |F_t| <= cap
      out.p_tangential_damping = -(ft - fs).dot(vt);
    }
    // Stiffness change at the trapezoidal level: U_{n+1} - U_n + (work of the spring force,
    // averaged over the step) = 1/2 (k_{n+1} - k_n) xi_n . xi_{n+1}.
    out.e_stiffness = 0.5 * (s.k_t - kt_old) * xi_start.dot(h.xi);
    out.u_elastic += 0.5 * s.k_t * h.xi.squaredNorm();
    out.ft = ft;

    if constexpr (Rolling::active) {
      const Vec3 wr = g.w_rel - g.w_rel.dot(g.n) * g.n;
      const Vec3 wh = g.w_half - g.w_half.dot(g.n) * g.n;
      Rolling::apply(p.rolling, g, wr, wh, fn, s.k_n, dt, hr.rolling, out);
    }
    out.force = (f_coh - fn) * g.n + ft;
    return out;
  }
};

}  // namespace lbdem::dem
