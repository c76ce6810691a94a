// An elastic block 0.2 x 0.1 (E = 1e6, nu = 0.3, rho = 1000, plane strain)
// starts at rest 0.05 above a floor with Coulomb friction (mu = 0.3), falls
// under gravity and comes to rest on the floor (local damping 0.2), with
// linear functions and quadratic B-splines on cells of 0.02. At rest its
// base lies on the floor and it is compressed by its weight: with free
// sides, sigma_yy = -rho g (0.1 - Y) and eps_yy = (1 - nu^2) sigma_yy / E,
// so the mean height of its points is 0.05 - rho g H^2 (1 - nu^2) / (3 E) =
// 0.049970. The frictional floor acts only where the material touches it;
// a floor that held every node with mass would catch the block up to a
// cell (0.02) above it. The mean height must be within 1 % of a cell of
// the exact one, and the lowest point's lower edge within 1 % of a cell of
// the floor.

#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double cell = 0.02;
  const double exact =
    0.05 - 1000. * 9.81 * 0.1 * 0.1 * (1. - 0.3 * 0.3) / (3. * 1e6);
  for (const std::string functions : {"linear", "B-spline"})
    {
      auto simulator = make_simulator<2>(
        "",
        "set Dimension = 2\n"
        "set Problem = custom\n"
        "set Method = MPM\n"
        "set Update scheme = MUSL\n"
        "set Mass matrix = lumped\n"
        "set Shape functions = " +
          functions +
          "\n"
          "set Bodies = block\n"
          "set Boundaries = floor\n"
          "subsection Time\n set End time = 0.3\n set Time step = 3e-4\nend\n"
          "subsection Particles\n set Particles per cell = 2\nend\n"
          "subsection Mesh\n set Lower corner = 0, 0\n"
          " set Upper corner = 0.4, 0.2\n set Subdivisions = 20, 10\nend\n"
          "subsection Material\n set Model = hypo-elastic\n"
          " set Young's modulus = 1e6\n set Poisson's ratio = 0.3\n"
          " set Density = 1000\nend\n"
          "subsection Body block\n set Shape = box\n"
          " set Lower corner = 0.1, 0.05\n set Upper corner = 0.3, 0.15\nend\n"
          "subsection Boundary floor\n set Type = friction\n"
          " set Boundary ids = 2\n set Friction coefficient = 0.3\nend\n"
          "subsection Gravity\n set Vector = 0, -9.81\nend\n"
          "subsection Damping\n set Local damping coefficient = 0.2\nend\n"
          "subsection Output\n set Interval = 1000\n"
          " set Write particle CSV = false\nend\n",
        "output-block_dropped_on_floor");
      simulator->run();

      using Layout  = PropertyLayout<2>;
      double height = 0, lowest_edge = 1, n_points = 0;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const double y = particle.get_location()[1];
          height += y;
          lowest_edge = std::min(lowest_edge,
                                 y - 0.5 * std::sqrt(Layout::volume(
                                             particle.get_properties())));
          ++n_points;
        }
      height /= n_points;
      deallog << functions << ": mean height " << rounded(height, 2)
              << " (exact " << rounded(exact, 2) << ")" << std::endl;
      check(std::abs(height - exact) < 0.01 * cell,
            "the block does not rest on the floor at its compressed height");
      check(std::abs(lowest_edge) < 0.01 * cell,
            "the block's base is not on the floor");
    }
}
