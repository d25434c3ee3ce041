#include "core/stl.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string_view>

namespace lbdem {
namespace {

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == y;
         });
}

/// Whitespace tokens of an ASCII STL, with the line number for error messages.
class AsciiTokens {
 public:
  explicit AsciiTokens(std::string_view s) : s_(s) {}
  std::string_view next() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_])))
      line_ += s_[pos_++] == '\n';
    const std::size_t start = pos_;
    while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    return s_.substr(start, pos_ - start);
  }
  void skip_line() {  // the solid name after "solid"/"endsolid" may hold any words
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
  }
  int line() const { return line_; }

 private:
  std::string_view s_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

/// Parses ASCII STL; on failure returns false with the reason in `why`.
bool parse_ascii(std::string_view s, std::vector<Triangle>& out, std::string& why) {
  AsciiTokens tok(s);
  std::string_view t;
  auto fail = [&](const std::string& wanted) {
    why = "line " + std::to_string(tok.line()) + ": expected " + wanted + ", found " +
          (t.empty() ? std::string("end of file") : "'" + std::string(t.substr(0, 20)) + "'");
    return false;
  };
  auto word = [&](std::string_view w) { return iequals(t = tok.next(), w); };
  auto number = [&](double& x) {
    t = tok.next();
    std::string_view d = t.starts_with('+') ? t.substr(1) : t;  // from_chars rejects a leading '+'
    const auto r = std::from_chars(d.data(), d.data() + d.size(), x);
    return r.ec == std::errc() && r.ptr == d.data() + d.size() && std::isfinite(x);
  };
  double x, y, z;
  int solids = 0;
  while (!(t = tok.next()).empty()) {
    if (!iequals(t, "solid")) return fail("'solid'");
    tok.skip_line();
    ++solids;
    while (!word("endsolid")) {
      if (!iequals(t, "facet")) return fail("'facet' or 'endsolid'");
      if (!word("normal")) return fail("'normal'");
      for (int k = 0; k < 3; ++k)
        if (!number(x)) return fail("a number");
      if (!word("outer")) return fail("'outer'");
      if (!word("loop")) return fail("'loop'");
      Triangle tri;
      for (Vec3& v : tri) {
        if (!word("vertex")) return fail("'vertex'");
        if (!number(x) || !number(y) || !number(z)) return fail("a number");
        v = {x, y, z};
      }
      if (!word("endloop")) return fail("'endloop'");
      if (!word("endfacet")) return fail("'endfacet'");
      out.push_back(tri);
    }
    tok.skip_line();
  }
  if (solids == 0) return fail("'solid'");
  return true;
}

std::uint32_t get_le32(const std::string& s, std::size_t at) {
  std::uint32_t u = 0;
  for (int i = 3; i >= 0; --i) u = (u << 8) | static_cast<unsigned char>(s[at + i]);
  return u;
}

}  // namespace

std::vector<Triangle> read_stl(const std::string& path, double scale, const std::string& key) {
  if (!(scale > 0) || !std::isfinite(scale))
    throw InputError(key, path, "STL scale " + to_text(scale) + " must be positive and finite",
                     "give the length of one file unit in metres, e.g. 1e-3 for mm");
  std::ifstream f(path, std::ios::binary);
  if (!f)
    throw InputError(key, path, "cannot open the STL file",
                     "check the path (relative paths start from the working directory)");
  const std::string data((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (f.bad())
    throw InputError(key, path, "cannot read the STL file", "check the file permissions");

  std::vector<Triangle> tris;
  std::string why;
  const std::size_t first = data.find_first_not_of(" \t\r\n");
  const bool says_solid = first != std::string::npos && iequals(data.substr(first, 5), "solid");
  if (!says_solid || !parse_ascii(data, tris, why)) {
    tris.clear();
    const std::uint64_t n = data.size() >= 84 ? get_le32(data, 80) : 0;
    if (data.size() < 84 || data.size() != 84 + 50 * n)
      throw InputError(
          key, path,
          "not an STL file: " +
              (says_solid ? "as ASCII, " + why + "; as binary, " : std::string("as binary, ")) +
              (data.size() < 84 ? "shorter than the 84-byte header"
                                : "header counts " + std::to_string(n) +
                                      " facets = " + std::to_string(84 + 50 * n) +
                                      " bytes, file has " + std::to_string(data.size())),
          "export the geometry again as binary or ASCII STL");
    tris.resize(n);
    for (std::size_t t = 0; t < n; ++t)
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d)  // facet: normal (12 bytes), 3 vertices, attribute (2 bytes)
          tris[t][k][d] = std::bit_cast<float>(get_le32(data, 84 + 50 * t + 12 + 12 * k + 4 * d));
  }
  for (Triangle& tri : tris)
    for (Vec3& v : tri) v *= scale;
  return tris;
}

}  // namespace lbdem
