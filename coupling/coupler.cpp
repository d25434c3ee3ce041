#include "coupling/coupler.hpp"

#include "core/phase_timer.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/deterministic_sum.hpp"
#include "core/parallel_for.hpp"
#include "coupling/drag/coarse_grain_drag.hpp"
#include "lbm/d3q19.hpp"

namespace lbdem::coupling {

Coupler::Coupler(lbm::LbmSolver& gas, const lbm::LatticeFrame& frame,
                 const lbm::LatticeUnits& units, CouplerSettings s)
    : gas_(gas),
      units_(units),
      s_(s),
      kernel_(gas.grid(), frame, s.kernel_width, ParticleKernel::solid_mask(gas.flags()),
              s.particle_box) {
  if (!(s_.size_factor >= 1)) throw std::invalid_argument("coupling: size factor must be >= 1");
  if (!(s_.viscosity > 0)) throw std::invalid_argument("coupling: gas viscosity must be > 0");
  if (!(s_.eps_min > 0 && s_.eps_min < 1))
    throw std::invalid_argument("coupling: eps_min must lie in (0, 1)");
  const auto n = std::size_t(gas.grid().cells());
  eps_.assign(n, 1.0);
  alpha_.assign(n, 0.0);
  if (s_.two_way) {
    gas_.enable_porosity();
    gas_.enable_force_field();
    gas_.enable_velocity_sum();
  }
}

void Coupler::pressure(std::vector<double>& p) const {
  gas_.density(p);
  density_to_pressure(p);
}

void Coupler::density_to_pressure(std::vector<double>& p) const {
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static) if (n >= std::size_t(ParticleKernel::kMinParallelCells))
  for (std::size_t c = 0; c < n; ++c)
    p[c] = p[c] > 0 ? units_.pressure_to_si((p[c] - 1.0) * lbm::kCs2) : 0.0;  // solid: 0
}

Vec3 Coupler::gas_momentum() const {
  const double per = units_.rho * units_.dx * units_.dx * units_.dx * units_.dx / units_.dt;
  return per * gas_.raw_momentum();
}

void Coupler::begin_interval(const dem::ParticleArrays& p, int gas_steps) {
  if (gas_steps < 1) throw std::invalid_argument("coupling: an interval needs >= 1 gas step");
  steps_ = gas_steps;
  steps_done_ = 0;
  PhaseLap lap;
  const std::size_t np = p.size();
  if (np == 0 && empty_fields_set_) {
    report_ = empty_report_;
    beta_.clear(), v_p_.clear(), f_grad_.clear();
    return lap.to(Phase::coupling_interpolation_drag);
  }
  report_ = ExchangeReport{};
  map_particles(p, lap);
  // The density for grad p comes from the same pass over the populations.
  if (s_.pressure_gradient)
    gas_.raw_moments(pressure_, cell_vec_);
  else
    gas_.raw_velocity(cell_vec_);
  const auto ncell = cell_vec_.size();
  const bool many_cells = ncell >= std::size_t(ParticleKernel::kMinParallelCells);
  if (s_.two_way) {
#pragma omp parallel for schedule(static) if (many_cells)
    for (std::size_t c = 0; c < ncell; ++c) cell_vec_[c] /= eps_[c];
  }
  const double to_si = units_.velocity_to_si(1.0);
  // eps at the particle through the same kernel as everything else the gas gives it; the slip that
  // sets beta_p only needs a local value (the exchange is exact whatever beta_p is). With grad p,
  // eps and grad p go through the kernel together (one filter over four components).
  kernel_.interpolate_local(cell_vec_, u_p_);
  if (s_.pressure_gradient) {
    density_to_pressure(pressure_);
    kernel_.pressure_gradient(pressure_, cell_vec_, true);  // the velocity is read: reuse its field
    kernel_.interpolate(eps_, cell_vec_, eps_p_, f_grad_);
  } else {
    kernel_.interpolate(eps_, eps_p_);
    f_grad_.assign(np, Vec3::Zero());
  }

  // Drag coefficients (the law of one original times l^3, coarse_grain_drag.hpp), held over the
  // interval, and the particle velocities they act on.
  beta_.resize(np);
  v_p_.assign(p.v.begin(), p.v.end());
  const double mu = s_.viscosity, rho_f = units_.rho;
  std::visit(
      [&](const auto& law) {
        // The law throws on a non-finite slip (a diverged gas): the lowest particle's error.
        parallel_for(np, ParticleKernel::kMinParallelParticles, [&](std::size_t k) {
          const DragInput in{rho_f, mu, std::clamp(eps_p_[k], s_.eps_min, 1.0), 2 * p.radius[k]};
          const double slip = (to_si * u_p_[k] - v_p_[k]).norm();
          beta_[k] = parcel_drag_coefficient(law, in, s_.size_factor, slip);
        });
      },
      s_.drag);
  double eps_sum = 0;
  for (std::size_t k = 0; k < np; ++k) eps_sum += eps_p_[k];
  report_.mean_eps_particles = np ? eps_sum / double(np) : 1.0;
  // Pressure-gradient force -V_p grad p at the particles.
  if (s_.pressure_gradient) {
#pragma omp parallel for schedule(static) if (np >= ParticleKernel::kMinParallelParticles)
    for (std::size_t k = 0; k < np; ++k)
      f_grad_[k] = pressure_gradient_force(2 * p.radius[k], f_grad_[k]);
  }
  apply_to_gas(p, lap);
}

