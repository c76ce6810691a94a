// B4 (BENCHMARKS.md B4, thesis Sect. 3.6): the L2 projection of
// f = sin(pi x) sin(pi y) onto linear Lagrange functions (P1) on the grids of
// b4_projection (unit square, n x n vertices, parallel diagonals),
// consistent mass matrix integrated exactly, no boundary conditions. The
// errors must be within 1 % of the P1 column of BENCHMARKS.md B4 (a correct
// P1 projection of this f; the printed Table 3.2 used another function and
// a flawed quadrature) for n = 5, 9, 17, 33, and the rate between the last
// two n within 0.05 of 2.

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
  // BENCHMARKS.md B4, column "P1, same f: true L2".
  const std::array<std::pair<unsigned int, double>, 4> published = {
    {{5, 2.7726e-02}, {9, 6.5955e-03}, {17, 1.6180e-03}, {33, 4.0235e-04}}};
  double previous = 0;
  for (const auto &[n, reference] : published)
    {
      Triangulation<2> triangulation;
      make_b4_grid(triangulation, n);
      const ProjectionError result =
        l2_projection_error(triangulation, ProjectionSpace::linear_lagrange, f);
      check(result.n_functions == n * n, "not n^2 functions");
      const double error = result.l2_error;
      check(std::abs(error / reference - 1.) < 0.01,
            "n = " + std::to_string(n) + ": error " + rounded(error, 5) +
              " not within 1 % of " + rounded(reference, 5));
      deallog << "n = " << n << ": n^2 = " << n * n << " functions, L2 error "
              << rounded(error, 3)
              << " (BENCHMARKS.md B4: " << rounded(reference, 3) << ")";
      if (previous > 0)
        {
          const double rate = std::log2(previous / error);
          deallog << ", rate " << std::fixed << std::setprecision(1) << rate
                  << std::defaultfloat;
          if (n == 33)
            check(std::abs(rate - 2.) < 0.05, "rate not close to 2");
        }
      deallog << std::endl;
      previous = error;
    }
}
