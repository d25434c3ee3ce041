#pragma once
// The reference of every config key, docs/config.md, generated from the code (lbdem-cli config).
//
// What a key is comes from two places. Type, default, allowed range and choices are what the
// readers themselves pass to the Config getters (Config::read_keys()), collected by reading every
// preset in scenarios/<name>/presets/ as its scenario: nothing is written twice, and a changed
// default or bound changes the reference. Keys no preset sets (walls, explicit particles, the
// other forms of a gas face, the jet mill's feed, ...) come from probe configs in
// scenarios/config_reference/, each read as the scenarios its probe_for list names (README.md
// there). Unit and meaning cannot be taken from a getter call, so they are a table here
// (config_reference.cpp), keyed by path pattern; the generator joins the two and names every read
// key the table does not cover and every table entry no read key falls under, so the test
// (tests/scenarios/test_config_doc.cpp) fails on an undocumented key, on a documented key that
// nothing reads and on a stale docs/config.md. A table beside the readers keeps the readers' code
// as it is (no unit and meaning argument on every getter call) at the price of one list to extend
// when a key is added (and a probe, if no preset sets it); the test says which.
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/config.hpp"

namespace lbdem::scenarios {

/// Unit and meaning of the keys whose path (indices removed) matches `pattern`, where '*' stands
/// for any run of characters without a '.'. `default_text`, when given, replaces the default the
/// readers pass (for defaults computed from other keys).
struct KeyDoc {
  std::string_view pattern, unit, meaning, default_text = {};
};
const std::vector<KeyDoc>& key_docs();

/// One key of the reference: how it was read, and by which scenarios.
struct ReferenceKey {
  KeyInfo info;
  std::set<std::string> scenarios;
  bool default_varies = false;  // read with different defaults (computed from other keys)
};

/// Every key read when each scenario is built from its presets and its probes under `source_dir`
/// (one of each set of inputs that set the same paths and strings: those read the same keys).
std::map<std::string, ReferenceKey> collect_keys(const std::string& source_dir);

/// The patterns of key_docs() that no key of `keys` falls under (the first match wins): entries
/// for keys that nothing reads, or that no preset or probe reaches.
std::vector<std::string> unread_docs(const std::map<std::string, ReferenceKey>& keys);

/// The markdown reference of `keys`; keys no KeyDoc matches are appended to `undocumented`.
std::string reference_markdown(const std::map<std::string, ReferenceKey>& keys,
                               std::vector<std::string>& undocumented);

}  // namespace lbdem::scenarios
