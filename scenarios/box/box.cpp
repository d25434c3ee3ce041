#include "scenarios/box/box.hpp"

#include <sstream>

#include "core/error.hpp"
#include "core/h5.hpp"
#include "core/memory.hpp"
#include "scenarios/common/fluid_output.hpp"

namespace lbdem::scenarios {

namespace {

const char* kAxes[3] = {"x", "y", "z"};

bool inside(const Vec3& x, double r, const Vec3& lo, const Vec3& hi) {
  for (int a = 0; a < 3; ++a)
    if (x[a] - r < lo[a] - 1e-12 || x[a] + r > hi[a] + 1e-12) return false;
  return true;
}

// [B] memory per particle of a DEM run, neighbour list and contact history included
// (results/bench/size.csv: 1,042 B at 10^6 settled particles, 1,121 at 3 x 10^5).
constexpr double kDemBytesPerParticle = 1000;

// A fill that cannot succeed is refused before it is tried, which for 10^8 particles would take
// minutes: more particle volume than 0.74 of the region (no packing of equal spheres is denser;
// random placement without overlap stops near 0.38, the jamming limit of random sequential
// addition), or more particles than memory holds. The fewest particles the request can mean
// (a mass in the largest radius) bound both from below.
void check_fill_size(const dem::FillRequest& req, const std::string& key,
                     const std::string& value) {
  const auto volume = [](double r) { return 4.0 / 3.0 * kPi * r * r * r; };
  const double fewest =
      req.count > 0 ? double(req.count) : req.mass / (req.density * volume(req.radius.largest()));
  const double solid =
      req.count > 0 ? fewest * volume(req.radius.smallest()) : req.mass / req.density;  // [m^3]
  double region = 1;
  for (int a = 0; a < 3; ++a) region *= req.hi[a] - req.lo[a];
  if (solid > 0.74 * region)
    throw InputError(key, value,
                     "the particles' volume (at least " + to_text(solid) +
                         " m^3) would fill the region's " + to_text(region) +
                         " m^3 to a solid fraction of " + to_text(solid / region) +
                         "; random placement without overlap reaches about 0.38",
                     "enlarge the fill region or ask for fewer particles");
  require_memory(fewest * kDemBytesPerParticle,
                 "at least " + to_text(fewest) + " particles (about " +
                     to_text(kDemBytesPerParticle) + " B each)",
                 key, value,
                 "ask for fewer particles, or coarse-grain them (coarse_grain.size_factor)");
}

}  // namespace

BoxScenario::BoxScenario(const Config& cfg) {
  const Config run = cfg.section("run");
  const Config box = cfg.section("box");
  dem::DemSettings s;
  s.domain.lo = box.require_vec3("lo");
  s.domain.hi = box.require_vec3("hi");
  for (int a = 0; a < 3; ++a)
    if (!(s.domain.hi[a] > s.domain.lo[a]))
      throw InputError(box.path("hi"), vec_text(s.domain.hi),
                       "not above box.lo along " + std::string(kAxes[a]),
                       "give hi > lo on every axis");
  // A [fluid] box without [[materials]] may hold no particles: its walls get a placeholder
  // material (never in contact with anything).
  const bool has_fluid = cfg.has("fluid");
  std::vector<dem::Material> mats;
  if (has_fluid && !cfg.has("materials") && !cfg.has("fill") && !cfg.has("particle") &&
      !cfg.section("inflow").get_bool("enabled", false)) {
    mats.emplace_back();
    mats.back().name = "none";
  } else {
    mats = read_materials(cfg);
    implausible_ = implausible_inputs(cfg, mats);
  }
  const std::string wall_mat_name = box.get_string("wall_material", mats.front().name);
  const int wall_mat = material_index(mats, wall_mat_name, box.path("wall_material"));
  std::vector<dem::Wall> walls;
  for (int a = 0; a < 3; ++a) {
    const std::string lo_key = std::string(kAxes[a]) + "_lo",
                      hi_key = std::string(kAxes[a]) + "_hi";
    const std::string lo = box.get_choice(lo_key, "wall", {"wall", "periodic", "open"});
    const std::string hi =
        box.get_choice(hi_key, a == 2 ? "open" : "wall", {"wall", "periodic", "open"});
    if ((lo == "periodic") != (hi == "periodic"))
      throw InputError(box.path(lo == "periodic" ? hi_key : lo_key),
                       "\"" + (lo == "periodic" ? hi : lo) + "\"", "periodic faces come in pairs",
                       "make both " + lo_key + " and " + hi_key + " periodic");
    s.domain.periodic[a] = lo == "periodic";
    for (int side = 0; side < 2; ++side) {
      if ((side ? hi : lo) != "wall") continue;
      dem::PlaneWall p;
      p.point = side ? s.domain.hi : s.domain.lo;
      p.normal = Vec3::Zero();
      p.normal[a] = side ? -1 : 1;
      dem::Wall w;
      w.name = side ? hi_key : lo_key;
      w.material = wall_mat;
      w.shape = p;
      w.torque_origin = p.point;
      walls.push_back(w);
    }
  }
  for (const Config& w : cfg.table_array("walls")) walls.push_back(read_wall(w, mats));
  s.gravity = cfg.section("physics").get_vec3("gravity", Vec3(0, 0, -9.81));
  if (has_fluid)
    fluid_ =
        read_fluid(cfg.section("fluid"), s.domain.lo, s.domain.hi, s.domain.periodic, s.gravity);
  s.contact = read_contact(cfg.section("contact"));
  cg_ = read_coarse_grain(cfg.section("coarse_grain"), s.contact.normal);
  const double l = cg_.l();
  s.collisions = read_collisions(cfg.section("output").section("collisions"));

  // Particles: explicit list, then random fills, all inside the box.
  rng_.seed(static_cast<std::uint64_t>(run.get_int("seed", 1, Range::non_negative())));
  struct Init {
    Vec3 x, v, w;
    double r;
    int mat;
  };
  std::vector<Init> init;
  std::vector<dem::Placed> placed;
  const auto parts = cfg.table_array("particle");
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Config& p = parts[k];
    Init q{p.require_vec3("position"), p.get_vec3("velocity", Vec3::Zero()),
           p.get_vec3("angular_velocity", Vec3::Zero()),
           l * p.require("radius", Range::positive("give the particle radius in m")),
           material_index(mats, p.get_string("material", mats.front().name), p.path("material"))};
    if (!inside(q.x, 0, s.domain.lo, s.domain.hi))
      throw InputError(p.path("position"), vec_text(q.x),
                       "outside the box " + vec_text(s.domain.lo) + " - " + vec_text(s.domain.hi),
                       "move the particle into the box or enlarge box.lo/box.hi");
    init.push_back(q);
    placed.push_back({q.x, q.r});
  }
  for (const Config& f : cfg.table_array("fill")) {
    dem::FillRequest req;
    req.lo = f.get_vec3("lo", s.domain.lo);
    req.hi = f.get_vec3("hi", s.domain.hi);
    for (const auto& [key, corner] : {std::pair{"lo", req.lo}, std::pair{"hi", req.hi}})
      if (!inside(corner, 0, s.domain.lo, s.domain.hi))
        throw InputError(f.path(key), vec_text(corner), "fill region corner outside the box",
                         "keep the fill region inside box.lo = " + vec_text(s.domain.lo) +
                             " - box.hi = " + vec_text(s.domain.hi));
    req.count = f.get_int("count", 0, Range::non_negative());
    req.mass = f.get("mass", 0.0, Range::non_negative());
    if ((req.count > 0) == (req.mass > 0))
      throw InputError(f.path("count"), std::to_string(req.count),
                       "give exactly one of count and mass", "set count = N or mass = M [kg]");
    const int mat =
        material_index(mats, f.get_string("material", mats.front().name), f.path("material"));
    req.density = mats[mat].density;
    req.radius = scaled(read_radius(f.section("radius")), l);
    const Vec3 v = f.get_vec3("velocity", Vec3::Zero());
    check_fill_size(req, f.path(req.count > 0 ? "count" : "mass"),
                    req.count > 0 ? std::to_string(req.count) : to_text(req.mass));
    const auto got = dem::random_fill(req, placed, rng_);
    const bool short_count = req.count > 0 && static_cast<std::int64_t>(got.size()) < req.count;
    double m = 0;
    for (const auto& g : got) m += mats[mat].density * 4.0 / 3.0 * kPi * g.r * g.r * g.r;
    if (short_count || (req.mass > 0 && m < req.mass))
      throw InputError(f.path(req.count > 0 ? "count" : "mass"),
                       req.count > 0 ? std::to_string(req.count) : to_text(req.mass),
                       "only " + std::to_string(got.size()) +
                           " particles fit in the fill region without overlap",
                       "enlarge the fill region or ask for fewer particles");
    for (const auto& g : got) init.push_back({g.x, v, Vec3::Zero(), g.r, mat}), placed.push_back(g);
  }

