#include "lbm/lbm_solver.hpp"

#include "core/phase_timer.hpp"

#include "core/deterministic_sum.hpp"
#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "lbm/equilibrium.hpp"
#include "lbm/moments.hpp"
#include "lbm/solver_passes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

namespace lbdem::lbm {

namespace {
Grid make_grid(const LbmSettings& s) {
  if (s.nx < 1 || s.ny < 1 || s.nz < 1)
    throw std::invalid_argument("lattice needs at least one cell per axis");
  for (int f = 0; f < 6; ++f) {
    const double rho = s.faces[f].density;
    if (s.faces[f].kind == FaceKind::outlet && !(rho > 0 && std::isfinite(rho)))
      throw InputError("faces." + std::string(BoxFaces::kNames[std::size_t(f)]) + ".density",
                       to_text(rho), "an outlet density must be positive",
                       "give the outlet density in lattice units, about 1");
    const FaceBoundary& face = s.faces[f];
    const std::string name(BoxFaces::kNames[std::size_t(f)]);
    if (!(face.slip >= 0 && face.slip <= 1))
      throw std::invalid_argument("face " + name + ": slip fraction must lie in [0, 1], got " +
                                  std::to_string(face.slip));
    if (face.slip > 0 && (face.kind != FaceKind::wall || !face.wall_velocity.isZero()))
      throw std::invalid_argument("face " + name +
                                  ": a slip fraction applies to a wall at rest only (not to a "
                                  "moving wall, an inlet, an outlet or a periodic face)");
  }
  return Grid(s.nx, s.ny, s.nz, s.faces.periodic_axes());
}

std::variant<LatticeFields<double>, LatticeFields<float>> make_lattice(const LbmSettings& s) {
  const Grid g = make_grid(s);
  if (s.precision == Precision::float32)
    return std::variant<LatticeFields<double>, LatticeFields<float>>(
        std::in_place_type<LatticeFields<float>>, g);
  return std::variant<LatticeFields<double>, LatticeFields<float>>(
      std::in_place_type<LatticeFields<double>>, g);
}

WallVelocity uniform_velocity(const Vec3& u) {
  if (u.isZero()) return {};
  return [u](const Vec3&) { return u; };
}
}  // namespace

LbmSolver::LbmSolver(const LbmSettings& s)
    : settings_(s),
      lat_(make_lattice(s)),
      flags_(with_pdf([](const auto& p) { return p.grid(); })) {
  std::array<CellFlag, 6> walls{}, open{};
  for (int f = 0; f < 6; ++f) {
    const FaceBoundary& face = s.faces[f];
    std::string name(BoxFaces::kNames[std::size_t(f)]);
    int body = 0;
    if (face.kind == FaceKind::wall) {
      body = add_body(std::move(name), uniform_velocity(face.wall_velocity));
      Body& b = bodies_[std::size_t(body - 1)];
      b.slip = face.slip;  // checked in make_grid: a wall at rest
      b.slip_axis = f / 2;
      b.slip_sign = f % 2 ? -1 : 1;
    } else if (face.kind == FaceKind::inlet)
      body = add_inlet(std::move(name), uniform_velocity(face.wall_velocity));
    else if (face.kind == FaceKind::outlet) {
      body = add_outlet(std::move(name), face.density);
      bodies_[std::size_t(body - 1)].outlet_backflow = face.backflow;
    }
    face_body_[std::size_t(f)] = body;
    (face.kind == FaceKind::wall ? walls : open)[std::size_t(f)] = CellFlag(body);
  }
  // Inlets and outlets own the edge ghosts they share with walls: the diagonal links of the
  // cells next to the edge then carry their share of the inflow, so a plug inlet delivers exactly
  // rho U A (with the wall owning the edge, each edge row lost a sixth of its inflow).
  mark_box_faces(flags_, walls);
  mark_box_faces(flags_, open);
  initialize([](int, int, int, double& rho, Vec3& u) {
    rho = 1.0;
    u.setZero();
  });
}

int LbmSolver::add_body(std::string name, WallVelocity u) {
  if (int(bodies_.size()) >= kMaxBodies)
    throw std::invalid_argument("at most 255 solid bodies per lattice");
  Body& b = bodies_.emplace_back();
  b.name = std::move(name);
  b.velocity = std::move(u);
  links_dirty_ = true;
  return int(bodies_.size());
}

int LbmSolver::add_inlet(std::string name, WallVelocity u) {
  return add_body(std::move(name), std::move(u));
}

int LbmSolver::add_outlet(std::string name, double density) {
  const int body = add_body(std::move(name));
  set_outlet_density(body, density);
  return body;
}

void LbmSolver::set_outlet_density(int body, double density) {
  if (!(density > 0 && std::isfinite(density)))
    throw std::invalid_argument("outlet density must be positive, got " + std::to_string(density));
  Body& b = bodies_[std::size_t(body - 1)];
  if (b.wall_function)
    throw std::invalid_argument("body '" + b.name +
                                "' has the wall function and cannot be an outlet");
  if (b.slip > 0)
    throw std::invalid_argument("body '" + b.name + "' is a slip wall and cannot be an outlet");
  if (b.outlet_density <= 0) links_dirty_ = true;  // a new outlet needs its velocity samples
  b.outlet_density = density;
  b.outlet.density = density;  // an existing outlet: no rebuild, so a ramp per step stays cheap
}

void LbmSolver::set_outlet_extrapolation(int body, bool on) {
  Body& b = bodies_[std::size_t(body - 1)];
  if (b.outlet_density <= 0) throw std::invalid_argument("body '" + b.name + "' is not an outlet");
  if (b.outlet_extrapolate != on) links_dirty_ = true;
  b.outlet_extrapolate = on;
}

void LbmSolver::set_outlet_backflow(int body, bool allowed) {
  Body& b = bodies_[std::size_t(body - 1)];
  if (b.outlet_density <= 0) throw std::invalid_argument("body '" + b.name + "' is not an outlet");
  if (b.outlet_backflow != allowed) links_dirty_ = true;
  b.outlet_backflow = allowed;
}

void LbmSolver::set_cell(int x, int y, int z, int body) {
  settle_mass_sources();
  if (body != 0)
    for (const MassSource& m : mass_sources_)
      if (m.x == x && m.y == y && m.z == z)
        throw std::invalid_argument("cell (" + std::to_string(x) + ", " + std::to_string(y) + ", " +
                                    std::to_string(z) +
                                    ") holds a mass source and cannot turn solid");
  if (body < 0 || body > body_count()) throw std::invalid_argument("unknown body id");
  // The mass ledger: a fluid cell that turns solid takes its populations out of total_mass(), a
  // solid cell that turns fluid brings its own in; booked as exchanged, so the ledger closes.
  const auto fluid_mass = [&] {
    if (flags_.at(x, y, z) != kFluid) return 0.0;
    double f[kQ], m = 0;
    cell_populations(x, y, z, f);
    for (double v : f) m += v;
    return m;
  };
  const double before = fluid_mass();
  flags_.set(x, y, z, CellFlag(body));
  exchanged_mass_ += fluid_mass() - before;
  links_dirty_ = true;
}

void LbmSolver::set_wall_velocity(int body, WallVelocity u) {
  Body& b = bodies_[std::size_t(body - 1)];
  if (u && b.wall_function)
    throw std::invalid_argument("body '" + b.name +
                                "' has the wall function: it must stay at rest");
  if (u && b.slip > 0)
    throw std::invalid_argument("body '" + b.name +
                                "' is a slip wall: it must stay at rest (moving slip walls are "
                                "not supported)");
  b.velocity = std::move(u);
  set_wall_velocity_terms(b);
}

void LbmSolver::set_wall_function(int body, bool on) {
  if (body < 1 || body > body_count()) throw std::invalid_argument("unknown body id");
  Body& b = bodies_[std::size_t(body - 1)];
  if (on && (b.outlet_density > 0 || b.velocity))
    throw std::invalid_argument("the wall function applies to walls at rest; body '" + b.name +
                                "' is an outlet, an inlet or moving");
  if (on && b.slip > 0)
    throw std::invalid_argument("body '" + b.name +
                                "' is a slip wall; the wall function replaces no-slip walls only");
  b.wall_function = on;
  links_dirty_ = true;
}

void LbmSolver::set_wall_velocity_terms(Body& b) {
  lbm::set_wall_velocity(b.links, grid(), b.velocity, settings_.wall_density);
}

void LbmSolver::rebuild_links() {
  auto lists = build_links(flags_, body_count());
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    Body& b = bodies_[k];
    b.links = std::move(lists[k]);
    if (b.slip > 0)
      b.slip_links =
          split_slip_links(b.links, flags_, CellFlag(k + 1), b.slip_axis, b.slip_sign, b.slip);
    set_wall_velocity_terms(b);
    if (b.outlet_density > 0)
      b.outlet =
          build_outlet(b.links, flags_, b.outlet_density, b.outlet_extrapolate, b.outlet_backflow);
    b.wall_cells = b.wall_function ? build_wall_function_cells(b.links) : WallFunctionCells{};
  }
  // Runs in whole 64-byte vectors (the widest the kernels use): 16 cells in single, 8 in double.
  const int lanes = settings_.precision == Precision::float32 ? 16 : 8;
  runs_ = fluid_runs(grid(), flags_, lanes);
  bool any_wall_function = false;
  for (const Body& b : bodies_) any_wall_function = any_wall_function || b.wall_function;
  keep_moments_ = any_wall_function;
  with_lattice([&](auto& l) {
    using T = typename std::decay_t<decltype(l)>::value_type;
    for (auto& a : l.moments)
      if (any_wall_function)
        a.assign(std::size_t(grid().storage_cells()), T(0));
      else
        std::vector<T>().swap(a);
  });
  links_dirty_ = false;
}

