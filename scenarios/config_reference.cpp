#include "scenarios/config_reference.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "scenarios/run_command.hpp"

namespace lbdem::scenarios {

namespace {

// '*' matches any run of characters other than '.'.
bool matches(std::string_view pattern, std::string_view path) {
  if (pattern.empty()) return path.empty();
  if (pattern.front() == '*') {
    for (std::size_t k = 0; k <= path.size(); ++k) {
      if (matches(pattern.substr(1), path.substr(k))) return true;
      if (k < path.size() && path[k] == '.') break;
    }
    return false;
  }
  return !path.empty() && pattern.front() == path.front() &&
         matches(pattern.substr(1), path.substr(1));
}

const KeyDoc* doc_of(const std::string& path) {
  for (const KeyDoc& d : key_docs())
    if (matches(d.pattern, path)) return &d;
  return nullptr;
}

// What decides which keys the readers ask for: the paths a preset sets, with the text of its
// string and boolean values (contact.normal, inflow.enabled select other readers); numbers do
// not. Presets with the same signature read the same keys, so the collection reads one of them:
// the jet mill's and the fluidized bed's series differ only in numbers.
void add_signature(const toml::node& n, const std::string& path, std::string& out) {
  if (const auto* t = n.as_table()) {
    for (const auto& [k, v] : *t)
      add_signature(v, path.empty() ? std::string(k.str()) : path + "." + std::string(k.str()),
                    out);
  } else if (const auto* a = n.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i)
      add_signature(*a->get(i), path + "[" + std::to_string(i) + "]", out);
  } else {
    out += path;
    if (const auto* str = n.as_string()) out += "=" + str->get();
    if (const auto* b = n.as_boolean()) out += b->get() ? "=true" : "=false";
    out += "\n";
  }
}

// The probe configs (scenarios/config_reference/README.md) and the mark in them that stands for
// the source tree.
constexpr std::string_view kProbeDir = "scenarios/config_reference";
constexpr std::string_view kSourceDirMark = "@LBDEM_SOURCE_DIR@";

std::vector<std::string> toml_files(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string read_text(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "", "cannot read the file", "check the source tree");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string cell(std::string s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::map<std::string, ReferenceKey> collect_keys(const std::string& source_dir) {
  namespace fs = std::filesystem;
  const std::vector<std::string> names = scenario_names();
  // What each scenario reads: its presets, then the probes that name it.
  struct Input {
    std::string file, text;
    bool probe = false;
  };
  std::map<std::string, std::vector<Input>> inputs;
  for (const std::string& name : names) {
    std::vector<std::string> files = toml_files(source_dir + "/scenarios/" + name + "/presets");
    // A preset based on another (base = FILE) is read as it resolves.
    for (const std::string& file : files)
      inputs[name].push_back({file, Config::from_file(file).resolved_toml(), false});
    // Of presets that read the same keys the first is read: the one on the coarsest gas grid,
    // which builds fastest (the jet mill's paper-scale grids take seconds).
    const auto dx = [](const Input& in) {
      return toml::parse(in.text, in.file)["fluid"]["dx"].value_or(0.0);
    };
    std::stable_sort(inputs[name].begin(), inputs[name].end(),
                     [&](const Input& a, const Input& b) { return dx(a) > dx(b); });
  }
  const std::string probe_dir = source_dir + "/" + std::string(kProbeDir);
  for (const std::string& file : toml_files(probe_dir)) {
    std::string text = read_text(file);
    for (std::size_t at; (at = text.find(kSourceDirMark)) != std::string::npos;)
      text.replace(at, kSourceDirMark.size(), source_dir);
    const toml::table t = toml::parse(text, file);
    const toml::array* to = t["probe_for"].as_array();
    if (!to || to->empty())
      throw InputError(file, "", "a probe without probe_for",
                       "name the scenarios it is read as: probe_for = [\"box\", ...]");
    for (const auto& n : *to) {
      const std::string name = n.value_or(std::string());
      if (std::find(names.begin(), names.end(), name) == names.end())
        throw InputError(file, name, "probe_for names no scenario",
                         "name scenarios of ./lbdem run --list");
      inputs[name].push_back({file, text, true});
    }
  }
  std::map<std::string, ReferenceKey> keys;
  for (const std::string& name : names) {
    std::set<std::string> seen;
    for (const Input& in : inputs[name]) {
      std::string signature;
      add_signature(toml::parse(in.text, in.file), "", signature);
      if (!seen.insert(signature).second) continue;
      Config cfg = Config::from_string(in.text, in.file);
      if (in.probe) cfg.erase("probe_for");
      try {
        read_as_scenario(name, cfg);
      } catch (const InputError& e) {
        throw InputError(in.file, "",
                         std::string(in.probe ? "probe" : "preset") + " does not read as " + name +
                             ": " + e.what(),
                         in.probe ? "correct the probe" : "correct the preset");
      }
      for (const auto& [path, info] : cfg.read_keys()) {
        auto [it, fresh] = keys.try_emplace(path, ReferenceKey{info, {}, false});
        ReferenceKey& k = it->second;
        if (!fresh) {
          k.default_varies |=
              !info.required && !k.info.required && info.default_text != k.info.default_text;
          k.info.required |= info.required;
          if (k.info.range_text.empty()) k.info.range_text = info.range_text;
          if (k.info.choices.empty()) k.info.choices = info.choices;
          if (info.type == "choice" || info.type == "vector") k.info.type = info.type;
        }
        k.scenarios.insert(name);
      }
    }
  }
  return keys;
}

std::vector<std::string> unread_docs(const std::map<std::string, ReferenceKey>& keys) {
  std::vector<std::string> out;
  for (const KeyDoc& d : key_docs()) {
    bool read = false;
    for (const auto& [path, k] : keys) read = read || doc_of(path) == &d;
    if (!read) out.emplace_back(d.pattern);
  }
  return out;
}

std::string reference_markdown(const std::map<std::string, ReferenceKey>& keys,
                               std::vector<std::string>& undocumented) {
  const std::size_t all = scenario_names().size();
  std::string md =
      "# Configuration reference\n\n"
      "Generated by `build/bin/lbdem-cli config > docs/config.md` from the code: type, default "
      "and allowed\nrange are what the readers use, collected by reading every preset in "
      "`scenarios/<name>/presets/` and\nthe probe configs in `scenarios/config_reference/`, which "
      "set the keys no preset needs; unit\nand meaning come from "
      "`scenarios/config_reference.cpp`. A test fails when this file differs from\nwhat the "
      "command prints, a key has no meaning or a meaning no key; edit the code, not this\nfile. "
      "How the tables fit together, with examples: "
      "[user-guide.md](user-guide.md#configuration).\n\n"
      "A path `fill.radius.kind` is the key `kind` in the table `radius` of each `[[fill]]` "
      "entry. \"required\"\nkeys must be given where the table is used; \"depends\" defaults are "
      "computed from other keys\n(the meaning says how). Every scenario reads the keys it lists "
      "and refuses any other.\n";
  std::string table;
  for (const auto& [path, k] : keys) {
    const std::string top = path.substr(0, path.find('.'));
    if (top != table) {
      table = top;
      md += "\n## " +
            (path.find('.') == std::string::npos ? std::string("top level") : "`" + top + "`") +
            "\n\n| key | type | default | allowed | unit | scenarios | meaning |\n"
            "| --- | --- | --- | --- | --- | --- | --- |\n";
    }
    const KeyDoc* d = doc_of(path);
    if (!d) undocumented.push_back(path);
    // A default computed from other keys is described by the table, in words.
    const bool described = !k.info.required && d && !d->default_text.empty();
    const std::string def = k.info.required    ? "required"
                            : described        ? std::string(d->default_text)
                            : k.default_varies ? "depends"
                                               : "`" + k.info.default_text + "`";
    std::string allowed = k.info.range_text;
    for (const auto& c : k.info.choices) allowed += (allowed.empty() ? "" : ", ") + ("`" + c + "`");
    std::string where;
    if (k.scenarios.size() == all)
      where = "all";
    else
      for (const auto& s : k.scenarios) where += (where.empty() ? "" : ", ") + s;
    md += "| `" + path + "` | " + k.info.type + " | " + cell(def) + " | " + cell(allowed) + " | " +
          (d ? cell(std::string(d->unit)) : "") + " | " + where + " | " +
          (d ? cell(std::string(d->meaning)) : "(undocumented)") + " |\n";
  }
  return md;
}

int print_config_reference() {
  std::vector<std::string> undocumented;
  const auto keys = collect_keys(LBDEM_SOURCE_DIR);
  std::cout << reference_markdown(keys, undocumented);
  for (const auto& k : undocumented)
    std::cerr << "lbdem: warning: config key " << k
              << " has no unit and meaning in scenarios/config_reference.cpp\n";
  const std::vector<std::string> unread = unread_docs(keys);
  for (const auto& p : unread)
    std::cerr << "lbdem: warning: no preset or probe reads a key of the pattern " << p
              << " (scenarios/config_reference.cpp; probes: scenarios/config_reference/)\n";
  return undocumented.empty() && unread.empty() ? 0 : 1;
}

const std::vector<KeyDoc>& key_docs() {
  // Unit and meaning by path pattern (the first match wins); the default column, where given,
  // describes a default computed from other keys.
  static const std::vector<KeyDoc> table = {
      {"scenario", "",
       "the scenario this file is for; `run --config FILE` needs no scenario name, and a file for "
       "another scenario is refused",
       "the command's scenario"},
      {"run.end_time", "s",
       "simulated end time; on resume it may be raised to extend a finished run"},
      {"run.seed", "", "seed of the random insertion (fills, inflow, the rheometer's jitter)"},
      {"run.phase_timers", "",
       "time each phase of the step and print the table at the end of log.txt"},
      {"output.interval", "s", "time between time-series rows", "end_time / 200"},
      {"output.snapshot_interval", "s", "time between particle (and gas) snapshots",
       "end_time / 10"},
      {"output.checkpoint_interval", "s",
       "simulated time between checkpoints; \"never\": none but at the start, the end and a "
       "signal stop (warned about; output.checkpoint_wall_interval is then off too)",
       "end_time / 4"},
      {"output.checkpoint_wall_interval", "s",
       "wall time of stepping (suspensions left out) after which a checkpoint is written anyway; "
       "a run killed outright loses at most this much work, or one checkpoint_interval if that "
       "is shorter; \"never\": by simulated time only",
       "900"},
      {"output.collisions.rows", "",
       "write one row per contact to collisions.h5 (large: a dense bed makes about 1e8 contacts in "
       "a few hundredths of a second)"},
      {"output.collisions.rows_start", "s", "first time at which contact rows are written"},
      {"output.collisions.rows_end", "s", "last time at which contact rows are written", "never"},
      {"output.collisions.row_budget", "", "most contact rows kept"},
      {"output.collisions.grid_cells", "",
       "cells per axis of the spatial collision grid in collisions.h5"},
      {"physics.gravity", "m/s^2", "gravitational acceleration"},
      {"box.lo", "m",
       "lower corner of the particle domain; the gas grid is centred on the box (where an edge is "
       "not whole cells, its corner lies within dx/4 of this)"},
      {"box.hi", "m",
       "upper corner of the particle domain; the gas grid is centred on the box (where an edge is "
       "not whole cells, its corner lies within dx/4 of this)"},
      {"box.*_lo", "",
       "lower face along that axis for the particles: a wall, periodic (in pairs) or open "
       "(particles leave)"},
      {"box.*_hi", "",
       "upper face along that axis for the particles: a wall, periodic (in pairs) or open "
       "(particles leave)"},
      {"box.wall_material", "", "material of the box walls, by name", "the first material"},
      {"materials.name", "", "name by which fills, walls and particles refer to this material",
       "material<index>"},
      {"materials.density", "kg/m^3", "solid density"},
      {"materials.youngs_modulus", "Pa", "Young's modulus (Hertz-Mindlin)"},
      {"materials.poisson_ratio", "", "Poisson's ratio (Hertz-Mindlin)"},
      {"materials.stiffness", "N/m", "normal spring stiffness (linear law)"},
      {"materials.restitution", "", "normal coefficient of restitution of a pair of this material"},
      {"materials.friction", "", "sliding (Coulomb) friction coefficient"},
      {"materials.rolling_friction", "", "rolling friction coefficient mu_r"},
      {"materials.hamaker", "J", "Hamaker constant for van der Waals cohesion"},
      {"contact.normal", "",
       "normal contact law: linear spring-dashpot or Hertz-Mindlin with Tsuji damping"},
      {"contact.rolling", "",
       "rolling resistance: none, constant torque or elastic-plastic spring-dashpot (EPSD)"},
      {"contact.cohesion", "", "cohesion between particles: none or van der Waals"},
      {"contact.rolling_arm_factor", "",
       "rolling torque arm as a multiple of the reduced radius R* (MercuryDPM uses 2)"},
      {"contact.tangential_stiffness_ratio", "", "k_t / k_n of the linear law"},
      {"contact.tangential_damping", "",
       "damp the tangential spring with the normal damping ratio"},
      {"contact.h_min", "m",
       "van der Waals: smallest surface separation (the force is clamped there)"},
      {"contact.h_max", "m", "van der Waals: cut-off separation beyond which the force is zero"},
      {"dem.dt", "s",
       "DEM time step (of the original particles under coarse graining); refused above t_c/20 "
       "unless force_dt",
       "t_c / steps_per_contact"},
      {"dem.steps_per_contact", "", "time steps per contact time when dt is not given"},
      {"dem.impact_speed", "m/s", "impact speed at which the Hertz contact time is evaluated"},
      {"dem.force_dt", "", "accept a dt above t_c/20 (with a warning)"},
      {"dem.max_speed_factor", "",
       "the DEM watchdog stops a run when a particle is this many times faster than the largest "
       "expected speed (the banner prints the limit)"},
      {"dem.max_energy_error", "",
       "the DEM watchdog stops a run when the energy-balance error exceeds this fraction of the "
       "energy moved (kinetic, elastic, dissipated and sources)"},
      {"dem.skin", "m", "neighbour-list skin", "0.2 x the smallest radius (rheometer: 0.4 x)"},
      {"dem.sort_every", "",
       "neighbour-list rebuilds between spatial sorts of the particles (0: never)"},
      {"fill.lo", "m", "lower corner of the fill region", "box.lo"},
      {"fill.hi", "m", "upper corner of the fill region", "box.hi"},
      {"fill.count", "", "particles (parcels under coarse graining) to insert; 0: use mass"},
      {"fill.mass", "kg", "mass to insert; kept under coarse graining"},
      {"fill.material", "", "material of the inserted particles, by name", "the first material"},
      {"fill.velocity", "m/s", "initial velocity of the inserted particles"},
      {"*.radius.kind", "", "radius distribution: fixed, uniform in [min, max] or lognormal"},
      {"*.radius.radius", "m", "the radius of a fixed distribution"},
      {"*.radius.min", "m", "smallest radius (uniform, lognormal)"},
      {"*.radius.max", "m", "largest radius (uniform, lognormal)"},
      {"*.radius.median", "m", "median radius (lognormal)"},
      {"*.radius.sigma", "", "standard deviation of ln r (lognormal)"},
      {"particle.position", "m", "centre of an explicitly placed particle"},
      {"particle.velocity", "m/s", "its initial velocity"},
      {"particle.angular_velocity", "rad/s", "its initial angular velocity"},
      {"particle.radius", "m", "its radius (of the original under coarse graining)"},
      {"particle.material", "", "its material, by name", "the first material"},
      {"walls.kind", "",
       "wall shape: an infinite plane, a cylinder, a cuboid or an STL triangle mesh"},
      {"walls.name", "", "name of the wall's time-series columns (wall_<name>_*)", "the kind"},
      {"walls.material", "", "the wall's material, by name", "the first material"},
      {"walls.point", "m", "plane: a point on it"},
      {"walls.normal", "", "plane: its normal, pointing to the particles' side"},
      {"walls.velocity", "m/s", "velocity of a moving plane, box or mesh wall"},
      {"walls.hole_radius", "m", "plane: radius of a round hole particles pass through (0: none)"},
      {"walls.hole_centre", "m", "plane: centre of the hole (projected onto the plane)",
       "walls.point"},
      {"walls.origin", "m", "cylinder: a point on its axis"},
      {"walls.axis", "", "cylinder: its axis; box and mesh: the rotation axis"},
      {"walls.radius", "m", "cylinder: its radius"},
      {"walls.inside", "", "cylinder: the particles are inside it"},
      {"walls.rpm", "1/min", "rotation speed about the axis (cylinder, box, mesh)"},
      {"walls.axial_min", "m", "cylinder: lower end along the axis from origin", "unbounded"},
      {"walls.axial_max", "m", "cylinder: upper end along the axis from origin", "unbounded"},
      {"walls.center", "m", "box: its centre"},
      {"walls.size", "m", "box: its three edge lengths"},
      {"walls.x_axis", "", "box: direction of its first edge"},
      {"walls.y_axis", "", "box: direction of its second edge"},
      {"walls.file", "", "stl: path of the triangle mesh"},
      {"walls.scale", "", "stl: factor from file units to m (1e-3 for mm)"},
      {"walls.translate", "m", "stl: shift applied after scaling"},
      {"walls.axis_point", "m", "box and mesh: a point on the rotation axis"},
      {"walls.start", "s", "box and mesh: time the rotation starts"},
      {"walls.ramp", "s", "box and mesh: time over which the rotation reaches rpm"},
      {"inflow.enabled", "",
       "insert particles continuously (the other inflow keys are read only when true)"},
      {"inflow.lo", "m", "lower corner of the insertion region"},
      {"inflow.hi", "m", "upper corner of the insertion region"},
      {"inflow.mass_rate", "kg/s", "mass inserted per second"},
      {"inflow.start", "s", "time insertion starts"},
      {"inflow.end", "s",
       "time insertion stops; mass still owed follows at the next insertion steps", "never"},
      {"inflow.insert_interval", "s", "time between insertion steps"},
      {"inflow.material", "", "material of the inserted particles, by name", "the first material"},
      {"inflow.velocity", "m/s", "initial velocity of the inserted particles"},
      {"outlet.enabled", "", "remove particles whose centre enters a region"},
      {"outlet.lo", "m", "lower corner of the outlet region"},
      {"outlet.hi", "m", "upper corner of the outlet region"},
      {"outlet.check_every", "", "steps between outlet checks"},
      {"fluid.density", "kg/m^3", "gas density"},
      {"fluid.viscosity", "Pa s", "dynamic viscosity of the gas"},
      {"fluid.dx", "m",
       "lattice cell edge; a periodic box edge must be a whole number of cells, any other edge L "
       "gets round(L/dx) cells centred on it (gas walls within dx/4 of the particles')"},
      {"fluid.dt", "s", "gas time step (not with lattice_velocity)",
       "lattice_velocity dx / max_speed"},
      {"fluid.lattice_velocity", "", "lattice velocity of max_speed when dt is not given"},
      {"fluid.max_speed", "m/s", "largest gas speed expected; sizes the step and the Mach checks"},
      {"fluid.pressure_difference", "Pa",
       "largest static pressure difference in the box; checked against the step",
       "from the body force, walls and outlets"},
      {"fluid.collision", "", "collision operator: BGK, TRT or regularized LES (Smagorinsky)"},
      {"fluid.magic", "", "TRT magic parameter Lambda (3/16 puts half-way walls exactly)"},
      {"fluid.smagorinsky", "", "Smagorinsky constant C_s of the LES operator"},
      {"fluid.wall_function", "",
       "Werner-Wengle law of the wall on walls at rest (LES with a coarse first cell)"},
      {"fluid.precision", "",
       "single: populations, per-cell fields and arithmetic of the gas in float (half the bytes)"},
      {"fluid.body_force", "N/m^3", "body force on the gas per volume"},
      {"fluid.gravity", "", "apply physics.gravity to the gas as well"},
      {"fluid.initial_velocity", "m/s", "uniform gas velocity at the start"},
      {"fluid.faces.*", "",
       "gas face given by name: wall (no slip), free_slip or periodic; a moving_wall, inlet or "
       "outlet needs its values and is given as a table (the face's keys below)",
       "periodic where the box face is, else wall"},
      {"fluid.faces.*.kind", "",
       "kind of a gas face given as a table {kind = ..., ...} instead of a name: wall takes "
       "slip_length, moving_wall velocity, inlet velocity and the ramp, outlet pressure and "
       "backflow"},
      {"fluid.faces.*.slip_length", "m",
       "wall: Navier slip length b, the wall's tangential gas velocity is b du/dn (exact for TRT "
       "at magic 3/16); 0 no slip; for free slip make the face \"free_slip\""},
      {"fluid.faces.*.velocity", "m/s",
       "moving_wall: the wall's velocity, in its plane; inlet: the inflow velocity, into the box"},
      {"fluid.faces.*.pressure", "Pa", "outlet: gauge pressure"},
      {"fluid.faces.*.backflow", "",
       "outlet: gas may also enter through it; false bounces back the links of a cell with "
       "inflow, for an outlet that vortices cross (a bed's erupting bubbles, a swirl)"},
      {"fluid.faces.*.ramp_start", "s", "inlet: time the ramp from ramp_from to velocity starts"},
      {"fluid.faces.*.ramp_time", "s", "inlet: duration of the linear ramp"},
      {"fluid.faces.*.ramp_from", "m/s",
       "inlet: velocity before the ramp (a multiple of velocity)"},
      {"coupling.two_way", "", "the particles' drag acts back on the gas"},
      {"coupling.drag", "", "drag law"},
      {"coupling.kernel_width", "m",
       "width of the smoothing kernel for deposition and interpolation",
       "max(dx, 2 D), D the largest parcel diameter"},
      {"coupling.eps_min", "",
       "smallest gas fraction the gas sees (denser cells are clipped, and the log says so)"},
      {"coupling.pressure_gradient", "",
       "apply -V_p grad p to the particles and its reaction to the gas"},
      {"coupling.exchange_every", "", "coupling cycles per momentum exchange"},
      {"coupling.displaced_gas", "",
       "d(eps)/dt in the gas continuity equation: moving particles push their gas out (two-way)"},
      {"coarse_grain.size_factor", "", "parcel radius / original radius l"},
      {"coarse_grain.particles_per_parcel", "",
       "originals per parcel l^3 (instead of size_factor)"},
      {"coarse_grain.rule", "",
       "contact scaling rule; hertz needs contact.normal = hertz_mindlin, the others linear"},
      {"coarse_grain.cohesion", "",
       "cohesion scaling: keep the Bond number, keep the tensile strength, or none"},
      {"coarse_grain.scale_dt", "", "multiply a given dem.dt by l for the parcels"},
      {"bed.height_fraction", "", "the bed height holds this fraction of the particle volume"},
      {"bed.pressure_taps", "m", "the two heights between which the pressure drop is measured",
       "the distributor and the outlet"},
      {"rheometer.cup_radius", "m", "inner radius of the cup"},
      {"rheometer.cup_height", "m", "height of the cup"},
      {"rheometer.blade_span", "m", "tip-to-tip span of the two blades"},
      {"rheometer.blade_height", "m", "height of a blade"},
      {"rheometer.blade_thickness", "m", "thickness of a blade"},
      {"rheometer.blade_bottom", "m", "height of the blades' lower edge above the floor"},
      {"rheometer.shaft_width", "m", "edge of the square shaft"},
      {"rheometer.impeller", "", "impeller as triangle meshes or as analytic cuboids"},
      {"rheometer.rpm", "1/min", "impeller speed"},
      {"rheometer.start", "s", "time the impeller starts"},
      {"rheometer.ramp", "s", "time over which it reaches rpm"},
      {"rheometer.fill_mass", "kg", "powder mass in the cup"},
      {"rheometer.wall_material", "", "material of cup and impeller, by name", "the powder's"},
      {"particles.material", "", "material of the powder, by name", "the first material"},
      {"jet_mill.outlet_radius", "m", "radius of the vortex finder", "0.2 x chamber radius"},
      {"jet_mill.chamber_stl", "",
       "path of a closed STL surface around the gas, for another chamber shape than the box's "
       "inscribed cylinder (not with a classifier ring)",
       "the cylinder"},
      {"jet_mill.chamber_stl_scale", "", "factor from the STL's units to m (1e-3 for mm)"},
      {"jet_mill.classifier.radius", "m",
       "mean radius of a classifier ring hanging from the top plate between the outlet and the "
       "grinding zone (the ring is there when [jet_mill.classifier] is; not with chamber_stl)"},
      {"jet_mill.classifier.thickness", "m", "wall thickness of the ring (at least sqrt(2) cells)",
       "1.5 dx"},
      {"jet_mill.classifier.height", "m", "how far the ring reaches below the top plate"},
      {"jet_mill.feed.position_deg", "degree",
       "feed injector: azimuth on the wall, counter-clockwise from +x",
       "between the first two grinding nozzles"},
      {"jet_mill.feed.source_speed", "m/s",
       "feed injector: speed its notional source is sized for (at most fluid.max_speed)",
       "jet_mill.nozzles.source_speed"},
      {"jet_mill.*.count", "", "number of grinding nozzles, equally spaced"},
      {"jet_mill.*.angle_deg", "degree", "nozzle angle to the wall tangent"},
      {"jet_mill.*.first_deg", "degree", "azimuth of the first nozzle (counter-clockwise from +x)"},
      {"jet_mill.*.height", "m", "height of the nozzle axis above the floor", "mid-height"},
      {"jet_mill.*.diameter", "m", "nozzle exit diameter"},
      {"jet_mill.*.speed", "m/s",
       "jet exit speed of an incompressible jet (not with supply_pressure)"},
      {"jet_mill.*.mass_flow", "kg/s", "jet mass flow (with speed)", "rho U pi d^2 / 4"},
      {"jet_mill.*.supply_pressure", "Pa",
       "absolute supply pressure of an ideal convergent nozzle (instead of speed and mass_flow)"},
      {"jet_mill.*.supply_temperature", "K", "supply temperature (with supply_pressure)"},
      {"jet_mill.*.ambient_pressure", "Pa",
       "absolute pressure in the chamber (with supply_pressure)"},
      {"jet_mill.*.source_speed", "m/s",
       "speed the notional source is sized for (at most fluid.max_speed)", "fluid.max_speed"},
  };
  return table;
}

}  // namespace lbdem::scenarios
