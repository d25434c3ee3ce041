#pragma once
// The run-time choice of drag law: one checked-in table, names taken from the laws themselves.
// A particle loop std::visit's the model once and runs compiled per law (docs/architecture.md).
#include "core/variant_names.hpp"
#include "coupling/drag/beetstra.hpp"
#include "coupling/drag/di_felice.hpp"
#include "coupling/drag/drag_law.hpp"
#include "coupling/drag/gidaspow.hpp"
#include "coupling/drag/morsi_alexander.hpp"
#include "coupling/drag/schiller_naumann.hpp"
#include "coupling/drag/wen_yu.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

namespace lbdem::coupling {

static_assert(DragLaw<SchillerNaumann>);
static_assert(DragLaw<MorsiAlexander>);
static_assert(DragLaw<WenYu>);
static_assert(DragLaw<Gidaspow>);
static_assert(DragLaw<DiFelice>);
static_assert(DragLaw<Beetstra>);

using DragModel =
    std::variant<SchillerNaumann, MorsiAlexander, WenYu, Gidaspow, DiFelice, Beetstra>;

static_assert(variant_names_unique<DragModel>(), "two drag laws share a name");

/// Every law, in the order of the variant; the config value is the law's name.
inline const std::array<DragModel, std::variant_size_v<DragModel>> kDragModels{
    SchillerNaumann{}, MorsiAlexander{}, WenYu{}, Gidaspow{}, DiFelice{}, Beetstra{}};

inline std::string_view name_of(const DragModel& m) {
  return std::visit([](const auto& law) -> std::string_view { return law.name; }, m);
}

/// The law called `name`; std::invalid_argument listing the known names otherwise.
inline DragModel make_drag_model(std::string_view name) {
  std::string known;
  for (const auto& m : kDragModels) {
    if (name_of(m) == name) return m;
    known += (known.empty() ? "" : ", ") + std::string(name_of(m));
  }
  throw std::invalid_argument("unknown drag law '" + std::string(name) + "'; known: " + known);
}

/// beta_p [kg/s] through the variant: for rare calls (set-up, logging); loops visit once.
inline double drag_coefficient(const DragModel& m, const DragInput& in, double slip_speed) {
  return std::visit([&](const auto& law) { return law.coefficient(in, slip_speed); }, m);
}

}  // namespace lbdem::coupling
