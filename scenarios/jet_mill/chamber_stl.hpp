#pragma once
// A jet mill chamber from a user's STL (jet_mill.chamber_stl): reading it against the box, the
// facets that are the particles' side wall, and the checks that stand in for what the analytic
// cylinder guarantees by construction (README, "A chamber of another shape").
#include "core/config.hpp"
#include "core/stl.hpp"
#include "core/types.hpp"
#include "lbm/lbm_solver.hpp"
#include "scenarios/jet_mill/jet_mill_geometry.hpp"

#include <cstddef>

namespace lbdem::scenarios {

struct FluidConfig;

/// Reads jet_mill.chamber_stl and chamber_stl_scale into g (g.axis, height and outlet_radius set;
/// `hi` the box's upper corner). Throws InputError naming the key when a corner lies outside the
/// box, every facet lies in a plate's plane, a facet within 1.5 cells below the roof covers the
/// vortex finder (gas would pass, particles not), a classifier is given beside it, or the scale
/// comes without a file.
void read_chamber_stl(const Config& section, const FluidConfig& f, const Vec3& hi,
                      JetMillGeometry& g);

/// Nozzle k's place in an STL chamber, on the gas's cells: its notional source (axis from s0
/// along the jet, length 2 r_s) must clear every solid cell by 1.5 cells (every cell centred
/// within r_s + 1.5 dx of the axis, along its length, is gas: read_jet_mill's guarantee for the
/// cylinder), and the wall must pass through the exit on the nominal circle (the cell 0.75 dx
/// behind the exit is not gas, or the jet would start inside the gas). Throws InputError naming
/// the file.
void check_source_in_stl(const lbm::LbmSolver& gas, const FluidConfig& f, const JetMillGeometry& g,
                         std::size_t k, double s0);

/// Whether triangle t meets the axis-aligned box [lo, hi], touching included: no separating axis
/// among the box's three, the triangle's normal and the nine edge-axis products (Akenine-Moller
/// 2001, J. Graphics Tools 6(1), 29).
bool triangle_meets_box(const Triangle& t, const Vec3& lo, const Vec3& hi);

}  // namespace lbdem::scenarios
