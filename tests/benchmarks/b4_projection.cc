// B4 (thesis Sect. 3.6, Table 3.1): the L2 projection of
// f = sin(pi x) sin(pi y) onto the quadratic Powell-Sabin splines of the
// unit square with n x n vertices, squares cut by parallel diagonals
// (BENCHMARKS.md B4), consistent mass matrix, no boundary conditions
// (thesis Eqs. 3.65-3.71), computed by l2_projection_error() (7-point
// degree-5 rule on each of the six sub-triangles of every triangle, which
// integrates the mass matrix exactly; error with an 8 x 8 collapsed Gauss
// rule per sub-triangle). The errors must be within 1 % of the "true L2"
// column of BENCHMARKS.md B4 (the errors behind Table 3.1) for
// n = 3, 5, 9, 17, and the rate between the last two n close to 3.

#include <mpm_otm/shape_functions/l2_projection.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const auto f = [](const Point<2> &x) {
    return std::sin(numbers::PI * x[0]) * std::sin(numbers::PI * x[1]);
  };
  // BENCHMARKS.md B4, "true L2" column.
  const std::array<std::pair<unsigned int, double>, 4> published = {
    {{3, 1.17809e-02}, {5, 1.14274e-03}, {9, 1.31697e-04}, {17, 1.60825e-05}}};
  double previous = 0;
  for (const auto &[n, reference] : published)
    {
      Triangulation<2> triangulation;
      make_b4_grid(triangulation, n);
      const double error =
        l2_projection_error(triangulation, ProjectionSpace::powell_sabin, f)
          .l2_error;
      check(std::abs(error / reference - 1.) < 0.01,
            "n = " + std::to_string(n) + ": error " + rounded(error, 5) +
              " not within 1 % of " + rounded(reference, 5));
      deallog << "n = " << n << ": 3 n^2 = " << 3 * n * n
              << " functions, L2 error " << rounded(error, 3)
              << " (BENCHMARKS.md B4: " << rounded(reference, 3) << ")";
      if (previous > 0)
        {
          const double rate = std::log2(previous / error);
          deallog << ", rate " << std::fixed << std::setprecision(1) << rate
                  << std::defaultfloat;
          if (n == 17)
            check(std::abs(rate - 3.) < 0.1, "rate not close to 3");
        }
      deallog << std::endl;
      previous = error;
    }
}
