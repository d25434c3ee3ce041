#pragma once
// Values passed into and out of a contact law (values in, values out, no shared scratch).
#include "core/types.hpp"

namespace lbdem::dem {

/// Kinematics of one contact between particle i and partner j (a particle or a wall).
struct ContactGeometry {
  Vec3 n;         // unit normal from i towards j [-]
  double delta;   // overlap [m]: > 0 in contact, < 0 is the gap
  double r_star;  // effective radius R1 R2/(R1+R2) (R for a wall) [m]
  double m_star;  // effective mass [kg]
  double i_star;  // effective moment of inertia I1 I2/(I1+I2) [kg m^2] (rolling-torque limiter)
  Vec3 v_rel;     // velocity of i's contact point relative to j's, end of step (dashpots) [m/s]
  Vec3 w_rel;     // omega_i - omega_j, end of step [rad/s]
  Vec3 v_half;    // the same at mid-step: v_half dt is the relative displacement of the step [m/s]
  Vec3 w_half;    // omega_i - omega_j at mid-step: w_half dt is the relative rotation [rad/s]
};

/// State a contact carries from step to step (like LAMMPS' per-pair history), in two parts: the
/// tangential spring every law has, and the rolling spring only rolling models read or write, so
/// a law without rolling moves 32 B of history per contact and step instead of 64.
struct SpringHistory {
  Vec3 xi = Vec3::Zero();  // tangential spring elongation of i relative to j [m]
  double kt = 0;           // tangential stiffness at the last step [N/m]
};
struct RollingHistory {
  Vec3 theta = Vec3::Zero();  // rolling spring rotation (EPSD) [rad]
  double kr = 0;              // rolling stiffness at the last step [N m/rad]
};
/// Both parts together (wall contacts keep them so).
struct ContactHistory {
  SpringHistory spring;
  RollingHistory rolling;
};
/// The history a law evaluation updates, wherever its parts are stored.
struct HistoryRef {
  SpringHistory& spring;
  RollingHistory& rolling;
};

/// Result of one evaluation. Energies: powers at this time level (integrated by the caller with the
/// trapezoidal rule) and jumps that happened in this step.
struct ContactForce {
  Vec3 force = Vec3::Zero();        // total force on i [N]
  Vec3 ft = Vec3::Zero();           // its tangential part [N] (torque arm n x ft)
  Vec3 m_roll = Vec3::Zero();       // rolling torque on i [N m] (j gets -m_roll)
  double fn = 0;                    // normal contact force, elastic + damping, > 0 repulsive [N]
  double p_normal_damping = 0;      // [W]
  double p_tangential_damping = 0;  // [W]
  double e_sliding = 0;             // energy lost to Coulomb sliding this step [J]
  double e_rolling = 0;             // energy lost to rolling resistance this step [J]
  double e_stiffness = 0;           // change of stored spring energy by stiffness change at fixed
                           // elongation this step [J] (no force did this work; booked apart)
  double u_elastic = 0;  // energy stored in this contact (springs + cohesion) [J]
};

}  // namespace lbdem::dem
