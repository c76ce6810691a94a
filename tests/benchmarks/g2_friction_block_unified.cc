// G2 (BENCHMARKS.md) with the unified approach: the elastic block of
// prm/G2-friction-block-unified.prm, whose grid is the block and moves with
// it, on a floor with Coulomb friction (the named condition "floor" on the
// grid's side y = 0, a plane fixed in space), the slope modelled by tilted
// gravity g = 9.81 (sin theta, -cos theta). A rigid block slides with
// a = g (sin theta - mu cos theta) when tan theta > mu, x(t) = a t^2 / 2,
// and stays otherwise. As for MPM's grid (g2_friction_block): the centre of
// mass at t = 0.5 within 3 % of x(0.5) for theta = 30 deg with mu = 0.3
// (0.2945) and mu = 0 (0.6131), less than 1 % of the block's length 0.2
// for theta = 10 deg, mu = 0.3; the floor's normal reaction averaged over
// the run within 1 % of m g cos theta; the centre of mass rises by less
// than 0.5 mm off the floor.

#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double g = 9.81, mass = 1000. * 0.2 * 0.1;
  for (const auto &[theta_degrees, mu] :
       std::vector<std::pair<double, double>>{{30, 0.3}, {30, 0}, {10, 0.3}})
    {
      const double       theta = theta_degrees * numbers::PI / 180.;
      std::ostringstream changes;
      changes << std::setprecision(16)
              << "subsection Gravity\n set Vector = " << g * std::sin(theta)
              << ", " << -g * std::cos(theta)
              << "\nend\nsubsection Boundary floor\n"
              << " set Friction coefficient = " << mu << "\nend\n"
              << "subsection Output\n set Write particle CSV = false\n"
              << " set Interval = 2500\nend\n";
      auto       simulator  = make_simulator<2>("G2-friction-block-unified.prm",
                                         changes.str(),
                                         "output-G2-unified");
      const auto statistics = simulator->run();

      using Layout  = PropertyLayout<2>;
      double centre = 0, rise = 0, total = 0;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const auto   properties = particle.get_properties();
          const double m          = properties[Layout::mass];
          centre += m * (particle.get_location()[0] -
                         properties[Layout::initial_position]);
          rise += m * (particle.get_location()[1] -
                       properties[Layout::initial_position + 1]);
          total += m;
        }
      centre /= total;
      rise /= total;
      const double a =
        std::max(g * (std::sin(theta) - mu * std::cos(theta)), 0.);
      const double exact  = 0.5 * a * 0.25;
      const double normal = statistics.boundary_reactions[0].first[1];
      deallog << "theta = " << theta_degrees << ", mu = " << mu
              << ": centre of mass moved " << rounded(centre)
              << " (rigid block " << rounded(exact) << "), rose "
              << rounded(rise) << ", normal reaction " << rounded(normal)
              << " (m g cos theta " << rounded(mass * g * std::cos(theta))
              << ")" << std::endl;
      if (a > 0)
        check(std::abs(centre / exact - 1.) < 0.03,
              "centre of mass not within 3 % of the rigid block's");
      else
        check(std::abs(centre) < 0.01 * 0.2,
              "the block moved although tan theta < mu");
      check(std::abs(rise) < 5e-4, "the block rose off the floor");
      check(std::abs(normal / (mass * g * std::cos(theta)) - 1.) < 0.01,
            "the floor's normal reaction is not m g cos theta");
    }
}
