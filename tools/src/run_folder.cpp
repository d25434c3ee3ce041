#include "tools/src/run_folder.hpp"

#include "core/error.hpp"
#include "core/h5.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

namespace lbdem::tools {

namespace fs = std::filesystem;

bool Table::has(std::string_view name) const {
  return std::find(names.begin(), names.end(), name) != names.end();
}

const std::vector<double>& Table::column(std::string_view name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw ToolError("unknown column '" + std::string(name) + "' in " + source +
                    "; known: " + join(names, ", "));
  return columns[std::size_t(it - names.begin())];
}

double Table::number(std::string_view name, std::size_t row) const {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? std::numeric_limits<double>::quiet_NaN()
                           : columns[std::size_t(it - names.begin())][row];
}

const std::string& Table::cell(std::string_view name, std::size_t row) const {
  if (text.empty()) throw ToolError(source + " was read without its text cells");
  column(name);  // the error for an unknown column
  return text[std::size_t(std::find(names.begin(), names.end(), name) - names.begin())][row];
}

namespace {
// The cells of one line, trimmed; a cell in double quotes keeps its commas and loses its quotes,
// and "" inside it is one quote (RFC 4180).
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  bool quoted = false, was_quoted = false;
  const auto finish = [&] {
    if (!was_quoted) {
      const auto b = cell.find_first_not_of(" \t\r");
      const auto e = cell.find_last_not_of(" \t\r");
      cell = b == std::string::npos ? "" : cell.substr(b, e - b + 1);
    }
    out.push_back(cell);
    cell.clear();
    was_quoted = false;
  };
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (c == '"' && quoted && k + 1 < line.size() && line[k + 1] == '"') {
      cell += '"';
      ++k;
    } else if (c == '"') {
      quoted = !quoted;
      was_quoted = true;
    } else if (c == ',' && !quoted) {
      finish();
    } else if (!(was_quoted && !quoted && (c == ' ' || c == '\r' || c == '\t'))) {
      cell += c;
    }
  }
  if (!line.empty()) finish();
  return out;
}
}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

Table read_csv(const std::string& path, bool keep_text) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw ToolError("cannot read " + path);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  Table t;
  t.source = path;
  std::size_t pos = 0;
  bool header = true;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) break;  // partial last line of a file still being written
    const auto cells = split(text.substr(pos, nl - pos));
    pos = nl + 1;
    if (header) {
      t.names = cells;
      t.columns.resize(cells.size());
      if (keep_text) t.text.resize(cells.size());
      header = false;
      continue;
    }
    if (cells.size() != t.names.size()) continue;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      const bool ok = !cells[c].empty() && end && *end == '\0';
      t.columns[c].push_back(ok ? v : std::numeric_limits<double>::quiet_NaN());
      if (keep_text) t.text[c].push_back(cells[c]);
    }
  }
  if (header) throw ToolError(path + " has no header line");
  return t;
}

namespace {
toml::table parse_toml(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw ToolError(source + ": not valid TOML: " + std::string(e.description()));
  }
}
}  // namespace

double size_factor_from_toml(std::string_view toml_text, const std::string& source) {
  const auto tbl = parse_toml(toml_text, source);
  const auto cg = tbl["coarse_grain"];
  if (const auto l = cg["size_factor"].value<double>()) return *l;
  if (const auto n = cg["particles_per_parcel"].value<double>()) return std::cbrt(*n);
  return 1.0;
}

std::vector<Material> materials_from_toml(std::string_view toml_text, const std::string& source) {
  std::vector<Material> out;
  const auto tbl = parse_toml(toml_text, source);
  if (const auto* arr = tbl["materials"].as_array()) {
    for (const auto& node : *arr) {
      const auto* m = node.as_table();
      if (!m) continue;
      out.push_back({(*m)["name"].value_or(std::string()),
                     (*m)["density"].value_or(std::numeric_limits<double>::quiet_NaN())});
    }
  }
  return out;
}

std::string default_label(double size_factor) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "l = %g", size_factor);
  return buf;
}

