#include "scenarios/common/dem_config.hpp"

#include <cmath>

#include "core/error.hpp"

namespace lbdem::scenarios {

std::vector<dem::Material> read_materials(const Config& cfg) {
  std::vector<dem::Material> out;
  for (const Config& m : cfg.table_array("materials")) {
    dem::Material x;
    x.name = m.get_string("name", "material" + std::to_string(out.size()));
    x.density = m.get("density", x.density, Range::positive("give the solid density in kg/m^3"));
    x.youngs_modulus =
        m.get("youngs_modulus", x.youngs_modulus, Range::positive("give Young's modulus in Pa"));
    x.poisson_ratio = m.get("poisson_ratio", x.poisson_ratio,
                            {-1, 0.5, true, true, "give a Poisson ratio in (-1, 0.5)"});
    x.stiffness =
        m.get("stiffness", x.stiffness, Range::positive("give the linear normal stiffness in N/m"));
    x.restitution =
        m.get("restitution", x.restitution, {0, 1, true, false, "give a restitution in (0, 1]"});
    x.friction = m.get("friction", x.friction, Range::non_negative("give a sliding friction >= 0"));
    x.rolling_friction = m.get("rolling_friction", x.rolling_friction,
                               Range::non_negative("give a rolling friction >= 0"));
    x.hamaker =
        m.get("hamaker", x.hamaker, Range::non_negative("give a Hamaker constant in J (>= 0)"));
    for (std::size_t j = 0; j < out.size(); ++j)
      if (out[j].name == x.name)
        throw InputError(m.path("name"), "\"" + x.name + "\"",
                         "materials[" + std::to_string(j) + "] has this name too",
                         "give each [[materials]] its own name");
    out.push_back(x);
  }
  if (out.empty())
    throw InputError("materials", "", "no [[materials]] table",
                     "add at least one [[materials]] with a name");
  return out;
}

std::string Implausible::warning() const {
  return "warning: " + InputError::format(key, value, problem, "") + "; the run goes on";
}

std::vector<Implausible> implausible_inputs(const Config& cfg,
                                            const std::vector<dem::Material>& mats) {
  std::vector<Implausible> out;
  const auto tables = cfg.table_array("materials");
  const auto outside = [&](const Config& m, const char* key, double v, double lo, double hi,
                           const std::string& unit, const std::string& what) {
    if (m.has(key) && !(v >= lo && v <= hi))
      out.push_back({m.path(key), shortest_text(v),
                     "outside " + to_text(lo) + " - " + to_text(hi) + " " + unit + ", " + what});
  };
  for (std::size_t k = 0; k < tables.size() && k < mats.size(); ++k) {
    const Config& m = tables[k];
    const dem::Material& x = mats[k];
    outside(m, "density", x.density, 100, 25000, "kg/m^3",
            "the solids from aerogels to osmium (a value in g/cm^3?)");
    outside(m, "youngs_modulus", x.youngs_modulus, 1e4, 1e12, "Pa",
            "the solids from soft rubber to diamond (a value in MPa or GPa?)");
    outside(m, "stiffness", x.stiffness, 1e-3, 1e10, "N/m",
            "the linear springs of DEM practice (a value in N/mm?)");
    if (m.has("poisson_ratio") && x.poisson_ratio < 0)
      out.push_back({m.path("poisson_ratio"), shortest_text(x.poisson_ratio),
                     "below 0, which only auxetic foams have"});
  }
  return out;
}

namespace {
// The step's culprit: the key the user wrote, not the derived dt.
[[noreturn]] void refuse_step(double dt, double end_time, const std::string& problem,
                              const std::string& dt_key, const std::string& dt_value,
                              const std::vector<Implausible>& suspects) {
  if (!dt_key.empty())
    throw InputError(dt_key, dt_value, problem,
                     "give a step that divides run.end_time = " + to_text(end_time) +
                         " s into 1 to 2^53 steps, or leave " + dt_key +
                         " out for t_c / dem.steps_per_contact");
  if (!suspects.empty()) {
    const Implausible& s = suspects.front();
    throw InputError(s.key, s.value,
                     "makes the contact time, and with it the step dt = " + to_text(dt) +
                         " s, unusable: " + problem + " (" + s.problem + ")",
                     "give a real material's value");
  }
  throw InputError("run.end_time", shortest_text(end_time),
                   problem + " at the step dt = " + to_text(dt) + " s",
                   "give a run.end_time of many steps, or a shorter step");
}
}  // namespace

void check_step_count(double dt, double end_time, const std::string& dt_key,
                      const std::string& dt_value, const std::vector<Implausible>& suspects) {
  if (!(dt > 0) || !std::isfinite(dt))
    refuse_step(dt, end_time, "the step is not a finite positive time", dt_key, dt_value, suspects);
  const double steps = end_time / dt;
  if (!(steps >= 0.5))
    refuse_step(dt, end_time, "the run would take no step to run.end_time", dt_key, dt_value,
                suspects);
  if (!(steps <= 9007199254740992.0))  // 2^53: step counts stay exact in a double
    refuse_step(dt, end_time,
                "the run would take " + to_text(steps) + " steps to run.end_time (more than 2^53)",
                dt_key, dt_value, suspects);
}

int material_index(const std::vector<dem::Material>& mats, const std::string& name,
                   const std::string& key) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < mats.size(); ++k) {
    if (mats[k].name == name) return static_cast<int>(k);
    names.push_back(mats[k].name);
  }
  throw InputError(key, "\"" + name + "\"", "no such material",
                   "did you mean \"" + nearest(name, names) + "\"?");
}