  const Config inflow = cfg.section("inflow");
  inflow_.on = inflow.get_bool("enabled", false);
  double r_min = 1e300;
  for (const auto& q : init) r_min = std::min(r_min, q.r);
  if (inflow_.on) {
    inflow_.lo = inflow.require_vec3("lo");
    inflow_.hi = inflow.require_vec3("hi");
    inflow_.mass_rate =
        inflow.require("mass_rate", Range::positive("give the inflow mass rate in kg/s"));
    inflow_.start = inflow.get("start", 0.0, Range::non_negative());
    inflow_.end = inflow.get("end", 1e300, Range::non_negative());
    inflow_.period =
        inflow.get("insert_interval", 1e-3, Range::positive("give the insertion interval in s"));
    inflow_.material = material_index(mats, inflow.get_string("material", mats.front().name),
                                      inflow.path("material"));
    inflow_.velocity = inflow.get_vec3("velocity", Vec3::Zero());
    inflow_.radius = scaled(read_radius(inflow.section("radius")), l);
    r_min = std::min(r_min, inflow_.radius.smallest());
  }
  const Config outlet = cfg.section("outlet");
  outlet_.on = outlet.get_bool("enabled", false);
  if (outlet_.on) {
    outlet_.lo = outlet.require_vec3("lo");
    outlet_.hi = outlet.require_vec3("hi");
    outlet_.every = outlet.get_int("check_every", outlet_.every,
                                   Range::closed(1, 1e9, "give the DEM steps between checks"));
  }
  gas_only_ = has_fluid && init.empty() && !inflow_.on;
  if (init.empty() && !inflow_.on && !gas_only_)
    throw InputError("fill", "", "no particles",
                     "add a [[fill]] or [[particle]] table or an [inflow]");