void LbmSolver::initialize(
    const std::function<void(int x, int y, int z, double& rho, Vec3& u)>& init) {
  mass_pending_ = false;
  const Grid& g = grid();
  const double rho_w = settings_.wall_density;
  with_pdf([&](auto& pdf) {
    for (int q = 0; q < kQ; ++q)
      for (Index n = 0; n < pdf.stride(); ++n) pdf.set(q, n, kW[q] * rho_w);
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x) {
          const Index n = g.index(x, y, z);
          if (!flags_.fluid(n)) continue;
          double rho = 1.0;
          Vec3 u = Vec3::Zero();
          init(x, y, z, rho, u);
          const double inv_eps = has_porosity() ? 1.0 / eps_[std::size_t(n)] : 1.0;
          for (int q = 0; q < kQ; ++q)
            pdf.set(q, n, equilibrium(q, rho, u.x(), u.y(), u.z(), inv_eps));
        }
  });
  state_ = AaState::natural;
  initial_mass_ = total_mass();
  exchanged_mass_ = 0;
}

bool LbmSolver::has_force_field() const {
  return with_lattice([](const auto& l) { return !l.force[0].empty(); });
}

bool LbmSolver::has_velocity_sum() const {
  return with_lattice([](const auto& l) { return !l.u_sum[0].empty(); });
}

