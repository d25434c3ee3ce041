// The Palabos side of lbdem's LBM benchmark (bench/lbm_bench.cpp runs the same case): D3Q19 BGK in
// double precision on a fully periodic N^3 box, Taylor-Green initial field with u0 = 0.05 (lattice
// units), tau = 0.6. After `warmup` untimed steps it times `steps` calls of collideAndStream()
// between MPI barriers and prints MLUPS = N^3 steps / wall / 1e6 (wall: the slowest rank).
// run: mpirun -np P ./plb_tgv_bench N [steps=200] [warmup=20]
#include "palabos3D.h"
// palabos3D.hh of Debian's Palabos 1.5r1 includes multiGrid/coarseGridProcessors3D.hh, which GCC 12
// rejects (a std::vector::assign call with no matching overload); so the template sources (.hh)
// of the modules this program uses are included one by one, multiGrid left out.
#include <parallelism/headers3D.hh>
#include <latticeBoltzmann/headers3D.hh>
#include <core/headers3D.hh>
#include <basicDynamics/headers3D.hh>
#include <boundaryCondition/headers3D.hh>
#include <complexDynamics/headers3D.hh>
#include <multiPhysics/headers3D.hh>
#include <io/headers3D.hh>
#include <atomicBlock/headers3D.hh>
#include <multiBlock/headers3D.hh>
#include <algorithm/headers3D.hh>
#include <dataProcessors/headers3D.hh>
#include <coProcessors/headers3D.hh>
#include <core/headers2D.hh>
#include <atomicBlock/headers2D.hh>
#include <multiBlock/headers2D.hh>
#include <cmath>
#include <cstdlib>
#include <iomanip>

using namespace plb;
typedef double T;
#define DESCRIPTOR descriptors::D3Q19Descriptor

struct TaylorGreen {
  TaylorGreen(plint n_, T u0_) : n(n_), u0(u0_) {}
  void operator()(plint iX, plint iY, plint iZ, T& rho, Array<T, 3>& u) const {
    const T k = 2. * std::acos(-1.) / (T)n;
    const T x = k * (iX + 0.5), y = k * (iY + 0.5), z = k * (iZ + 0.5);
    rho = 1.;
    u[0] = u0 * std::sin(x) * std::cos(y) * std::cos(z);
    u[1] = -u0 * std::cos(x) * std::sin(y) * std::cos(z);
    u[2] = 0.;
  }
  plint n;
  T u0;
};

int main(int argc, char* argv[]) {
  plbInit(&argc, &argv);
  global::directories().setOutputDir("./");
  const plint N = argc > 1 ? std::atoi(argv[1]) : 64;
  const plint steps = argc > 2 ? std::atoi(argv[2]) : 200;
  const plint warmup = argc > 3 ? std::atoi(argv[3]) : 20;
  const T tau = 0.6, u0 = 0.05;

  MultiBlockLattice3D<T, DESCRIPTOR> lattice(N, N, N, new BGKdynamics<T, DESCRIPTOR>(1. / tau));
  lattice.periodicity().toggleAll(true);
  initializeAtEquilibrium(lattice, lattice.getBoundingBox(), TaylorGreen(N, u0));
  lattice.initialize();

  for (plint i = 0; i < warmup; ++i) lattice.collideAndStream();
  const T e0 = computeAverageEnergy(lattice);

  global::mpi().barrier();
  const double t0 = global::mpi().getTime();
  for (plint i = 0; i < steps; ++i) lattice.collideAndStream();
  global::mpi().barrier();
  const double wall = global::mpi().getTime() - t0;

  const T e1 = computeAverageEnergy(lattice);
  const T rho = computeAverageDensity(lattice);
  const double mlups = (double)N * N * N * (double)steps / wall / 1e6;
  pcout << std::setprecision(6) << "PALABOS_RESULT N=" << N << " ranks=" << global::mpi().getSize()
        << " steps=" << steps << " wall_s=" << wall << " MLUPS=" << mlups << " E_ratio=" << e1 / e0
        << " rho_avg=" << rho << std::endl;
  return 0;
}
