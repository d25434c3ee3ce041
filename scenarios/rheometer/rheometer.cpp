#include "scenarios/rheometer/rheometer.hpp"

#include <cmath>
#include <sstream>

#include "core/deterministic_sum.hpp"
#include "core/error.hpp"
#include "core/h5.hpp"
#include "dem/walls/cuboid_mesh.hpp"

namespace lbdem::scenarios {

namespace {

// Impeller parts as cuboids at t = 0: the blades (one cuboid through the axis, the span along x)
// and the shaft above them.
std::vector<dem::BoxWall> impeller_parts(const RheometerGeometry& g) {
  std::vector<dem::BoxWall> parts;
  dem::BoxWall blade;
  blade.center = Vec3(0, 0, g.blade_bottom + 0.5 * g.blade_height);
  blade.half = 0.5 * Vec3(g.blade_span, g.blade_thickness, g.blade_height);
  parts.push_back(blade);
  const double top = g.blade_bottom + g.blade_height;
  if (g.shaft_width > 0 && g.cup_height > top) {
    dem::BoxWall shaft;
    shaft.center = Vec3(0, 0, 0.5 * (top + g.cup_height));
    shaft.half = 0.5 * Vec3(g.shaft_width, g.shaft_width, g.cup_height - top);
    parts.push_back(shaft);
  }
  return parts;
}

}  // namespace

RheometerScenario::RheometerScenario(const Config& cfg) {
  const Config run = cfg.section("run");
  const Config rc = cfg.section("rheometer");
  auto& g = geo_;
  const auto len = [&](const char* key, double def) {
    return rc.get(key, def, Range::positive("give the length in m"));
  };
  g.cup_radius = len("cup_radius", g.cup_radius);
  g.cup_height = len("cup_height", g.cup_height);
  g.blade_span = len("blade_span", g.blade_span);
  g.blade_height = len("blade_height", g.blade_height);
  g.blade_thickness = len("blade_thickness", g.blade_thickness);
  g.blade_bottom = rc.get("blade_bottom", g.blade_bottom, Range::non_negative());
  g.shaft_width = rc.get("shaft_width", g.shaft_width, Range::non_negative());
  g.mesh = rc.get_choice("impeller", "mesh", {"mesh", "analytic"}) == "mesh";
  if (!(g.gap() > 0))
    throw InputError(rc.path("blade_span"), to_text(g.blade_span),
                     "the blades do not fit in the cup (radius " + to_text(g.cup_radius) + " m)",
                     "give blade_span < 2 cup_radius");
  if (g.blade_bottom + g.blade_height > g.cup_height)
    throw InputError(rc.path("blade_bottom"), to_text(g.blade_bottom), "blades above the cup rim",
                     "lower blade_bottom or blade_height");
  rpm_ = rc.get("rpm", rpm_);
  start_ = rc.get("start", start_, Range::non_negative("give the time the impeller starts, in s"));
  ramp_ = rc.get("ramp", ramp_, Range::non_negative("give the spin-up time in s"));
  fill_mass_ = rc.require("fill_mass", Range::positive("give the powder mass in kg"));

  dem::DemSettings s;
  s.gravity = cfg.section("physics").get_vec3("gravity", Vec3(0, 0, -9.81));
  s.contact = read_contact(cfg.section("contact"));
  s.collisions = read_collisions(cfg.section("output").section("collisions"));
  cg_ = read_coarse_grain(cfg.section("coarse_grain"), s.contact.normal);
  auto mats = read_materials(cfg);
  implausible_ = implausible_inputs(cfg, mats);
  const Config pc = cfg.section("particles");
  const int mat =
      material_index(mats, pc.get_string("material", mats.front().name), pc.path("material"));
  const int wall_mat = material_index(mats, rc.get_string("wall_material", mats[mat].name),
                                      rc.path("wall_material"));
  const dem::RadiusDistribution radius = scaled(read_radius(pc.section("radius")), cg_.l());
  const double r_max = radius.largest(), r_min = radius.smallest();
  if (2 * r_max >= g.gap() + g.blade_thickness && 2 * r_max >= g.blade_height)
    throw InputError(pc.path("radius"), to_text(r_max), "parcels larger than the blades",
                     "use a smaller coarse_grain.size_factor");

  // Domain: the cup, with head room for the neighbour grid above the rim.
  s.domain.lo = Vec3(-g.cup_radius, -g.cup_radius, 0);
  s.domain.hi = Vec3(g.cup_radius, g.cup_radius, 1.2 * g.cup_height);

  // Walls: floor, cup (unbounded above: a grain thrown over the rim stays in), impeller.
  std::vector<dem::Wall> walls;
  {
    dem::Wall floor;
    floor.name = "floor";
    floor.material = wall_mat;
    dem::PlaneWall p;
    p.point = Vec3::Zero();
    p.normal = Vec3::UnitZ();
    floor.shape = p;
    walls.push_back(floor);
    dem::Wall cup;
    cup.name = "cup";
    cup.material = wall_mat;
    dem::CylinderWall c;
    c.radius = g.cup_radius;
    c.lo = 0;
    cup.shape = c;
    walls.push_back(cup);
  }
  floor_wall_ = 0, cup_wall_ = 1;
  dem::PrescribedMotion motion;
  motion.axis = Vec3::UnitZ();
  motion.omega = rpm_ * 2 * kPi / 60;
  motion.start = start_;
  motion.ramp = ramp_;
  const auto parts = impeller_parts(g);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    dem::Wall w;
    w.name = k == 0 ? "blades" : "shaft";
    w.material = wall_mat;
    if (g.mesh) {
      dem::MeshWall m;
      m.mesh = dem::cuboid_mesh(parts[k].center, parts[k].axes, parts[k].half);
      m.motion = motion;
      w.shape = std::move(m);
    } else {
      dem::BoxWall b = parts[k];
      b.motion = motion;
      w.shape = b;
    }
    impeller_walls_.push_back(walls.size());
    walls.push_back(std::move(w));
  }

