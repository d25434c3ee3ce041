#include "scenarios/common/fluid_config.hpp"

#include <cmath>
#include <exception>
#include <limits>
#include <utility>
#include <variant>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "lbm/d3q19.hpp"

namespace lbdem::scenarios {

namespace {

// [B] a gas lattice's memory per storage cell, halo included, without the coupling's fields
// (results/bench/size.csv, the coupled kernel's fields: double 222.2 B at 256^3 cells, 244.2 at
// 128^3; single 131.0 at 128^3, its fields 117 B where double's are 225).
constexpr double kGasBytesPerCell = 222, kGasBytesPerCellSingle = 118;

const char* kAxes[3] = {"x", "y", "z"};
const std::vector<std::string> kFaceKinds = {"wall",        "free_slip", "periodic",
                                             "moving_wall", "inlet",     "outlet"};

// One face: a plain string, or an inline table with a kind.
FluidFace read_face(const Config& faces, int f, bool periodic_default) {
  const std::string name(lbm::BoxFaces::kNames[std::size_t(f)]);
  const int axis = f / 2;
  const double inward = f % 2 ? -1.0 : 1.0;  // sign of the inward normal along `axis`
  FluidFace out;
  const Config table = faces.section(name);
  if (!table.has("kind")) {
    out.kind = faces.get_choice(name, periodic_default ? "periodic" : "wall", kFaceKinds);
    if (out.kind == "free_slip") {  // a wall at rest that takes no tangential momentum
      out.kind = "wall";
      out.slip_length = std::numeric_limits<double>::infinity();
      return out;
    }
    if (out.kind != "wall" && out.kind != "periodic")
      throw InputError(faces.path(name), "\"" + out.kind + "\"", "this kind needs its parameters",
                       out.kind == "outlet"
                           ? "write {kind = \"outlet\", pressure = 0.0} (gauge pressure in Pa)"
                           : "write {kind = \"" + out.kind + "\", velocity = [x, y, z]} in m/s");
    return out;
  }
  out.kind = table.get_choice("kind", "wall", kFaceKinds);
  if (out.kind == "free_slip") {
    out.kind = "wall";
    out.slip_length = std::numeric_limits<double>::infinity();
  } else if (out.kind == "wall") {
    // Navier's slip length b (u_wall = b du/dn): 0 no slip; free slip is the face "free_slip".
    out.slip_length =
        table.get("slip_length", 0.0,
                  Range::non_negative("give the slip length in m (0: no slip), or make the face "
                                      "\"free_slip\""));
  } else if (out.kind == "moving_wall") {
    out.velocity = table.require_vec3("velocity");
    // Ladd's term moves a wall in its own plane; a normal component would push mass through it.
    if (out.velocity[axis] != 0)
      throw InputError(table.path("velocity"), vec_text(out.velocity),
                       "a moving wall slides in its plane; the " + std::string(kAxes[axis]) +
                           " component must be 0",
                       "set it to 0, or use {kind = \"inlet\", velocity = [..]} for inflow");
  } else if (out.kind == "inlet") {
    out.velocity = table.require_vec3("velocity");
    if (!(out.velocity[axis] * inward > 0))
      throw InputError(table.path("velocity"), vec_text(out.velocity),
                       "an inlet's velocity must point into the box (" +
                           std::string(inward > 0 ? "+" : "-") + kAxes[axis] + ")",
                       "flip the sign of its " + std::string(kAxes[axis]) + " component");
    // Gas started late or ramped (a fluidized bed settles first): velocity x clamp((t -
    // ramp_start) / ramp_time, 0, 1), a step at ramp_start when ramp_time = 0.
    out.ramp_start =
        table.get("ramp_start", 0.0, Range::non_negative("give the time the inflow starts in s"));
    out.ramp_time =
        table.get("ramp_time", 0.0, Range::non_negative("give the ramp duration in s (0: a step)"));
    // Where the ramp starts from (a bed kept just below minimum fluidization, or a CFD code's
    // small start value): zero, or an inflow along the same direction.
    out.ramp_from = table.get_vec3("ramp_from", Vec3::Zero());
    const Vec3 along = out.ramp_from.dot(out.velocity) / out.velocity.squaredNorm() * out.velocity;
    if (out.ramp_from != Vec3::Zero() &&
        ((out.ramp_from - along).norm() > 1e-12 * out.ramp_from.norm() ||
         !(out.ramp_from.dot(out.velocity) > 0)))
      throw InputError(
          table.path("ramp_from"), vec_text(out.ramp_from),
          "the ramp must start from zero or from an inflow along velocity " +
              vec_text(out.velocity),
          "give a multiple of velocity, e.g. " + vec_text(0.01 * out.velocity) + " for 1 % of it");
    if (out.ramp_from != Vec3::Zero() && out.ramp_start == 0 && out.ramp_time == 0)
      throw InputError(table.path("ramp_from"), vec_text(out.ramp_from),
                       "the ramp never runs: ramp_start and ramp_time are 0",
                       "set ramp_time (and ramp_start) in s, or drop ramp_from");
  } else if (out.kind == "outlet") {
    out.pressure = table.get("pressure", 0.0);
    // false: links of a cell with inflow bounce back (open_boundary.hpp), for an outlet that
    // vortices cross (bubbles erupting below it, a swirl).
    out.backflow = table.get_bool("backflow", true);
  }
  return out;
}

// The gas cells along a box edge, and how far the grid's faces lie outside the box's [m].
// Periodic: a whole number of cells within 1e-9 relative, since the gas and the particles share
// one period (a grid of another length would wrap the gas at another place than the particles).
// Otherwise n = round(L/dx) cells centred on the edge: the half-way bounce-back walls at the
// grid's faces then lie (n dx - L)/2, at most dx/4, outside (or inside) the particles' walls,
// which stay where the box puts them (docs/physics.md, Gas boundaries). An edge within 1e-9 of
// whole cells is whole: offset exactly 0, the grid exactly on the box.
int cells_along(const Config& fluid, int axis, double length, double dx, bool periodic,
                double& offset) {
  const double r = length / dx;
  const double n = std::round(r);
  offset = 0;
  if (n >= 1 && std::abs(r - n) <= 1e-9 * r) return static_cast<int>(n);
  if (periodic)
    throw InputError(fluid.path("dx"), to_text(dx),
                     "the periodic box edge along " + std::string(kAxes[axis]) + " (" +
                         to_text(length) + " m) is " + to_text(r) +
                         " cells, not a whole number; the gas and the particles share one period",
                     // 12 digits: a suggestion that passes the 1e-9 check when typed in
                     "choose dx = L/n, e.g. " + to_text(length / std::max(1.0, std::floor(r)), 12) +
                         " or " + to_text(length / std::ceil(r), 12) + " m");
  if (n < 1)
    throw InputError(fluid.path("dx"), to_text(dx),
                     "the box edge along " + std::string(kAxes[axis]) + " (" + to_text(length) +
                         " m) is " + to_text(r) +
                         " cells, under half a cell: its gas walls would lie more than dx/4 from "
                         "the particles' walls",
                     "choose dx <= " + to_text(length, 12) + " m (one cell across that edge)");
  offset = 0.5 * (n * dx - length);
  return static_cast<int>(n);
}

// Set while read_fluid reads a changed input to see whether a fix passes, so that the try does
// not look for fixes of its own; restored by the guard, whatever a try throws.
thread_local bool g_trying_fix = false;
struct TryingFix {
  bool outer = g_trying_fix;
  TryingFix() { g_trying_fix = true; }
  ~TryingFix() { g_trying_fix = outer; }
  TryingFix(const TryingFix&) = delete;
  TryingFix& operator=(const TryingFix&) = delete;
};

// A change of [fluid]: keys set (value as TOML) and keys dropped, as the message prints it.
struct Change {
  std::vector<std::pair<std::string, std::string>> set;
  std::vector<std::string> drop;
};

std::string change_text(const Config& fluid, const Change& ch) {
  std::string s;
  for (const auto& [k, v] : ch.set) s += (s.empty() ? "" : " and ") + fluid.path(k) + " = " + v;
  for (const auto& k : ch.drop) s += " (without " + fluid.path(k) + ")";
  return s;
}

// The [fluid] reader on a detached copy of the input with the change made: the FluidConfig, or
// the error it stops with.
std::variant<FluidConfig, std::string> try_read(const Config& fluid, const Change& ch,
                                                const Vec3& lo, const Vec3& hi,
                                                const std::array<bool, 3>& periodic,
                                                const Vec3& gravity) {
  const TryingFix guard;
  try {
    Config trial = fluid.detached();
    for (const auto& [k, v] : ch.set) trial.set_override(fluid.path(k) + "=" + v);
    for (const auto& k : ch.drop) trial.erase(fluid.path(k));
    return read_fluid(trial, lo, hi, periodic, gravity);
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
}

// Of the changes, in order, those with which the whole of read_fluid passes (every check a run
// would meet at start-up) and which change what runs (the time step, the grid or the operator:
// a lower lattice velocity changes nothing where the pressure rule sets dt); at most `keep`.
std::vector<std::string> passing(const Config& fluid, const FluidConfig& now,
                                 const std::vector<Change>& changes, const Vec3& lo, const Vec3& hi,
                                 const std::array<bool, 3>& periodic, const Vec3& gravity,
                                 std::size_t keep = 3) {
  std::vector<std::string> out;
  for (const Change& ch : changes) {
    if (out.size() == keep) break;
    const auto r = try_read(fluid, ch, lo, hi, periodic, gravity);
    const auto* c = std::get_if<FluidConfig>(&r);
    if (!c) continue;  // this change alone does not pass: not offered
    if (c->dt == now.dt && c->dx == now.dx && c->collision == now.collision &&
        c->smagorinsky == now.smagorinsky)
      continue;  // passes, but runs the same gas
    out.push_back(change_text(fluid, ch));
  }
  return out;
}

std::string join_or(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", or " : "") + items[i];
  return s;
}

// The changes that can cure a gas that will not start (tau too close to 1/2, Mach, Dp) or that
// diverged: another collision operator (dropping the old one's parameter, which the new one
// would refuse as unused), a finer grid (dx / 2 and dx / 3 keep a periodic edge a whole number of
// cells), and the time step (a divergence wants it shorter, a tau near 1/2 longer), given as
// fluid.dt: the lattice velocity may not be what sets it.
std::vector<Change> gas_changes(const FluidConfig& c, bool diverged) {
  std::vector<Change> ch;
  // From TRT the fix names its magic parameter whether or not the input sets it: a resumed run's
  // config.toml writes it out, and its message must read as the first run's did.
  if (c.collision != "les")
    ch.push_back(
        {{{"collision", "\"les\""}},
         c.collision == "trt" ? std::vector<std::string>{"magic"} : std::vector<std::string>{}});
  if (c.collision == "les" && c.smagorinsky < 0.17) ch.push_back({{{"smagorinsky", "0.17"}}, {}});
  if (c.collision == "bgk") ch.push_back({{{"collision", "\"trt\""}}, {}});
  // A step set by the lattice velocity (given or by default) is given as fluid.dt without it, in
  // the same words whether or not the input names it (a resumed run's config.toml does).
  ch.push_back({{{"dt", to_text(diverged ? 0.5 * c.dt : 2 * c.dt, 12)}},
                c.dt_from == "fluid.dt" ? std::vector<std::string>{}
                                        : std::vector<std::string>{"lattice_velocity"}});
  ch.push_back({{{"dx", to_text(c.dx / 2, 12)}}, {}});
  ch.push_back({{{"dx", to_text(c.dx / 3, 12)}}, {}});
  return ch;
}

}  // namespace

FluidConfig read_fluid(const Config& fluid, const Vec3& lo, const Vec3& hi,
                       const std::array<bool, 3>& box_periodic, const Vec3& gravity) {
  FluidConfig c;
  c.box_lo = lo;
  c.box_hi = hi;
  c.density = fluid.require("density", Range::positive("give the gas density in kg/m^3"));
  c.viscosity = fluid.require("viscosity",
                              Range::positive("give the dynamic viscosity in Pa s (air 1.8e-5)"));
  c.dx = fluid.require("dx", Range::positive("give the cell size in m"));
  c.lo = lo;
  for (int a = 0; a < 3; ++a) {
    double offset = 0;
    c.cells[std::size_t(a)] =
        cells_along(fluid, a, hi[a] - lo[a], c.dx, box_periodic[std::size_t(a)], offset);
    c.lo[a] -= offset;  // the grid centred on the edge
  }
  // Run folders written before fluid.precision carry population_storage: its float slots held
  // f - w as single precision's do, so they resume as single; the old key leaves the input.
  std::string precision_default = "double";
  if (fluid.has("population_storage")) {
    if (fluid.has("precision"))
      throw InputError(fluid.path("population_storage"), "",
                       "is the old name of fluid.precision, which is also given",
                       "remove fluid.population_storage");
    const std::string old =
        fluid.detached().get_choice("population_storage", "double", {"double", "float"});
    precision_default = old == "float" ? "single" : "double";
    Config(fluid).erase(fluid.path("population_storage"));
  }
  c.precision = fluid.get_choice("precision", precision_default, {"double", "single"});
  // Before anything is allocated; the coupling's fields add to this lower bound.
  double storage = 1;
  for (int n : c.cells) storage *= double(n) + 2;
  const double per_cell = c.precision == "single" ? kGasBytesPerCellSingle : kGasBytesPerCell;
  require_memory(storage * per_cell,
                 "the gas's " + to_text(storage) + " cells (with the halo, at least " +
                     to_text(per_cell) + " B each in " + c.precision + " precision)",
                 fluid.path("dx"), to_text(c.dx),
                 "choose a larger fluid.dx (twice the cell size is an eighth of the cells) or a "
                 "smaller box");

  const Config faces = fluid.section("faces");
  std::array<bool, 3> periodic{};
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2;
    c.faces[std::size_t(f)] = read_face(faces, f, box_periodic[std::size_t(axis)]);
    const bool p = c.faces[std::size_t(f)].kind == "periodic";
    const std::string name(lbm::BoxFaces::kNames[std::size_t(f)]);
    // The gas and the particles live in one box: a periodic gas face with a walled DEM face (or
    // the reverse) would let one phase through where the other stops.
    if (p != box_periodic[std::size_t(axis)])
      throw InputError(
          faces.path(name), "\"" + c.faces[std::size_t(f)].kind + "\"",
          std::string("the DEM box face box.") + name + " is " +
              (box_periodic[std::size_t(axis)] ? "" : "not ") + "periodic",
          "make fluid.faces." + name + " and box." + name + " both periodic, or neither");
    periodic[std::size_t(axis)] = p;
  }

