// Benchmark B4 (BENCHMARKS.md B4, thesis Sect. 3.6, Tables 3.1-3.2): the L2
// projection of f = sin(pi x) sin(pi y) onto quadratic Powell-Sabin splines
// (PS) and linear Lagrange functions (P1) on the unit square with n x n
// vertices, squares cut by parallel diagonals, and on the same grids with
// randomly perturbed vertices. Prints one row per n: the L2 errors and the
// rates log2(E(2h) / E(h)). No time stepping, hence a program of its own
// instead of a parameter file; doc/scripts/reproduce_benchmarks.sh runs it
// into doc/data/B4-projection.dat.
//
// Usage: b4-projection [largest n = 65] [perturbation = 0.2] [seed = 1]
// (perturbation: largest shift of a vertex coordinate in units of the
// spacing h, see make_b4_grid()).

#include <deal.II/base/mpi.h>

#include <mpm_otm/shape_functions/l2_projection.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  using namespace MpmOtm;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const unsigned int largest      = argc > 1 ? std::stoul(argv[1]) : 65;
      const double       perturbation = argc > 2 ? std::stod(argv[2]) : 0.2;
      const unsigned int seed         = argc > 3 ? std::stoul(argv[3]) : 1;
      const auto         f            = [](const Point<2> &x) {
        return std::sin(numbers::PI * x[0]) * std::sin(numbers::PI * x[1]);
      };

      std::printf(
        "# B4: L2 error of the L2 projection of sin(pi x) sin(pi y) on the "
        "unit square, n x n vertices, parallel diagonals (BENCHMARKS.md B4); "
        "perturbed: vertex coordinates shifted by up to %g h (seed %u)\n"
        "# n  h  PS_functions  PS_error  PS_rate  P1_functions  P1_error  "
        "P1_rate  PS_error_perturbed  PS_rate_perturbed  P1_error_perturbed  "
        "P1_rate_perturbed\n",
        perturbation,
        seed);
      double previous[4] = {0, 0, 0, 0};
      for (unsigned int n = 3; n <= largest; n = 2 * n - 1)
        {
          std::printf("%u %.6g", n, 1. / (n - 1));
          unsigned int column = 0;
          for (const double shift : {0., perturbation})
            {
              Triangulation<2> triangulation;
              make_b4_grid(triangulation, n, shift, seed);
              for (const auto space : {ProjectionSpace::powell_sabin,
                                       ProjectionSpace::linear_lagrange})
                {
                  const ProjectionError result =
                    l2_projection_error(triangulation, space, f);
                  if (shift == 0.)
                    std::printf(" %u", (unsigned int)result.n_functions);
                  std::printf(" %.5e", result.l2_error);
                  if (previous[column] > 0)
                    std::printf(" %.3f",
                                std::log2(previous[column] / result.l2_error));
                  else
                    std::printf(" -");
                  previous[column++] = result.l2_error;
                }
            }
          std::printf("\n");
          std::fflush(stdout);
        }
    }
  catch (const std::exception &exception)
    {
      std::cerr << "\nb4-projection stopped with an error:\n"
                << exception.what() << std::endl;
      return 1;
    }
  return 0;
}
