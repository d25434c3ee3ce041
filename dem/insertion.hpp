#pragma once
// Particle insertion: radius distributions and random non-overlapping fill of a box region, seeded
// (std::mt19937_64 with explicit distributions written here, so a seed gives the same particles on
// every platform: the standard's distributions are implementation-defined).
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace lbdem::dem {

struct RadiusDistribution {
  std::string kind = "fixed";     // fixed | uniform | lognormal
  double radius = 5e-4;           // fixed [m]
  double min = 4e-4, max = 6e-4;  // uniform range, and clipping range of lognormal [m]
  double median = 5e-4;           // lognormal median radius [m]
  double sigma = 0.2;             // lognormal: standard deviation of ln r [-]

  double largest() const { return kind == "fixed" ? radius : max; }
  double smallest() const { return kind == "fixed" ? radius : min; }
  double sample(std::mt19937_64& rng) const;
};

double uniform01(std::mt19937_64& rng);

struct FillRequest {
  Vec3 lo, hi;             // region [m]
  std::int64_t count = 0;  // particles to place (or:)
  double mass = 0;         // total mass to place [kg]
  double density = 2500;   // [kg/m^3] (for the mass target)
  RadiusDistribution radius;
  int max_attempts = 200;  // per particle
};

struct Placed {
  Vec3 x;
  double r;
};

/// Random sequential addition without overlap with `existing` or among the new particles. Returns
/// what it placed; fewer than asked if the region is too full (the caller reports it).
std::vector<Placed> random_fill(const FillRequest& req, const std::vector<Placed>& existing,
                                std::mt19937_64& rng);

}  // namespace lbdem::dem