  c.max_speed = fluid.require(
      "max_speed", Range::positive("give the largest gas speed expected, in m/s (Mach check)"));
  c.initial_velocity = fluid.get_vec3("initial_velocity", Vec3::Zero());
  const auto check_speed = [&](const std::string& key, const Vec3& u) {
    if (u.norm() > c.max_speed)
      throw InputError(key, vec_text(u),
                       "faster (" + to_text(u.norm()) +
                           " m/s) than fluid.max_speed = " + to_text(c.max_speed) + " m/s",
                       "raise fluid.max_speed to at least " + to_text(u.norm()));
  };
  check_speed(fluid.path("initial_velocity"), c.initial_velocity);
  for (int f = 0; f < 6; ++f) {
    const std::string face = faces.path(std::string(lbm::BoxFaces::kNames[std::size_t(f)]));
    check_speed(face + ".velocity", c.faces[std::size_t(f)].velocity);
    check_speed(face + ".ramp_from", c.faces[std::size_t(f)].ramp_from);
  }

  c.body_force = fluid.get_vec3("body_force", Vec3::Zero());
  c.weighs = fluid.get_bool("gravity", false);
  if (c.weighs) c.body_force += c.density * gravity;
  // Along a wall-bounded axis a force density F is held by a static pressure gradient, so the
  // pressure varies by |F_a| L_a across the box; along a periodic axis it drives flow instead.
  // An outlet held at a gauge pressure p differs from the reference by |p| as well.
  double dp_default = 0, dp_outlets = 0;
  for (int a = 0; a < 3; ++a)
    if (!periodic[std::size_t(a)]) dp_default += std::abs(c.body_force[a]) * (hi[a] - lo[a]);
  for (const FluidFace& f : c.faces) dp_outlets = std::max(dp_outlets, std::abs(f.pressure));
  // An outlet's gauge pressure is a static difference the lattice carries whatever the user
  // declares, so it always enters the check.
  c.pressure_difference = std::max(
      dp_outlets,
      fluid.get("pressure_difference", std::max(dp_default, dp_outlets),
                Range::non_negative(
                    "give the largest static pressure difference in Pa (bed weight, ...)")));

