#pragma once
// What the post-processing tools read from a run folder: timeseries.csv (SI column names), the
// coarse-graining size factor and the materials of the resolved config.toml, and snapshot masses.
#include <cstddef>
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace lbdem::tools {

/// A user-facing error: the tools print it as one line and exit with kToolErrorExit.
class ToolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
inline constexpr int kToolErrorExit = 2;  // the same code as lbdem's input errors

/// A CSV with a header line, stored by column: every cell as a number (NaN where it is not one),
/// and as text where asked for (tables with names in them: run folders, labels).
struct Table {
  std::string source;
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  std::vector<std::vector<std::string>> text;  // by column; empty unless read with keep_text

  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  bool has(std::string_view name) const;
  /// The column `name`; ToolError listing the known columns otherwise.
  const std::vector<double>& column(std::string_view name) const;
  /// The cell of column `name` in row `row` as a number; NaN if the table has no such column.
  double number(std::string_view name, std::size_t row) const;
  /// The text cell (quotes removed); ToolError if the table was read without its text.
  const std::string& cell(std::string_view name, std::size_t row) const;
};

/// Reads a CSV. A row of the wrong width or without its final newline is dropped: the solver
/// appends and flushes row by row, so a file read during a run can end in a partial line. A cell
/// in double quotes may hold commas; the quotes are not part of its text.
Table read_csv(const std::string& path, bool keep_text = false);
/// One CSV cell as read_csv reads it back: the text as is, or in double quotes (each quote
/// doubled) when it holds a comma, a quote or a newline.
std::string csv_field(const std::string& text);

/// l from a config.toml text: [coarse_grain] size_factor, else particles_per_parcel^(1/3), else 1.
double size_factor_from_toml(std::string_view toml_text, const std::string& source);
/// "l = 2.5" (%g of the size factor).
std::string default_label(double size_factor);
/// The window and --label checks every tool makes (ToolError on an empty window or a label count
/// that is neither 0 nor one per folder).
void check_window_and_labels(double from, double to, std::size_t labels, std::size_t dirs);
/// Label of run k: labels[k], or default_label(size_factor) when no labels were given.
std::string run_label(const std::vector<std::string>& labels, std::size_t k, double size_factor);
std::string join(const std::vector<std::string>& words, std::string_view sep);

struct Material {
  std::string name;
  double density = 0;  // [kg/m³]
};
/// The [[materials]] array of a config.toml text, in file order (a snapshot's material index).
std::vector<Material> materials_from_toml(std::string_view toml_text, const std::string& source);

struct RunFolder {
  std::string dir;
  std::string name;          // last path component, for tables
  std::string config_text;   // config.toml ("" if absent: then l = 1)
  double size_factor = 1.0;  // l: one parcel stands for l³ originals
  Table series;              // timeseries.csv

  /// Checks that `dir` is a folder with a timeseries.csv; ToolError otherwise.
  static RunFolder open(const std::string& dir);
  const std::vector<double>& time() const { return series.column("time_s"); }
};

/// "window [T0, T1] s holds n row(s) of DIR/timeseries.csv (it covers [a, b] s); need m".
std::string window_error(const RunFolder& run, double from, double to, std::size_t rows,
                         std::size_t needed);

/// A number of the run's config.toml at a dotted path ("output.collisions.rows_start"), or def.
double config_number(const RunFolder& run, std::string_view dotted_key, double def);

/// Mass of the particles [kg] in the latest snapshot at or before t (the first one if all are
/// later), as Σ 4/3 π r³ ρ(material); NaN if the run has no snapshots or no densities.
double snapshot_mass(const RunFolder& run, double t);

/// Mass of the particles [kg] at the last row of timeseries.csv at or before t, from the run's
/// own ledger: mass_inserted_kg - mass_removed_kg. Only for a run that starts empty (particles = 0
/// in its first row), whose every particle came in through the inflow; NaN otherwise, without
/// those columns, before the first row, or while nothing is in (no mass to divide by). It stands
/// in for snapshot_mass in a folder of kept small outputs (no snapshots).
double ledger_mass(const RunFolder& run, double t);

/// Runs body() and maps ToolError, and an output that cannot be written (a missing folder, a full
/// disk: "cannot write PATH: why"), to one line "tool: message" on stderr with kToolErrorExit, any
/// other exception to "tool: failed: message" with exit 1.
template <class Body>
int guarded_main(const char* tool, Body&& body) {
  try {
    return body();
  } catch (const ToolError& e) {
    std::cerr << tool << ": " << e.what() << "\n";
    return kToolErrorExit;
  } catch (const WriteError& e) {
    std::cerr << tool << ": " << e.what() << "\n";
    return kToolErrorExit;
  } catch (const std::exception& e) {
    std::cerr << tool << ": failed: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace lbdem::tools
