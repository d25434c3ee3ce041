#pragma once
// Rolling resistance models (Ai, Chen, Rotter & Ooi 2011, Powder Technol. 206:269).
// Convention: the torque arm is r_arm = arm_factor * R*; arm_factor = 1 is LIGGGHTS' and the
// default here, MercuryDPM's rolling friction uses 2 R* (arm_factor = 2). Torques act on the
// relative rolling rotation omega_r = (omega_i - omega_j) projected onto the tangent plane
// (twisting excluded).
#include <algorithm>
#include <cmath>
#include <string_view>

#include "dem/contact/geometry.hpp"

namespace lbdem::dem {

struct NoRolling {
  struct Params {};
  static constexpr std::string_view name = "none";
  static constexpr bool active = false;
};

/// Model A (constant directional torque): M = -mu_r r_arm F_n omega_r/|omega_r|. The torque is
/// limited to the value that stops omega_r within one step (I* |omega_r| / dt), so it cannot
/// reverse the rotation and chatter around rest.
struct ConstantTorqueRolling {
  struct Params {
    double mu_r;        // rolling friction coefficient [-]
    double arm_factor;  // r_arm / R* [-]
  };
  static constexpr std::string_view name = "constant_torque";
  static constexpr bool active = true;

  static void apply(const Params& p, const ContactGeometry& g, const Vec3& omega_r,
                    const Vec3& /*half*/, double fn, double /*k_n*/, double dt,
                    RollingHistory& /*h*/, ContactForce& out) {
    const double w = omega_r.norm();
    if (w <= 0 || fn <= 0) return;
    const double m = std::min(p.mu_r * p.arm_factor * g.r_star * fn, g.i_star * w / dt);
    out.m_roll = -(m / w) * omega_r;
    out.e_rolling = m * w * dt;
  }
};

/// Model C without its viscous part (elastic-plastic spring, "EPSD"): k_r = 2.25 k_n mu_r^2 r_arm^2
/// (Ai et al. 2011, eq. 16), M = -k_r theta with theta the accumulated rolling rotation, capped at
/// mu_r r_arm F_n (full mobilisation, eq. 14); the limit torque times the plastic rotation is the
/// rolling dissipation.
struct EpsdRolling {
  struct Params {
    double mu_r;
    double arm_factor;
  };
  static constexpr std::string_view name = "epsd";
  static constexpr bool active = true;

  static void apply(const Params& p, const ContactGeometry& g, const Vec3& /*omega_r*/,
                    const Vec3& omega_half, double fn, double k_n, double dt, RollingHistory& h,
                    ContactForce& out) {
    const double arm = p.arm_factor * g.r_star;
    const double kr = 2.25 * k_n * p.mu_r * p.mu_r * arm * arm;
    // Keep theta in the tangent plane (rotate with the contact, keep its magnitude).
    const double t2 = h.theta.squaredNorm();
    if (t2 > 0) {
      Vec3 t = h.theta - h.theta.dot(g.n) * g.n;
      const double tn2 = t.squaredNorm();
      h.theta = tn2 > 0 ? Vec3(t * std::sqrt(t2 / tn2)) : Vec3::Zero();
    }
    const Vec3 theta_start = h.theta;
    const double kr_old = h.kr;
    const double m_start = kr_old * h.theta.norm();
    h.kr = kr;
    h.theta += omega_half * dt;  // rotation of the step (mid-step rate, see contact_law.hpp)
    Vec3 m = -kr * h.theta;
    const double cap = p.mu_r * arm * std::max(fn, 0.0);
    const double mm = m.norm();
    if (mm > cap) {
      m *= cap / mm;
      const Vec3 theta_trial = h.theta;
      h.theta = kr > 0 ? Vec3(-m / kr) : Vec3::Zero();
      out.e_rolling +=
          0.5 * (m_start + cap) * (theta_trial - h.theta).norm();  // torque x plastic rotation
    }
    out.e_stiffness +=
        0.5 * (kr - kr_old) * theta_start.dot(h.theta);  // as for the tangential spring
    out.m_roll = m;
    out.u_elastic += 0.5 * kr * h.theta.squaredNorm();
  }
};

}  // namespace lbdem::dem