void Coupler::map_particles(const dem::ParticleArrays& p, PhaseLap& lap) {
  kernel_.locate(p.x);
  report_.unmapped = kernel_.unmapped_count();

  // Gas fraction, and the gas's intrinsic velocity now for the slip that sets beta_p: the
  // populations' own momentum over the new eps. It leaves out the half-force shift and the
  // implicit drag of the last step (a few % of the slip, which moves beta_p only through the
  // inertial part of the law); what it gains is that it depends on the populations alone, so a
  // run resumed from a checkpoint takes the same beta_p as one that never stopped. The exchange
  // itself is exact whatever beta_p is.
  report_.porosity = kernel_.gas_fraction(p.radius, s_.eps_min, cell_scalar_);
  eps_.swap(cell_scalar_);
  lap.to(Phase::coupling_porosity);
}

// What the interval's drag coefficients, pressure-gradient forces and particle velocities put into
// the gas's fields, and the interval's report from them.
void Coupler::apply_to_gas(const dem::ParticleArrays& p, PhaseLap& lap) {
  const std::size_t np = p.size();
  const auto ncell = std::size_t(gas_.grid().cells());
  const bool many_cells = ncell >= std::size_t(ParticleKernel::kMinParallelCells);
  double rate = 0;
  for (std::size_t k = 0; k < np; ++k)
    rate = std::max(rate, beta_[k] * steps_ * units_.dt / p.mass[k]);
  report_.max_particle_rate = rate;
  report_.pressure_force = deterministic_sum(
      np, [&](std::size_t k) { return f_grad_[k]; }, Vec3(Vec3::Zero()));
  u_sum_.assign(std::size_t(gas_.grid().cells()), Vec3::Zero());
  if (!s_.two_way) return lap.to(Phase::coupling_interpolation_drag);

  // The gas side: implicit drag coefficient A_c / eps_c on the superficial velocity and the
  // explicit rest, sum_p (beta_p v_p - F_gradp,p) K_p / dx^3 - (1 - eps) a rho_f g (see the
  // header): (1 - eps) a is the particles' volume per cell volume, a the part of the particles'
  // box the cell stands for (kernel.hpp), so the weight taken out is that of the gas the
  // particles displace, which the deposited reactions of their pressure-gradient forces give back
  // in a resting gas.
  work_.resize(np);
#pragma omp parallel for schedule(static) if (np >= ParticleKernel::kMinParallelParticles)
  for (std::size_t k = 0; k < np; ++k) work_[k] = beta_[k] * v_p_[k] - f_grad_[k];
  kernel_.deposit(beta_, work_, cell_scalar_, cell_vec_);  // A_c [kg/(m^3 s)] and the rest
  const double drag_to_lattice = units_.dt / units_.rho;   // (A / eps) [SI] -> alpha [lattice]
  const double force_to_lattice = units_.force_density_to_lattice(1.0);
  force_lat_.resize(ncell);
  const std::vector<double>& volume = kernel_.accessible();
#pragma omp parallel for schedule(static) if (many_cells)
  for (std::size_t c = 0; c < ncell; ++c) {
    alpha_[c] = cell_scalar_[c] / eps_[c] * drag_to_lattice;
    force_lat_[c] = force_to_lattice * (cell_vec_[c] - (1 - eps_[c]) * volume[c] * s_.gas_weight);
    if (!source_lat_.empty()) force_lat_[c] += source_lat_[c];
  }
  gas_.set_porosity_field(eps_, alpha_);
  gas_.set_force_field(force_lat_);
  if (s_.displaced_gas) {
    // The solids volume flux j [m/s] and each cell's mass source per step, -dt div j (lattice
    // density 1 per unit cell volume): positive where particles crowd in, so that the raised
    // pressure pushes the gas out, negative where they leave.
#pragma omp parallel for schedule(static) if (np >= ParticleKernel::kMinParallelParticles)
    for (std::size_t k = 0; k < np; ++k)
      work_[k] = (4.0 / 3.0 * kPi * p.radius[k] * p.radius[k] * p.radius[k]) * v_p_[k];
    kernel_.deposit(work_, cell_vec_);
    kernel_.divergence(cell_vec_, displaced_);
    const double per_step = -units_.dt;
#pragma omp parallel for schedule(static) if (many_cells)
    for (std::size_t c = 0; c < ncell; ++c) displaced_[c] *= per_step;
    gas_.set_mass_source_field(np ? std::span<const double>(displaced_)
                                  : std::span<const double>());
  }
  empty_fields_set_ = np == 0;
  if (empty_fields_set_) empty_report_ = report_;
  lap.to(Phase::coupling_interpolation_drag);
}