void check_window_and_labels(double from, double to, std::size_t labels, std::size_t dirs) {
  if (!(from < to)) throw ToolError("empty window: --from must be below --to");
  if (labels != 0 && labels != dirs)
    throw ToolError(std::to_string(labels) + " --label for " + std::to_string(dirs) +
                    " run folders; give one per folder or none");
}

std::string run_label(const std::vector<std::string>& labels, std::size_t k, double size_factor) {
  return labels.empty() ? default_label(size_factor) : labels[k];
}

std::string join(const std::vector<std::string>& words, std::string_view sep) {
  std::string s;
  for (std::size_t k = 0; k < words.size(); ++k) s += (k ? std::string(sep) : "") + words[k];
  return s;
}

RunFolder RunFolder::open(const std::string& dir) {
  if (!fs::is_directory(dir)) throw ToolError("no run folder " + dir);
  const std::string csv = dir + "/timeseries.csv";
  if (!fs::is_regular_file(csv)) throw ToolError("no timeseries.csv in " + dir);
  RunFolder r;
  r.dir = dir;
  r.name = fs::path(dir).lexically_normal().filename().string();
  if (r.name.empty()) r.name = fs::path(dir).lexically_normal().parent_path().filename().string();
  if (std::ifstream f{dir + "/config.toml"}) {
    r.config_text.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    r.size_factor = size_factor_from_toml(r.config_text, dir + "/config.toml");
  }
  r.series = read_csv(csv);
  r.time();  // a series without time_s is no run's series: fail here, naming the columns
  return r;
}

std::string window_error(const RunFolder& run, double from, double to, std::size_t rows,
                         std::size_t needed) {
  const auto& t = run.time();
  const std::string covers =
      t.empty() ? "it has no rows"
                : "it covers [" + to_text(t.front()) + ", " + to_text(t.back()) + "] s";
  return "window [" + to_text(from) + ", " + to_text(to) + "] s holds " + std::to_string(rows) +
         " row(s) of " + run.series.source + " (" + covers + "); need " + std::to_string(needed);
}

double config_number(const RunFolder& run, std::string_view dotted_key, double def) {
  const auto tbl = parse_toml(run.config_text, run.dir + "/config.toml");
  return tbl.at_path(dotted_key).value_or(def);
}

double snapshot_mass(const RunFolder& run, double t) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::string master = run.dir + "/particles.h5";
  if (!fs::is_regular_file(master)) return kNaN;
  const auto mats = materials_from_toml(run.config_text, run.dir + "/config.toml");
  if (mats.empty()) return kNaN;
  const auto times = H5In(master).doubles("/time_s");
  if (times.empty()) return kNaN;
  const auto after = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t k = after == times.begin() ? 0 : std::size_t(after - times.begin()) - 1;
  char name[64];
  std::snprintf(name, sizeof name, "/snapshots/particles_%06zu.h5", k);
  const H5In snap(run.dir + name);
  const auto r = snap.doubles("/radius_m");
  const auto m = snap.int32s("/material");
  double mass = 0;
  for (std::size_t p = 0; p < r.size(); ++p) {
    const std::size_t id = p < m.size() ? std::size_t(std::max(0, m[p])) : 0;
    if (id >= mats.size()) return kNaN;
    mass += 4.0 / 3.0 * std::numbers::pi * r[p] * r[p] * r[p] * mats[id].density;
  }
  return mass;
}

double ledger_mass(const RunFolder& run, double t) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const Table& s = run.series;
  if (s.rows() == 0 || !s.has("particles") || !s.has("mass_inserted_kg") ||
      !s.has("mass_removed_kg") || s.column("particles").front() != 0)
    return kNaN;
  const auto& time = run.time();
  const auto after = std::upper_bound(time.begin(), time.end(), t);
  if (after == time.begin()) return kNaN;
  const std::size_t k = std::size_t(after - time.begin()) - 1;
  const double mass = s.column("mass_inserted_kg")[k] - s.column("mass_removed_kg")[k];
  return mass > 0 ? mass : kNaN;
}

}  // namespace lbdem::tools
