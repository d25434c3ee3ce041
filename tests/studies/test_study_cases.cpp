// Which cases a study invocation runs, and in what order (studies/study_case.hpp): a
// user resuming a long series names the case to run first, so --cases keeps the order given.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "studies/study_case.hpp"

using lbdem::studies::cases_to_run;

TEST_CASE("study cases run in the order --cases gives, or the study's defaults in its order",
          "[studies]") {
  const std::vector<std::string> known = {"cg1", "cg2", "cg4", "cg8", "cg10", "extra"};
  const std::vector<bool> by_default = {true, true, true, true, true, false};
  using V = std::vector<std::size_t>;
  // The order given, not the study's (CG-8 resumed before CG-2 and CG-1).
  CHECK(cases_to_run({"cg8", "cg2", "cg1"}, known, by_default) == V{3, 1, 0});
  // A name given twice runs once, at its first place.
  CHECK(cases_to_run({"cg4", "cg1", "cg4"}, known, by_default) == V{2, 0});
  // A case outside the defaults runs when named.
  CHECK(cases_to_run({"extra"}, known, by_default) == V{5});
  // Without --cases: the defaults in the study's order.
  CHECK(cases_to_run({}, known, by_default) == V{0, 1, 2, 3, 4});
}