  if (gas_only_) {
    // No particles: the DEM step has no contact time to resolve, so it is the gas step.
    if (cfg.has("dem"))
      throw InputError("dem", "", "a box without particles has no DEM step to set",
                       "remove the [dem] table, or add particles");
    sub_ = conform_dem_step(fluid_.dt, fluid_.dt);
    s.dt = sub_.dem_dt;
    s.skin = fluid_.dx;  // unused: nothing to track
  } else {
    const Config dcfg = cfg.section("dem");
    std::vector<int> wall_mats;
    for (const auto& w : walls) wall_mats.push_back(w.material);
    // Contact parameters of parcels (the config gives the originals); r_min is a parcel radius.
    const double dt_factor = cg_.dt_factor(mats.front(), r_min / l);
    cg_.apply(mats, r_min / l);
    step_ = choose_time_step(dcfg, s.contact, mats, wall_mats, r_min, dt_factor, implausible_);
    s.dt = step_.dt;
    if (has_fluid) {
      sub_ = conform_dem_step(step_.dt, fluid_.dt);
      s.dt = sub_.dem_dt;
    }
    s.skin = dcfg.get("skin", 0.2 * r_min,
                      Range::positive("give the neighbour skin in m, e.g. 0.2 r_min"));
    s.sort_every = static_cast<int>(dcfg.get_int("sort_every", 1, Range::closed(0, 1e6)));
  }
  out_ = OutputSettings::from(run, cfg.section("output"));
  const bool dt_given = !gas_only_ && cfg.has("dem.dt");
  check_step_count(s.dt, out_.end_time, dt_given ? "dem.dt" : "",
                   dt_given ? shortest_text(step_.dt / step_.dt_factor) : "", implausible_);