void LbmSolver::enable_force_field() {
  if (has_force_field()) return;
  with_lattice([&](auto& l) {
    for (auto& f : l.force) f.assign(std::size_t(grid().storage_cells()), 0);
  });
}

void LbmSolver::set_cell_force(int x, int y, int z, const Vec3& f) {
  if (!has_force_field()) throw std::logic_error("set_cell_force before enable_force_field");
  const auto n = std::size_t(grid().index(x, y, z));
  with_lattice([&](auto& l) {
    using T = typename std::decay_t<decltype(l)>::value_type;
    for (int a = 0; a < 3; ++a) l.force[std::size_t(a)][n] = T(f[a]);
  });
}

void LbmSolver::enable_porosity() {
  if (has_porosity()) return;
  eps_.assign(std::size_t(grid().storage_cells()), 1.0);
  with_lattice([&](auto& l) {
    l.inv_eps.assign(std::size_t(grid().storage_cells()), 1);
    l.alpha.assign(std::size_t(grid().storage_cells()), 0);
  });
}

void LbmSolver::set_cell_porosity(int x, int y, int z, double eps, double alpha) {
  if (!has_porosity()) throw std::logic_error("set_cell_porosity before enable_porosity");
  if (!(eps > 0 && eps <= 1))
    throw std::invalid_argument("fluid fraction must lie in (0, 1], got " + std::to_string(eps));
  if (!(alpha >= 0 && std::isfinite(alpha)))
    throw std::invalid_argument("Darcy rate must be >= 0, got " + std::to_string(alpha));
  const auto n = std::size_t(grid().index(x, y, z));
  eps_[n] = eps;
  with_lattice([&](auto& l) {
    using T = typename std::decay_t<decltype(l)>::value_type;
    l.inv_eps[n] = T(1.0 / eps);
    l.alpha[n] = T(alpha);
  });
}