IntervalState Coupler::interval_state() const {
  IntervalState st;
  st.steps = steps_;
  st.steps_done = steps_done_;
  st.beta = beta_;
  st.f_grad = f_grad_;
  st.mean_eps = report_.mean_eps_particles;
  if (s_.two_way)
    gas_.velocity_sum(st.velocity_sum);
  else
    st.velocity_sum = u_sum_;
  return st;
}

void Coupler::resume_interval(const dem::ParticleArrays& p, const IntervalState& st) {
  const auto ncell = std::size_t(gas_.grid().cells());
  if (!(st.steps >= 1 && st.steps_done >= 0 && st.steps_done <= st.steps) ||
      st.beta.size() != p.size() || st.f_grad.size() != p.size() || st.velocity_sum.size() != ncell)
    throw std::invalid_argument(
        "coupling: an interval's state of " + std::to_string(st.steps_done) + " of " +
        std::to_string(st.steps) + " steps, " + std::to_string(st.beta.size()) + " particles and " +
        std::to_string(st.velocity_sum.size()) + " cells does not fit " + std::to_string(p.size()) +
        " particles and " + std::to_string(ncell) + " cells");
  PhaseLap lap;
  steps_ = st.steps;
  steps_done_ = st.steps_done;
  report_ = ExchangeReport{};
  // The particles stand where begin_interval found them (the DEM has not stepped), so the mapping
  // and everything the gas receives are recomputed to the bit from them and the saved values.
  map_particles(p, lap);
  beta_ = st.beta;
  f_grad_ = st.f_grad;
  v_p_.assign(p.v.begin(), p.v.end());
  report_.mean_eps_particles = st.mean_eps;
  apply_to_gas(p, lap);
  if (s_.two_way)
    gas_.set_velocity_sum(st.velocity_sum);
  else
    u_sum_ = st.velocity_sum;
}

void Coupler::set_gas_source(std::vector<Vec3> force) {
  const lbm::Grid& g = gas_.grid();
  if (!force.empty() && force.size() != std::size_t(g.nx()) * g.ny() * g.nz())
    throw std::invalid_argument("coupling: a gas source needs one force per interior cell");
  source_lat_ = std::move(force);
  empty_fields_set_ = false;  // the force field changes
}

void Coupler::before_gas_step() {
  if (steps_done_ >= steps_)
    throw std::logic_error("coupling: more gas steps than begin_interval announced");
  ++steps_done_;
  // The velocity each step's collision uses (the fields are those begin_interval set), summed
  // over the interval: interpolation is linear, so the mean drag each particle gets at the end is
  // exactly what the gas lost over the steps. Two-way, the collision itself keeps the sum of u/eps
  // (LbmSolver::enable_velocity_sum); one-way, the gas's velocity is read before each step.
  if (s_.two_way) return;
  PhaseLap lap;
  gas_.velocity(cell_vec_);
  for (std::size_t c = 0; c < cell_vec_.size(); ++c) u_sum_[c] += cell_vec_[c];
  lap.to(Phase::coupling_interpolation_drag);
}

const ExchangeReport& Coupler::end_interval(dem::ParticleArrays& p) {
  if (steps_done_ != steps_)
    throw std::logic_error("coupling: end_interval after " + std::to_string(steps_done_) + " of " +
                           std::to_string(steps_) + " gas steps");
  if (p.size() != beta_.size())
    throw std::logic_error("coupling: the particles changed during an exchange interval");
  PhaseLap lap;
  const double inv = 1.0 / steps_;
  if (s_.two_way) gas_.take_velocity_sum(u_sum_);
  kernel_.interpolate(u_sum_, u_p_);
  const double to_si = units_.velocity_to_si(1.0) * inv;
  acc_.resize(p.size());
#pragma omp parallel for schedule(static) if (acc_.size() >= ParticleKernel::kMinParallelParticles)
  for (std::size_t k = 0; k < acc_.size(); ++k) {
    acc_[k] = beta_[k] * (to_si * u_p_[k] - v_p_[k]);
    p.external[k] = acc_[k] + f_grad_[k];
  }
  report_.drag = deterministic_sum(
      acc_.size(), [&](std::size_t k) { return acc_[k]; }, Vec3(Vec3::Zero()));
  lap.to(Phase::coupling_interpolation_drag);
  return report_;
}

}  // namespace lbdem::coupling
