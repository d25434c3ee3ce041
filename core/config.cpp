#include "core/config.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <filesystem>
#include <charconv>
#include <cmath>
#include <sstream>

namespace lbdem {

struct Config::State {
  toml::table input;     // what the user gave (file + --set)
  toml::table resolved;  // input plus every default that was read
  std::set<std::string> known;
  std::map<std::string, KeyInfo> read;  // by path without indices (read_keys())
  std::string source;
};

namespace {

// "a.b[2].c" -> {"a", "b", "[2]", "c"}
std::vector<std::string> split_path(std::string_view p) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : p) {
    if (c == '.') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else if (c == '[') {
      if (!cur.empty()) out.push_back(cur);
      cur = "[";
    } else if (c == ']') {
      cur += ']';
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

// Navigates (creating tables as needed) to the parent of the last component and returns it.
toml::table* parent_table(toml::table& root, const std::vector<std::string>& parts) {
  toml::node* node = &root;
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    const std::string& c = parts[k];
    if (c.front() == '[') {
      auto* arr = node->as_array();
      const auto idx = std::stoul(c.substr(1, c.size() - 2));
      if (!arr || idx >= arr->size()) return nullptr;
      node = arr->get(idx);
    } else {
      auto* tbl = node->as_table();
      if (!tbl) return nullptr;
      // Tables are made as needed; entries of an array of tables are not (their fields have no
      // defaults to fill them).
      if (!tbl->contains(c) && parts[k + 1].front() == '[') return nullptr;
      if (!tbl->contains(c)) tbl->insert(c, toml::table{});
      node = tbl->get(c);
    }
  }
  return node ? node->as_table() : nullptr;
}

// A value as the user wrote it, on one line: numbers as shortest_text() gives them, strings
// quoted with their control characters escaped, arrays element by element and tables inline.
std::string describe_full(const toml::node& n) {
  if (const auto* a = n.as_array()) {
    std::string s = "[";
    for (std::size_t i = 0; i < a->size(); ++i) s += (i ? ", " : "") + describe_full(*a->get(i));
    return s + "]";
  }
  if (const auto* t = n.as_table()) {
    std::string s = "{";
    for (auto&& [k, v] : *t)
      s += (s.size() > 1 ? ", " : "") + std::string(k.str()) + " = " + describe_full(v);
    return s + "}";
  }
  if (const auto* d = n.as_floating_point()) return shortest_text(d->get());
  if (const auto* str = n.as_string()) {
    std::string s = "\"";
    for (char c : str->get()) {
      if (c == '\n')
        s += "\\n";
      else if (c == '\t')
        s += "\\t";
      else if (c == '\r')
        s += "\\r";
      else if (c == '"' || c == '\\')
        s += '\\', s += c;
      else
        s += c;
    }
    return s + '"';
  }
  std::ostringstream os;
  n.visit([&](auto&& v) { os << v; });
  return os.str();
}

// describe_full cut to fit the error's one line (a whole [[fill]] table written where a value
// belongs would fill a screen).
std::string describe(const toml::node& n) {
  std::string s = describe_full(n);
  if (s.size() > 80) s = s.substr(0, 76) + " ...";
  return s;
}

void collect_unknown(const toml::table& t, const std::string& prefix,
                     const std::set<std::string>& known, std::vector<std::string>& out) {
  for (auto&& [k, v] : t) {
    const std::string p =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (auto* sub = v.as_table()) {
      collect_unknown(*sub, p, known, out);
    } else if (auto* arr = v.as_array(); arr && arr->is_array_of_tables() && !arr->empty()) {
      for (std::size_t i = 0; i < arr->size(); ++i)
        collect_unknown(*arr->get(i)->as_table(), p + "[" + std::to_string(i) + "]", known, out);
    } else if (!known.count(p)) {
      out.push_back(p);
    }
  }
}

std::string strip_indices(std::string_view p) {
  std::string s;
  bool in = false;
  for (char c : p) {
    if (c == '[') in = true;
    if (!in) s += c;
    if (c == ']') in = false;
  }
  return s;
}

// "> 0", ">= 1 and <= 512": the bounds of a Range as check_range states them.
std::string range_text(const Range& r) {
  std::string want;
  if (std::isfinite(r.lo)) want += std::string(r.lo_open ? "> " : ">= ") + to_text(r.lo);
  if (std::isfinite(r.hi))
    want += std::string(want.empty() ? "" : " and ") + (r.hi_open ? "< " : "<= ") + to_text(r.hi);
  return want;
}

std::string quoted(std::string_view s) {
  return "\"" + std::string(s) + "\"";
}

std::string list_default(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + shortest_text(v[i]);
  return s + "]";
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string nearest(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const auto& c : candidates) {
    const auto d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

Config Config::from_string(std::string_view text, const std::string& source) {
  auto s = std::make_shared<State>();
  s->source = source;
  try {
    s->input = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw InputError(source + ":" + std::to_string(b.line) + ":" + std::to_string(b.column), "",
                     std::string(e.description()), "correct the TOML syntax at that line");
  }
  s->resolved = s->input;
  return Config(s, "");
}

namespace {

// `over` laid on `into` key by key: a table merges with the table of the same name, anything else
// (a value, an array, an array of tables) replaces what `into` had.
void merge_into(toml::table& into, const toml::table& over) {
  for (auto&& [key, node] : over) {
    if (const toml::table* t = node.as_table())
      if (toml::table* d = into.get_as<toml::table>(key)) {
        merge_into(*d, *t);
        continue;
      }
    into.insert_or_assign(key, node);
  }
}

// The file's table with its `base` chain resolved (the outermost file's keys win). `chain` holds
// the files above, to refuse a base that leads back to one of them.
toml::table read_with_base(const std::string& path, std::vector<std::string>& chain) {
  toml::table t;
  try {
    t = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    if (b.line == 0)
      throw InputError(chain.empty() ? "--config" : "base", path, "cannot read the file",
                       chain.empty() ? "give the path of a TOML file"
                                     : "give base as a path relative to " + chain.back());
    throw InputError(path + ":" + std::to_string(b.line) + ":" + std::to_string(b.column), "",
                     std::string(e.description()), "correct the TOML syntax at that line");
  }
  const toml::node* base = t.get("base");
  if (!base) return t;
  const auto name = base->value<std::string>();
  if (!name || name->empty())
    throw InputError("base", path, "is not a file name",
                     "give base = \"other.toml\", a path relative to " + path);
  namespace fs = std::filesystem;
  const fs::path file = fs::path(*name).is_absolute()
                            ? fs::path(*name)
                            : fs::path(path).parent_path() / fs::path(*name);
  const std::string canonical = fs::weakly_canonical(path).string();
  chain.push_back(canonical);
  if (std::find(chain.begin(), chain.end(), fs::weakly_canonical(file).string()) != chain.end())
    throw InputError("base", "\"" + *name + "\"",
                     "leads back to " + file.string() + ", which it is based on",
                     "base each preset on one that does not return to it");
  toml::table merged = read_with_base(file.string(), chain);
  chain.pop_back();
  t.erase("base");
  merge_into(merged, t);
  return merged;
}

}  // namespace

Config Config::from_file(const std::string& path) {
  auto s = std::make_shared<State>();
  s->source = path;
  std::vector<std::string> chain;
  s->input = read_with_base(path, chain);
  s->resolved = s->input;
  return Config(s, "");
}

Config Config::detached() const {
  return Config(std::make_shared<State>(*s_), prefix_);
}

void Config::erase(std::string_view full_key) {
  const auto parts = split_path(full_key);
  if (parts.empty()) return;
  for (toml::table* root : {&s_->input, &s_->resolved})
    if (toml::table* parent = parent_table(*root, parts)) parent->erase(parts.back());
}

void Config::set_override(std::string_view assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw InputError("--set", std::string(assignment), "expected key.path=value",
                     "write for example --set run.end_time=0.5");
  std::string key(assignment.substr(0, eq));
  std::string value(assignment.substr(eq + 1));
  key.erase(0, key.find_first_not_of(' '));
  key.erase(key.find_last_not_of(' ') + 1);
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    parsed = toml::table{{"v", value}};  // a bare word: take it as a string
  }
  const auto parts = split_path(key);
  if (parts.empty())
    throw InputError("--set", std::string(assignment), "names no key",
                     "write for example --set run.end_time=0.5");
  for (const std::string& c : parts)
    if (c.front() == '[' &&
        (c.size() < 3 || c.back() != ']' || c.find_first_not_of("0123456789", 1) != c.size() - 1))
      throw InputError(
          "--set", std::string(assignment), "index " + c + " is not a whole number",
          "write entries of an array of tables as e.g. --set 'materials[0].density=900'");
  for (toml::table* root : {&s_->input, &s_->resolved}) {
    toml::table* parent = parent_table(*root, parts);
    if (!parent) {
      // The path runs through a value (a face given as "wall" and then --set on one of its
      // fields), indexes what is not an array of tables, or indexes past its end: name the part.
      std::string at;
      const toml::node* node = root;
      std::size_t i = 0;
      for (; i + 1 < parts.size(); ++i) {
        const std::string& c = parts[i];
        if (c.front() == '[') {
          const auto* arr = node->as_array();
          if (!arr) break;
          const auto idx = std::stoul(c.substr(1, c.size() - 2));
          if (idx >= arr->size())
            throw InputError(at, "",
                             "has " + std::to_string(arr->size()) +
                                 (arr->size() == 1 ? " entry, so " : " entries, so ") + at + c +
                                 " is none of them",
                             "use an index below " + std::to_string(arr->size()) +
                                 ", or add the entry ([[" + at + "]]) to the config file");
          node = arr->get(idx);
        } else {
          const auto* tbl = node->as_table();
          if (!tbl) break;
          node = tbl->get(c);
          if (!node) {
            const std::string name = at + (at.empty() ? "" : ".") + c;
            throw InputError(
                name, "", "is not in the config, so " + key + " cannot be set",
                "correct the name, or add its entries ([[" + name + "]]) to the config file");
          }
        }
        at += (at.empty() || c.front() == '[' ? "" : ".") + c;
      }
      // A whole entry (--set materials[0]=...) is for the message below.
      const bool entry = i + 1 == parts.size() && parts[i].front() == '[';
      if (!entry && parts[i].front() == '[')
        throw InputError(at, describe(*node),
                         "is not an array of tables, so " + key + " has no place",
                         "drop the index " + parts[i] + ", or correct the key's path");
      if (!entry)
        throw InputError(at, describe(*node),
                         "holds a value, not a table, so " + key + " has no place",
                         "set " + at + " itself (--set " + at +
                             "=VALUE; a table value is written {key = value, ...}), or correct the "
                             "key's path");
    }
    if (!parent || parts.back().front() == '[')
      throw InputError("--set", std::string(assignment), "cannot place this key in the config",
                       "name a key inside a table, e.g. --set run.end_time=0.5");
    parent->insert_or_assign(parts.back(), *parsed.get("v"));
  }
}

std::string Config::path(std::string_view key) const {
  return prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
}

const toml::node* Config::find(std::string_view key) const {
  auto v = s_->input.at_path(path(key));
  return v.node();
}

bool Config::is_string(std::string_view key) const {
  const toml::node* n = find(key);
  return n && n->is_string();
}

bool Config::has(std::string_view key) const {
  return find(key) != nullptr;
}

void Config::record(std::string_view key, toml::node&& value_if_absent) const {
  const std::string p = path(key);
  s_->known.insert(p);
  if (s_->resolved.at_path(p)) return;
  const auto parts = split_path(p);
  if (toml::table* parent = parent_table(s_->resolved, parts))
    parent->insert(parts.back(), std::move(value_if_absent));
}

Config Config::section(std::string_view key) const {
  return Config(s_, path(key));
}

std::vector<Config> Config::table_array(std::string_view key) const {
  std::vector<Config> out;
  const toml::node* n = find(key);
  if (!n) return out;
  const auto* arr = n->as_array();
  if (!arr || !arr->is_array_of_tables())
    throw InputError(path(key), describe(*n), "expected an array of tables",
                     "write each entry as [[" + path(key) + "]]");
  for (std::size_t i = 0; i < arr->size(); ++i)
    out.push_back(Config(s_, path(key) + "[" + std::to_string(i) + "]"));
  return out;
}

const std::map<std::string, KeyInfo>& Config::read_keys() const {
  return s_->read;
}

KeyInfo& Config::note(std::string_view key, std::string type, std::string default_text) const {
  KeyInfo& k = s_->read[strip_indices(path(key))];
  k = KeyInfo{};
  k.type = std::move(type);
  k.default_text = std::move(default_text);
  return k;
}

void Config::check_range(std::string_view key, double v, const Range& r) const {
  const bool lo_bad = r.lo_open ? !(v > r.lo) : !(v >= r.lo);
  const bool hi_bad = r.hi_open ? !(v < r.hi) : !(v <= r.hi);
  if (!std::isfinite(v) || lo_bad || hi_bad) {
    const std::string want = range_text(r);
    throw InputError(path(key), shortest_text(v), "must be " + (want.empty() ? "finite" : want),
                     !r.fix.empty() ? std::string(r.fix)
                     : want.empty() ? "give a finite number"
                                    : "give a value in that range");
  }
}

double Config::get(std::string_view key, double def, Range r) const {
  const toml::node* n = find(key);
  double v = def;
  if (n) {
    if (auto x = n->value<double>()) {
      v = *x;
    } else {
      throw InputError(path(key), describe(*n), "expected a number",
                       "write a number in SI units, e.g. 1e-3");
    }
  }
  check_range(key, v, r);
  record(key, toml::value<double>(v));
  note(key, "number", shortest_text(def)).range_text = range_text(r);
  return v;
}

double Config::require(std::string_view key, Range r) const {
  if (!find(key))
    throw InputError(path(key), "", "missing", "add " + path(key) + " = <value> to the config");
  const double v = get(key, 0.0, r);
  note(key, "number", "").required = true;
  s_->read[strip_indices(path(key))].range_text = range_text(r);
  return v;
}

std::int64_t Config::get_int(std::string_view key, std::int64_t def, Range r) const {
  const toml::node* n = find(key);
  std::int64_t v = def;
  if (n) {
    if (auto x = n->as_integer()) {
      v = x->get();
    } else if (auto d = n->value<double>(); d && std::floor(*d) == *d && std::abs(*d) < 9e15) {
      v = static_cast<std::int64_t>(*d);
    } else {
      throw InputError(path(key), describe(*n), "expected an integer", "write a whole number");
    }
  }
  check_range(key, static_cast<double>(v), r);
  record(key, toml::value<std::int64_t>(v));
  note(key, "integer", std::to_string(def)).range_text = range_text(r);
  return v;
}

bool Config::get_bool(std::string_view key, bool def) const {
  const toml::node* n = find(key);
  bool v = def;
  if (n) {
    if (auto x = n->value<bool>()) {
      v = *x;
    } else {
      throw InputError(path(key), describe(*n), "expected true or false", "write true or false");
    }
  }
  record(key, toml::value<bool>(v));
  note(key, "bool", def ? "true" : "false");
  return v;
}

std::string Config::get_string(std::string_view key, std::string_view def) const {
  const toml::node* n = find(key);
  std::string v(def);
  if (n) {
    if (auto x = n->value<std::string>()) {
      v = *x;
    } else {
      throw InputError(path(key), describe(*n), "expected a string", "write the value in quotes");
    }
  }
  record(key, toml::value<std::string>(v));
  note(key, "string", quoted(def));
  return v;
}

std::string Config::get_choice(std::string_view key, std::string_view def,
                               const std::vector<std::string>& choices) const {
  std::string v = get_string(key, def);
  note(key, "choice", quoted(def)).choices = choices;
  if (std::find(choices.begin(), choices.end(), v) == choices.end()) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    throw InputError(path(key), "\"" + v + "\"", "unknown choice; known: " + list,
                     "did you mean \"" + nearest(v, choices) + "\"?");
  }
  return v;
}

std::vector<double> Config::get_list(std::string_view key, const std::vector<double>& def) const {
  const toml::node* n = find(key);
  std::vector<double> v = def;
  if (n) {
    const auto* arr = n->as_array();
    if (!arr)
      throw InputError(path(key), describe(*n), "expected an array of numbers",
                       "write [a, b, ...]");
    v.clear();
    for (const auto& e : *arr) {
      auto x = e.value<double>();
      if (!x)
        throw InputError(path(key), describe(*n), "expected an array of numbers",
                         "write [a, b, ...]");
      v.push_back(*x);
    }
  }
  toml::array a;
  for (double x : v) a.push_back(x);
  record(key, std::move(a));
  note(key, "list", list_default(def));
  return v;
}

Vec3 Config::get_vec3(std::string_view key, const Vec3& def) const {
  const auto v = get_list(key, {def.x(), def.y(), def.z()});
  if (v.size() != 3) {
    throw InputError(path(key), list_text(v), "expected three numbers [x, y, z]",
                     "write [x, y, z] in SI units");
  }
  note(key, "vector", list_default({def.x(), def.y(), def.z()}));
  return {v[0], v[1], v[2]};
}

Vec3 Config::require_vec3(std::string_view key) const {
  if (!find(key))
    throw InputError(path(key), "", "missing", "add " + path(key) + " = [x, y, z] to the config");
  const Vec3 v = get_vec3(key, Vec3::Zero());
  note(key, "vector", "").required = true;
  return v;
}

void Config::check_unknown_keys() const {
  std::vector<std::string> unknown;
  collect_unknown(s_->input, "", s_->known, unknown);
  if (unknown.empty()) return;
  std::set<std::string> known;
  for (const auto& k : s_->known) known.insert(strip_indices(k));
  const std::string& u = unknown.front();
  const toml::node* n = s_->input.at_path(u).node();
  throw InputError(u, n ? describe(*n) : "", "unknown key", unknown_key_fix(u, known));
}

namespace {

// The suggestion with the indices of the key as written, part by part where the parts match
// (materails[1].density: materials[1].density), so that it names the entry the user meant; a part
// of another table (materials[1].viscosity: fluid.viscosity) gets none.
std::string with_written_indices(const std::string& suggestion, const std::string& written) {
  std::vector<std::string> w;
  for (const auto& c : split_path(written)) {
    if (c.front() == '[' && !w.empty())
      w.back() += c;
    else
      w.push_back(c);
  }
  std::string out;
  std::size_t i = 0;
  for (const auto& c : split_path(suggestion)) {
    std::string part = c;
    if (i < w.size()) {
      const auto br = w[i].find('[');
      const std::string name = w[i].substr(0, br);
      if (br != std::string::npos &&
          edit_distance(name, c) <= std::max<std::size_t>(1, name.size() / 3))
        part += w[i].substr(br);
    }
    out += (out.empty() ? "" : ".") + part;
    ++i;
  }
  return out;
}

std::string did_you_mean(const std::vector<std::string>& keys, const std::string& written) {
  std::string s = "did you mean ";
  for (std::size_t i = 0; i < keys.size(); ++i)
    s += std::string(i == 0                 ? ""
                     : i + 1 == keys.size() ? " or "
                                            : ", ") +
         "'" + with_written_indices(keys[i], written) + "'";
  return s + "? (or remove it)";
}

}  // namespace

std::string unknown_key_fix(const std::string& written, const std::set<std::string>& known) {
  const std::string key = strip_indices(written);
  const auto dot = key.rfind('.');
  const std::string table = dot == std::string::npos ? "" : key.substr(0, dot);
  const std::string leaf = dot == std::string::npos ? key : key.substr(dot + 1);
  const auto table_of = [](const std::string& k) {
    const auto d = k.rfind('.');
    return d == std::string::npos ? std::string() : k.substr(0, d);
  };
  const auto leaf_of = [](const std::string& k) {
    const auto d = k.rfind('.');
    return d == std::string::npos ? k : k.substr(d + 1);
  };
  // A misspelling stays within its table: the nearest key there, if it is near (a third of the
  // name, at least 2 edits, but never the whole name: "e" is not a misspelt "dt"). Else the same
  // name in another table (a key written in the wrong one). Else nothing is near: the closest of
  // a few hundred paths, whatever table it is in, misleads more than it helps, so list the
  // table's keys instead.
  std::vector<std::string> siblings, leaves;
  for (const auto& k : known)
    if (table_of(k) == table) siblings.push_back(k), leaves.push_back(leaf_of(k));
  if (!leaves.empty()) {
    const std::string best = nearest(leaf, leaves);
    const std::size_t d = edit_distance(leaf, best);
    // The known keys carry no indices, so the name itself may be known from another entry of an
    // array of tables (a lognormal fill's sigma written in a fixed one).
    if (d == 0)
      return "remove it (other entries read it, not " + written.substr(0, written.rfind('.')) +
             ": its other settings do not use it)";
    if (d <= std::max<std::size_t>(2, leaf.size() / 3) && d < std::min(leaf.size(), best.size()))
      return did_you_mean({table.empty() ? best : table + "." + best}, written);
  }
  std::vector<std::string> same_leaf;
  for (const auto& k : known)
    if (leaf_of(k) == leaf) same_leaf.push_back(k);
  if (same_leaf.size() > 3) same_leaf = {nearest(key, same_leaf)};
  if (!same_leaf.empty()) return did_you_mean(same_leaf, written);
  if (siblings.empty()) {
    // A misspelt table: the nearest path, if it is near as a whole.
    const std::vector<std::string> all(known.begin(), known.end());
    const std::string best = nearest(key, all);
    if (!best.empty() && edit_distance(key, best) <= std::max<std::size_t>(2, key.size() / 4))
      return did_you_mean({best}, written);
    return "remove it";
  }
  std::string list;
  const std::size_t shown = std::min<std::size_t>(siblings.size(), 8);
  for (std::size_t i = 0; i < shown; ++i) list += (i ? ", " : "") + leaves[i];
  if (siblings.size() > shown) list += ", ...";
  return "remove it (the keys read from " +
         (table.empty() ? std::string("the top level") : "[" + table + "]") + " are " + list + ")";
}

namespace {
void flatten_values(const toml::table& t, const std::string& prefix,
                    std::vector<std::pair<std::string, std::string>>& out) {
  for (auto&& [k, v] : t) {
    const std::string p =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table()) {
      flatten_values(*sub, p, out);
    } else if (const auto* arr = v.as_array(); arr && arr->is_array_of_tables() && !arr->empty()) {
      for (std::size_t i = 0; i < arr->size(); ++i)
        flatten_values(*arr->get(i)->as_table(), p + "[" + std::to_string(i) + "]", out);
    } else {
      out.emplace_back(p, describe_full(v));
    }
  }
}
}  // namespace

std::vector<std::pair<std::string, std::string>> Config::resolved_values() const {
  std::vector<std::pair<std::string, std::string>> out;
  flatten_values(s_->resolved, "", out);
  return out;
}

std::string Config::resolved_toml() const {
  std::ostringstream os;
  os << s_->resolved << "\n";
  return os.str();
}

}  // namespace lbdem