  solver_ = std::make_unique<dem::DemSolver>(s, mats);
  for (auto& w : walls) add_wall(std::move(w));
  for (const auto& q : init) {
    solver_->add_particle(q.x, q.v, q.r, q.mat);
    solver_->particles().omega.back() = q.w;
  }
  if (has_fluid) {
    const lbm::LbmSettings lattice = fluid_.lattice();
    auto gas = std::make_unique<lbm::LbmSolver>(lattice);
    const Vec3 u0 = fluid_.initial_velocity * fluid_.units().velocity_to_lattice(1.0);
    // The velocity moment is (sum c f + F/2) / rho (Guo's half-force shift, lbm/cell.hpp): start
    // the populations at u0 - F / (2 rho), so the gas moves at initial_velocity (at rest under
    // gravity, in hydrostatic balance) from the first step.
    gas->initialize([&](int x, int y, int z, double& rho, Vec3& v) {
      rho = fluid_.rest_density(x, y, z);
      v = u0 - lattice.body_force / (2 * rho);
    });
    for (int f = 0; f < 6; ++f)
      inlet_set_[std::size_t(f)] = fluid_.faces[std::size_t(f)].velocity_at(0);
    if (fluid_.wall_function)
      for (int f = 0; f < 6; ++f)
        if (fluid_.faces[std::size_t(f)].kind == "wall")
          gas->set_wall_function(gas->face_body(f), true);
    gas_ = std::make_unique<run::CoupledGas>(std::move(gas), sub_, fluid_.dt,
                                             [this](double t) { ramp_inlets(t); });
  }
  if (cfg.has("coupling")) {
    if (!has_fluid || gas_only_)
      throw InputError("coupling", "", has_fluid ? "no particles to couple" : "no gas to couple",
                       has_fluid ? "add particles ([[fill]], [[particle]] or [inflow])"
                                 : "add a [fluid] table, or remove [coupling]");
    double r_lo = 1e300, r_hi = 0;
    for (const auto& q : init) r_lo = std::min(r_lo, q.r), r_hi = std::max(r_hi, q.r);
    if (inflow_.on) {
      r_lo = std::min(r_lo, inflow_.radius.smallest());
      r_hi = std::max(r_hi, inflow_.radius.largest());
    }
    coupling_ = read_coupling(cfg.section("coupling"), fluid_, 2 * r_lo, 2 * r_hi, l,
                              mats.front().density, fluid_.weighs, s.gravity);
    coupled_ = true;
    rebuild_coupler();
    solver_->track_external_work();
  }
}

void BoxScenario::add_wall(dem::Wall w) {
  wall_columns_.push_back("wall_" + w.name + "_force_z_N");
  wall_columns_.push_back("wall_" + w.name + "_torque_axis_Nm");
  solver_->add_wall(std::move(w));
}

void BoxScenario::rebuild_coupler() {
  if (!coupled_) return;
  gas_->couple(
      std::make_unique<coupling::Coupler>(gas_->gas(), lbm::LatticeFrame{fluid_.lo, fluid_.dx},
                                          fluid_.units(), coupling_.settings),
      exchange_interval(sub_, coupling_.exchange_every));
}

std::int64_t BoxScenario::cycle() const {
  return gas_ ? gas_->cycle() : sub_.cycle();
}

void BoxScenario::banner(Log& log) const {
  if (gas_only_) {
    log.line("DEM: no particles (a pure gas run); the DEM keeps the clock at the gas step");
  } else {
    for (const auto& w : implausible_) log.line(w.warning());
    for (const auto& line : cg_.banner) log.line(line);
    const DemWatch w = watch();
    dem_banner(log, *solver_, step_.impact_speed, step_.scales.contact_time,
               step_.scales.rayleigh_time, step_.scales.where,
               inflow_.on ? inflow_.radius.smallest() : 0.0,
               inflow_.on ? inflow_.radius.largest() : 0.0, &w);
    if (inflow_.on)
      log.derived(
          "feed (inflow) mass rate", inflow_.mass_rate, "kg/s",
          "(from " + to_text(inflow_.start) + " s to " + to_text(inflow_.end) + " s, " +
              to_text(inflow_.mass_rate * (std::min(inflow_.end, out_.end_time) - inflow_.start)) +
              " kg in this run)");
  }
  if (gas_) fluid_banner(log, fluid_, sub_);
  if (coupled_) {
    std::vector<double> eps;
    gas_->gas().porosity(eps);
    double cells = 0;
    for (double e : eps) cells += e > 0 ? 1.0 : 0.0;
    coupling_banner(log, coupling_, fluid_, sub_, solver_->particles().size(), cells);
    // The balanced kernel conserves each particle's volume exactly either way; an unconverged
    // balance leaves a uniform solid fraction deposited off uniform by this much at walls.
    const double balance = gas_->coupler()->kernel().balance_error();
    log.derived("kernel balance error", balance, "",
                "(a uniform solid fraction deposited at walls and solid cells is off by this)");
    if (balance > 1e-6)
      log.line("warning: coupling: the kernel's wall balance stopped at " + to_text(balance) +
               " after " + std::to_string(coupling::ParticleKernel::kBalanceIterations) +
               " passes: a uniform bed reads a solid fraction off by up to that share next to "
               "walls and solid cells (each particle's volume is still conserved)");
  }
}

