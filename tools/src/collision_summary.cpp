#include "tools/src/collision_summary.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/h5.hpp"
#include "tools/src/collision_file.hpp"
#include "tools/src/collision_metrics.hpp"
#include "tools/src/window_stats.hpp"

namespace lbdem::tools {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const char* const kMechanisms[4] = {"normal_damping", "tangential_damping", "sliding", "rolling"};
const char* const kPairs[2] = {"pp", "pw"};

}  // namespace

CollisionSummary analyse_collisions(const RunFolder& run, const std::string& label, double from,
                                    double to) {
  const auto& t = run.time();
  const IndexRange w = select_window(t, from, to);
  if (w.size() < 2) throw ToolError(window_error(run, from, to, w.size(), 2));
  const std::size_t a = w.begin, b = w.end - 1;
  const double ta = t[a], tb = t[b], span = tb - ta;
  const auto delta = [&](const char* col) {
    const auto& c = run.series.column(col);
    return c[b] - c[a];
  };
  CollisionSummary r;
  r.label = label;
  r.fields.emplace_back("run_dir", run.dir);
  r.fields.emplace_back("label", label);
  const double l = run.size_factor;
  r.add("size_factor", l);
  r.add("t_from_s", ta);
  r.add("t_to_s", tb);
  const auto& np = run.series.column("particles");
  const double parcels = moments({np.data() + a, w.size()}).mean;
  r.add("parcels", parcels);
  r.add("represented_originals", represented_originals(parcels, l));
  for (int p = 0; p < 2; ++p) {
    const double n = delta(p == 0 ? "collisions_pp" : "collisions_pw");
    const double fp = per_parcel_frequency(n, parcels, span,
                                           p == 0 ? Pair::particle_particle : Pair::particle_wall);
    const std::string k = kPairs[p];
    r.add("collisions_" + k, n);
    r.add("rate_" + k + "_per_s", n / span);
    r.add("freq_" + k + "_per_parcel_per_s", fp);
    r.add("freq_" + k + "_per_original_per_s", per_original_frequency(fp, l));
  }
  // A folder of kept small outputs has no snapshots: a run that started empty then has its
  // powder mass from the inflow's ledger in timeseries.csv.
  double mass = snapshot_mass(run, tb);
  if (std::isnan(mass)) mass = ledger_mass(run, tb);
  r.add("powder_mass_kg", mass);
  double total = 0;
  for (const char* m : kMechanisms) {
    const double e = delta(("dissipated_" + std::string(m) + "_J").c_str());
    r.add("dissipated_" + std::string(m) + "_J", e);
    total += e;
  }
  const double ncoll = r.get("collisions_pp") + r.get("collisions_pw");
  r.add("dissipated_J", total);
  r.add("dissipation_rate_W", total / span);
  r.add("dissipated_per_collision_J", ncoll > 0 ? total / ncoll : kNaN);
  r.add("dissipated_per_kg_J_per_kg", total / mass);
  r.add("dissipation_rate_per_kg_W_per_kg", total / span / mass);

  // Impact speeds: the rows of contacts begun in (ta, tb] where the rows hold every contact of
  // the window, else the solver's histograms, which run from t = 0 to the file's time. A folder
  // of a run's kept small outputs may lack collisions.h5: the figures above come from
  // timeseries.csv and stand; the impact speeds and the grid are then unknown (NaN), not zero.
  const bool have_file = std::filesystem::is_regular_file(run.dir + "/collisions.h5");
  if (!have_file)
    std::fprintf(stderr,
                 "lbdem-collision-stats: no collisions.h5 in %s: impact speeds and the "
                 "dissipation grid left empty\n",
                 run.dir.c_str());
  const CollisionFile f = have_file ? read_collisions(run.dir) : CollisionFile{};
  const Coverage cov =
      have_file ? rows_coverage(f, config_number(run, "output.collisions.rows_start", 0.0),
                                config_number(run, "output.collisions.rows_end", kInf))
                : Coverage{};
  double pw_share = kNaN;
  if (!have_file) {
    r.source = "none (no collisions.h5)";
  } else if (cov.covers(ta, tb)) {
    r.source = "rows";
    std::vector<double> vn[2], vt[2];
    double diss[2] = {0, 0};
    for (std::size_t k = 0; k < f.rows.size(); ++k) {
      if (!(f.rows.t_start[k] > ta && f.rows.t_start[k] <= tb)) continue;
      const int p = f.rows.id_j[k] < 0 ? 1 : 0;
      vn[p].push_back(f.rows.vn[k]);
      vt[p].push_back(f.rows.vt[k]);
      diss[p] += f.rows.dissipated[k];
    }
    for (int p = 0; p < 2; ++p) {
      r.vn[p] = bin_values(vn[p], f.vn[p].edges);
      r.vt[p] = bin_values(vt[p], f.vt[p].edges);
    }
    if (diss[0] + diss[1] > 0) pw_share = diss[1] / (diss[0] + diss[1]);
  } else {
    r.source = "histograms 0.." + lbdem::to_text(f.time) + " s";
    for (int p = 0; p < 2; ++p) r.vn[p] = f.vn[p], r.vt[p] = f.vt[p];
  }
  r.add("dissipated_pw_share_rows", pw_share);
  for (int p = 0; p < 2; ++p) {
    const std::string k = kPairs[p];
    r.add("impacts_" + k, have_file ? r.vn[p].total() : kNaN);
    r.add("impact_vn_" + k + "_median_m_per_s", histogram_quantile(r.vn[p], 0.5));
    r.add("impact_vn_" + k + "_p95_m_per_s", histogram_quantile(r.vn[p], 0.95));
    r.add("impact_vt_" + k + "_median_m_per_s", histogram_quantile(r.vt[p], 0.5));
  }
  r.fields.emplace_back("impact_source", r.source);
  const GridSummary g = f.has_grid
                            ? summarise_grid(f.grid_dissipated, f.nz, f.ny, f.nx, f.lo[2], f.hi[2])
                            : GridSummary{kNaN, kNaN, kNaN};
  r.add("grid_time_s", have_file ? f.time : kNaN);
  r.add("grid_dissipated_J", g.total);
  r.add("grid_top_decile_share", g.top_decile);
  r.add("grid_z_centroid_m", g.z_centroid);
  return r;
}

