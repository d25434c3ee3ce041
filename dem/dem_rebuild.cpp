// Neighbour rebuild of DemSolver: periodic wrap, removals, spatial sort, new pair and wall lists
// with the contact history carried over.
#include <algorithm>
#include <limits>
#include <numeric>

#include "core/error.hpp"
#include "dem/csr_build.hpp"
#include "dem/dem_solver.hpp"

namespace lbdem::dem {

namespace {
constexpr auto kGone = std::numeric_limits<std::uint32_t>::max();

bool outside(const Domain& d, const Vec3& x, double margin) {
  for (int a = 0; a < 3; ++a)
    if (!d.periodic[a] && (x[a] < d.lo[a] - margin || x[a] > d.hi[a] + margin)) return true;
  return false;
}
}  // namespace

void DemSolver::rebuild() {
  ++rebuilds_;
  const Domain& dom = s_.domain;
  const double extra = interaction_range() + s_.skin;
  const double cell = 2 * max_radius_ + extra;
  for (int a = 0; a < 3; ++a)
    if (dom.periodic[a] && dom.length()[a] < 2 * cell)
      throw InputError("domain", "periodic length " + to_text(dom.length()[a]) + " m",
                       "shorter than two interaction cut-offs (" + to_text(2 * cell) + " m)",
                       "make the periodic box longer or the particles smaller");
  const std::size_t n = p_.size();
  if (dom.any_periodic()) {
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
    for (std::size_t k = 0; k < n; ++k) p_.x[k] = dom.wrap(p_.x[k]);
  }

  // Removals: flagged (outlet) or lost through a non-periodic face. Found in parallel, booked in
  // index order.
  remove_flag_.resize(n, 0);
  const double margin = s_.lost_margin > 0 ? s_.lost_margin : cell;
  std::vector<std::uint8_t> gone(n, 0);
  std::size_t n_gone = 0;
#pragma omp parallel for schedule(static) reduction(+ : n_gone) if (n >= kMinParallel)
  for (std::size_t k = 0; k < n; ++k) {
    const bool lost = outside(dom, p_.x[k], margin);
    gone[k] = remove_flag_[k] ? 1 : lost ? 2 : 0;
    n_gone += gone[k] != 0;
  }
  for (std::size_t k = 0; k < n && n_gone > 0; ++k) {
    if (!gone[k]) continue;
    --n_gone;
    lost_ += gone[k] == 2;
    mass_removed_ += p_.mass[k];
    removed_ += 0.5 * p_.mass[k] * p_.v[k].squaredNorm() +
                0.5 * p_.inertia[k] * p_.omega[k].squaredNorm() -
                p_.mass[k] * s_.gravity.dot(p_.x[k]);
  }
  remove_flag_.clear();

  // One cell sort, on the positions of now: it gives the spatial order, and renumbered it is the
  // cell list of the sorted particles (particles keep their cells and, within a cell, their order).
  const CellGrid grid(dom, cell);
  cells_.build(p_.x, grid);
  const bool sort = s_.sort_every > 0 && (rebuilds_ - 1) % s_.sort_every == 0;
  std::vector<std::uint32_t> order;
  if (sort) {
    order = cells_.items;
  } else {
    order.resize(n);
    std::iota(order.begin(), order.end(), 0u);
  }
  const std::size_t before = order.size();
  order.erase(std::remove_if(order.begin(), order.end(), [&](std::uint32_t k) { return gone[k]; }),
              order.end());
  std::vector<std::uint32_t> inv(n, kGone);
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t k = 0; k < order.size(); ++k) inv[order[k]] = static_cast<std::uint32_t>(k);

  if (sort || order.size() != before) p_.permute(order);  // else the order is the identity
  cells_.renumber(inv);
  // The new list is built in the storage of the one before the last (build_pairs resets all of
  // it): its arrays are not reallocated, nor their pages touched for the first time, while the
  // pair count does not grow.
  std::swap(pairs_, spare_pairs_);
  const PairList& old_pairs = spare_pairs_;
  WallContactList old_wc = std::move(wc_);
  wc_ = WallContactList{};

  build_pairs(p_.x, p_.radius, dom, cells_, extra, pairs_);
  carry_over(old_pairs, inv, pairs_);
  build_wall_list(cells_, extra);

