#pragma once
// The two-way momentum exchange of unresolved CFD-DEM between the porous-medium lattice Boltzmann
// gas (lbm/forcing/porous.hpp) and the DEM particles, through one smoothing kernel (kernel.hpp).
//
// Formulation: Zhou, Kuang, Chu & Yu (2010, J. Fluid Mech. 661, 482), set II (Kafui's model A),
// on the Guo & Zhao (2002) lattice Boltzmann model for the superficial gas velocity u = eps u_f:
//   particle:  m dv/dt = F_c + m g + F_d - V_p grad p,                               (set II)
//   gas:       d(rho_f u)/dt + div(rho_f u u / eps) = -eps grad p + div tau + eps rho_f g - F_x,
//              F_x = sum_p F_d,p K_p / dx^3 (the reaction of the drag alone),
// with F_d the drag without its pressure-gradient (buoyancy) part (drag/drag_law.hpp). The lattice
// gives -grad(rho c_s^2), which we read as -grad p with p = c_s^2 (rho - rho_ref) the intrinsic
// gauge pressure, and -eps grad p = -grad p + (1 - eps) grad p. The second term is the reaction
// of the particles' pressure-gradient forces: sum_p V_p grad p K_p / dx^3 = (1 - eps) grad p for
// a grad p that varies slowly over the kernel. We pass it through the kernel like the drag, so the
// gas feels -grad p - sum_p (F_d,p - V_p grad p) K_p / dx^3 + eps rho_f g: set II to the kernel's
// accuracy, and every force the particles feel from the gas is taken from the gas to round-off.
// A quiescent gas over a settled bed is then hydrostatic, grad p = rho_f g, whatever eps does.
// (GZ read rho c_s^2 as eps p; with that reading a resting bed would push p by its own eps
// pattern.)
//
// Continuity: d(eps rho_f)/dt + div(rho_f u) = 0, so div u = -d(eps)/dt for a gas of nearly
// constant density: particles that crowd into a cell push its gas out. GZ's lattice form has
// div u = 0; without the term a dense plug spanning the bed passes the whole inflow through itself
// whatever it does, its slip is U/eps - v instead of (U - v)/eps, and the drag damps its motion by
// eps times too little, which favours slugging. The particles' own continuity gives the term
// without any history: d(eps)/dt = -d(phi)/dt = div j, with j = sum_p V_p v_p K_p / dx^3 the
// deposited solids volume flux, so the gas receives the mass source -rho_f div j per unit volume
// (settings.displaced_gas), at the lattice's reference density (its density departs from it by
// O(Ma^2), about 1 %). The divergence is conservative with no flux through walls or solids
// (ParticleKernel::divergence): the sources add to zero up to round-off. Left out: the grad(eps)
// terms of the averaged viscous stress, and the other interphase forces (virtual mass, lift,
// Basset), small for particle/gas density ratios of 10^3.
//
// Time stepping: an exchange interval holds a whole number of gas steps and of DEM steps. At its
// start, begin_interval() maps the particles (eps, drag coefficients beta_p from the slip then,
// the pressure-gradient forces) onto the gas. The gas then runs the interval's steps; its drag is
// implicit (semi-implicit GZ form: the cell's drag coefficient A_c / eps_c multiplies the new
// velocity), because the drag relaxes a light gas in a dense bed within microseconds
// (rho_f eps / beta_vol = 2 us for 100 um particles at eps = 0.4), shorter than the gas step.
// Before each gas step, before_gas_step() adds up the velocity that step's collision will use;
// end_interval() gives each particle beta_p (K_p * mean(u / eps) - v_p), the interval's mean of
// what the gas lost to it in each step, and the DEM holds that force over its steps.
// Gas and particles receive equal and opposite impulses over the interval to round-off.
// The particle side is explicit: beta_p dt_interval / m_p must stay well below 1 (the banner says;
// it is 5e-4 for 100 um particles in air at a 2 us interval).
//
// One-way coupling: the gas sees neither eps nor reactions; particles are dragged by the gas
// velocity as it is, with eps from the kernel for the voidage laws.
//
// Units: SI here and at every interface; lattice values only where they are handed to LbmSolver.
#include "core/phase_timer.hpp"
#include "coupling/drag/drag_model.hpp"
#include "coupling/kernel.hpp"
#include "dem/particles.hpp"
#include "lbm/lbm_solver.hpp"
#include "lbm/units.hpp"

#include <optional>
#include <vector>

