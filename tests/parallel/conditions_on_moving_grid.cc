// Named boundary conditions on the grid of the unified approach, which
// moves with the material: an elastic column W = 1 wide and H = 4 high
// (E = 1e7, nu = 0.3, rho = 1000, plane strain), the grid its own, base
// fixed and sides on slip conditions (the entry "Boundaries"), settles
// under gravity g = 9.81 with local damping. At rest, with rigid smooth
// walls, sigma_yy = -rho g (H - y) and sigma_xx = nu / (1 - nu) sigma_yy,
// so the base carries the weight rho g W H = 39240 N and each wall
// nu / (1 - nu) rho g H^2 / 2 = 33634 N. The reactions of the conditions
// (the mean over the last output interval) must be these within 1 % (the
// walls' corner nodes at the base share their reaction with the base),
// with linear functions and quadratic B-splines, on one MPI rank and on
// two (the same numbers). A side that the conditions did not hold would
// carry no such load. With a surcharge p = 10 kPa on the top (a traction
// condition), the base carries rho g W H + p W and the walls
// nu / (1 - nu) (rho g H^2 / 2 + p H), and the top's reaction is its load
// -p W to round-off.

#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double rho = 1000., g = 9.81, W = 1., H = 4., nu = 0.3;
  for (const double p : {0., 1e4})
    for (const std::string functions : {"linear", "B-spline"})
      {
        const double weight = rho * g * W * H + p * W;
        const double wall   = nu / (1. - nu) * (rho * g * H * H / 2. + p * H);
        const std::string top =
          p > 0. ? ", top\nsubsection Boundary top\n set Type = traction\n"
                   " set Boundary ids = 3\n set Traction = 0; -1e4\nend\n" :
                   "\n";
        auto simulator = make_simulator<2>(
          "",
          "set Dimension = 2\n"
          "set Problem = custom\n"
          "set Method = Unified\n"
          "set Update scheme = USL\n"
          "set Mass matrix = lumped\n"
          "set Shape functions = " +
            functions +
            "\n"
            "set Boundaries = left, right, base" +
            top +
            "subsection Time\n set End time = 2\n set Time step = 2e-3\nend\n"
            "subsection Particles\n set Particles per cell = 2\nend\n"
            "subsection Mesh\n set Lower corner = 0, 0\n"
            " set Upper corner = 1, 4\n set Subdivisions = 2, 8\nend\n"
            "subsection Material\n set Model = hypo-elastic\n"
            " set Young's modulus = 1e7\n set Poisson's ratio = 0.3\n"
            " set Density = 1000\nend\n"
            "subsection Boundary left\n set Type = slip\n"
            " set Boundary ids = 0\nend\n"
            "subsection Boundary right\n set Type = slip\n"
            " set Boundary ids = 1\nend\n"
            "subsection Boundary base\n set Type = fixed\n"
            " set Boundary ids = 2\nend\n"
            "subsection Gravity\n set Vector = 0, -9.81\nend\n"
            "subsection Damping\n set Local damping coefficient = 0.3\nend\n"
            "subsection Output\n set Interval = 100\n"
            " set Write particle CSV = false\nend\n",
          "output-conditions_on_moving_grid");
        const auto  statistics = simulator->run();
        const auto &reactions  = statistics.boundary_reactions;
        deallog << functions << ", surcharge " << p << ": base "
                << rounded(reactions[2].first[1]) << " (rho g W H + p W "
                << rounded(weight) << "), left "
                << rounded(reactions[0].first[0]) << ", right "
                << rounded(-reactions[1].first[0])
                << " (nu / (1 - nu) (rho g H^2 / 2 + p H) " << rounded(wall)
                << ")";
        if (p > 0.)
          deallog << ", top " << rounded(reactions[3].first[1]) << " (-p W "
                  << rounded(-p * W) << ")";
        deallog << std::endl;
        check(std::abs(reactions[2].first[1] / weight - 1.) < 0.01,
              "the base does not carry the weight and the surcharge");
        check(std::abs(reactions[0].first[0] / wall - 1.) < 0.01 &&
                std::abs(-reactions[1].first[0] / wall - 1.) < 0.01,
              "the walls do not carry the lateral pressure at rest");
        if (p > 0.)
          check(std::abs(reactions[3].first[1] / (-p * W) - 1.) < 1e-12,
                "the traction condition's load is not p W");
      }
}