void LbmSolver::enable_velocity_sum() {
  if (has_velocity_sum()) return;
  with_lattice([&](auto& l) {
    for (auto& a : l.u_sum) a.assign(std::size_t(grid().storage_cells()), 0);
  });
}

void LbmSolver::take_velocity_sum(std::vector<Vec3>& out) {
  velocity_sum(out);
  with_lattice([&](auto& l) {
    for (auto& a : l.u_sum) {
      const auto m = a.size();
#pragma omp parallel for schedule(static)
      for (std::size_t n = 0; n < m; ++n) a[n] = 0;
    }
  });
}

void LbmSolver::set_velocity_sum(std::span<const Vec3> sum) {
  const Grid& g = grid();
  if (sum.size() != std::size_t(g.cells()))
    throw std::invalid_argument("velocity sum: " + std::to_string(sum.size()) + " values for " +
                                std::to_string(g.cells()) + " cells");
  enable_velocity_sum();
  with_lattice([&](auto& l) {
    using T = typename std::decay_t<decltype(l)>::value_type;
    for_each_row(g, [&](int y, int z) {
      for (int x = 0; x < g.nx(); ++x) {
        const auto n = std::size_t(g.index(x, y, z));
        const Vec3& u = sum[std::size_t(g.compact_index(x, y, z))];
        for (int a = 0; a < 3; ++a)
          l.u_sum[std::size_t(a)][n] = flags_.fluid(Index(n)) ? T(u[a]) : T(0);
      }
    });
  });
}

void LbmSolver::velocity_sum(std::vector<Vec3>& out) const {
  const Grid& g = grid();
  out.resize(std::size_t(g.cells()));
  // Row by row on all threads (each entry written once): the exchange calls this on the whole
  // lattice, 0.2 s per millisecond of the jet mill's CG-8 case when serial.
  const bool summed = has_velocity_sum();
  with_lattice([&](const auto& l) {
    const auto& s = l.u_sum;
    for_each_row(g, [&](int y, int z) {
      for (int x = 0; x < g.nx(); ++x) {
        const auto n = std::size_t(g.index(x, y, z));
        const bool take = summed && flags_.fluid(Index(n));
        out[std::size_t(g.compact_index(x, y, z))] =
            take ? Vec3(double(s[0][n]), double(s[1][n]), double(s[2][n])) : Vec3(Vec3::Zero());
      }
    });
  });
}

