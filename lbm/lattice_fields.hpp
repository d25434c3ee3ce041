#pragma once
// The populations and the per-cell fields the stream-collide kernel reads and writes, all in one
// precision T (LbmSettings::precision): double, or float with the populations shifted
// (pdf_field.hpp) and the arithmetic in float (cell.hpp). The kernel of a coupled run moves the
// populations (19 loads and 19 stores) plus these fields (force 3, 1/eps and alpha, velocity sums
// 3 read and written, the wall function's moments 4 written): in float every one of them is half
// the bytes. Per storage cell (Grid::index); an empty vector is a field not in use.
#include "lbm/forcing/moment_store.hpp"
#include "lbm/grid.hpp"
#include "lbm/pdf_field.hpp"

#include <array>
#include <vector>

namespace lbdem::lbm {

template <class T>
struct LatticeFields {
  using value_type = T;
  explicit LatticeFields(const Grid& g) : pdf(g) {}

  PdfField<T> pdf;
  std::array<std::vector<T>, 3> force;  // force density [lattice units]
  std::vector<T> inv_eps, alpha;        // porous form (forcing/porous.hpp): 1/eps and Darcy drag
  // Sums of u / eps over the collisions since they were last taken; the kernel adds to them
  // through a const policy, hence mutable.
  mutable std::array<std::vector<T>, 3> u_sum;
  std::array<std::vector<T>, 4> moments;  // rho and u / eps of the last collision

  MomentFields<T> moment_fields() {
    return {moments[0].data(), {moments[1].data(), moments[2].data(), moments[3].data()}};
  }
};

}  // namespace lbdem::lbm