  c.collision = fluid.get_choice("collision", "trt", {"trt", "bgk", "les"});
  double tau_margin = 1e-4;  // check_stability's default, for TRT (units.hpp)
  double nu_turbulent_max = 0;
  if (c.collision == "trt") {
    c.magic = fluid.get("magic", lbm::Trt::kMagicDefault,
                        Range::positive("give the TRT magic parameter, 3/16 = 0.1875"));
  } else if (c.collision == "bgk") {
    // BGK's linearly stable range of lattice speeds shrinks as tau -> 1/2 (Sterling & Chen 1996,
    // J. Comput. Phys. 123, 196); TRT keeps its odd rate away from 2 through the magic parameter
    // and runs far closer (docs/physics.md, Lattice units and limits). BGK gets 50 times TRT's
    // margin: tau
    // >= 0.505.
    tau_margin = 5e-3;
  } else {
    c.smagorinsky = fluid.get("smagorinsky", lbm::RegularizedLes::kSmagorinskyDefault,
                              Range::non_negative("give the Smagorinsky constant, 0.1 - 0.17"));
    // The largest eddy viscosity a resolved flow shows: (C_s dx)^2 |S| at a strain of one
    // max_speed jump across one cell, |S| = max_speed / dx.
    nu_turbulent_max = c.smagorinsky * c.smagorinsky * c.dx * c.max_speed;
  }
  c.wall_function = fluid.get_bool("wall_function", false);
  for (int f = 0; f < 6; ++f)
    if (c.wall_function && c.faces[std::size_t(f)].slip_length > 0)
      throw InputError(fluid.path("wall_function"), "true",
                       "the wall function acts on every wall at rest, and face " +
                           std::string(lbm::BoxFaces::kNames[std::size_t(f)]) + " slips",
                       "drop fluid.wall_function, or make that face a no-slip wall");
  // A parameter of another operator would be silently ignored: say so.
  if (fluid.has("magic") && c.collision != "trt")
    throw InputError(fluid.path("magic"), "", "only used by fluid.collision = \"trt\"",
                     "remove it, or set fluid.collision = \"trt\"");
  if (fluid.has("smagorinsky") && c.collision != "les")
    throw InputError(fluid.path("smagorinsky"), "", "only used by fluid.collision = \"les\"",
                     "remove it, or set fluid.collision = \"les\"");