void LbmSolver::set_porosity_field(std::span<const double> eps, std::span<const double> alpha) {
  const Grid& g = grid();
  if (eps.size() != std::size_t(g.cells()) || alpha.size() != std::size_t(g.cells()))
    throw std::invalid_argument("porosity field: " + std::to_string(eps.size()) + " and " +
                                std::to_string(alpha.size()) + " values for " +
                                std::to_string(g.cells()) + " cells");
  enable_porosity();
  // Row by row on all threads; a bad value throws the error of the first such cell in compact
  // order (the lowest row's, parallel_for.hpp), whatever the thread count.
  const int ny = g.ny();
  with_lattice([&](auto& l) {
    using T = typename std::decay_t<decltype(l)>::value_type;
    parallel_for(std::size_t(ny) * std::size_t(g.nz()), 1, [&](std::size_t r) {
      const int y = int(r % std::size_t(ny)), z = int(r / std::size_t(ny));
      for (int x = 0; x < g.nx(); ++x) {
        const Index n = g.index(x, y, z);
        if (!flags_.fluid(n)) continue;
        const auto c = std::size_t(g.compact_index(x, y, z));
        if (!(eps[c] > 0 && eps[c] <= 1) || !(alpha[c] >= 0 && std::isfinite(alpha[c])))
          throw std::invalid_argument(
              "porosity field at cell (" + std::to_string(x) + ", " + std::to_string(y) + ", " +
              std::to_string(z) + "): eps = " + std::to_string(eps[c]) +
              ", alpha = " + std::to_string(alpha[c]) + "; need 0 < eps <= 1, alpha >= 0");
        eps_[std::size_t(n)] = eps[c];
        l.inv_eps[std::size_t(n)] = T(1.0 / eps[c]);
        l.alpha[std::size_t(n)] = T(alpha[c]);
      }
    });
  });
}

void LbmSolver::set_force_field(std::span<const Vec3> force) {
  const Grid& g = grid();
  if (force.size() != std::size_t(g.cells()))
    throw std::invalid_argument("force field: " + std::to_string(force.size()) + " values for " +
                                std::to_string(g.cells()) + " cells");
  enable_force_field();
  with_lattice([&](auto& l) {
    using T = typename std::decay_t<decltype(l)>::value_type;
    for_each_row(g, [&](int y, int z) {
      for (int x = 0; x < g.nx(); ++x) {
        const auto n = std::size_t(g.index(x, y, z));
        const Vec3& f = force[std::size_t(g.compact_index(x, y, z))];
        for (int a = 0; a < 3; ++a) l.force[std::size_t(a)][n] = T(f[a]);
      }
    });
  });
}

void LbmSolver::set_forchheimer(double beta) {
  if (!(beta >= 0 && std::isfinite(beta)))
    throw std::invalid_argument("Forchheimer coefficient must be >= 0, got " +
                                std::to_string(beta));
  beta_ = beta;
}

void LbmSolver::porosity(std::vector<double>& eps) const {
  const Grid& g = grid();
  eps.assign(std::size_t(g.cells()), 0.0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        const Index n = g.index(x, y, z);
        if (flags_.fluid(n))
          eps[std::size_t(g.compact_index(x, y, z))] = has_porosity() ? eps_[std::size_t(n)] : 1.0;
      }
}