void write_collision_csvs(const std::string& path, const std::vector<CollisionSummary>& res) {
  std::ostringstream f, h;
  for (std::size_t k = 0; k < res[0].fields.size(); ++k)
    f << (k ? "," : "") << res[0].fields[k].first;
  f << "\n";
  for (const auto& r : res) {
    for (std::size_t k = 0; k < r.fields.size(); ++k)
      f << (k ? "," : "") << csv_field(r.fields[k].second);
    f << "\n";
  }
  const std::string stem =
      path.size() > 4 && path.ends_with(".csv") ? path.substr(0, path.size() - 4) : path;
  h << "label,pair,kind,bin_lo_m_per_s,bin_hi_m_per_s,count,source\n";
  for (const auto& r : res)
    for (int p = 0; p < 2; ++p)
      for (const auto& [kind, hist] : {std::pair{"normal", &r.vn[p]}, {"tangential", &r.vt[p]}})
        for (std::size_t b = 0; b < hist->counts.size(); ++b)
          h << csv_field(r.label) << "," << kPairs[p] << "," << kind << "," << hist->edges[b] << ","
            << hist->edges[b + 1] << "," << hist->counts[b] << "," << csv_field(r.source) << "\n";
  write_file_atomic(path, f.str());
  write_file_atomic(stem + "_impact_speed.csv", h.str());
}

std::string collision_table(const std::vector<CollisionSummary>& res) {
  char line[512];
  std::string out;
  std::snprintf(line, sizeof line, "%-12s %9s %9s %10s %10s %10s %10s %10s %10s %10s %9s %9s  %s\n",
                "label", "from[s]", "to[s]", "parcels", "fpp/parc", "fpw/parc", "fpp/orig",
                "fpw/orig", "E_diss[J]", "J/kg", "vn_pp50", "vn_pw50", "impact speeds from");
  out += line;
  for (const auto& r : res) {
    std::snprintf(
        line, sizeof line,
        "%-12s %9.4g %9.4g %10.0f %10.4g %10.4g %10.4g %10.4g %10.4g %10.4g %9.3g %9.3g  %s\n",
        r.label.c_str(), r.get("t_from_s"), r.get("t_to_s"), r.get("parcels"),
        r.get("freq_pp_per_parcel_per_s"), r.get("freq_pw_per_parcel_per_s"),
        r.get("freq_pp_per_original_per_s"), r.get("freq_pw_per_original_per_s"),
        r.get("dissipated_J"), r.get("dissipated_per_kg_J_per_kg"),
        r.get("impact_vn_pp_median_m_per_s"), r.get("impact_vn_pw_median_m_per_s"),
        r.source.c_str());
    out += line;
  }
  return out;
}

}  // namespace lbdem::tools
