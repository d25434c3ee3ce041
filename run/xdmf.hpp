#pragma once
// The XDMF 3 files of a run folder (particles.xdmf, fluid.xdmf): what ParaView's default XDMF
// reader (Xdmf3ReaderS) and VisIt open. Each is a temporal collection with one grid per snapshot,
// rewritten whole and atomically after every snapshot from the HDF5 files on disk, so that it names
// only the datasets each snapshot holds (a run folder resumed from an older build keeps its older
// snapshots readable, without the arrays they lack). Both files print their time values with
// xdmf_time, so the particle and gas grids of one instant carry the same text and a reader puts
// them on the same time step.
#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace lbdem::run {

/// The text of a time value [s] in every XDMF file: 17 significant digits, which read back to the
/// same double.
std::string xdmf_time(double t);

/// particles.xdmf over snapshots/particles_NNNNNN.h5, NNNNNN < times.size(): per snapshot one
/// vertex cell per particle (Polyvertex, one node per element, connectivity /vertex_index) at
/// /position_m, with the point arrays of the snapshot (radius, velocity, angular velocity, force,
/// id, material, coordination number) that it holds.
void write_particles_xdmf(const std::string& dir, const std::vector<double>& times);

/// The gas lattice in SI: its lower corner, cell edge and cells per axis (x, y, z).
struct GasGrid {
  Vec3 lower_corner;
  double dx;
  std::array<int, 3> cells;
};

/// fluid.xdmf over snapshots/fluid_NNNNNN.h5: per snapshot a 3DCoRectMesh whose nodes are the
/// cells' corners (cells + 1 per axis from the lower corner: the grid covers the lattice) with the
/// snapshot's fields as cell data (velocity, pressure, porosity, the solid mask).
void write_fluid_xdmf(const std::string& dir, const std::vector<double>& times, const GasGrid& g);

}  // namespace lbdem::run