void LbmSolver::step() {
  PhaseLap lap;
  if (links_dirty_) rebuild_links();
  with_lattice([&](const auto& l) {
    with_forcing(l, [&](const auto& forcing) {
      for (Body& b : bodies_)
        if (b.outlet_density > 0)
          sample_outlet_velocity(l.pdf, state_, forcing, b.outlet,
                                 mass_pending_ ? mass_source_storage_.data() : nullptr);
    });
  });
  lap.to(Phase::lbm_boundaries);
  std::visit([&](const auto& op) { collide_pass(op); }, settings_.collision);
  lap.to(Phase::lbm_collide_stream);
  state_ = after_step(state_);
  const WernerWengle law{viscosity(settings_.collision)};
  for (Body& b : bodies_) b.previous_force = b.load.force;
  with_lattice([&](auto& l) {
    auto& pdf = l.pdf;
    const auto moments = l.moment_fields();
    for (Body& b : bodies_)
      b.load = b.outlet_density > 0
                   ? apply_anti_bounce_back(pdf, state_, b.links, b.outlet, b.origin)
               : b.wall_function ? apply_wall_function(pdf, state_, b.links, b.wall_cells, law,
                                                       moments, settings_.wall_density, b.origin)
                                 : apply_bounce_back(pdf, state_, b.links, b.origin);
    // Slip faces: the links with a specular partner (the rest bounced back above).
    for (Body& b : bodies_)
      if (b.slip > 0) b.load += apply_slip_links(pdf, state_, b.slip_links, b.origin);
  });
  add_mass_sources();
  for (const Body& b : bodies_) exchanged_mass_ += b.load.mass;  // bodies in a fixed order
  exchanged_mass_ += mass_source_rate();
  ++steps_;
  lap.to(Phase::lbm_boundaries);
}

void LbmSolver::set_mass_sources(std::vector<MassSource> sources) {
  const Grid& g = grid();
  for (const MassSource& m : sources) {
    const bool inside =
        m.x >= 0 && m.x < g.nx() && m.y >= 0 && m.y < g.ny() && m.z >= 0 && m.z < g.nz();
    if (!inside || !flags_.fluid(g.index(m.x, m.y, m.z)))
      throw std::invalid_argument("mass source at cell (" + std::to_string(m.x) + ", " +
                                  std::to_string(m.y) + ", " + std::to_string(m.z) +
                                  ") is not an interior fluid cell");
    if (!std::isfinite(m.mass))
      throw std::invalid_argument("mass source at cell (" + std::to_string(m.x) + ", " +
                                  std::to_string(m.y) + ", " + std::to_string(m.z) +
                                  ") has a non-finite mass");
  }
  mass_sources_ = std::move(sources);
}

void LbmSolver::set_mass_source_field(std::span<const double> mass) {
  const Grid& g = grid();
  if (!mass.empty() && mass.size() != std::size_t(g.cells()))
    throw std::invalid_argument("mass source field: " + std::to_string(mass.size()) +
                                " values for " + std::to_string(g.cells()) + " interior cells");
  for (int z = 0; z < g.nz() && !mass.empty(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        const double m = mass[std::size_t(g.compact_index(x, y, z))];
        if (std::isfinite(m) && (m == 0 || flags_.fluid(g.index(x, y, z)))) continue;
        throw std::invalid_argument("mass source field: cell (" + std::to_string(x) + ", " +
                                    std::to_string(y) + ", " + std::to_string(z) + ") " +
                                    (std::isfinite(m) ? "is solid" : "is not finite"));
      }
  settle_mass_sources();  // the pending step is the previous field's
  mass_source_field_.assign(mass.begin(), mass.end());
  mass_source_storage_.clear();
  if (!mass.empty()) {
    mass_source_storage_.assign(std::size_t(g.storage_cells()), 0.0);
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x)
          mass_source_storage_[std::size_t(g.index(x, y, z))] =
              mass[std::size_t(g.compact_index(x, y, z))];
  }
  mass_source_field_sum_ = deterministic_sum(
      mass_source_field_.size(), [&](std::size_t c) { return mass_source_field_[c]; }, 0.0);
}

double LbmSolver::mass_source_rate() const {
  double sum = 0;
  for (const MassSource& m : mass_sources_) sum += m.mass;
  return sum + mass_source_field_sum_;
}

