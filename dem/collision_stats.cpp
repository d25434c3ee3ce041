#include "dem/collision_stats.hpp"

#include <algorithm>
#include <cmath>

#include "core/h5.hpp"

namespace lbdem::dem {

namespace {
constexpr int kBins = 60;                    // log-spaced impact speed bins
constexpr double kVmin = 1e-5, kVmax = 1e3;  // [m/s]: covers settling creep to jet-mill impacts
}  // namespace

void CollisionStats::setup(const CollisionSettings& s, const Domain& d) {
  s_ = s;
  edges_.resize(kBins + 1);
  for (int k = 0; k <= kBins; ++k) edges_[k] = kVmin * std::pow(kVmax / kVmin, double(k) / kBins);
  for (int w = 0; w < 2; ++w) hist_vn_[w].assign(kBins, 0), hist_vt_[w].assign(kBins, 0);
  const double longest = d.length().maxCoeff();
  grid_ = CellGrid(d, longest / std::max(1, s.grid_cells));
  grid_count_.assign(grid_.cells(), 0);
  grid_energy_.assign(grid_.cells(), 0.0);
}

int CollisionStats::bin(double v) const {
  if (v <= kVmin) return 0;
  const int k = static_cast<int>(std::log(v / kVmin) / std::log(kVmax / kVmin) * kBins);
  return std::clamp(k, 0, kBins - 1);
}

void CollisionStats::on_start(bool wall, double vn, double vt) {
  ++started_[wall];
  ++hist_vn_[wall][bin(std::abs(vn))];
  ++hist_vt_[wall][bin(std::abs(vt))];
}

void CollisionStats::add_dissipated(double normal_damping, double tangential_damping,
                                    double sliding, double rolling) {
  dissipated_[0] += normal_damping;
  dissipated_[1] += tangential_damping;
  dissipated_[2] += sliding;
  dissipated_[3] += rolling;
}

void CollisionStats::on_end(const ContactTally& t, const ContactRecord& r, double t_end,
                            std::int64_t id_i, std::int64_t id_j, const Vec3& where) {
  const std::size_t c = grid_.cell_of(where);
  ++grid_count_[c];
  grid_energy_[c] += t.e_dissipated;
  if (s_.rows && t_end >= s_.rows_t0 && t_end <= s_.rows_t1) {
    if (static_cast<std::int64_t>(rows_.size()) < s_.row_budget) {
      rows_.push_back({r.t_start, t_end, id_i, id_j, r.vn_impact, r.vt_impact, r.max_overlap,
                       r.max_force, t.e_dissipated});
    } else {
      ++rows_dropped_;
    }
  }
}

void CollisionStats::write(const std::string& path, double time) const {
  H5Out f(path);
  f.group("/histograms");
  f.write("/histograms/impact_normal_speed_edges_m_per_s", edges_);
  f.write("/histograms/impact_tangential_speed_edges_m_per_s", edges_);
  f.write("/histograms/impact_normal_speed_counts_pp", hist_vn_[0]);
  f.write("/histograms/impact_normal_speed_counts_pw", hist_vn_[1]);
  f.write("/histograms/impact_tangential_speed_counts_pp", hist_vt_[0]);
  f.write("/histograms/impact_tangential_speed_counts_pw", hist_vt_[1]);
  f.group("/totals");
  f.attr("collisions_pp", started_[0], "/totals");
  f.attr("collisions_pw", started_[1], "/totals");
  f.attr("dissipated_normal_damping_J", dissipated_[0], "/totals");
  f.attr("dissipated_tangential_damping_J", dissipated_[1], "/totals");
  f.attr("dissipated_sliding_J", dissipated_[2], "/totals");
  f.attr("dissipated_rolling_J", dissipated_[3], "/totals");
  f.attr("time_s", time, "/totals");
  f.attr("rows_dropped_over_budget", rows_dropped_, "/totals");
  f.group("/grid");
  std::vector<double> counts(grid_count_.begin(), grid_count_.end());
  // x varies fastest in the cell index, so the HDF5 shape is (nz, ny, nx).
  const std::vector<std::size_t> shape = {std::size_t(grid_.n[2]), std::size_t(grid_.n[1]),
                                          std::size_t(grid_.n[0])};
  f.write_array("/grid/counts", counts, shape);
  f.write_array("/grid/dissipated_J", grid_energy_, shape);
  f.attr("axis_order", std::string("zyx"), "/grid");
  std::vector<double> lo = {grid_.lo[0], grid_.lo[1], grid_.lo[2]};
  std::vector<double> hi = {grid_.lo[0] + grid_.n[0] / grid_.inv_h[0],
                            grid_.lo[1] + grid_.n[1] / grid_.inv_h[1],
                            grid_.lo[2] + grid_.n[2] / grid_.inv_h[2]};
  f.write("/grid/lo_m", lo);
  f.write("/grid/hi_m", hi);
  if (s_.rows) {
    f.group("/rows");
    const auto col = [&](auto get) {
      std::vector<decltype(get(rows_.front()))> v;
      v.reserve(rows_.size());
      for (const auto& r : rows_) v.push_back(get(r));
      return v;
    };
    if (!rows_.empty()) {
      f.write("/rows/t_start_s", col([](const CollisionRow& r) { return r.t_start; }));
      f.write("/rows/t_end_s", col([](const CollisionRow& r) { return r.t_end; }));
      f.write("/rows/id_i", col([](const CollisionRow& r) { return r.id_i; }));
      f.write("/rows/id_j", col([](const CollisionRow& r) { return r.id_j; }));
      f.write("/rows/impact_normal_speed_m_per_s", col([](const CollisionRow& r) { return r.vn; }));
      f.write("/rows/impact_tangential_speed_m_per_s",
              col([](const CollisionRow& r) { return r.vt; }));
      f.write("/rows/max_overlap_m", col([](const CollisionRow& r) { return r.max_overlap; }));
      f.write("/rows/max_normal_force_N", col([](const CollisionRow& r) { return r.max_force; }));
      f.write("/rows/dissipated_J", col([](const CollisionRow& r) { return r.dissipated; }));
    }
  }
  f.commit();
}

void CollisionStats::save(H5Out& out, const std::string& g) const {
  out.group(g);
  for (int w = 0; w < 2; ++w) {
    out.write(g + "/hist_vn" + std::to_string(w), hist_vn_[w]);
    out.write(g + "/hist_vt" + std::to_string(w), hist_vt_[w]);
  }
  out.write(g + "/started", std::vector<std::int64_t>{started_[0], started_[1], rows_dropped_});
  out.write(g + "/dissipated", std::vector<double>(dissipated_, dissipated_ + 4));
  out.write(g + "/grid_count", grid_count_);
  out.write(g + "/grid_energy", grid_energy_);
  std::vector<double> rows;
  for (const auto& r : rows_)
    rows.insert(rows.end(), {r.t_start, r.t_end, double(r.id_i), double(r.id_j), r.vn, r.vt,
                             r.max_overlap, r.max_force, r.dissipated});
  out.write(g + "/rows", rows);
}

void CollisionStats::load(const H5In& in, const std::string& g) {
  // Sizes checked before use: a checkpoint of another run (another output.collisions.grid_cells)
  // must fail here, not write past the arrays.
  const auto fits = [&](std::size_t got, std::size_t want, const char* what) {
    if (got != want)
      throw std::runtime_error("checkpoint's collision statistics do not fit this run (" +
                               std::string(what) + ": " + std::to_string(got) + " entries, " +
                               std::to_string(want) + " expected)");
  };
  for (int w = 0; w < 2; ++w) {
    const auto vn = in.int64s(g + "/hist_vn" + std::to_string(w));
    const auto vt = in.int64s(g + "/hist_vt" + std::to_string(w));
    fits(vn.size(), hist_vn_[w].size(), "histogram"),
        fits(vt.size(), hist_vt_[w].size(), "histogram");
    hist_vn_[w] = vn, hist_vt_[w] = vt;
  }
  const auto st = in.int64s(g + "/started");
  fits(st.size(), 3, "counts");
  started_[0] = st[0], started_[1] = st[1], rows_dropped_ = st[2];
  const auto cl = in.doubles(g + "/dissipated");
  fits(cl.size(), 4, "dissipated energies");
  std::copy(cl.begin(), cl.end(), dissipated_);
  const auto count = in.int64s(g + "/grid_count");
  const auto energy = in.doubles(g + "/grid_energy");
  fits(count.size(), grid_count_.size(), "grid cells (output.collisions.grid_cells)");
  fits(energy.size(), grid_energy_.size(), "grid cells (output.collisions.grid_cells)");
  grid_count_ = count;
  grid_energy_ = energy;
  const auto rows = in.doubles(g + "/rows");
  rows_.clear();
  for (std::size_t k = 0; k + 9 <= rows.size(); k += 9)
    rows_.push_back({rows[k], rows[k + 1], std::int64_t(rows[k + 2]), std::int64_t(rows[k + 3]),
                     rows[k + 4], rows[k + 5], rows[k + 6], rows[k + 7], rows[k + 8]});
}

}  // namespace lbdem::dem
