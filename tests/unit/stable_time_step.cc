// The stable time step 2 / omega_max that the simulator estimates at the
// start (StableTimeStep, Lanczos), against closed forms.
//
// A 1D bar with fixed ends (prm/B1b-bar-fixed-ends.prm: 31 cells of
// h = 1/31, E = 4e3, rho = 1, c = sqrt(E / rho)), linear functions and two
// points per cell at h/4 and 3h/4. Its n = 30 free nodes share the
// eigenvectors sin(j pi i / (n + 1)) of the Toeplitz matrices
// K = (E / h) tridiag(-1, 2, -1), the consistent mass
// M_C = rho h tridiag(3/16, 10/16, 3/16) (sum_p m_p phi_i phi_j with these
// points) and the lumped one M_L = rho h I, so with theta = n pi / (n + 1),
// k = (c / h)^2 (2 - 2 cos theta) and s = 10/16 + 6/16 cos theta (the
// eigenvalue of M_L^-1 M_C) in the highest mode:
//   consistent:  omega_max^2 = k / s (any update scheme), 0.5026 h / c;
//   lumped, MUSL: omega_max^2 = k, 1.0013 h / c (the thesis' h / c,
//                Eq. 2.48, for an infinite bar);
//   lumped, USL: omega_max^2 = k (2 - s), 0.7573 h / c: the FLIP update
//                of the points carries the accelerations that the
//                projection to the grid sees only through M_L^-1 M_C;
// and dt_stable = 2 / omega_max. The estimate must match within 1e-6. With
// Time step = auto the run's time step is the Courant factor times it, and
// a time step above it is rejected.

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double      h = 1. / 31., c = std::sqrt(4e3), theta = 30. * M_PI / 31.;
  const std::string points = "subsection Particles\n"
                             " set Particles per cell = 2\nend\n";
  const double      k      = (c / h) * (c / h) * (2. - 2. * std::cos(theta));
  const double      s      = 10. / 16. + 6. / 16. * std::cos(theta);
  const auto        exact_time_step = [&](const std::string &mass,
                                   const std::string &scheme) {
    const double omega_squared =
      mass == "consistent" ? k / s : (scheme == "USL" ? k * (2. - s) : k);
    return 2. / std::sqrt(omega_squared);
  };
  for (const std::string mass : {"lumped", "consistent"})
    for (const std::string scheme : {"USL", "MUSL"})
      {
        const double exact = exact_time_step(mass, scheme);
        auto         simulator =
          make_simulator<1>("B1b-bar-fixed-ends.prm",
                            "set Mass matrix = " + mass +
                              "\nset Update scheme = " + scheme + "\n" + points,
                            "output-stable-time-step");
        const double estimate = simulator->stable_time_step();
        deallog << mass << " mass, " << scheme << ": stable time step "
                << rounded(estimate, 6) << " (exact " << rounded(exact, 6)
                << ") = " << rounded(estimate * c / h, 4) << " h / c"
                << std::endl;
        check(std::abs(estimate / exact - 1.) < 1e-6,
              mass + ", " + scheme +
                ": the estimate is not the exact stable time step");
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
                          std::to_string(1.01 *
                                         exact_time_step("lumped", "USL")) +
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
