#include "run/xdmf.hpp"

#include <cstdio>

#include "core/h5.hpp"

namespace lbdem::run {

namespace {

/// A dataset an XDMF grid may reference: its name in the snapshot (also the array's name in
/// ParaView), XDMF number type and bytes, and components (1: scalar, 3: vector).
struct Field {
  const char* name;
  const char* type;
  int precision;
  int components;
};

constexpr Field kParticleFields[] = {
    {"radius_m", "Float", 8, 1},
    {"velocity_m_per_s", "Float", 8, 3},
    {"angular_velocity_rad_per_s", "Float", 8, 3},
    {"force_N", "Float", 8, 3},
    {"id", "Int", 8, 1},
    {"material", "Int", 4, 1},
    {"coordination_number", "Int", 4, 1},
};

constexpr Field kGasFields[] = {
    {"velocity_m_per_s", "Float", 8, 3},
    {"pressure_Pa", "Float", 8, 1},
    {"porosity", "Float", 8, 1},
    {"solid", "UChar", 1, 1},
};

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string snapshot_name(const char* kind, std::size_t k) {
  char name[64];
  std::snprintf(name, sizeof name, "snapshots/%s_%06zu.h5", kind, k);
  return name;
}

/// <DataItem> of dataset `set` in `file`, of `dims` (slowest first) and the field's type.
std::string data_item(const std::string& dims, const char* type, int precision,
                      const std::string& file, const std::string& set) {
  return "<DataItem Dimensions=\"" + dims + "\" Format=\"HDF\" NumberType=\"" + type +
         "\" Precision=\"" + std::to_string(precision) + "\">" + file + ":/" + set + "</DataItem>";
}

/// The fields of `fields` that snapshot `in` holds, as attributes centred on `center`.
template <std::size_t N>
std::string attributes(const Field (&fields)[N], const H5In& in, const std::string& file,
                       const std::string& dims, const char* center) {
  std::string x;
  for (const Field& f : fields) {
    if (!in.has(std::string("/") + f.name)) continue;
    x += std::string("    <Attribute Name=\"") + f.name + "\" AttributeType=\"" +
         (f.components == 3 ? "Vector" : "Scalar") + "\" Center=\"" + center + "\">" +
         data_item(dims + (f.components == 3 ? " 3" : ""), f.type, f.precision, file, f.name) +
         "</Attribute>\n";
  }
  return x;
}

std::string document(const char* name, const std::string& grids) {
  return std::string(
             "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n  <Grid Name=\"") +
         name + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n" + grids +
         "  </Grid>\n </Domain>\n</Xdmf>\n";
}

}  // namespace

std::string xdmf_time(double t) {
  return num(t);
}

void write_particles_xdmf(const std::string& dir, const std::vector<double>& times) {
  std::string grids;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::string file = snapshot_name("particles", k);
    const H5In in(dir + "/" + file);
    const std::string n = std::to_string(in.dims("/position_m").at(0));
    grids += "   <Grid Name=\"particles\" GridType=\"Uniform\">\n    <Time Value=\"" +
             xdmf_time(times[k]) + "\"/>\n";
    // One vertex cell per particle: without the connectivity ParaView's XDMF 3 reader makes no
    // cells, and its Surface and Points representations draw nothing (snapshots written before
    // /vertex_index keep that form).
    grids += "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + n +
             "\" NodesPerElement=\"1\">";
    if (in.has("/vertex_index")) grids += data_item(n, "Int", 4, file, "vertex_index");
    grids += "</Topology>\n";
    grids += "    <Geometry GeometryType=\"XYZ\">" +
             data_item(n + " 3", "Float", 8, file, "position_m") + "</Geometry>\n";
    grids += attributes(kParticleFields, in, file, n, "Node");
    grids += "   </Grid>\n";
  }
  write_file_atomic(dir + "/particles.xdmf", document("particles", grids));
}

void write_fluid_xdmf(const std::string& dir, const std::vector<double>& times, const GasGrid& g) {
  // XDMF lists dimensions, origin and spacing slowest axis first (z y x). The mesh's nodes are
  // the cells' corners, so a field of one value per cell is Center="Cell".
  const auto text = [](std::size_t z, std::size_t y, std::size_t x) {
    return std::to_string(z) + " " + std::to_string(y) + " " + std::to_string(x);
  };
  const std::size_t nx = std::size_t(g.cells[0]), ny = std::size_t(g.cells[1]),
                    nz = std::size_t(g.cells[2]);
  const std::string cells = text(nz, ny, nx), nodes = text(nz + 1, ny + 1, nx + 1);
  const std::string geometry =
      "    <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" + nodes +
      "\"/>\n"
      "    <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
      "     <DataItem Dimensions=\"3\" Format=\"XML\" NumberType=\"Float\" Precision=\"8\">" +
      num(g.lower_corner[2]) + " " + num(g.lower_corner[1]) + " " + num(g.lower_corner[0]) +
      "</DataItem>\n"
      "     <DataItem Dimensions=\"3\" Format=\"XML\" NumberType=\"Float\" Precision=\"8\">" +
      num(g.dx) + " " + num(g.dx) + " " + num(g.dx) + "</DataItem>\n    </Geometry>\n";
  std::string grids;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::string file = snapshot_name("fluid", k);
    const H5In in(dir + "/" + file);
    grids += "   <Grid Name=\"gas\" GridType=\"Uniform\">\n    <Time Value=\"" +
             xdmf_time(times[k]) + "\"/>\n" + geometry +
             attributes(kGasFields, in, file, cells, "Cell") + "   </Grid>\n";
  }
  write_file_atomic(dir + "/fluid.xdmf", document("gas", grids));
}

}  // namespace lbdem::run
