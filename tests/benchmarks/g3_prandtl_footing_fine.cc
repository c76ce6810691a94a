// G3 (BENCHMARKS.md) on 80 x 96 cells, 16 per footing half-width, with the
// default 2 x 2 points per cell and the default F-bar remedy: the mean load
// at settlements 0.03-0.06 (to keep the Debug run short; doc/benchmarks.md
// has 0.03-0.1) within 3 % of Prandtl's (2 + pi) c for linear functions and
// quadratic B-splines (g3_prandtl_footing.h; the coarse grid and the runs
// without a remedy: g3_prandtl_footing).

#include "g3_prandtl_footing.h"

int
main(int argc, char **argv)
{
  using namespace G3;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double linear =
    report("linear, F-bar",
           mean_load("G3-prandtl-footing.prm", 80, "F-bar", 0.06));
  const double splines =
    report("B-splines, F-bar",
           mean_load("G3-prandtl-footing-bspline.prm", 80, "F-bar", 0.06));
  check(std::abs(linear) < 3.,
        "linear functions: the load is not within 3 % of Prandtl's");
  check(std::abs(splines) < 3.,
        "B-splines: the load is not within 3 % of Prandtl's");
}
