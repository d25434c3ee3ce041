#include "run/coupled_gas.hpp"

#include <stdexcept>
#include <string>

namespace lbdem::run {

namespace {

// Populations, AA state and gas step count under /fluid of a checkpoint.
void save_gas(H5Out& f, const lbm::LbmSolver& s) {
  f.group("/fluid");
  // The slots as stored (single: f - w in float, widened exactly). A build from before single
  // precision cannot misread them: it rejects the run folder's fluid.precision key before loading.
  f.write("/fluid/populations", s.stored_slots());
  f.attr("precision", std::string(lbm::to_string(s.precision())), "/fluid");
  f.attr("aa_swapped", std::int64_t(s.state() == lbm::AaState::swapped ? 1 : 0), "/fluid");
  f.attr("steps", std::int64_t(s.steps()), "/fluid");
  f.attr("initial_mass", s.initial_mass(), "/fluid");
  f.attr("exchanged_mass", s.exchanged_mass(), "/fluid");
}

void load_gas(const H5In& f, lbm::LbmSolver& s) {
  if (!f.has("/fluid/populations"))
    throw std::runtime_error(
        "the checkpoint holds no gas state (/fluid); was it written by a run "
        "without [fluid]?");
  // Older checkpoints name the storage ("population_storage": float slots held f - w as single's
  // do) or nothing (doubles).
  std::string stored = "double";
  if (f.has_attr("precision", "/fluid"))
    stored = f.attr_string("precision", "/fluid");
  else if (f.has_attr("population_storage", "/fluid") &&
           f.attr_string("population_storage", "/fluid") == "float")
    stored = "single";
  if (stored != lbm::to_string(s.precision()))
    throw std::runtime_error("the checkpoint holds the gas in " + stored +
                             " precision, this run computes in " +
                             std::string(lbm::to_string(s.precision())) +
                             "; resume with fluid.precision = \"" + stored + "\"");
  s.load_state(f.doubles("/fluid/populations"),
               f.attr_int("aa_swapped", "/fluid") ? lbm::AaState::swapped : lbm::AaState::natural,
               long(f.attr_int("steps", "/fluid")));
  // Checkpoints from before the mass ledger: start it at the loaded mass.
  if (f.has_attr("initial_mass", "/fluid"))
    s.set_mass_ledger(f.attr_double("initial_mass", "/fluid"),
                      f.attr_double("exchanged_mass", "/fluid"));
  else
    s.set_mass_ledger(s.total_mass(), 0.0);
}

}  // namespace

CoupledGas::CoupledGas(std::unique_ptr<lbm::LbmSolver> gas, SubCycle sub, double gas_dt,
                       std::function<void(double)> before_gas_step)
    : gas_(std::move(gas)), sub_(sub), dt_(gas_dt), before_gas_step_(std::move(before_gas_step)) {}

void CoupledGas::couple(std::unique_ptr<coupling::Coupler> c, ExchangeInterval interval) {
  coupler_ = std::move(c);
  interval_ = interval;
}

void CoupledGas::advance(dem::DemSolver& s, const std::function<bool()>& stop) {
  const auto step = [&] {
    if (before_gas_step_) before_gas_step_(double(gas_->steps()) * dt_);
  };
  if (coupler_) {
    if (coupler_->steps_left() == 0) {  // else an interval resumed part-way
      if (s.steps() % interval_.dem_steps != 0) return;
      coupler_->begin_interval(s.particles(), interval_.gas_steps);
    }
    while (coupler_->steps_left() > 0) {
      if (stop()) return;
      step();
      coupler_->before_gas_step();
      gas_->step();
    }
    report_ = coupler_->end_interval(s.particles());
    return;
  }
  const std::int64_t due = steps_due(s.steps() + 1);
  while (gas_->steps() < due) {
    if (stop()) return;
    step();
    gas_->step();
  }
}

void CoupledGas::step_alone() {
  if (coupler_) throw std::logic_error("CoupledGas::step_alone: the gas is coupled to particles");
  if (before_gas_step_) before_gas_step_(time());
  gas_->step();
}

std::int64_t CoupledGas::steps_due(std::int64_t n) const {
  // The gas leads: by whole exchange intervals when coupled, else by the DEM step it holds.
  const std::int64_t m = sub_.dem_per_gas, k = interval_.dem_steps;
  return coupler_ ? (n + k - 1) / k * interval_.gas_steps
         : m > 1  ? (n + m - 1) / m
                  : n * sub_.gas_per_dem;
}

bool CoupledGas::behind(const dem::DemSolver& s) const {
  return coupler_ ? coupler_->steps_left() > 0 : gas_->steps() < steps_due(s.steps() + 1);
}

void CoupledGas::save(H5Out& f) const {
  save_gas(f, *gas_);
  if (!coupler_ || coupler_->steps_left() == 0) return;  // stopped between intervals
  const coupling::IntervalState st = coupler_->interval_state();
  f.group("/coupling_interval");
  f.attr("steps", std::int64_t(st.steps), "/coupling_interval");
  f.attr("steps_done", std::int64_t(st.steps_done), "/coupling_interval");
  f.attr("mean_eps", st.mean_eps, "/coupling_interval");
  f.write("/coupling_interval/beta", st.beta);
  f.write("/coupling_interval/f_grad", st.f_grad);
  f.write("/coupling_interval/velocity_sum", st.velocity_sum);
}

void CoupledGas::load_alone(const H5In& f) {
  load_gas(f, *gas_);
}

void CoupledGas::load(const H5In& f, dem::DemSolver& s) {
  load_gas(f, *gas_);
  // The gas leads by design (steps_due); any other count means a different time step. A coupled
  // checkpoint at a DEM step inside an interval resumes too: the gas has run the interval and the
  // particles hold its force (ParticleArrays::external, checkpointed); only a row at that
  // interval's end would miss its exchange report (drag columns), which is not kept. A stop
  // between gas steps leaves the gas part of the way to the next DEM step's count, and a coupled
  // one the interval's state.
  const std::int64_t n = s.steps(), due = steps_due(n), g = gas_->steps();
  const auto wrong = [&](const std::string& expected) {
    return std::runtime_error("checkpoint: " + std::to_string(g) + " gas steps at DEM step " +
                              std::to_string(n) + ", expected " + expected);
  };
  if (f.has("/coupling_interval")) {
    coupling::IntervalState st;
    st.steps = int(f.attr_int("steps", "/coupling_interval"));
    st.steps_done = int(f.attr_int("steps_done", "/coupling_interval"));
    st.mean_eps = f.attr_double("mean_eps", "/coupling_interval");
    st.beta = f.doubles("/coupling_interval/beta");
    st.f_grad = f.vec3s("/coupling_interval/f_grad");
    st.velocity_sum = f.vec3s("/coupling_interval/velocity_sum");
    if (!coupler_ || n % interval_.dem_steps != 0 || st.steps != interval_.gas_steps ||
        g != due + st.steps_done)
      throw wrong(std::to_string(due) + " and an interval of " +
                  std::to_string(interval_.gas_steps) + " gas steps (the checkpoint's: " +
                  std::to_string(st.steps_done) + " of " + std::to_string(st.steps) + ")");
    coupler_->resume_interval(s.particles(), st);
  } else if (g != due && !(!coupler_ && g > due && g < steps_due(n + 1))) {
    throw wrong(std::to_string(due));
  }
}

}  // namespace lbdem::run
