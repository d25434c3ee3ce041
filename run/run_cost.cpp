#include "run/run_cost.hpp"

#include "core/h5.hpp"

namespace lbdem::run {

namespace {

constexpr std::size_t kPhases = std::size_t(Phase::count);

// The phase names, one per line, in the order of the stored seconds: a later lbdem with other
// phases reads the sums by name.
std::string phase_names() {
  std::string s;
  for (std::size_t p = 0; p < kPhases; ++p) s += std::string(phase_name(Phase(p))) + "\n";
  return s;
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> out;
  std::size_t a = 0;
  for (std::size_t b; (b = s.find('\n', a)) != std::string::npos; a = b + 1)
    out.push_back(s.substr(a, b - a));
  return out;
}

}  // namespace

void RunCostMeter::begin(double t) {
  from_s_ = t;
  wall0_ = 0;
  phase0_.fill(0.0);
  t0_ = clock::now();
}

void RunCostMeter::resume(const H5In& f, double t) {
  begin(t);
  const std::optional<RunCost> c = read_run_cost(f);
  if (!c) return;
  from_s_ = c->from_s;
  wall0_ = c->wall_s;
  for (const auto& [name, sec] : c->phases)
    for (std::size_t p = 0; p < kPhases; ++p)
      if (name == phase_name(Phase(p))) phase0_[p] = sec;
}

void RunCostMeter::save(H5Out& f, double t) const {
  const PhaseTimer& timer = PhaseTimer::global();
  std::vector<double> sec(kPhases);
  for (std::size_t p = 0; p < kPhases; ++p) sec[p] = phase0_[p] + timer.seconds(Phase(p));
  f.group("/timing");
  f.write("/timing/phase_s", sec);
  f.attr("phases", phase_names(), "/timing");
  f.attr("from_s", from_s_, "/timing");
  f.attr("to_s", t, "/timing");
  f.attr("wall_s", wall0_ + std::chrono::duration<double>(clock::now() - t0_).count(), "/timing");
}

std::optional<RunCost> read_run_cost(const H5In& f) {
  if (!f.has("/timing") || !f.has("/timing/phase_s")) return std::nullopt;
  RunCost c;
  c.from_s = f.attr_double("from_s", "/timing");
  c.to_s = f.attr_double("to_s", "/timing");
  c.wall_s = f.attr_double("wall_s", "/timing");
  const auto names = split_lines(f.attr_string("phases", "/timing"));
  const auto sec = f.doubles("/timing/phase_s");
  if (names.size() != sec.size()) return std::nullopt;
  for (std::size_t k = 0; k < names.size(); ++k) c.phases.emplace_back(names[k], sec[k]);
  return c;
}

std::optional<RunCost> read_run_cost(const std::string& checkpoint) {
  try {
    return read_run_cost(H5In(checkpoint));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace lbdem::run
