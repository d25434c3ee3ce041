#pragma once
// The spiral jet mill's maps and profiles (as in Figs. 3, 4 and 6 of Scott, Borissova, Di Renzo
// & Ghadiri; docs/studies.md): particle speed binned on the x-y plane and against the distance
// from the chamber's outer wall, both averaged over every particle sample (each particle in each
// snapshot of the window counts once); the gas's tangential and radial velocity against radius; the
// mean speed of the samples in the jets' regions. Plain formulas on arrays, tested in tests/tools/.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "core/types.hpp"

namespace lbdem::tools {

/// The chamber seen from above: axis (cx, cy), radius R.
struct MillAxis {
  double cx = 0, cy = 0, radius = 0;
  double r(const Vec3& x) const;              // distance from the axis
  double wall_distance(const Vec3& x) const;  // R - r (negative outside)
};

/// Mean of a value over samples in uniform bins of width h from lo (values outside are dropped).
class Bins1D {
 public:
  Bins1D(double lo, double h, std::size_t n);
  void add(double s, double value);
  std::size_t size() const { return sum_.size(); }
  double centre(std::size_t k) const { return lo_ + (double(k) + 0.5) * h_; }
  double samples(std::size_t k) const { return count_[k]; }
  double mean(std::size_t k) const;  // NaN where a bin is empty

 private:
  double lo_, h_;
  std::vector<double> sum_, count_;
};

/// Mean of a value over samples in square x-y bins of width h covering [x0, x0 + n h) x
/// [y0, y0 + n h); index (i, j) = (x, y).
class Bins2D {
 public:
  Bins2D(double x0, double y0, double h, std::size_t n);
  void add(double x, double y, double value);
  std::size_t n() const { return n_; }
  double x(std::size_t i) const { return x0_ + (double(i) + 0.5) * h_; }
  double y(std::size_t j) const { return y0_ + (double(j) + 0.5) * h_; }
  double samples(std::size_t i, std::size_t j) const { return count_[j * n_ + i]; }
  double mean(std::size_t i, std::size_t j) const;  // NaN where a bin is empty

 private:
  double x0_, y0_, h_;
  std::size_t n_;
  std::vector<double> sum_, count_;
};

/// A jet's region: within half_width of its axis, from the exit (on the wall) to length along it.
struct JetRegion {
  Vec3 exit = Vec3::Zero(), dir = Vec3::UnitX();  // dir: unit, in the x-y plane
  double half_width = 0, length = 0;
  bool contains(const Vec3& x) const;  // tested in x-y (the jets span the chamber's height)
};

/// Gas velocity against radius: the mean tangential (counter-clockwise positive) and radial
/// (outwards positive) components over the gas cells (porosity > 0) whose centres lie in each
/// radial bin, from a (z, y, x, 3) velocity array [m/s] on cells of spacing dx with the first
/// centre at origin, over the layers z_from <= z < z_to (cell indices).
struct GasProfile {
  std::vector<double> radius, u_theta, u_r, cells;
};
GasProfile gas_profile(std::span<const double> velocity, std::span<const double> porosity,
                       const std::array<int, 3>& cells, const Vec3& origin, double dx,
                       const MillAxis& axis, double bin, int z_from, int z_to);

/// The gas speed |u| [m/s] of one layer z of a (z, y, x, 3) velocity array, NaN in solid cells
/// (porosity 0), x fastest.
std::vector<double> layer_speed(std::span<const double> velocity, std::span<const double> porosity,
                                const std::array<int, 3>& cells, int z);

}  // namespace lbdem::tools
