// B5 small deformation (thesis Sect. 4.1, Table 4.2) from
// prm/B5-bar-2d-small.prm: Lagrange MPM on triangles, 16 x 14 points per
// block, dt = 1e-5, t = 0.02. The L2 displacement error (thesis Eq. 4.4) for
// n_x = 5, 9, 17 must be within 15 % of Table 4.2 and converge at rate
// 2 +/- 0.2. Every point must stay inside its triangle (barycentric
// coordinates in [0, 1]; deal.II 9.4's own sorting gets this wrong).

#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const unsigned int  n_x[3]       = {5, 9, 17};
  const double        published[3] = {1.80956e-04, 4.44076e-05, 1.07531e-05};
  std::vector<double> errors;
  for (unsigned int i = 0; i < 3; ++i)
    {
      auto simulator =
        make_simulator<2>("B5-bar-2d-small.prm",
                          "subsection Mesh\n set Subdivisions = " +
                            std::to_string(n_x[i] - 1) + ", 1\nend",
                          "output-" + std::to_string(n_x[i]));
      const auto   statistics = simulator->run();
      const double error      = statistics.displacement_l2_error;
      errors.push_back(error);
      const double deviation = error / published[i] - 1.;
      check(std::abs(deviation) < 0.15,
            "n_x = " + std::to_string(n_x[i]) +
              ": more than 15 % from thesis Table 4.2");

      double worst = 0;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const Point<2> xi = particle.get_reference_location();
          worst = std::max({worst, -xi[0], -xi[1], xi[0] + xi[1] - 1.});
        }
      check(worst < 1e-10, "a material point lies outside its triangle");

      deallog << "n_x = " << n_x[i] << ": L2 error " << rounded(error, 2)
              << " (Table 4.2: " << rounded(published[i], 2) << ", "
              << std::fixed << std::setprecision(0) << 100. * deviation
              << std::defaultfloat << " %)";
      if (i > 0)
        {
          const double rate = std::log2(errors[i - 1] / errors[i]);
          check(std::abs(rate - 2.) < 0.2, "rate not 2 +/- 0.2");
          deallog << ", rate " << std::fixed << std::setprecision(1) << rate
                  << std::defaultfloat;
        }
      deallog << std::endl;
    }
}
