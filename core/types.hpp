#pragma once
// Shared vocabulary types. No physics here.
#include <Eigen/Core>

#include <cstdint>

namespace lbdem {

using Vec3 = Eigen::Vector3d;  // SI vector (m, m/s, N, ...): one contiguous 24-byte triple
using Index = std::int64_t;

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace lbdem
