#pragma once
// Cohesion laws. They act beyond the point of touch, so the neighbour search adds `range` to the
// cut-off.
#include <algorithm>
#include <string_view>

namespace lbdem::dem {

struct NoCohesion {
  struct Params {};
  static constexpr std::string_view name = "none";
  static constexpr bool active = false;
};

/// Van der Waals attraction of two spheres (Hamaker 1937): F = A R* / (6 h^2), with the gap h
/// clamped to h >= h_min (in contact h = h_min, so the pull stays finite) and F = 0 beyond h_max.
/// Equal spheres of diameter d give A d / (24 h^2). Potential (zero at h_max so energy is
/// continuous there): U = -A R*/6 (1/h - 1/h_max) for h_min <= h <= h_max, continued linearly with
/// slope F(h_min) below.
struct VanDerWaals {
  struct Params {
    double hamaker;  // A [J]
    double h_min;    // minimum separation [m]
    double h_max;    // cut-off separation [m]
  };
  static constexpr std::string_view name = "van_der_waals";
  static constexpr bool active = true;

  /// Attractive force magnitude [N] and potential [J] at overlap delta (gap h = -delta).
  struct Result {
    double f, u;
  };
  static Result eval(const Params& p, double delta, double r_star) {
    const double gap = -delta;
    if (p.hamaker <= 0 || gap > p.h_max) return {0, 0};
    const double h = std::max(gap, p.h_min);
    const double c = p.hamaker * r_star / 6.0;
    const double f = c / (h * h);
    double u = -c * (1.0 / h - 1.0 / p.h_max);
    if (gap < p.h_min) u -= f * (p.h_min - gap);
    return {f, u};
  }
  static double range(const Params& p) { return p.hamaker > 0 ? p.h_max : 0.0; }
};

}  // namespace lbdem::dem