  // Time step: given, or from the target lattice velocity (and the pressure limit).
  std::string key_dt = fluid.path("dt");
  if (fluid.has("dt") && fluid.has("lattice_velocity"))
    throw InputError(fluid.path("lattice_velocity"), "", "give either fluid.dt or it, not both",
                     "remove fluid.dt or fluid.lattice_velocity");
  if (fluid.has("dt")) {
    c.dt = fluid.get("dt", 0.0, Range::positive("give the gas time step in s"));
    c.dt_from = "fluid.dt";
  } else {
    const double ul =
        fluid.get("lattice_velocity", 0.1,
                  {0, 0.3, true, false, "give a lattice velocity in (0, 0.3], e.g. 0.1"});
    c.dt = lbm::dt_for_lattice_velocity(c.max_speed, c.dx, ul);
    c.dt_from = "lattice velocity " + to_text(ul) + " at max_speed";
    // docs/physics.md, Lattice units and limits: a static Dp of more than 1 % of rho c_s^2 limits
    // dt below what Mach allows.
    if (c.pressure_difference > 0) {
      const double dt_p = lbm::max_dt_for_pressure(c.pressure_difference, c.density, c.dx, 0.01);
      if (dt_p < c.dt) c.dt = dt_p, c.dt_from = "Dp / (rho c_s^2) = 1 %";
    }
    key_dt = "fluid.dt (from fluid.lattice_velocity = " + to_text(ul) + ")";
  }