dem::ContactSettings read_contact(const Config& c) {
  dem::ContactSettings s;
  s.normal = c.get_choice("normal", s.normal, dem::kNormalLaws);
  s.rolling = c.get_choice("rolling", s.rolling, dem::kRollingModels);
  s.cohesion = c.get_choice("cohesion", s.cohesion, dem::kCohesionModels);
  s.rolling_arm_factor =
      c.get("rolling_arm_factor", s.rolling_arm_factor,
            Range::positive("torque arm / R*, e.g. 1 (LIGGGHTS) or 2 (MercuryDPM)"));
  s.kt_ratio =
      c.get("tangential_stiffness_ratio", s.kt_ratio, Range::positive("k_t/k_n, e.g. 2/7"));
  s.tangential_damping = c.get_bool("tangential_damping", s.tangential_damping);
  if (s.cohesion != "none") {
    s.h_min =
        c.get("h_min", s.h_min, Range::positive("give the minimum separation in m, e.g. 4e-10"));
    s.h_max =
        c.get("h_max", s.h_max, Range::positive("give the cohesion cut-off in m, e.g. 0.1 d"));
    if (s.h_max <= s.h_min)
      throw InputError(c.path("h_max"), to_text(s.h_max), "must exceed h_min = " + to_text(s.h_min),
                       "raise h_max");
  }
  return s;
}

dem::RadiusDistribution read_radius(const Config& c) {
  dem::RadiusDistribution r;
  r.kind = c.get_choice("kind", "fixed", {"fixed", "uniform", "lognormal"});
  if (r.kind == "fixed") {
    r.radius = c.require("radius", Range::positive("give the particle radius in m"));
  } else {
    r.min = c.require("min", Range::positive("give the smallest radius in m"));
    r.max = c.require("max", Range::positive("give the largest radius in m"));
    if (r.max < r.min)
      throw InputError(c.path("max"), to_text(r.max), "below min", "give max >= min");
    if (r.kind == "lognormal") {
      r.median = c.require("median", Range::positive("give the median radius in m"));
      r.sigma = c.get("sigma", r.sigma, Range::positive("give the standard deviation of ln r"));
    }
  }
  return r;
}

