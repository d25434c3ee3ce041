#pragma once
// Typed, range-checked access to a TOML run description (toml++).
//
// Every key a scenario reads is recorded together with the value it resolved to (the default where
// the file is silent), so that (1) the run folder gets the fully resolved config.toml, (2) any
// key in the input that nobody read is reported as unknown, with a fix (unknown_key_fix), and
// (3) how each key was read (type, default, range, choices: read_keys()) can be listed in the
// generated reference docs/config.md (lbdem-cli config).
#include "core/types.hpp"

#include <toml++/toml.h>

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace lbdem {

/// Allowed interval of a numeric key; `fix` tells the user what to do when the value is outside.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;  // true: value must be > lo (not >=)
  bool hi_open = false;
  std::string_view fix = {};

  static Range positive(std::string_view fix = "give a value > 0") {
    return {0, kInf, true, false, fix};
  }
  static Range non_negative(std::string_view fix = "give a value >= 0") {
    return {0, kInf, false, false, fix};
  }
  static Range closed(double lo, double hi, std::string_view fix = {}) {
    return {lo, hi, false, false, fix};
  }
  static constexpr double kInf = std::numeric_limits<double>::infinity();
};

/// How a key was read, for the generated reference: what the getter was given, nothing more.
struct KeyInfo {
  std::string type;          // number, integer, bool, string, choice, vector [x, y, z], list
  std::string default_text;  // the default as TOML text; empty when required
  bool required = false;
  std::string range_text;  // "> 0", ">= 1 and <= 512"; empty when any finite value is allowed
  std::vector<std::string> choices;
};

class Config {
 public:
  static Config from_file(const std::string& path);
  static Config from_string(std::string_view text, const std::string& source = "<string>");

  /// Applies "a.b.c=value" (value in TOML syntax; bare words are taken as strings).
  void set_override(std::string_view assignment);

  /// A deep copy of the whole input behind this view (the same view into it): set_override() on
  /// it leaves this one untouched, to try a changed value through the same readers.
  Config detached() const;
  /// Removes a key (full dotted path, no array indices) from the input, if there: with
  /// detached(), to try an input without a setting.
  void erase(std::string_view full_key);

  /// A view of the table at `key` (created empty if absent), with paths reported in full.
  Config section(std::string_view key) const;
  /// The tables of an array of tables ([[key]]); empty if absent.
  std::vector<Config> table_array(std::string_view key) const;

  bool has(std::string_view key) const;
  /// Whether the key is given as a string (for a key that takes a number or a word).
  bool is_string(std::string_view key) const;

  double get(std::string_view key, double def, Range r = {}) const;
  double require(std::string_view key, Range r = {}) const;
  std::int64_t get_int(std::string_view key, std::int64_t def, Range r = {}) const;
  bool get_bool(std::string_view key, bool def) const;
  std::string get_string(std::string_view key, std::string_view def) const;
  /// A string that must be one of `choices`; the error names the nearest choice.
  std::string get_choice(std::string_view key, std::string_view def,
                         const std::vector<std::string>& choices) const;
  Vec3 get_vec3(std::string_view key, const Vec3& def) const;
  Vec3 require_vec3(std::string_view key) const;
  std::vector<double> get_list(std::string_view key, const std::vector<double>& def) const;

  /// Throws InputError for the first key in the input that no getter has read.
  void check_unknown_keys() const;
  /// The input with every default that was read filled in, as TOML text.
  std::string resolved_toml() const;
  /// Every value of the resolved config as {path, value on one line}, in path order; tables
  /// (inline ones too) are opened and arrays of tables indexed: materials[0].restitution.
  std::vector<std::pair<std::string, std::string>> resolved_values() const;
  /// Full dotted path of `key` under this view.
  std::string path(std::string_view key) const;
  /// Every key read so far, by path with the indices of arrays of tables removed
  /// (fill[2].radius.kind -> fill.radius.kind); a key read twice keeps its last reading.
  const std::map<std::string, KeyInfo>& read_keys() const;

 private:
  struct State;
  Config(std::shared_ptr<State> s, std::string prefix)
      : s_(std::move(s)), prefix_(std::move(prefix)) {}
  const toml::node* find(std::string_view key) const;
  void record(std::string_view key, toml::node&& value_if_absent) const;
  void check_range(std::string_view key, double v, const Range& r) const;
  KeyInfo& note(std::string_view key, std::string type, std::string default_text) const;

  std::shared_ptr<State> s_;
  std::string prefix_;
};

/// Levenshtein distance, for "did you mean" hints.
std::size_t edit_distance(std::string_view a, std::string_view b);
/// The entry of `candidates` nearest to `word` (empty if none).
std::string nearest(std::string_view word, const std::vector<std::string>& candidates);
/// The fix for an unknown key (as written, with any indices) given the keys the scenario read
/// (indices stripped): the nearest key of the same table; the same name in other tables; the
/// nearest whole path, for a misspelt table; or the table's keys. Suggestions keep the written
/// indices where their parts match.
std::string unknown_key_fix(const std::string& written, const std::set<std::string>& known);

}  // namespace lbdem