  lbm::StabilityInput in;
  in.units = c.units();
  in.nu_si = c.nu();
  in.u_max_si = c.max_speed;
  in.dp_static_si = c.pressure_difference;
  in.nu_turbulent_max_si = nu_turbulent_max;
  in.tau_margin = tau_margin;
  in.key_dt = key_dt;
  in.key_dx = fluid.path("dx");
  try {
    c.report = lbm::check_stability(in);
  } catch (const InputError& e) {
    if (g_trying_fix) throw;
    // Offer only what passes every check a run meets: a longer step or a finer grid may each run
    // into another limit (the pressure rule caps dt; a box edge must stay whole cells).
    const auto fixes = passing(fluid, c, gas_changes(c, false), lo, hi, box_periodic, gravity);
    throw e.with_fix(fixes.empty()
                         ? "no single change of fluid.collision, fluid.dx or the gas time step "
                           "passes every check; lower fluid.max_speed or "
                           "fluid.pressure_difference if the flow allows"
                         : "set " + join_or(fixes));
  }

  // Reynolds number on the narrowest wall-to-wall distance (the channel width), or the longest
  // edge of a fully periodic box.
  double l_wall = 0, l_max = 0;
  for (int a = 0; a < 3; ++a) {
    const double l = hi[a] - lo[a];
    l_max = std::max(l_max, l);
    if (!periodic[std::size_t(a)]) l_wall = l_wall > 0 ? std::min(l_wall, l) : l;
  }
  c.reynolds_length = l_wall > 0 ? l_wall : l_max;
  c.reynolds = c.max_speed * c.reynolds_length / c.nu();
  // What a divergence message may offer: the changes that pass these same checks.
  if (!g_trying_fix) {
    c.divergence_fixes = passing(fluid, c, gas_changes(c, true), lo, hi, box_periodic, gravity);
    c.try_change = [input = fluid.detached(), lo, hi, box_periodic, gravity](
                       const std::vector<std::pair<std::string, std::string>>& set,
                       const std::vector<std::string>& drop) -> std::string {
      const auto r = try_read(input, {set, drop}, lo, hi, box_periodic, gravity);
      const auto* err = std::get_if<std::string>(&r);
      return err ? *err : std::string();
    };
  }
  return c;
}

