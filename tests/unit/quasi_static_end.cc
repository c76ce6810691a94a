// The quasi-static end (subsection "Quasi-static end"; manual) on the block
// of prm/G2-friction-block.prm (elastic, 0.2 x 0.1, rho = 1000, on a floor
// with Coulomb friction mu = 0.3, the incline modelled by tilted gravity),
// with local damping 0.3 and Kinetic energy ratio = 1e-6:
//  - theta = 10 deg (tan theta < mu): the block comes to rest; the run
//    ends before its end time of 2 s, at rest, and the block's mean
//    stresses are those of the static state, sigma_yy = -rho g cos(theta)
//    (h - y) and sigma_xy = rho g sin(theta) (h - y) (the floor carries the
//    weight and holds it by friction), averaged over the height h:
//    -rho g cos(theta) h / 2 and rho g sin(theta) h / 2, each within 2 % of
//    rho g h / 2;
//  - theta = 30 deg (tan theta > mu): the block slides with
//    a = g (sin theta - mu cos theta); the run reaches its end time (0.5 s)
//    not at rest, and the report says that the motion has not decayed.

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using Layout = PropertyLayout<2>;
  for (const double theta : {10., 30.})
    {
      const double       angle = theta * numbers::PI / 180.;
      std::ostringstream changes;
      changes << std::setprecision(12)
              << "subsection Gravity\n set Vector = " << 9.81 * std::sin(angle)
              << ", " << -9.81 * std::cos(angle)
              << "\nend\nsubsection Damping\n set Local damping coefficient "
                 "= 0.3\n set End time = 100\nend\n"
              << "subsection Quasi-static end\n set Kinetic energy ratio = "
                 "1e-6\nend\nsubsection Time\n set End time = "
              << (theta < 20. ? 2. : 0.5) << "\nend\n";
      auto simulator =
        make_simulator<2>("G2-friction-block.prm", changes.str(), "output-qs");
      simulator->run();
      double sigma_yy = 0, sigma_xy = 0, volume = 0;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const auto   properties = particle.get_properties();
          const double V          = Layout::volume(properties);
          const auto   sigma      = Layout::get_stress(properties);
          sigma_yy += V * sigma[1][1];
          sigma_xy += V * sigma[0][1];
          volume += V;
        }
      sigma_yy /= volume;
      sigma_xy /= volume;
      const double scale = 1000. * 9.81 * 0.1 / 2.;
      deallog << "theta = " << theta
              << " deg: " << (simulator->at_rest() ? "at rest" : "not at rest")
              << " at t = " << std::setprecision(3) << simulator->time();
      if (theta < 20.)
        {
          deallog << ", mean sigma_yy " << sigma_yy / scale
                  << " rho g h / 2 (exact " << -std::cos(angle)
                  << "), sigma_xy " << sigma_xy / scale << " (exact "
                  << std::sin(angle) << ")" << std::endl;
          check(simulator->at_rest() && simulator->time() < 2.,
                "the resting block is not found at rest");
          check(std::abs(sigma_yy / scale + std::cos(angle)) < 0.02 &&
                  std::abs(sigma_xy / scale - std::sin(angle)) < 0.02,
                "the resting block's stresses are not the static ones");
        }
      else
        {
          deallog << std::endl;
          check(!simulator->at_rest() && simulator->time() == 0.5,
                "the sliding block is called at rest");
        }
    }
}
