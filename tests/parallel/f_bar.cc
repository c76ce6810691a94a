// The F-bar remedy on one and on two ranks (the same program writes
// f_bar.output on one rank and f_bar.mpirun=2.output on two; both hold the
// same digits): the G3 footing of prm/G3-prandtl-footing.prm on 20 x 24
// cells, pushed to a settlement of 0.03, with linear functions and with
// quadratic B-splines (whose functions reach over the ranks' boundary; the
// average over a cell needs no communication, since a cell's points are on
// its owner). Printed: the footing load with and without the remedy, to 6
// digits; asserted: the remedy lowers the locked load (by more than 10 %
// for linear functions, which lock most). On a moving grid: OTM with linear
// functions on the manufactured plate B3 (prm/B3-plate-manufactured-otm.prm,
// elastic, nearly homogeneous in each cell), where F-bar must leave the
// displacement error against the exact solution within 1 % of the run
// without it.

#include <array>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  double
  load(const std::string &family, const std::string &remedy)
  {
    const double       h       = 2.5 / 20;
    const bool         splines = family == "B-spline";
    const double       half    = splines ? h : 0.5 * h;
    std::ostringstream changes;
    changes << std::setprecision(10)
            << "set Volumetric locking remedy = " << remedy
            << "\nset Shape functions = " << (splines ? "B-spline" : "linear")
            << "\nsubsection Mesh\n set Subdivisions = 20, 24\n"
            << "end\nsubsection Time\n set Time step = 8e-4\n"
            << " set End time = 0.36\nend\n"
            << "subsection Boundary footing\n"
            << " set Box lower corner = 0, " << 2.5 - half + 1e-6
            << "\n set Box upper corner = 0.5001, " << 2.5 + half - 1e-6
            << "\nend\nsubsection Output\n set Interval = 10\nend\n";
    auto   simulator = make_simulator<2>("G3-prandtl-footing.prm",
                                       changes.str(),
                                       "output-f-bar-" + family + "-" + remedy);
    double force     = 0;
    simulator->run([&](const unsigned int, const Statistics<2> &statistics) {
      force = -statistics.boundary_reactions[0].first[1];
    });
    return force;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const std::string family : {"linear", "B-spline"})
    {
      const double locked = load(family, "none");
      const double f_bar  = load(family, "F-bar");
      deallog << family << ": footing load at a settlement of 0.03 "
              << std::setprecision(6) << locked << " N/m without a remedy, "
              << f_bar << " N/m with F-bar" << std::endl;
      check(f_bar < (family == "B-spline" ? 1. : 0.9) * locked,
            family + ": F-bar does not lower the locked load");
    }
  std::array<double, 2> error{};
  for (const unsigned int remedy : {0u, 1u})
    make_simulator<2>("B3-plate-manufactured-otm.prm",
                      std::string("set Volumetric locking remedy = ") +
                        (remedy ? "F-bar" : "none"),
                      "output-f-bar-otm")
      ->run([&](const unsigned int, const Statistics<2> &statistics) {
        error[remedy] = statistics.displacement_rms_error;
      });
  deallog << "OTM, B3: displacement RMS error " << std::setprecision(6)
          << error[0] << " without a remedy, " << error[1] << " with F-bar"
          << std::endl;
  check(std::abs(error[1] / error[0] - 1.) < 0.01,
        "OTM: F-bar changes the error of B3");
}
