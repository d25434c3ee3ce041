#pragma once
// A run's timeseries.csv read back by a test: the header names and the rows as numbers.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace lbdem::test {

struct CsvTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  int col(const std::string& n) const {
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == n) return int(k);
    FAIL("no column " << n);
    return -1;
  }
};

inline CsvTable read_csv(const std::string& path) {
  CsvTable t;
  std::ifstream f(path);
  if (!f) FAIL("cannot open " << path);
  std::string line;
  std::getline(f, line);
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) t.names.push_back(c);
  while (std::getline(f, line)) {
    std::stringstream ls(line);
    std::vector<double> r;
    for (std::string c; std::getline(ls, c, ',');) r.push_back(std::stod(c));
    t.rows.push_back(r);
  }
  return t;
}

}  // namespace lbdem::test