DemWatch BoxScenario::watch() const {
  if (gas_only_) return {};
  std::vector<ExpectedSpeed> others;
  if (inflow_.on) others.push_back({inflow_.velocity.norm(), "inflow.velocity"});
  // Particles the gas carries move at most as fast as the gas, which its own watchdog bounds.
  if (gas_)
    others.push_back(
        {fluid_.units().velocity_to_si(kHealthySpeed), "the gas watchdog's speed limit", true});
  return dem_watch(step_, *solver_, others);
}

void BoxScenario::ramp_inlets(double t) {
  // Ramped inlets take the velocity of the time the coming gas step starts at.
  for (int f = 0; f < 6; ++f) {
    const FluidFace& face = fluid_.faces[std::size_t(f)];
    if (!face.ramped()) continue;
    const Vec3 v = face.velocity_at(t);
    if (v == inlet_set_[std::size_t(f)]) continue;
    inlet_set_[std::size_t(f)] = v;
    const Vec3 lu = v * fluid_.units().velocity_to_lattice(1.0);
    lbm::LbmSolver& gas = gas_->gas();
    gas.set_wall_velocity(gas.face_body(f), [lu](const Vec3&) { return lu; });
  }
}

void BoxScenario::before_step(const run::Instant& now) {
  if (gas_only_) return;
  dem::DemSolver& s = *solver_;
  const double t = now.time_s;
  // Insertions fall on whole multiples of llround(period / dt) steps, so the last one before
  // `end` may come up to a period early, when only rate x (t - start) is due: the first insertion
  // step after `end` delivers the rest (before, up to one period's mass was never fed: 0.6-1.0 %
  // of the jet mill's 1 g).
  if (inflow_.on && t >= inflow_.start &&
      (t <= inflow_.end || inflow_.inserted < inflow_.mass_rate * (inflow_.end - inflow_.start))) {
    const std::int64_t every =
        std::max<std::int64_t>(1, std::llround(inflow_.period / s.settings().dt));
    if (now.step % every == 0) {
      const double target = inflow_.mass_rate * (std::min(t, inflow_.end) - inflow_.start);
      if (target > inflow_.inserted) {
        dem::FillRequest req;
        req.lo = inflow_.lo, req.hi = inflow_.hi;
        req.mass = target - inflow_.inserted;
        req.density = s.materials()[inflow_.material].density;
        req.radius = inflow_.radius;
        std::vector<dem::Placed> existing;
        const auto& p = s.particles();
        const double m = 2 * inflow_.radius.largest();
        for (std::size_t k = 0; k < p.size(); ++k)
          if (inside(p.x[k], -m, inflow_.lo, inflow_.hi)) existing.push_back({p.x[k], p.radius[k]});
        for (const auto& g : dem::random_fill(req, existing, rng_)) {
          s.add_particle(g.x, inflow_.velocity, g.r, inflow_.material);
          inflow_.inserted += s.particles().mass.back();
        }
        // Behind by more than two of the largest particles: the region is full.
        const double r = inflow_.radius.largest();
        if (target - inflow_.inserted > 2 * req.density * 4.0 / 3.0 * kPi * r * r * r &&
            inflow_.behind_at < 0) {
          inflow_.behind_at = t;
          inflow_.behind_target = target;
        }
      }
    }
  }
  if (outlet_.on && now.step % outlet_.every == 0) {
    std::vector<std::uint32_t> out;
    const auto& p = s.particles();
    for (std::size_t k = 0; k < p.size(); ++k)
      if (inside(p.x[k], 0, outlet_.lo, outlet_.hi)) out.push_back(static_cast<std::uint32_t>(k));
    if (!out.empty()) s.remove_particles(out);
  }
  warn_once(now);
}

void BoxScenario::warn_once(const run::Instant& now) {
  if (!log_) return;
  if (inflow_.behind_at >= 0 && !inflow_.behind_warned) {
    inflow_.behind_warned = true;
    log_->line("warning: inflow: the feed region is full at t = " + to_text(inflow_.behind_at) +
               " s: " + to_text(inflow_.inserted) + " kg inserted of the " +
               to_text(inflow_.behind_target) +
               " kg asked by then (the rest follows as room frees); enlarge inflow.lo - "
               "inflow.hi or give the feed a velocity");
  }
  // Clipped gas fractions: said once per run, with where (kernel.hpp).
  if (coupled_ && gas_->report().porosity.clipped > 0 && !clip_warned_) {
    clip_warned_ = true;
    const auto& p = gas_->report().porosity;
    log_->line("warning: coupling: eps fell below coupling.eps_min = " +
               to_text(coupling_.settings.eps_min) + " in " + std::to_string(p.clipped) +
               " cells at t = " + to_text(now.time_s) + " s (lowest " + to_text(p.lowest) +
               ", first at cell " + std::to_string(p.first[0]) + ", " + std::to_string(p.first[1]) +
               ", " + std::to_string(p.first[2]) +
               "); clipped there. A wider coupling.kernel_width smooths the bed");
  }
}

