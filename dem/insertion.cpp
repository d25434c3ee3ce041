#include "dem/insertion.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace lbdem::dem {

double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

double RadiusDistribution::sample(std::mt19937_64& rng) const {
  if (kind == "uniform") return min + (max - min) * uniform01(rng);
  if (kind == "lognormal") {
    for (;;) {  // Box-Muller, clipped to [min, max] by rejection
      const double u1 = 1.0 - uniform01(rng), u2 = uniform01(rng);
      const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2 * kPi * u2);
      const double r = median * std::exp(sigma * z);
      if (r >= min && r <= max) return r;
    }
  }
  return radius;
}

std::vector<Placed> random_fill(const FillRequest& req, const std::vector<Placed>& existing,
                                std::mt19937_64& rng) {
  double rmax = req.radius.largest();
  for (const auto& e : existing) rmax = std::max(rmax, e.r);
  const double h = 2 * rmax;
  // Hash grid of everything placed so far, cell 2 r_max (of old and new): overlap checks look at 27
  // cells.
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  std::vector<Placed> all = existing;
  const auto key = [&](const Vec3& x) {
    const auto c = [&](int a) {
      return static_cast<std::int64_t>(std::floor(x[a] / h)) + (1 << 20);
    };
    return (c(2) << 42) | (c(1) << 21) | c(0);
  };
  for (int k = 0; k < static_cast<int>(all.size()); ++k) grid[key(all[k].x)].push_back(k);
  std::vector<Placed> out;
  const double vol = 4.0 / 3.0 * kPi;
  double mass = 0;
  const auto done = [&] {
    return req.count > 0 ? static_cast<std::int64_t>(out.size()) >= req.count : mass >= req.mass;
  };
  while (!done()) {
    const double r = req.radius.sample(rng);
    bool ok = false;
    Vec3 x;
    for (int a = 0; a < req.max_attempts && !ok; ++a) {
      for (int d = 0; d < 3; ++d) {
        const double span = req.hi[d] - req.lo[d] - 2 * r;
        x[d] = req.lo[d] + r + std::max(span, 0.0) * uniform01(rng);
      }
      ok = true;
      for (int dz = -1; dz <= 1 && ok; ++dz)
        for (int dy = -1; dy <= 1 && ok; ++dy)
          for (int dx = -1; dx <= 1 && ok; ++dx) {
            const auto it = grid.find(key(x + h * Vec3(dx, dy, dz)));
            if (it == grid.end()) continue;
            for (int q : it->second)
              if ((all[q].x - x).norm() < all[q].r + r) {
                ok = false;
                break;
              }
          }
    }
    if (!ok) break;  // region full
    grid[key(x)].push_back(static_cast<int>(all.size()));
    all.push_back({x, r});
    out.push_back({x, r});
    mass += req.density * vol * r * r * r;
  }
  return out;
}

}  // namespace lbdem::dem
