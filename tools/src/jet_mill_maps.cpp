// lbdem-jet-mill-maps: the jet mill's particle and gas fields of one run folder as CSVs under
// PREFIX_* (tools/src/mill_map_files.hpp); tools/jet_mill_figures.py draws them.
#include "tools/src/mill_map_files.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace lbdem::tools;
using lbdem::Vec3;

namespace {

JetRegion parse_jet(const std::string& text, double half_width, double length) {
  std::vector<double> v;
  std::stringstream s(text);
  for (std::string c; std::getline(s, c, ',');) {
    try {
      v.push_back(std::stod(c));
    } catch (const std::exception&) {
      throw ToolError("--jet '" + text + "': give X,Y,DX,DY in m (exit) and a direction");
    }
  }
  const double n = v.size() == 4 ? std::hypot(v[2], v[3]) : 0;
  if (!(n > 0)) throw ToolError("--jet '" + text + "': give X,Y,DX,DY with a non-zero direction");
  JetRegion j;
  j.exit = Vec3(v[0], v[1], 0);
  j.dir = Vec3(v[2] / n, v[3] / n, 0);
  j.half_width = half_width;
  j.length = length;
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  return guarded_main("lbdem-jet-mill-maps", [&] {
    CLI::App app{
        "Jet mill maps of one run folder: positions from above, mean particle speed on x-y bins "
        "and against the distance from the outer wall over [--from, --to], gas speed on the "
        "mid-plane and gas velocity against radius at the window's end. Writes PREFIX_*.csv."};
    MillMapOptions o;
    double jet_half_width = kJetHalfWidth, jet_length = kJetLength;
    std::vector<std::string> jets;
    app.add_option("run_dir", o.dir, "run folder")->required();
    app.add_option("--from", o.from, "window start [s]");
    app.add_option("--to", o.to,
                   "window end [s], inclusive (a run writes its last snapshot up to an exchange "
                   "cycle past its end time, so a window ending there needs a pad)");
    app.add_option("--out", o.prefix, "output prefix (PREFIX_speed_map.csv, ...)")->required();
    app.add_option("--bin", o.bin, "x-y bin width of the speed map and radial bin of the gas [m]");
    app.add_option("--wall-bin", o.wall_bin, "bin width of the wall-distance profile [m]");
    app.add_option("--jet", jets, "a jet's exit and direction X,Y,DX,DY [m] (repeatable)");
    app.add_option("--jet-half-width", jet_half_width, "jet region: half-width [m]");
    app.add_option("--jet-length", jet_length, "jet region: length along the axis [m]");
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      return app.exit(e);
    }
    for (const auto& j : jets) o.jets.push_back(parse_jet(j, jet_half_width, jet_length));
    std::fputs(write_mill_maps(o).c_str(), stdout);
    return 0;
  });
}