namespace lbdem::coupling {

struct CouplerSettings {
  bool two_way = true;
  DragModel drag = Gidaspow{};
  double size_factor = 1;   // parcel size factor l (l^3 originals per parcel), >= 1
  double kernel_width = 0;  // sigma [m], >= dx
  double eps_min = kDefaultEpsMin;
  bool pressure_gradient = true;   // apply -V_p grad p (and its reaction)
  double viscosity = 0;            // gas dynamic viscosity mu [Pa s]
  Vec3 gas_weight = Vec3::Zero();  // rho_f g [N/m^3] if the gas's uniform body force is its weight:
                                   // the exchange removes (1 - eps) of it (set II: eps rho_f g)
  // The particles' box where its faces are not the grid's (kernel.hpp): the outer cells then
  // stand for more or less than their own volume of it.
  std::optional<ParticleBox> particle_box;
  bool displaced_gas = true;  // d(eps)/dt in the gas's continuity equation (see the header)
};

/// What one interval's exchange did (SI), for the time series and the log.
struct ExchangeReport {
  PorosityReport porosity;
  Vec3 drag = Vec3::Zero();            // sum of F_d over particles [N] (interval mean)
  Vec3 pressure_force = Vec3::Zero();  // sum of -V_p grad p [N]
  double mean_eps_particles = 1;       // mean eps at the particles
  double max_particle_rate = 0;        // max beta_p dt_interval / m_p [-]
  std::size_t unmapped = 0;            // particles with no gas cell within the kernel
};

/// An exchange interval stopped part-way, as a checkpoint keeps it (a stop on SIGTERM within the
/// interval's gas steps): what begin_interval took from the gas at the interval's start, which the
/// gas no longer holds, and the velocity sums of the steps done.
struct IntervalState {
  int steps = 0;                   // gas steps of the interval
  int steps_done = 0;              // of them run
  std::vector<double> beta;        // drag coefficients beta_p [kg/s]
  std::vector<Vec3> f_grad;        // pressure-gradient forces -V_p grad p [N]
  double mean_eps = 1;             // mean eps at the particles, for the report
  std::vector<Vec3> velocity_sum;  // sum of u / eps over the steps done, compact [lattice units]
};

class Coupler {
 public:
  /// frame: the lattice in SI; units: dx, dt, rho_ref of the gas; steps_per_interval: gas steps
  /// per exchange. Enables the gas's porosity and force fields when two-way.
  Coupler(lbm::LbmSolver& gas, const lbm::LatticeFrame& frame, const lbm::LatticeUnits& units,
          CouplerSettings s);

  const CouplerSettings& settings() const { return s_; }
  const ParticleKernel& kernel() const { return kernel_; }

  /// Maps the particles onto the gas for an interval of `gas_steps` steps (see the header).
  void begin_interval(const dem::ParticleArrays& p, int gas_steps);
  /// Before each gas step of the interval: the particles' share of that step's drag.
  void before_gas_step();
  /// Sets p.external to the interval's mean gas force; p must be the arrays begin_interval saw.
  const ExchangeReport& end_interval(dem::ParticleArrays& p);
  /// Gas steps of the current interval not yet run (0 between intervals).
  int steps_left() const { return steps_ - steps_done_; }
  /// The current interval's state, and the interval taken up again from it on the same particles
  /// and the gas as it stood then: the rest of the interval, and end_interval, then run as they
  /// would have without the stop (bitwise). std::invalid_argument if the sizes do not fit.
  IntervalState interval_state() const;
  void resume_interval(const dem::ParticleArrays& p, const IntervalState& st);

  /// A force density the gas feels besides the exchange (compact order, lattice units; e.g. the
  /// jet mill's nozzles): two-way coupling rewrites the gas's force field every interval and adds
  /// this to it. Empty: none.
  void set_gas_source(std::vector<Vec3> force);

  /// The gas fraction of the last begin_interval (compact order; 1 in one-way runs only where no
  /// particle is).
  const std::vector<double>& eps() const { return eps_; }
  /// The gauge pressure p = c_s^2 (rho - rho_ref) of the gas now [Pa], compact order, 0 in solids.
  void pressure(std::vector<double>& p) const;
  /// Gas momentum before the half-force shift, in SI [kg m/s] (LbmSolver::raw_momentum).
  Vec3 gas_momentum() const;

 private:
  lbm::LbmSolver& gas_;
  lbm::LatticeUnits units_;
  CouplerSettings s_;
  ParticleKernel kernel_;
  int steps_ = 0, steps_done_ = 0;
  std::vector<double> eps_, alpha_, beta_, radius_, cell_scalar_, eps_p_, pressure_;
  std::vector<Vec3> cell_vec_, force_lat_, v_p_, f_grad_, acc_, u_p_, work_, u_sum_, source_lat_;
  std::vector<double> displaced_;  // the displaced gas's mass source per gas step [lattice units]
  ExchangeReport report_;
  // Two-way: the gas holds the fields of an interval without particles (eps = 1, no drag, the
  // source alone), and that interval's report. A following interval without particles would set
  // the same values again, so it skips its grid passes (the jet mill's gas spin-up: 12 % of the
  // run's time went to them). This holds while nothing outside the coupler writes the gas's
  // porosity or force fields (the jet mill sets its sources through set_gas_source).
  bool empty_fields_set_ = false;
  ExchangeReport empty_report_;
  void density_to_pressure(std::vector<double>& p) const;  // in place, lattice density -> [Pa]
  // begin_interval's parts: the particles' places and eps; the fields the gas receives.
  void map_particles(const dem::ParticleArrays& p, PhaseLap& lap);
  void apply_to_gas(const dem::ParticleArrays& p, PhaseLap& lap);
};

}  // namespace lbdem::coupling
