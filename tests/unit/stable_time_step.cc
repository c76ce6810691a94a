// The stable time step 2 / omega_max that the simulator estimates at the
// start (StableTimeStep, Lanczos on M^-1 K), against closed forms.
//
// A 1D bar with fixed ends (prm/B1b-bar-fixed-ends.prm: 31 cells of
// h = 1/31, E = 4e3, rho = 1, c = sqrt(E / rho)), linear functions and two
// points per cell at h/4 and 3h/4. Its n = 30 free nodes share the
// eigenvectors sin(j pi i / (n + 1)) of the Toeplitz matrices
// K = (E / h) tridiag(-1, 2, -1) and, with these points,
// M = rho h tridiag(3/16, 10/16, 3/16) (consistent; sum_p m_p phi_i phi_j)
// or rho h I (lumped), so with theta = n pi / (n + 1)
//   lumped:     omega_max^2 = (c / h)^2 (2 - 2 cos theta),
//   consistent: omega_max^2 = (c / h)^2 (2 - 2 cos theta)
//                                / (10/16 + 6/16 cos theta),
// and dt_stable = 2 / omega_max: 1.0013 h / c lumped (the thesis' h / c,
// Eq. 2.48, for an infinite bar) and 0.5026 h / c consistent. The estimate
// must match within 1e-6. With Time step = auto the run's time step is the
// Courant factor times it, and a time step above it is rejected.

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double      h = 1. / 31., c = std::sqrt(4e3), theta = 30. * M_PI / 31.;
  const std::string points          = "subsection Particles\n"
                                      " set Particles per cell = 2\nend\n";
  const auto        exact_time_step = [&](const std::string &mass) {
    return 2. /
           std::sqrt(
             (c / h) * (c / h) * (2. - 2. * std::cos(theta)) /
             (mass == "lumped" ? 1. : 10. / 16. + 6. / 16. * std::cos(theta)));
  };
  for (const std::string mass : {"lumped", "consistent"})
    {
      const double exact = exact_time_step(mass);
      auto         simulator =
        make_simulator<1>("B1b-bar-fixed-ends.prm",
                          "set Mass matrix = " + mass + "\n" + points,
                          "output-stable-time-step");
      const double estimate = simulator->stable_time_step();
      deallog << mass << " mass: stable time step " << rounded(estimate, 6)
              << " (exact " << rounded(exact, 6)
              << ") = " << rounded(estimate * c / h, 4) << " h / c"
              << std::endl;
      check(std::abs(estimate / exact - 1.) < 1e-6,
            mass + ": the estimate is not the exact stable time step");
    }

  auto simulator =
    make_simulator<1>("B1b-bar-fixed-ends.prm",
                      points + "subsection Time\n set Time step = auto\n"
                               " set Courant factor = 0.25\nend\n",
                      "output-stable-time-step");
  check(std::abs(simulator->time_step_size() /
                   (0.25 * simulator->stable_time_step()) -
                 1.) < 1e-14,
        "Time step = auto is not the Courant factor times the stable one");
  deallog << "Time step = auto, Courant factor = 0.25: "
          << rounded(simulator->time_step_size() /
                     simulator->stable_time_step())
          << " of the stable time step" << std::endl;

  bool rejected = false;
  try
    {
      make_simulator<1>("B1b-bar-fixed-ends.prm",
                        points + "subsection Time\n set Time step = " +
                          std::to_string(1.01 * exact_time_step("lumped")) +
                          "\nend\n",
                        "output-stable-time-step");
    }
  catch (const std::exception &error)
    {
      rejected =
        std::string(error.what()).find("exceeds the stable time step") !=
        std::string::npos;
    }
  check(rejected, "a time step 1 % above the stable one was accepted");
  deallog << "a time step 1 % above the stable one is rejected" << std::endl;
}