dem::RadiusDistribution scaled(dem::RadiusDistribution r, double l) {
  r.radius *= l, r.min *= l, r.max *= l, r.median *= l;
  return r;
}

dem::CollisionSettings read_collisions(const Config& c) {
  dem::CollisionSettings s;
  s.rows = c.get_bool("rows", s.rows);
  s.rows_t0 = c.get("rows_start", s.rows_t0, Range::non_negative());
  s.rows_t1 = c.get("rows_end", 1e300, Range::non_negative());
  s.row_budget =
      c.get_int("row_budget", s.row_budget, Range::positive("give the most rows to keep"));
  s.grid_cells = static_cast<int>(c.get_int("grid_cells", s.grid_cells, Range::closed(1, 512)));
  return s;
}

StepChoice choose_time_step(const Config& d, const dem::ContactSettings& cs,
                            const std::vector<dem::Material>& mats,
                            const std::vector<int>& wall_mats, double r_min, double dt_factor,
                            const std::vector<Implausible>& suspects) {
  StepChoice c{};
  c.impact_speed =
      d.get("impact_speed", 1.0, Range::positive("give the characteristic impact speed in m/s"));
  c.scales = dem::time_scales(cs, mats, wall_mats, r_min, c.impact_speed);
  const double tc = c.scales.contact_time;
  const double per = d.get("steps_per_contact", 50.0, Range::closed(1, 1e6));
  // dem.dt is the ORIGINAL particles' step, scaled for parcels; the default is recorded that way
  // too (t_c / per of the parcels over the factor), so the resolved config of a coarse-grained run
  // resumes with the same step instead of scaling it a second time.
  // A default step of inf or 0 comes from an input that made t_c so: name that input, not dem.dt.
  if (const double def = tc / per; !d.has("dt") && (!(def > 0) || !std::isfinite(def)))
    check_step_count(def, 1.0, "", "", suspects);
  c.dt = d.get("dt", tc / per / dt_factor, Range::positive("give the time step in s")) * dt_factor;
  const bool force = d.get_bool("force_dt", false);
  c.dt_factor = dt_factor, c.forced = force;
  c.max_speed_factor = d.get("max_speed_factor", c.max_speed_factor,
                             Range::positive("give the multiple of the largest expected speed "
                                             "above which a particle stops the run, e.g. 10"));
  c.max_energy_error =
      d.get("max_energy_error", c.max_energy_error,
            Range::positive("give the energy-balance error, as a fraction of the energy moved, "
                            "that stops the run, e.g. 0.1"));
  // The message speaks in dem.dt's own terms (the originals' step): with coarse graining the
  // parcels step dt_factor times that, so the limit the user must meet is t_c/20 / dt_factor.
  if (c.dt > tc / 20 && !force) {
    const std::string scaled = dt_factor != 1 ? " (the parcels step " + to_text(dt_factor) +
                                                    " x dem.dt = " + to_text(c.dt) + " s)"
                                              : "";
    throw InputError(
        d.path("dt"), to_text(c.dt / dt_factor),
        "above t_c/20" + std::string(dt_factor != 1 ? " / " + to_text(dt_factor) : "") + " = " +
            to_text(tc / 20 / dt_factor) + " s" + scaled + " (contact time t_c = " + to_text(tc) +
            " s for " + c.scales.where + " at " + to_text(c.impact_speed) + " m/s)",
        "lower dem.dt to at most " + to_text(tc / 20 / dt_factor) +
            " s, or set dem.force_dt = true to accept fewer than 20 steps per contact");
  }
  return c;
}

