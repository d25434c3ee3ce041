#pragma once
// Reading the DEM parts of a config that every DEM scenario shares: [[materials]], [contact],
// [dem], [output.collisions], particle fills and lists, and [[walls]] tables (plane, cylinder,
// stl).
#include <random>
#include <string>
#include <vector>

#include "core/config.hpp"
#include "dem/dem_solver.hpp"
#include "dem/insertion.hpp"
#include "dem/time_step.hpp"
#include "run/step_choice.hpp"

namespace lbdem::scenarios {

/// The [[materials]] tables; a name used twice is refused (fills and walls name materials).
std::vector<dem::Material> read_materials(const Config& cfg);

/// A value the user wrote that no real solid has: likely a slip of units (a density in g/cm^3).
struct Implausible {
  std::string key, value, problem;
  /// "warning: 'key' = value: problem; the run goes on", one line for the log.
  std::string warning() const;
};
/// The values written in [[materials]] outside the plausible ranges: density 100 - 25,000 kg/m^3
/// (aerogels to osmium), Young's modulus 1e4 - 1e12 Pa (soft rubber to diamond), linear stiffness
/// 1e-3 - 1e10 N/m, Poisson's ratio below 0. Warnings only: a model may use soft materials on
/// purpose.
std::vector<Implausible> implausible_inputs(const Config& cfg,
                                            const std::vector<dem::Material>& mats);

/// Refuses a step dt [s] that is not finite and positive, or a run to end_time of no step or of
/// more than 2^53 steps, naming the key the user wrote: `dt_key` (= `dt_value`) if the step was
/// given, else the first implausible input (which made t_c), else run.end_time.
void check_step_count(double dt, double end_time, const std::string& dt_key,
                      const std::string& dt_value, const std::vector<Implausible>& suspects);
int material_index(const std::vector<dem::Material>& mats, const std::string& name,
                   const std::string& key);
dem::ContactSettings read_contact(const Config& c);
dem::RadiusDistribution read_radius(const Config& c);
dem::CollisionSettings read_collisions(const Config& c);

/// [dem] time step and watchdog limits: dt given (times dt_factor, the coarse-graining rule's step
/// factor), or t_c / steps_per_contact. A dt above t_c/20 at the impact speed is an error unless
/// force_dt = true (the seed studies run at t_c/9 to t_c/16 and force it).
using run::StepChoice;  // run/step_choice.hpp
/// A default step (t_c / steps_per_contact) that is not finite and positive is refused naming
/// the first of `suspects`, the inputs that made t_c.
StepChoice choose_time_step(const Config& dem_cfg, const dem::ContactSettings& cs,
                            const std::vector<dem::Material>& mats,
                            const std::vector<int>& wall_mats, double r_min, double dt_factor = 1.0,
                            const std::vector<Implausible>& suspects = {});

/// A radius distribution for parcels of size factor l (every radius times l).
dem::RadiusDistribution scaled(dem::RadiusDistribution r, double l);

/// Prescribed motion keys of a moving wall: velocity, axis_point, axis, rpm, start, ramp.
dem::PrescribedMotion read_motion(const Config& w);

/// Reads one [[walls]] table into a wall (kind = plane | cylinder | stl | box).
dem::Wall read_wall(const Config& w, const std::vector<dem::Material>& mats);

}  // namespace lbdem::scenarios