  // Powder on a jittered simple-cubic lattice (spacing 2.2 r_max, jitter 0.09 r_max per axis, so
  // no two overlap), clear of the impeller, the cup and the floor (the lowest layer's centres at
  // 1.05 r_max or higher: an overlap there would release its spring energy, which the energy
  // balance never saw put in), layer by layer from the floor until the mass is reached; it then
  // settles under gravity before the impeller starts.
  std::mt19937_64 rng(static_cast<std::uint64_t>(run.get_int("seed", 1, Range::non_negative())));
  const double a = 2.2 * r_max, jitter = 0.09 * r_max;
  const int nxy = static_cast<int>(std::floor(2 * (g.cup_radius - r_max) / a));
  std::vector<std::pair<Vec3, double>> placed;
  const double rho = mats[mat].density;
  for (int iz = 0; placed_mass_ < fill_mass_; ++iz) {
    const double z = r_max * 1.05 + jitter + iz * a;
    if (z + r_max > g.cup_height)
      throw InputError(rc.path("fill_mass"), to_text(fill_mass_),
                       "the powder does not fit in the cup as placed (" + to_text(placed_mass_) +
                           " kg reach the rim)",
                       "lower fill_mass or raise cup_height");
    for (int iy = 0; iy <= nxy && placed_mass_ < fill_mass_; ++iy)
      for (int ix = 0; ix <= nxy && placed_mass_ < fill_mass_; ++ix) {
        Vec3 x(-0.5 * nxy * a + ix * a, -0.5 * nxy * a + iy * a, z);
        for (int d = 0; d < 3; ++d) x[d] += jitter * (2 * dem::uniform01(rng) - 1);
        const double r = radius.sample(rng);
        if (std::hypot(x.x(), x.y()) + r > g.cup_radius - 0.05 * r) continue;
        bool clear = true;
        for (const auto& part : parts) clear = clear && dem::wall_point(part, x, 0).dist > 1.05 * r;
        if (!clear) continue;
        placed.push_back({x, r});
        placed_mass_ += rho * 4.0 / 3.0 * kPi * r * r * r;
        bed_top_ = z + r;
      }
  }
  mean_diameter_ = 0;
  for (const auto& q : placed) mean_diameter_ += 2 * q.second / double(placed.size());

  const Config dcfg = cfg.section("dem");
  std::vector<int> wall_mats(walls.size(), wall_mat);
  const double dt_factor = cg_.dt_factor(mats[mat], r_min / cg_.l());
  cg_.apply(mats, r_min / cg_.l());
  step_ = choose_time_step(dcfg, s.contact, mats, wall_mats, r_min, dt_factor, implausible_);
  s.dt = step_.dt;
  // The impeller flings the powder across a 0.2 r skin every few steps; at 0.4 r the default run
  // rebuilds half as often for a 5-10 % longer row walk: 6-10 % faster on 2 threads (0.6 r lies
  // between them; docs/performance.md).
  s.skin = dcfg.get("skin", 0.4 * r_min, Range::positive("give the neighbour skin in m"));
  s.sort_every = static_cast<int>(dcfg.get_int("sort_every", 1, Range::closed(0, 1e6)));
  out_ = OutputSettings::from(run, cfg.section("output"));
  const bool dt_given = cfg.has("dem.dt");
  check_step_count(s.dt, out_.end_time, dt_given ? "dem.dt" : "",
                   dt_given ? shortest_text(step_.dt / step_.dt_factor) : "", implausible_);

