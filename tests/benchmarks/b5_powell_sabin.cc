// B5 small deformation with Powell-Sabin splines (thesis Sect. 4.1,
// Table 4.3) from prm/B5-bar-2d-small-powell-sabin.prm: PS-MPM (MUSL,
// consistent mass, hypo-elastic) on n_x - 1 by 1 blocks of four triangles,
// 16 x 14 points per block (56 per triangle), dt = 1e-5, t = 0.02.
//
// For n_x = 2, 3, 5, 9 the L2 displacement error (thesis Eq. 4.4) must be
// within 15 % of Table 4.3, and each rate log2(E(h) / E(h/2)) within 0.2 of
// the thesis's rate for the same pair of grids and between 2.5 and 3.7. The
// rates are not held to 3 +/- 0.2 because these grids are coarse: the
// thesis's own rates are 3.56, 3.14 and 2.86 (its one-block grid has only the
// functions left by the clamped ends), so the band around 3 is wide at the
// top and its lower end, 2.5, still separates third order from the second
// order of Lagrange MPM (tests/benchmarks/b5_small). The check against the
// thesis's rate is the sharper one; 0.2 is what the 15 % on the errors
// leaves if both errors of a pair deviate by 7 % in opposite directions.
// (n_x = 17, where the thesis's value depends on its point layout, is in
// doc/benchmarks.md.) Every point must stay inside its triangle, and the
// y-displacement, zero in the exact solution, must stay below 1e-5 of the
// x-displacement (it is not round-off: the splines' projection of a field
// that varies in x only is not exactly constant in y; measured at most
// 1.2e-6 of it, at n_x = 3).

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const unsigned int  n_x[4]         = {2, 3, 5, 9};
  const double        published[4]   = {3.70985e-04,
                                        3.13639e-05,
                                        3.56528e-06,
                                        4.90397e-07};
  const double        thesis_rate[4] = {0., 3.56, 3.14, 2.86};
  std::vector<double> errors;
  for (unsigned int i = 0; i < 4; ++i)
    {
      auto simulator =
        make_simulator<2>("B5-bar-2d-small-powell-sabin.prm",
                          "subsection Mesh\n set Subdivisions = " +
                            std::to_string(n_x[i] - 1) + ", 1\nend",
                          "output-" + std::to_string(n_x[i]));
      const auto   statistics = simulator->run();
      const double error      = statistics.displacement_l2_error;
      errors.push_back(error);
      const double deviation = error / published[i] - 1.;
      check(std::abs(deviation) < 0.15,
            "n_x = " + std::to_string(n_x[i]) +
              ": more than 15 % from thesis Table 4.3");

      double       worst_location = 0;
      Tensor<1, 2> largest_displacement;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const Point<2> xi = particle.get_reference_location();
          worst_location =
            std::max({worst_location, -xi[0], -xi[1], xi[0] + xi[1] - 1.});
          const auto properties = particle.get_properties();
          for (unsigned int d = 0; d < 2; ++d)
            largest_displacement[d] =
              std::max(largest_displacement[d],
                       std::abs(
                         particle.get_location()[d] -
                         properties[PropertyLayout<2>::initial_position + d]));
        }
      check(worst_location < 1e-10,
            "a material point lies outside its triangle");
      check(largest_displacement[1] < 1e-5 * largest_displacement[0],
            "the y-displacement is not small");

      deallog << "n_x = " << n_x[i] << ": "
              << simulator->shape_function_family().n_functions()
              << " functions, L2 error " << rounded(error, 2)
              << " (Table 4.3: " << rounded(published[i], 2)
              << "), within 15 %";
      if (i > 0)
        {
          const double rate = std::log2(errors[i - 1] / errors[i]);
          check(std::abs(rate - thesis_rate[i]) < 0.2,
                "rate more than 0.2 from the thesis's");
          check(rate > 2.5 && rate < 3.7, "rate not between 2.5 and 3.7");
          deallog << ", rate " << std::fixed << std::setprecision(2) << rate
                  << " (thesis " << thesis_rate[i] << ")" << std::defaultfloat;
        }
      deallog << std::endl;
    }
}
