// Insertion: radius distributions against their analytic statistics, fills without overlap, and the
// same particles for the same seed.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "dem/insertion.hpp"

using namespace lbdem;

TEST_CASE("radius distributions have their analytic statistics", "[dem][insertion]") {
  std::mt19937_64 rng(3);
  const int n = 200000;
  dem::RadiusDistribution u;
  u.kind = "uniform";
  u.min = 1e-4, u.max = 3e-4;
  double sum = 0, lo = 1, hi = 0;
  for (int k = 0; k < n; ++k) {
    const double r = u.sample(rng);
    sum += r, lo = std::min(lo, r), hi = std::max(hi, r);
  }
  // Mean of U(1e-4, 3e-4) is 2e-4; the standard error with n = 2e5 is 5.8e-5/sqrt(n) = 1.3e-7: 1e-6
  // is ~8 sigma.
  CHECK(sum / n == Approx(2e-4).margin(1e-6));
  CHECK(lo >= 1e-4);
  CHECK(hi <= 3e-4);
  dem::RadiusDistribution g;
  g.kind = "lognormal";
  g.median = 2e-4, g.sigma = 0.3, g.min = 1e-5, g.max = 1e-2;  // clipping far in the tails
  std::vector<double> rs(n);
  for (auto& r : rs) r = g.sample(rng);
  std::nth_element(rs.begin(), rs.begin() + n / 2, rs.end());
  // Median of a lognormal is exp(mu) = 2e-4; its sampling error ~ 1.25 sigma median / sqrt(n)
  // = 1.7e-7.
  CHECK(rs[n / 2] == Approx(2e-4).margin(1.5e-6));
}

TEST_CASE("random fill places particles without overlap, reproducibly", "[dem][insertion]") {
  dem::FillRequest req;
  req.lo = Vec3(0, 0, 0);
  req.hi = Vec3(0.01, 0.01, 0.01);
  req.count = 1000;
  req.radius.kind = "uniform";
  req.radius.min = 2e-4, req.radius.max = 4e-4;
  std::vector<dem::Placed> existing = {{Vec3(0.005, 0.005, 0.005), 2e-3}};  // a large obstacle
  std::mt19937_64 a(9), b(9);
  const auto p = dem::random_fill(req, existing, a), q = dem::random_fill(req, existing, b);
  REQUIRE(p.size() == 1000);
  REQUIRE(q.size() == p.size());
  for (std::size_t k = 0; k < p.size(); ++k) CHECK(p[k].x == q[k].x);
  std::vector<dem::Placed> all = existing;
  all.insert(all.end(), p.begin(), p.end());
  int overlaps = 0;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      overlaps += (all[i].x - all[j].x).norm() < all[i].r + all[j].r;
  CHECK(overlaps == 0);
  for (const auto& s : p)
    for (int d = 0; d < 3; ++d) CHECK((s.x[d] - s.r >= 0 && s.x[d] + s.r <= 0.01));
}
