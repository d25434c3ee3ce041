#pragma once
// The spiral jet mill's gas geometry (docs/physics.md, Jet model; Scott, Borissova, Di Renzo &
// Ghadiri): a flat cylindrical chamber with grinding nozzles on its wall and a central outlet
// (vortex finder) through the top plate, all in SI, and the jets' sources on the lattice.
//
// Jet model (notional nozzle with mass and momentum sources). Real grinding nozzles are choked and
// their jets under-expanded and supersonic; a weakly compressible LBM holds lattice speeds of about
// 0.1 only. Each jet is therefore given by what drives the mill, its mass flow mdot and momentum
// flux J = mdot U (U: the exit speed of the preset or, from a supply pressure, the speed J / mdot
// that carries a real nozzle's thrust: nozzle_flow.hpp), and both enter the gas exactly, whatever
// the grid:
//   - mass: mdot dt per gas step, as resting gas (lbm::LbmSolver::set_mass_sources),
//   - momentum: a force density whose integral is J (the lattice's Guo forcing),
// spread over a notional source, a cylinder on the nozzle axis from the exit at the wall, of radius
//   r_s = max(d/2, sqrt(J / (pi rho U_cap^2)))
// and length 2 r_s, U_cap the gas speed the time step was set for (fluid.max_speed) unless
// jet_mill.nozzles.source_speed gives a lower one: a jet with the
// same momentum flux at the speed the lattice can carry (the pseudo-diameter idea: Birch et al.
// 1984, Combust. Sci. Technol. 36, 249, and Ewan & Moodie 1986, ibid. 45, 275, conserve the mass of
// an under-expanded jet across its shock cells; Birch, Hughes & Swaffield 1987, ibid. 52, 161, its
// mass and momentum, as here). Beyond a few diameters a turbulent
// jet depends on J alone (momentum-conserving self-similar jet: Pope, Turbulent Flows, §5.1), and
// the mill's vortex on the jets' angular momentum J R cos(angle) and on mdot (its radial outflow).
// Limits: the jet's core (a few nozzle diameters) is wider and slower than the real one, so
// particles entrained close to the nozzle see a lower peak speed than in a compressible solver;
// the gas density is uniform (no expansion cooling); the source's cells are weighted by the part
// of each cell (4^3 samples) that lies in the notional cylinder and in the chamber, normalised to
// 1 per nozzle, so the injected mass and momentum are exact on any grid.
#include "core/config.hpp"
#include "core/stl.hpp"
#include "core/types.hpp"
#include "lbm/lbm_solver.hpp"
#include "lbm/units.hpp"

#include <string>
#include <vector>

namespace lbdem::scenarios {

struct FluidConfig;

struct Nozzle {
  Vec3 exit = Vec3::Zero();    // centre of the exit, on the chamber wall [m]
  Vec3 dir = Vec3::UnitX();    // unit jet axis, into the chamber
  double diameter = 0;         // [m]
  double speed = 0;            // exit speed U [m/s]
  double mass_flow = 0;        // mdot [kg/s]
  double supply_pressure = 0;  // p0 [Pa] when the jet comes from a supply pressure, else 0
  double source_radius = 0;    // notional source radius r_s [m]
  bool feed = false;           // the feed injector's gas (jet_mill.feed), not a grinding jet
  double momentum_flux() const { return mass_flow * speed; }  // J [N]
};

struct JetMillGeometry {
  Vec3 axis = Vec3::Zero();  // the chamber axis at the floor [m] (the box's x-y centre, z_lo)
  double radius = 0;         // chamber [m]
  double height = 0;         // [m]
  double outlet_radius = 0;  // vortex finder in the top plate [m]
  std::vector<Nozzle> nozzles;
  // Optional classifier ring hanging from the top plate: a tube of mean radius classifier_radius
  // and wall thickness classifier_thickness reaching classifier_height below the plate (all 0:
  // none). Gas and particles see the same ring (solid cells; an analytic DEM tube wall).
  double classifier_radius = 0, classifier_thickness = 0, classifier_height = 0;
  // Optional chamber from a user's STL (jet_mill.chamber_stl): a closed surface around the gas,
  // in SI, inside the box. Its solid cells and the particles' side walls come from it in place of
  // the cylinder; facets in the floor's or the roof's plane are left to the plates (the roof keeps
  // the vortex finder's hole). `radius` stays half the box's width: the nozzles sit on that
  // circle and the analysis (rings, distance from the wall) measures from it. Empty: the cylinder.
  // The file is read again on a resume: a changed file gives another chamber.
  std::vector<Triangle> chamber_mesh;
  std::string chamber_key;  // the config key of the file, named in errors
  double plate_tol = 0;     // a facet within this of the floor's or roof's plane lies in it [m]
  bool meshed() const { return !chamber_mesh.empty(); }
  /// The chamber mesh's facets that are not in the floor's or the roof's plane (within
  /// plate_tol, 1e-3 of a gas cell: float32 STL corners far from the origin): the particles'
  /// side walls.
  std::vector<Triangle> side_facets() const;
  /// Whether SI point x lies in the classifier ring's solid.
  bool in_classifier(const Vec3& x) const;
  /// Whether SI point x lies inside the chamber's cylinder (the plates are the box's faces) and
  /// not in the classifier ring.
  bool inside(const Vec3& x) const;
};

/// Reads [jet_mill] against the gas ([fluid] already read: the box must be the chamber's bounding
/// box). Keys: outlet_radius [m]; chamber_stl (path of a closed STL around the gas, relative to
/// the working directory) with chamber_stl_scale (1 for metres, 1e-3 for mm); [jet_mill.classifier]
/// (optional): radius, thickness (at least sqrt(2) gas cells, default 1.5), height [m];
/// [jet_mill.nozzles]: count, angle_deg (to the wall tangent), first_deg (azimuth of the first
/// nozzle), height [m] (default mid-height), diameter [m], and either speed [m/s] with mass_flow
/// [kg/s per nozzle; default rho U pi d^2 / 4], or supply_pressure [Pa absolute] with
/// supply_temperature [K, default 293.15] and ambient_pressure [Pa, default 101325]
/// (nozzle_flow.hpp: air through an ideal convergent nozzle). The jets turn counter-clockwise seen
/// from +z. Throws InputError naming the key.
JetMillGeometry read_jet_mill(const Config& section, const FluidConfig& fluid);

/// The lattice side of the geometry: solid cells outside the chamber's cylinder or STL (body
/// "chamber"; an STL that leaves no gas cell under the vortex finder is an InputError), the outlet
/// cells in the top plate's ghost layer (a density outlet at the reference pressure), and the jets'
/// mass sources and force density (lattice units, compact order). Returns the outlet's body id.
struct JetSources {
  std::vector<lbm::LbmSolver::MassSource> mass;  // per gas step [lattice units]
  std::vector<Vec3> force;                       // per interior cell, compact order [lattice]
  std::vector<int> cells_per_nozzle;             // cells each source touches
  // Per nozzle, the part of its notional cylinder's samples that fall in gas cells inside the
  // chamber (the banner): 1 for a source clear of the walls, which read_jet_mill ensures for the
  // cylinder and jet_sources checks on the cells for an STL chamber (an InputError naming the
  // file when its wall comes within 1.5 cells of a source or misses the nozzles' circle).
  std::vector<double> gas_fraction;
};
int build_chamber(lbm::LbmSolver& gas, const FluidConfig& fluid, const JetMillGeometry& g);
JetSources jet_sources(const lbm::LbmSolver& gas, const FluidConfig& fluid,
                       const JetMillGeometry& g);

}  // namespace lbdem::scenarios
