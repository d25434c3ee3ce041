#include "tools/src/mill_maps.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lbdem::tools {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

double MillAxis::r(const Vec3& x) const {
  return std::hypot(x.x() - cx, x.y() - cy);
}
double MillAxis::wall_distance(const Vec3& x) const {
  return radius - r(x);
}

Bins1D::Bins1D(double lo, double h, std::size_t n) : lo_(lo), h_(h), sum_(n, 0.0), count_(n, 0.0) {
  if (!(h > 0) || n == 0) throw std::invalid_argument("Bins1D needs h > 0 and at least one bin");
}

void Bins1D::add(double s, double value) {
  const double k = std::floor((s - lo_) / h_);
  if (!(k >= 0 && k < double(sum_.size()))) return;
  sum_[std::size_t(k)] += value;
  count_[std::size_t(k)] += 1;
}

double Bins1D::mean(std::size_t k) const {
  return count_[k] > 0 ? sum_[k] / count_[k] : kNaN;
}

Bins2D::Bins2D(double x0, double y0, double h, std::size_t n)
    : x0_(x0), y0_(y0), h_(h), n_(n), sum_(n * n, 0.0), count_(n * n, 0.0) {
  if (!(h > 0) || n == 0) throw std::invalid_argument("Bins2D needs h > 0 and at least one bin");
}

void Bins2D::add(double x, double y, double value) {
  const double i = std::floor((x - x0_) / h_), j = std::floor((y - y0_) / h_);
  if (!(i >= 0 && i < double(n_) && j >= 0 && j < double(n_))) return;
  const std::size_t c = std::size_t(j) * n_ + std::size_t(i);
  sum_[c] += value;
  count_[c] += 1;
}

double Bins2D::mean(std::size_t i, std::size_t j) const {
  const std::size_t c = j * n_ + i;
  return count_[c] > 0 ? sum_[c] / count_[c] : kNaN;
}

bool JetRegion::contains(const Vec3& x) const {
  const double dx = x.x() - exit.x(), dy = x.y() - exit.y();
  const double along = dx * dir.x() + dy * dir.y();
  const double across = -dx * dir.y() + dy * dir.x();
  return along >= 0 && along <= length && std::abs(across) <= half_width;
}

GasProfile gas_profile(std::span<const double> velocity, std::span<const double> porosity,
                       const std::array<int, 3>& cells, const Vec3& origin, double dx,
                       const MillAxis& axis, double bin, int z_from, int z_to) {
  const std::size_t nx = std::size_t(cells[0]), ny = std::size_t(cells[1]),
                    nz = std::size_t(cells[2]);
  if (velocity.size() != 3 * nx * ny * nz || porosity.size() != nx * ny * nz)
    throw std::invalid_argument("gas_profile: arrays do not match the cell counts");
  const std::size_t nbins = std::size_t(std::ceil(axis.radius / bin));
  Bins1D ut(0.0, bin, nbins), ur(0.0, bin, nbins);
  for (int z = std::max(0, z_from); z < std::min(int(nz), z_to); ++z)
    for (std::size_t y = 0; y < ny; ++y)
      for (std::size_t x = 0; x < nx; ++x) {
        const std::size_t c = (std::size_t(z) * ny + y) * nx + x;
        if (!(porosity[c] > 0)) continue;
        const double px = origin.x() + double(x) * dx - axis.cx;
        const double py = origin.y() + double(y) * dx - axis.cy;
        const double r = std::hypot(px, py);
        if (r <= 0) continue;
        const double u = velocity[3 * c], v = velocity[3 * c + 1];
        ut.add(r, (-u * py + v * px) / r);
        ur.add(r, (u * px + v * py) / r);
      }
  GasProfile p;
  for (std::size_t k = 0; k < nbins; ++k) {
    if (ut.samples(k) == 0) continue;
    p.radius.push_back(ut.centre(k));
    p.u_theta.push_back(ut.mean(k));
    p.u_r.push_back(ur.mean(k));
    p.cells.push_back(ut.samples(k));
  }
  return p;
}

std::vector<double> layer_speed(std::span<const double> velocity, std::span<const double> porosity,
                                const std::array<int, 3>& cells, int z) {
  const std::size_t nx = std::size_t(cells[0]), ny = std::size_t(cells[1]);
  if (z < 0 || z >= cells[2] || velocity.size() != 3 * nx * ny * std::size_t(cells[2]) ||
      porosity.size() != nx * ny * std::size_t(cells[2]))
    throw std::invalid_argument("layer_speed: layer or arrays do not match the cell counts");
  std::vector<double> s(nx * ny);
  for (std::size_t k = 0; k < nx * ny; ++k) {
    const std::size_t c = std::size_t(z) * nx * ny + k;
    s[k] = porosity[c] > 0 ? std::sqrt(velocity[3 * c] * velocity[3 * c] +
                                       velocity[3 * c + 1] * velocity[3 * c + 1] +
                                       velocity[3 * c + 2] * velocity[3 * c + 2])
                           : kNaN;
  }
  return s;
}

}  // namespace lbdem::tools