  solver_ = std::make_unique<dem::DemSolver>(s, mats);
  for (auto& w : walls) solver_->add_wall(std::move(w));
  for (const auto& q : placed) solver_->add_particle(q.first, Vec3::Zero(), q.second, mat);
}

double RheometerScenario::drive_torque() const {
  double t = 0;
  for (std::size_t w : impeller_walls_) t -= solver_->walls()[w].torque.z();
  return t;
}

double RheometerScenario::cup_torque() const {
  return solver_->walls()[cup_wall_].torque.z();
}

double RheometerScenario::floor_torque() const {
  return solver_->walls()[floor_wall_].torque.z();
}

double RheometerScenario::angular_momentum() const {
  const auto& p = solver_->particles();
  return deterministic_sum(
      p.size(),
      [&](std::size_t k) {
        const Vec3& x = p.x[k];
        const Vec3& v = p.v[k];
        return p.mass[k] * (x.x() * v.y() - x.y() * v.x()) + p.inertia[k] * p.omega[k].z();
      },
      0.0);
}

void RheometerScenario::banner(Log& log) const {
  const auto& g = geo_;
  for (const auto& w : implausible_) log.line(w.warning());
  for (const auto& line : cg_.banner) log.line(line);
  log.line("Rheometer:");
  log.derived("cup radius / height", g.cup_radius, "m", "height " + to_text(g.cup_height) + " m");
  log.derived("blade span x height x thickness", g.blade_span, "m",
              to_text(g.blade_height) + " x " + to_text(g.blade_thickness) + " m, bottom " +
                  to_text(g.blade_bottom) + " m above the floor (" +
                  (g.mesh ? "triangle meshes" : "analytic cuboids") + ")");
  log.derived("blade tip to cup wall gap", g.gap(), "m",
              to_text(g.gap() / mean_diameter_) + " mean parcel diameters");
  log.derived("parcels across the blade height", g.blade_height / mean_diameter_, "");
  log.derived("impeller speed", rpm_, "rpm",
              "from t = " + to_text(start_) + " s, ramp " + to_text(ramp_) + " s; tip speed " +
                  to_text(rpm_ * 2 * kPi / 60 * 0.5 * g.blade_span) + " m/s");
  log.derived("powder mass placed", placed_mass_, "kg", "asked " + to_text(fill_mass_) + " kg");
  log.derived("placed bed top (before settling)", bed_top_, "m");
  const DemWatch w = dem_watch(step_, *solver_);
  dem_banner(log, *solver_, step_.impact_speed, step_.scales.contact_time,
             step_.scales.rayleigh_time, step_.scales.where, 0.0, 0.0, &w);
}

namespace {
const std::vector<std::string> kRheometerColumns = {"torque_Nm", "cup_torque_Nm", "floor_torque_Nm",
                                                    "particle_angular_momentum_Nms",
                                                    "impeller_angle_rad"};
}  // namespace

std::vector<std::string> RheometerScenario::columns() const {
  std::vector<std::string> c = loop_columns();
  c.insert(c.end(), kRheometerColumns.begin(), kRheometerColumns.end());
  return c;
}

std::vector<std::string> RheometerScenario::row_columns() const {
  return kRheometerColumns;
}

void RheometerScenario::on_row(const run::Instant& now, std::vector<double>& row) const {
  const auto& w = solver_->walls()[impeller_walls_.front()];
  double angle = 0;
  if (const auto* m = std::get_if<dem::MeshWall>(&w.shape))
    angle = m->motion.omega * m->motion.travel_time(now.time_s);
  if (const auto* b = std::get_if<dem::BoxWall>(&w.shape))
    angle = b->motion.omega * b->motion.travel_time(now.time_s);
  row.insert(row.end(), {drive_torque(), cup_torque(), floor_torque(), angular_momentum(), angle});
}

int RheometerScenario::run(const RunContext& ctx) {
  RunParts parts;
  parts.observers = {this};
  parts.watch = dem_watch(step_, *solver_);
  RunLoop loop(*solver_, out_, std::move(parts));
  return loop.run(ctx);
}

}  // namespace lbdem::scenarios