std::vector<std::string> BoxScenario::row_columns() const {
  std::vector<std::string> c;
  if (!gas_only_) {
    c = wall_columns_;
    c.push_back("mass_inserted_kg");
  }
  if (gas_) {
    const auto cols = fluid_columns(fluid_);
    c.insert(c.end(), cols.begin(), cols.end());
  }
  if (coupled_)
    for (const char* name :
         {"drag_force_x_N", "drag_force_y_N", "drag_force_z_N", "pressure_gradient_force_z_N",
          "mean_eps_at_particles", "eps_clipped_cells", "gas_work_on_particles_J"})
      c.emplace_back(name);
  return c;
}

std::vector<std::string> BoxScenario::columns() const {
  std::vector<std::string> c = loop_columns(!gas_only_);
  const auto own = row_columns();
  c.insert(c.end(), own.begin(), own.end());
  if (extension_) {
    const auto more = extension_->row_columns();
    c.insert(c.end(), more.begin(), more.end());
  }
  return c;
}

void BoxScenario::on_row(const run::Instant& /*now*/, std::vector<double>& v) const {
  if (!gas_only_) {
    for (const auto& w : solver_->walls()) {
      Vec3 axis = Vec3::UnitZ();
      if (const auto* c = std::get_if<dem::CylinderWall>(&w.shape)) axis = c->axis;
      if (const auto* m = std::get_if<dem::MeshWall>(&w.shape)) axis = m->motion.axis;
      if (const auto* b = std::get_if<dem::BoxWall>(&w.shape)) axis = b->motion.axis;
      v.push_back(w.force[2]);
      v.push_back(w.torque.dot(axis));
    }
    v.push_back(inflow_.inserted);
  }
  if (gas_) {
    const auto g = fluid_values(gas_->gas(), fluid_);
    v.insert(v.end(), g.begin(), g.end());
  }
  if (coupled_) {
    const auto& r = gas_->report();
    v.insert(v.end(), {r.drag[0], r.drag[1], r.drag[2], r.pressure_force[2], r.mean_eps_particles,
                       double(r.porosity.clipped), solver_->energy().external_work});
  }
}

void BoxScenario::on_checkpoint(H5Out& f) const {
  std::ostringstream os;
  os << rng_;
  f.attr("rng_state", os.str());
  f.attr("inflow_inserted_kg", inflow_.inserted);
}

void BoxScenario::on_resume(const H5In& f) {
  std::istringstream is(f.attr_string("rng_state"));
  is >> rng_;
  inflow_.inserted = f.attr_double("inflow_inserted_kg");
}

void BoxScenario::on_snapshot(const std::string& dir, const std::vector<double>& times,
                              const std::vector<run::SnapshotArray>& gas_arrays) {
  if (gas_) write_fluid_snapshot(dir, gas_->gas(), fluid_, times, gas_arrays);
}

std::optional<std::string> BoxScenario::health(const run::Instant& now) {
  if (!gas_) return std::nullopt;
  auto error = check_fluid_health(gas_->gas(), fluid_, now.time_s, now.step);
  if (!error && !mach_warned_ && log_)
    if (auto w = check_fluid_mach(gas_->gas(), fluid_, now.time_s)) {
      mach_warned_ = true;
      log_->line(*w);
    }
  return error;
}

std::array<std::int64_t, 3> BoxScenario::lattice() const {
  if (!gas_) return {0, 0, 0};
  const auto& g = gas_->gas().settings();
  return {g.nx, g.ny, g.nz};
}

int BoxScenario::run(const RunContext& ctx) {
  // The run's log for the warnings said once, for as long as the run lasts.
  log_ = ctx.log;
  struct Forget {
    Log*& log;
    ~Forget() { log = nullptr; }
  } forget{log_};
  RunParts parts;
  parts.observers.push_back(this);
  if (extension_) parts.observers.push_back(extension_);
  parts.gas = gas_.get();
  parts.watch = watch();
  if (gas_only_) return RunLoop(out_, std::move(parts)).run(ctx);
  return RunLoop(*solver_, out_, std::move(parts)).run(ctx);
}

}  // namespace lbdem::scenarios
