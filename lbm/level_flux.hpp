#pragma once
// Mass crossing nested surfaces between cells, counted link by link: the flux the lattice itself
// transports, where a cell-averaged velocity also counts populations that a wall sent back into the
// same cell (they carry momentum but cross no face). With a level per cell, the surface k bounds
// the cells of level >= k; a population that streamed from x to y = x + c_q during the last step
// crossed every surface between level(x) and level(y). In either AA state the post-streaming
// f_q(y) is readable (aa_pattern.hpp), and for a fluid x it is the f_q*(x) that left x plus, at a
// cell with a mass source, the w_q m the source added after streaming, which is taken out again
// (`added`). So the count is exact: over a step, the mass of the cells of level >= k changes by
// flux[k] plus what the boundary links and sources in them add (tested,
// tests/lbm/test_level_flux.cpp).
#include "lbm/aa_pattern.hpp"
#include "lbm/boundary/flags.hpp"
#include "lbm/pdf_field.hpp"

#include <span>
#include <vector>

namespace lbdem::lbm {

/// flux[k], k = 0 .. levels - 1: mass [lattice units, per step] that entered the cells of level
/// >= k from those below during the last step, less what left them (flux[0] = 0). `level` holds one
/// value in [0, levels) per interior cell in compact order (Grid::compact_index); solid cells and
/// links to or from them do not count. Bitwise the same for any thread count (a serial sum).
/// Throws std::invalid_argument if `level` does not match the grid or a fluid cell's level is out
/// of range.
/// Mass added to a cell's populations after streaming as w_q mass (the solver's mass sources; a
/// cell may appear more than once).
struct AddedMass {
  Index cell;  // storage index (Grid::index)
  double mass;
};
template <class T>
std::vector<double> level_flux(const PdfField<T>& pdf, AaState s, const FlagField& flags,
                               std::span<const int> level, int levels,
                               std::span<const AddedMass> added = {});

}  // namespace lbdem::lbm