lbm::LbmSettings FluidConfig::lattice() const {
  const lbm::LatticeUnits u = units();
  lbm::LbmSettings s;
  s.nx = cells[0], s.ny = cells[1], s.nz = cells[2];
  const auto to_lattice = [&](const Vec3& v) {
    return Vec3(u.velocity_to_lattice(v[0]), u.velocity_to_lattice(v[1]),
                u.velocity_to_lattice(v[2]));
  };
  for (int f = 0; f < 6; ++f) {
    const FluidFace& in = faces[std::size_t(f)];
    lbm::FaceBoundary& out = s.faces[f];
    if (in.kind == "periodic") {
      out.kind = lbm::FaceKind::periodic;
    } else if (in.kind == "inlet") {
      out.kind = lbm::FaceKind::inlet;
      out.wall_velocity = to_lattice(in.velocity_at(0));
    } else if (in.kind == "outlet") {
      // p - p_ref = (rho - 1) c_s^2 in lattice units.
      out.kind = lbm::FaceKind::outlet;
      out.density = 1.0 + u.density_change(in.pressure);
      out.backflow = in.backflow;
    } else {
      out.kind = lbm::FaceKind::wall;
      out.wall_velocity = to_lattice(in.velocity);
      out.slip = slip_fraction(in);
    }
  }
  const double tau = report.tau;
  if (collision == "trt")
    s.collision = lbm::Trt::from_tau(tau, magic);
  else if (collision == "bgk")
    s.collision = lbm::Bgk::from_tau(tau);
  else
    s.collision = lbm::RegularizedLes::from_tau(tau, smagorinsky);
  for (int a = 0; a < 3; ++a) s.body_force[a] = u.force_density_to_lattice(body_force[a]);
  s.precision = precision == "single" ? lbm::Precision::float32 : lbm::Precision::float64;
  return s;
}

std::string FluidConfig::divergence_fix() const {
  if (divergence_fixes.empty())
    return "no single change of fluid.collision, fluid.dx or the gas time step passes the "
           "start-up checks; lower fluid.max_speed, or the inflow or forcing that drives the gas";
  return "set " + join_or(divergence_fixes);
}

double FluidConfig::slip_fraction(const FluidFace& face) const {
  if (face.slip_length == 0) return 0.0;
  if (std::isinf(face.slip_length)) return 1.0;
  return face.slip_length / (face.slip_length + 3.0 * report.nu_lattice * dx);
}

double FluidConfig::rest_density(int x, int y, int z) const {
  const lbm::LatticeUnits u = units();
  const int at[3] = {x, y, z};
  double rho = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (faces[std::size_t(2 * a)].kind == "periodic") continue;
    const double offset = at[a] + 0.5 - 0.5 * cells[std::size_t(a)];  // from the centre [cells]
    rho += u.force_density_to_lattice(body_force[a]) * offset / lbm::kCs2;
  }
  return rho;
}

Vec3 FluidConfig::cell_centre(int x, int y, int z) const {
  return lo + dx * Vec3(x + 0.5, y + 0.5, z + 0.5);
}