  // Wall contacts carry over by (particle, wall, triangle): distinct old entries go to distinct
  // new ones, so in parallel.
  const std::size_t nwc = old_wc.size();
#pragma omp parallel for schedule(static) if (nwc >= kMinParallel)
  for (std::size_t e = 0; e < nwc; ++e) {
    if (!old_wc.state[e]) continue;
    const std::uint32_t q = inv[old_wc.particle[e]];
    if (q != kGone)
      for (std::size_t f = wc_.first[q]; f < wc_.first[q + 1]; ++f)
        if (wc_.wall[f] == old_wc.wall[e] && wc_.tri[f] == old_wc.tri[e]) {
          wc_.history[f] = old_wc.history[e], wc_.tally[f] = old_wc.tally[e];
          wc_.record[f] = old_wc.record[e], wc_.state[f] = old_wc.state[e];
          break;
        }
  }
  // Contacts not carried (a partner removed, a wall entry gone) end here: the energy they
  // dissipated is in the ledgers already (book_energy), and their stored energy leaves with them.

  x_ref_ = p_.x;
  wall_ref_.assign(walls_.size(), {});
  for (std::size_t w = 0; w < walls_.size(); ++w)
    if (const auto* m = std::get_if<MeshWall>(&walls_[w].shape)) {
      wall_ref_[w] = m->current;
    } else if (const auto* b = std::get_if<BoxWall>(&walls_[w].shape)) {
      const auto c = b->corners(t_);
      wall_ref_[w].assign(c.begin(), c.end());
    }
  need_rebuild_ = false;
}

void DemSolver::build_wall_list(const CellList& cells, double extra) {
  const std::size_t n = p_.size();
  const CellGrid& g = cells.grid;
  // Triangles of each mesh binned into the occupied cells their inflated bounding box overlaps (a
  // triangle within reach of a centre overlaps the centre's cell): bins for the cells that hold
  // particles only, so the binning costs the triangles' cell coverage, not the grid.
  const double inflate = max_radius_ + extra;
  const std::size_t nocc = cells.cell.size();
  std::vector<std::vector<std::uint32_t>> bin_start(walls_.size()), bin_tris(walls_.size());
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const auto* m = std::get_if<MeshWall>(&walls_[w].shape);
    if (!m) continue;
    std::vector<std::uint32_t> count(nocc + 1, 0);
    const auto for_cells = [&](std::size_t t, auto&& f) {
      const auto& tri = m->mesh.triangles[t];
      Vec3 lo = m->current[tri[0]], hi = lo;
      for (int c = 1; c < 3; ++c)
        lo = lo.cwiseMin(m->current[tri[c]]), hi = hi.cwiseMax(m->current[tri[c]]);
      lo.array() -= inflate, hi.array() += inflate;
      for (int z = g.coord(lo[2], 2); z <= g.coord(hi[2], 2); ++z)
        for (int y = g.coord(lo[1], 1); y <= g.coord(hi[1], 1); ++y)
          for (int x = g.coord(lo[0], 0); x <= g.coord(hi[0], 0); ++x)
            if (const std::uint32_t s = cells.find(g.index(x, y, z)); s != UINT32_MAX) f(s);
    };
    for (std::size_t t = 0; t < m->mesh.size(); ++t)
      for_cells(t, [&](std::uint32_t s) { ++count[s + 1]; });
    prefix_sum(count);
    bin_tris[w].resize(count.back());
    std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
    for (std::size_t t = 0; t < m->mesh.size(); ++t)
      for_cells(t,
                [&](std::uint32_t s) { bin_tris[w][fill[s]++] = static_cast<std::uint32_t>(t); });
    bin_start[w] = std::move(count);
  }

  const auto visit = [&](std::size_t k, auto&& add) {
    const Vec3& x = p_.x[k];
    const double reach = p_.radius[k] + extra;
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      if (const auto* m = std::get_if<MeshWall>(&walls_[w].shape)) {
        const std::uint32_t c = cells.find(g.cell_of(x));  // occupied: k is in it
        for (std::uint32_t b = bin_start[w][c]; b < bin_start[w][c + 1]; ++b) {
          const int t = static_cast<int>(bin_tris[w][b]);
          if (m->closest(t, x).dist2 < reach * reach) add(w, t);
        }
      } else {
        const WallPoint wp = analytic_wall_point(walls_[w], x, t_);
        if (wp.dist < reach) add(w, -1);
      }
    }
  };
  build_rows(
      n, wc_.first, visit, [&](std::size_t total) { wc_.resize(total); },
      [&](std::uint32_t e, std::size_t k, std::size_t w, int t) {
        wc_.particle[e] = static_cast<std::uint32_t>(k);
        wc_.wall[e] = static_cast<std::uint16_t>(w);
        wc_.tri[e] = t;
      });
}

}  // namespace lbdem::dem