void LbmSolver::add_mass_sources() {
  // The populations the next step reads (aa_pattern.hpp); the solver owns them, so the cast only
  // undoes read_pointers' const. A few cells: serial, in list order (deterministic).
  with_pdf([&](auto& pdf) {
    using T = typename std::decay_t<decltype(pdf)>::value_type;
    for (const MassSource& m : mass_sources_) {
      const T* in[kQ];
      read_pointers(pdf, state_, m.x, m.y, m.z, in);
      for (int q = 0; q < kQ; ++q) {
        T& slot = *const_cast<T*>(in[q]);
        slot = with_mass(slot, q, T(m.mass));
      }
    }
  });
  // The field's share waits for the next step's collision (or settle_mass_sources()).
  mass_pending_ = !mass_source_field_.empty();
}

void LbmSolver::settle_mass_sources() const {
  if (!mass_pending_) return;
  // The populations as the next step reads them are the solver's state, which a reader of it
  // brings up to date: the pass changes no observable value.
  const_cast<LbmSolver*>(this)->add_mass_source_field();
}

void LbmSolver::add_mass_source_field() {
  mass_pending_ = false;
  // Each cell writes only its own populations, so the rows go to the threads. Row by row with one
  // set of addresses per x range (aa_pattern.hpp), direction by direction along x so that the
  // update runs in vector lanes, trimmed to the range's first and last source (rows away from the
  // particles hold none).
  const Grid& g = grid();
  const double* mass = mass_source_storage_.data();
  with_pdf([&](auto& pdf) {
    using T = typename std::decay_t<decltype(pdf)>::value_type;
    for_each_row(g, [&](int y, int z) {
      for_each_x_range(g, [&](int x0, int x1) {
        const double* m = mass + g.index(x0, y, z);
        int lo = 0, hi = x1 - x0;
        while (lo < hi && m[lo] == 0) ++lo;
        while (hi > lo && m[hi - 1] == 0) --hi;
        if (lo == hi) return;
        const T* in[kQ];
        read_pointers(pdf, state_, x0, y, z, in);
        for (int q = 0; q < kQ; ++q) {
          T* const slot = const_cast<T*>(in[q]);
#pragma omp simd
          for (int i = lo; i < hi; ++i) slot[i] = with_mass(slot[i], q, T(m[i]));
        }
      });
    });
  });
}