Vec3 FluidConfig::hi() const {
  return lo + dx * Vec3(cells[0], cells[1], cells[2]);
}

double FluidConfig::wall_offset(int axis) const {
  return box_lo[axis] - lo[axis];
}

void fluid_banner(Log& log, const FluidConfig& f, const SubCycle& sub) {
  const auto& r = f.report;
  const lbm::LatticeUnits u = f.units();
  const double n = double(f.cells[0]) * f.cells[1] * f.cells[2];
  log.line("gas derived numbers:");
  log.derived("cells per axis", f.cells[0], "",
              "x " + std::to_string(f.cells[1]) + " x " + std::to_string(f.cells[2]) + " = " +
                  to_text(n) + " cells, " +
                  to_text(n * (f.precision == "single" ? 76e-6 : 152e-6)) + " MB of " +
                  f.precision + " populations");
  log.derived("gas cells", n, "", "(the lattice, solid cells included)");
  log.derived("cell size dx", f.dx, "m");
  // Edges that are not whole cells: where the gas walls sit against the particles' (cells_along),
  // in mm for the cells of beds and mills, in m for larger ones.
  const auto length = [&](double v) {
    return f.dx < 0.1 ? to_text(1e3 * v) + " mm" : to_text(v) + " m";
  };
  for (int a = 0; a < 3; ++a) {
    const double off = f.wall_offset(a);
    if (off == 0) continue;
    std::string name = std::string("gas walls along ") + kAxes[a];
    name.resize(34, ' ');
    log.line("  " + name + " " + length(std::abs(off)) + (off > 0 ? " outside" : " inside") +
             " the particle walls (n = " + std::to_string(f.cells[std::size_t(a)]) + " cells of " +
             length(f.dx) + " for a " + length(f.box_hi[a] - f.box_lo[a]) + " edge)");
  }
  log.derived("gas time step dt", f.dt, "s", "(" + f.dt_from + ")");
  if (sub.dem_per_gas > 1)
    log.derived("DEM steps per gas step", sub.dem_per_gas, "",
                "(DEM dt " + to_text(sub.dem_dt) + " s, asked " + to_text(sub.dem_dt_asked) + ")");
  else
    log.derived("gas steps per DEM step", sub.gas_per_dem, "",
                "(DEM dt " + to_text(sub.dem_dt) + " s, asked " + to_text(sub.dem_dt_asked) + ")");
  log.derived("kinematic viscosity nu", f.nu(), "m^2/s");
  log.line("  collision operator                 " + f.collision +
           (f.collision == "trt" ? " (magic " + to_text(f.magic) + ")"
            : f.collision == "les"
                ? " (regularized, Smagorinsky C_s " + to_text(f.smagorinsky) + ")"
                : ""));
  if (f.wall_function)
    log.line("  walls                              Werner-Wengle wall function (walls at rest)");
  for (int k = 0; k < 6; ++k) {
    const FluidFace& face = f.faces[std::size_t(k)];
    if (face.kind != "wall" || face.slip_length == 0) continue;
    log.derived(std::string("wall ") + std::string(lbm::BoxFaces::kNames[std::size_t(k)]) +
                    " slip fraction",
                f.slip_fraction(face), "",
                std::isinf(face.slip_length) ? "(free slip)"
                                             : "(slip length " + to_text(face.slip_length) + " m)");
  }
  log.derived("tau (molecular)", r.tau, "", "(tau - 1/2 = " + to_text(r.tau - 0.5) + ")");
  log.derived("tau effective range", r.tau, "", "to " + to_text(r.tau_effective_max));
  log.derived("nu_lattice", r.nu_lattice, "");
  log.derived("lattice Mach at max_speed", r.mach, "",
              "(max_speed " + to_text(f.max_speed) + " m/s, c_s " + to_text(u.cs_si()) + " m/s)");
  log.derived("Dp / (rho c_s^2)", r.density_change, "",
              "(Dp " + to_text(f.pressure_difference) + " Pa)");
  log.derived("Reynolds number", f.reynolds, "",
              "(max_speed x " + to_text(f.reynolds_length) + " m / nu)");
  log.derived("body force on the gas", f.body_force.norm(), "N/m^3");
  for (const auto& w : r.warnings) log.line("warning: gas: " + w);
}

}  // namespace lbdem::scenarios
