// Time step = auto does not depend on the number of ranks (issue 36): the
// Lanczos estimate of the stable time step starts from a vector that
// depends on the points' initial positions, not on the global function
// numbers (which depend on the partition), so that one and two ranks find
// the same step to round-off, also where 60 Lanczos steps do not converge;
// and a run resumed from a checkpoint continues with the step it was
// started with, on any number of ranks.
//  - G5's slope (0.5 m cells, lumped mass, MUSL; 60 Lanczos steps do not
//    converge, and before one rank took 2.05967e-3 s and two 2.05968e-3 s)
//    and B5's bar with Powell-Sabin splines and a consistent mass on a fully
//    distributed grid of triangles: the step of one rank and of two agree
//    to 1e-9 and give the same number of steps to the end time (15 s and
//    10 s);
//  - G5 run on one rank with checkpoints and resumed on two: the resumed
//    run has the first run's step exactly.

#include <tuple>
#include <vector>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  /**
   * The time step of prm/@p prm with @p changes on @p communicator (0 on the
   * ranks outside it), known on every rank of the world.
   */
  double
  time_step(const std::string &prm,
            const std::string &changes,
            const std::string &directory,
            const MPI_Comm     communicator)
  {
    double step = 0;
    if (communicator != MPI_COMM_NULL)
      step = make_simulator<2>(prm, changes, directory, communicator)
               ->time_step_size();
    return Utilities::MPI::max(step, MPI_COMM_WORLD);
  }

  const std::string slope =
    "subsection Time\n set End time = 0.05\nend\n"
    "subsection Mesh\n set Subdivisions = 90, 32\nend\n";
  const std::string powell_sabin =
    "subsection Time\n set End time = 10\n set Time step = auto\nend\n";
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  MPI_Comm single = first_rank_only();

  for (const auto &[name, prm, changes, end_time] :
       std::vector<std::tuple<std::string, std::string, std::string, double>>{
         {"G5 slope", "G5-slope.prm", slope, 15.},
         {"B5 bar, Powell-Sabin, consistent mass",
          "B5-bar-2d-small-powell-sabin.prm",
          powell_sabin,
          10.}})
    {
      const double one = time_step(prm, changes, "output-auto-1", single);
      const double two =
        time_step(prm, changes, "output-auto-2", MPI_COMM_WORLD);
      const auto n_steps = [&](const double dt) {
        return static_cast<unsigned int>(std::ceil(end_time / dt - 1e-8));
      };
      const bool same =
        std::abs(one - two) <= 1e-9 * one && n_steps(one) == n_steps(two);
      deallog << name << ": the time step of 1 and 2 ranks "
              << (same ? "agrees to 1e-9" : "DIFFERS") << ", " << n_steps(one)
              << " steps to t = " << Utilities::to_string(end_time) << " s"
              << std::endl;
      check(same,
            name + ": 1 rank " + std::to_string(one) + " s, 2 ranks " +
              std::to_string(two) + " s");
    }

  // Started on one rank, resumed on two.
  const std::string checkpoints =
    slope + "subsection Checkpoint\n set Interval = 10\nend\n";
  double started = 0;
  if (single != MPI_COMM_NULL)
    {
      auto simulator = make_simulator<2>("G5-slope.prm",
                                         checkpoints,
                                         "output-auto-resume",
                                         single);
      started        = simulator->time_step_size();
      simulator->run();
    }
  started              = Utilities::MPI::max(started, MPI_COMM_WORLD);
  const double resumed = make_simulator<2>("G5-slope.prm",
                                           checkpoints,
                                           "output-auto-resume",
                                           MPI_COMM_WORLD,
                                           true)
                           ->time_step_size();
  deallog << "resumed on 2 ranks: the time step is the first run's "
          << (resumed == started ? "exactly" : "NOT") << std::endl;
  check(resumed == started, "the resumed run changed the time step");

  if (single != MPI_COMM_NULL)
    MPI_Comm_free(&single);
}