std::vector<double> LbmSolver::level_flux(std::span<const int> level, int levels) const {
  settle_mass_sources();
  std::vector<AddedMass> added;
  added.reserve(mass_sources_.size());
  for (const MassSource& m : mass_sources_) added.push_back({grid().index(m.x, m.y, m.z), m.mass});
  const Grid& g = grid();
  for (int z = 0; z < g.nz() && !mass_source_field_.empty(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        if (const double m = mass_source_field_[std::size_t(g.compact_index(x, y, z))]; m != 0)
          added.push_back({g.index(x, y, z), m});
  return with_pdf(
      [&](const auto& pdf) { return lbm::level_flux(pdf, state_, flags_, level, levels, added); });
}

void LbmSolver::cell_populations(int x, int y, int z, double (&f)[kQ]) const {
  settle_mass_sources();
  with_pdf([&](const auto& pdf) {
    using T = typename std::decay_t<decltype(pdf)>::value_type;
    const T* in[kQ];
    read_pointers(pdf, state_, x, y, z, in);
    for (int q = 0; q < kQ; ++q) f[q] = PopulationCodec<T>::load(*in[q], q);
  });
}

std::vector<double> LbmSolver::stored_slots() const {
  settle_mass_sources();
  return with_pdf(
      [](const auto& pdf) { return std::vector<double>(pdf.data(), pdf.data() + pdf.size()); });
}

void LbmSolver::load_state(const std::vector<double>& slots, AaState s, long steps) {
  mass_pending_ = false;  // the slots are the state the next step reads
  with_pdf([&](auto& pdf) {
    using T = typename std::decay_t<decltype(pdf)>::value_type;
    if (Index(slots.size()) != pdf.size())
      throw std::invalid_argument("checkpoint holds " + std::to_string(slots.size()) +
                                  " populations, this lattice " + std::to_string(pdf.size()));
    std::transform(slots.begin(), slots.end(), pdf.data(), [](double v) { return T(v); });
  });
  state_ = s;
  steps_ = steps;
}

std::optional<UnhealthyCell> LbmSolver::find_unhealthy(double rho_min, double rho_max,
                                                       double u_max) const {
  settle_mass_sources();
  const Grid& g = grid();
  // First bad x of every row (-1: none); rows are independent, so any thread split finds the same.
  std::vector<int> first_bad(std::size_t(g.ny()) * std::size_t(g.nz()), -1);
  with_lattice([&](const auto& l) {
    const auto& pdf = l.pdf;
    with_forcing(l, [&](const auto& forcing) {
      for_each_row(g, [&](int y, int z) {
        for (int x = 0; x < g.nx(); ++x) {
          if (!flags_.fluid(g.index(x, y, z))) continue;
          const CellMoments m = cell_moments_at(pdf, state_, forcing, x, y, z);
          const double u2 = m.ux * m.ux + m.uy * m.uy + m.uz * m.uz;
          // Written so that NaN fails every comparison and lands here.
          if (!(m.rho >= rho_min && m.rho <= rho_max && u2 <= u_max * u_max)) {
            first_bad[std::size_t(y) + std::size_t(g.ny()) * std::size_t(z)] = x;
            return;
          }
        }
      });
    });
  });
  for (std::size_t r = 0; r < first_bad.size(); ++r) {
    if (first_bad[r] < 0) continue;
    const int x = first_bad[r], y = int(r % std::size_t(g.ny())), z = int(r / std::size_t(g.ny()));
    const CellMoments m = moments(x, y, z);
    return UnhealthyCell{x, y, z, m.rho, std::sqrt(m.ux * m.ux + m.uy * m.uy + m.uz * m.uz)};
  }
  return std::nullopt;
}

CellMoments LbmSolver::moments(int x, int y, int z) const {
  settle_mass_sources();
  CellMoments m{};
  with_lattice([&](const auto& l) {
    with_forcing(
        l, [&](const auto& forcing) { m = cell_moments_at(l.pdf, state_, forcing, x, y, z); });
  });
  return m;
}

void LbmSolver::density(std::vector<double>& rho) const {
  settle_mass_sources();
  // rho = sum_q f_q whatever the force (cell.hpp): the forcing policy's moments would only add
  // the velocity's work.
  with_pdf([&](const auto& pdf) { moment_fields(pdf, state_, NoForce{}, flags_, &rho, nullptr); });
}

void LbmSolver::velocity(std::vector<Vec3>& u) const {
  settle_mass_sources();
  with_lattice([&](const auto& l) {
    with_forcing(l, [&](const auto& f) { moment_fields(l.pdf, state_, f, flags_, nullptr, &u); });
  });
}

void LbmSolver::raw_velocity(std::vector<Vec3>& u) const {
  settle_mass_sources();
  with_pdf([&](const auto& pdf) { moment_fields(pdf, state_, NoForce{}, flags_, nullptr, &u); });
}

void LbmSolver::raw_moments(std::vector<double>& rho, std::vector<Vec3>& u) const {
  settle_mass_sources();
  with_pdf([&](const auto& pdf) { moment_fields(pdf, state_, NoForce{}, flags_, &rho, &u); });
}

Vec3 LbmSolver::raw_momentum() const {
  settle_mass_sources();
  // NoForce moments: rho u = sum_q c_q f_q, with no half-force shift and no porous scaling.
  std::vector<double> rho;
  std::vector<Vec3> u;
  raw_moments(rho, u);
  return deterministic_sum(
      rho.size(), [&](std::size_t i) { return Vec3(rho[i] * u[i]); }, Vec3(Vec3::Zero()));
}

double LbmSolver::total_mass() const {
  settle_mass_sources();
  std::vector<double> rho;
  density(rho);
  return lbm::total_mass(rho);
}

}  // namespace lbdem::lbm
