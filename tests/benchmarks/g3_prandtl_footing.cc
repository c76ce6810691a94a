// G3 (BENCHMARKS.md): the smooth strip footing on a weightless Tresca soil
// (von Mises, yield stress sqrt(3) c), whose limit load is Prandtl's
// q_u = (2 + pi) c, 25.71 kN/m on the half model, on 40 x 48 cells (8 per
// footing half-width) with the default 2 x 2 points per cell, linear
// functions and quadratic B-splines, the footing at 0.1 m/s to a settlement
// of 0.1 (g3_prandtl_footing.h). Asserted, for the mean load at settlements
// 0.03-0.1:
//  - without a remedy, linear functions lock under the isochoric plastic
//    flow: more than 10 % above q_u (doc/benchmarks.md: 15 %); the
//    B-splines lock less, but also lie above the load with the remedy;
//  - with the F-bar remedy (the default for plastic materials): within 5 %
//    of q_u for both families (BENCHMARKS.md).
// g3_prandtl_footing_fine: 16 cells per half-width.

#include "g3_prandtl_footing.h"

int
main(int argc, char **argv)
{
  using namespace G3;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string linear  = "G3-prandtl-footing.prm";
  const std::string splines = "G3-prandtl-footing-bspline.prm";

  const double linear_locked =
    report("linear, no remedy", mean_load(linear, 40, "none", 0.1));
  const double linear_f_bar =
    report("linear, F-bar", mean_load(linear, 40, "F-bar", 0.1));
  const double splines_locked =
    report("B-splines, no remedy", mean_load(splines, 40, "none", 0.1));
  const double splines_f_bar =
    report("B-splines, F-bar", mean_load(splines, 40, "F-bar", 0.1));

  check(linear_locked > 10., "linear functions without a remedy do not lock");
  check(std::abs(linear_f_bar) < 5.,
        "linear functions with F-bar: the load is not within 5 % of "
        "Prandtl's");
  check(splines_locked > splines_f_bar,
        "B-splines: F-bar does not lower the load");
  check(std::abs(splines_f_bar) < 5.,
        "B-splines with F-bar: the load is not within 5 % of Prandtl's");
}
