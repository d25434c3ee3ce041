#include "tools/src/collision_file.hpp"

#include "core/h5.hpp"
#include "tools/src/run_folder.hpp"

#include <hdf5.h>

#include <algorithm>
#include <filesystem>

namespace lbdem::tools {

namespace {
std::vector<double> to_double(const std::vector<std::int64_t>& v) {
  return {v.begin(), v.end()};
}

// The shape of a dataset, which H5In does not report.
std::vector<std::size_t> dataset_dims(const std::string& path, const std::string& name) {
  std::vector<std::size_t> out;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return out;
  if (const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT); set >= 0) {
    const hid_t space = H5Dget_space(set);
    const int rank = H5Sget_simple_extent_ndims(space);
    if (rank > 0) {
      std::vector<hsize_t> d(std::size_t(rank), 0);
      H5Sget_simple_extent_dims(space, d.data(), nullptr);
      out.assign(d.begin(), d.end());
    }
    H5Sclose(space);
    H5Dclose(set);
  }
  H5Fclose(file);
  return out;
}

Histogram histogram(const H5In& in, const std::string& stem, const char* pair) {
  const std::string edges = "/histograms/" + stem + "_edges_m_per_s";
  const std::string counts = "/histograms/" + stem + "_counts_" + pair;
  if (!in.has(edges) || !in.has(counts)) return {};
  return {in.doubles(edges), to_double(in.int64s(counts))};
}
}  // namespace

CollisionFile read_collisions(const std::string& run_dir) {
  const std::string path = run_dir + "/collisions.h5";
  if (!std::filesystem::is_regular_file(path)) throw ToolError("no collisions.h5 in " + run_dir);
  const H5In in(path);
  CollisionFile f;
  if (!in.has("/totals")) throw ToolError(path + " has no /totals group");
  f.time = in.attr_double("time_s", "/totals");
  f.rows_dropped = in.attr_int("rows_dropped_over_budget", "/totals");
  const char* pairs[2] = {"pp", "pw"};
  for (int p = 0; p < 2; ++p) {
    f.vn[p] = histogram(in, "impact_normal_speed", pairs[p]);
    f.vt[p] = histogram(in, "impact_tangential_speed", pairs[p]);
  }
  if (in.has("/rows/t_start_s")) {
    f.has_rows = true;
    auto& r = f.rows;
    r.t_start = in.doubles("/rows/t_start_s");
    r.t_end = in.doubles("/rows/t_end_s");
    r.id_j = in.int64s("/rows/id_j");
    r.vn = in.doubles("/rows/impact_normal_speed_m_per_s");
    r.vt = in.doubles("/rows/impact_tangential_speed_m_per_s");
    r.dissipated = in.doubles("/rows/dissipated_J");
  } else if (in.has("/rows")) {
    f.has_rows = true;  // rows were asked for, but no contact ended inside their window
  }
  if (in.has("/grid/dissipated_J") && in.has("/grid/lo_m") && in.has("/grid/hi_m")) {
    f.grid_dissipated = in.doubles("/grid/dissipated_J");
    f.grid_counts = in.has("/grid/counts") ? in.doubles("/grid/counts") : std::vector<double>{};
    const auto lo = in.doubles("/grid/lo_m"), hi = in.doubles("/grid/hi_m");
    const auto dims = dataset_dims(path, "/grid/dissipated_J");
    if (lo.size() == 3 && hi.size() == 3 && dims.size() == 3 &&
        dims[0] * dims[1] * dims[2] == f.grid_dissipated.size()) {
      std::copy_n(lo.begin(), 3, f.lo);
      std::copy_n(hi.begin(), 3, f.hi);
      f.nz = dims[0], f.ny = dims[1], f.nx = dims[2];  // the writer's (nz, ny, nx), x fastest
      f.has_grid = true;
    }
  }
  return f;
}

Coverage rows_coverage(const CollisionFile& f, double rows_start, double rows_end) {
  if (!f.has_rows) return {};
  if (f.rows_dropped > 0) {
    const double last =
        f.rows.size() ? *std::max_element(f.rows.t_end.begin(), f.rows.t_end.end()) : rows_start;
    return {rows_start, last};
  }
  return {rows_start, std::min(rows_end, f.time)};
}

}  // namespace lbdem::tools
