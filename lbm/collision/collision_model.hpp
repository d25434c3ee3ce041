#pragma once
// The run-time choice of collision operator; the solver std::visit's it once per step, so the
// kernel is compiled per operator (dispatch once per loop, not once per cell).
#include "lbm/collision/bgk.hpp"
#include "lbm/collision/collision_operator.hpp"
#include "lbm/collision/regularized_les.hpp"
#include "lbm/collision/trt.hpp"

#include <variant>

namespace lbdem::lbm {

static_assert(CollisionOperator<Bgk>);
static_assert(CollisionOperator<Trt>);
static_assert(CollisionOperator<RegularizedLes>);

using CollisionModel = std::variant<Bgk, Trt, RegularizedLes>;

inline double viscosity(const CollisionModel& c) {
  return std::visit([](const auto& op) { return op.viscosity(); }, c);
}

}  // namespace lbdem::lbm
