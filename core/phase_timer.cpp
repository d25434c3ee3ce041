#include "core/phase_timer.hpp"

#include <cstdio>

namespace lbdem {

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::lbm_collide_stream:
      return "gas: stream-collide";
    case Phase::lbm_boundaries:
      return "gas: boundaries";
    case Phase::dem_integration:
      return "DEM: kick and drift";
    case Phase::dem_neighbour_search:
      return "DEM: neighbour search";
    case Phase::dem_pair_contacts:
      return "DEM: particle contacts";
    case Phase::dem_walls_and_kick:
      return "DEM: walls and second kick";
    case Phase::dem_bookkeeping:
      return "DEM: events and wall loads";
    case Phase::coupling_porosity:
      return "coupling: porosity mapping";
    case Phase::coupling_interpolation_drag:
      return "coupling: interpolation and drag";
    case Phase::output:
      return "output";
    case Phase::count:
      break;
  }
  return "?";
}

PhaseTimer& PhaseTimer::global() {
  static PhaseTimer t;
  return t;
}

double PhaseTimer::total() const {
  double s = 0;
  for (double v : seconds_) s += v;
  return s;
}

std::string PhaseTimer::table(double wall) const {
  std::string out;
  char line[128];
  const double w = wall > 0 ? wall : 1.0;
  for (int k = 0; k < int(Phase::count); ++k) {
    const double s = seconds_[std::size_t(k)];
    if (s <= 0) continue;
    std::snprintf(line, sizeof line, "  %-34s %12.3f s %6.1f %%\n", phase_name(Phase(k)), s,
                  100 * s / w);
    out += line;
  }
  std::snprintf(line, sizeof line, "  %-34s %12.3f s %6.1f %%\n", "rest (set-up, steering, plots)",
                wall - total(), 100 * (wall - total()) / w);
  return out + line;
}

}  // namespace lbdem
