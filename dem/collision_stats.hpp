#pragma once
// Collision statistics, always on and aggregated (counts, impact-speed histograms, energy
// dissipated by mechanism, over time and on a coarse spatial grid), plus, opt-in within a time
// window and a row budget, one row per contact for collisions.h5. A dense bed makes 1e8 contacts in
// a few hundredths of a second, so raw rows are never written unasked.
#include <cstdint>
#include <string>
#include <vector>

#include "dem/domain.hpp"
#include "dem/pair_list.hpp"

namespace lbdem {
class H5Out;
class H5In;
}  // namespace lbdem

namespace lbdem::dem {

struct CollisionRow {
  double t_start, t_end;
  std::int64_t id_i, id_j;  // id_j = -1 - wall index for particle-wall contacts
  double vn, vt, max_overlap, max_force, dissipated;
};

struct CollisionSettings {
  bool rows = false;                 // one row per contact (opt-in)
  double rows_t0 = 0, rows_t1 = 0;   // window of contact end times [s]
  std::int64_t row_budget = 100000;  // rows kept at most
  int grid_cells = 16;               // spatial grid cells along the longest box edge
};

class CollisionStats {
 public:
  void setup(const CollisionSettings& s, const Domain& d);
  void on_start(bool wall, double vn, double vt);
  void on_end(const ContactTally& t, const ContactRecord& r, double t_end, std::int64_t id_i,
              std::int64_t id_j, const Vec3& where);

  std::int64_t started_pp() const { return started_[0]; }
  std::int64_t started_pw() const { return started_[1]; }
  std::int64_t rows_dropped() const { return rows_dropped_; }
  /// Energy dissipated by all contacts so far, by mechanism [J]: normal damping, tangential
  /// damping, sliding, rolling (DemSolver integrates it each step).
  const double* dissipated() const { return dissipated_; }
  void add_dissipated(double normal_damping, double tangential_damping, double sliding,
                      double rolling);

  void write(const std::string& path, double time) const;  // collisions.h5, atomically
  void save(H5Out& out, const std::string& group) const;
  void load(const H5In& in, const std::string& group);

 private:
  int bin(double v) const;
  CollisionSettings s_;
  std::vector<double> edges_;  // impact speed bin edges [m/s]
  std::vector<std::int64_t> hist_vn_[2], hist_vt_[2];
  std::int64_t started_[2] = {0, 0};
  double dissipated_[4] = {0, 0, 0, 0};
  CellGrid grid_;
  std::vector<std::int64_t> grid_count_;
  std::vector<double> grid_energy_;
  std::vector<CollisionRow> rows_;
  std::int64_t rows_dropped_ = 0;
};

}  // namespace lbdem::dem
