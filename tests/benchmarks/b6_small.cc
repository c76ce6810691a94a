// B6 small deformation (thesis Sect. 4.3, Fig. 4.10, Lagrange MPM on 2 x 16
// blocks) from prm/B6-soil-column-small.prm: the vertical displacement of the
// top row of material points against the exact series solution over
// 0 <= t <= 0.5 (more than one period 4H/c = 0.447 s).

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/problems/problem.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  auto simulator =
    make_simulator<2>("B6-soil-column-small.prm",
                      "subsection Output\n set Write particle CSV = false\nend",
                      "output-B6");
  using Layout = PropertyLayout<2>;

  // Initial height of the top row: the largest X2.
  double top = 0;
  for (const auto &particle : simulator->material_points().particle_handler())
    top =
      std::max(top, particle.get_properties()[Layout::initial_position + 1]);

  double max_error = 0, max_exact = 0;
  simulator->run([&](const unsigned int step, const Statistics<2> &) {
    const double t   = simulator->time();
    double       sum = 0, exact = 0;
    unsigned int n = 0;
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const auto properties = particle.get_properties();
        if (properties[Layout::initial_position + 1] < top - 1e-12)
          continue;
        const Point<2> X(
          Layout::get_vector(properties, Layout::initial_position));
        sum += particle.get_location()[1] - X[1];
        exact = simulator->problem().exact_displacement(X, t)[1];
        ++n;
      }
    const double u = sum / n;
    max_error      = std::max(max_error, std::abs(u - exact));
    max_exact      = std::max(max_exact, std::abs(exact));
    if (step % 500 == 0)
      deallog << "t = " << std::fixed << std::setprecision(2) << t
              << std::defaultfloat << ": top displacement " << rounded(u, 2)
              << ", exact " << rounded(exact, 2) << std::endl;
  });
  const double relative = max_error / max_exact;
  check(relative < 0.05,
        "top displacement more than 5 % of its maximum from the exact "
        "solution: " +
          std::to_string(relative));
  deallog << "largest deviation below 5 % of the largest displacement"
          << std::endl;
}