dem::PrescribedMotion read_motion(const Config& w) {
  dem::PrescribedMotion m;
  m.velocity = w.get_vec3("velocity", Vec3::Zero());
  m.axis_point = w.get_vec3("axis_point", Vec3::Zero());
  m.axis = w.get_vec3("axis", Vec3::UnitZ());
  if (m.axis.norm() == 0)
    throw InputError(w.path("axis"), "[0, 0, 0]", "zero rotation axis", "give a non-zero axis");
  m.axis.normalize();
  m.omega = w.get("rpm", 0.0) * 2 * kPi / 60;
  m.start = w.get("start", 0.0, Range::non_negative());
  m.ramp = w.get("ramp", 0.0, Range::non_negative());
  return m;
}

dem::Wall read_wall(const Config& w, const std::vector<dem::Material>& mats) {
  dem::Wall out;
  const std::string kind = w.get_choice("kind", "plane", {"plane", "cylinder", "stl", "box"});
  out.name = w.get_string("name", kind);
  out.material =
      material_index(mats, w.get_string("material", mats.front().name), w.path("material"));
  if (kind == "plane") {
    dem::PlaneWall p;
    p.point = w.require_vec3("point");
    p.normal = w.require_vec3("normal");
    if (p.normal.norm() == 0)
      throw InputError(w.path("normal"), "[0, 0, 0]", "zero normal", "give a non-zero normal");
    p.normal.normalize();
    p.velocity = w.get_vec3("velocity", Vec3::Zero());
    p.hole_radius =
        w.get("hole_radius", 0.0,
              Range::non_negative("give the radius of the plate's hole in m (0: none)"));
    // The hole's centre is projected onto the plane (a point off it would shift nothing else).
    const Vec3 c = w.get_vec3("hole_centre", p.point);
    p.hole_centre = c - (c - p.point).dot(p.normal) * p.normal;
    out.shape = p;
    out.torque_origin = p.point;
  } else if (kind == "cylinder") {
    dem::CylinderWall c;
    c.origin = w.require_vec3("origin");
    c.axis = w.get_vec3("axis", Vec3::UnitZ()).normalized();
    c.radius = w.require("radius", Range::positive("give the cylinder radius in m"));
    c.inside = w.get_bool("inside", true);
    c.omega = w.get("rpm", 0.0) * 2 * kPi / 60;
    c.lo = w.get("axial_min", -1e300);
    c.hi = w.get("axial_max", 1e300);
    out.shape = c;
    out.torque_origin = c.origin;
  } else if (kind == "box") {
    dem::BoxWall b;
    b.center = w.require_vec3("center");
    b.half = 0.5 * w.require_vec3("size");
    if (b.half.minCoeff() <= 0)
      throw InputError(w.path("size"), to_text(2 * b.half.minCoeff()), "a box edge is not positive",
                       "give the three edge lengths in m");
    Vec3 ex = w.get_vec3("x_axis", Vec3::UnitX()), ey = w.get_vec3("y_axis", Vec3::UnitY());
    if (ex.norm() == 0 || ey.norm() == 0 || ex.normalized().cross(ey.normalized()).norm() < 1e-9)
      throw InputError(w.path("y_axis"), "", "x_axis and y_axis are zero or parallel",
                       "give two perpendicular edge directions");
    ex.normalize();
    ey = (ey - ey.dot(ex) * ex).normalized();
    b.axes = {ex, ey, ex.cross(ey)};
    b.motion = read_motion(w);
    out.torque_origin = b.motion.axis_point;
    out.shape = b;
  } else {
    dem::MeshWall m;
    const std::string file = w.get_string("file", "");
    if (file.empty())
      throw InputError(w.path("file"), "", "missing", "give the path of an STL file");
    const double scale = w.get("scale", 1.0, Range::positive("e.g. 1e-3 for a file in mm"));
    m.mesh = dem::TriangleMesh::from_stl(file, scale, w.path("file"));
    const Vec3 shift = w.get_vec3("translate", Vec3::Zero());
    for (auto& v : m.mesh.vertices) v += shift;
    m.motion = read_motion(w);
    out.torque_origin = m.motion.axis_point;
    out.shape = std::move(m);
  }
  return out;
}

}  // namespace lbdem::scenarios
