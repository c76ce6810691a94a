// B3 with MPM-P1 (journal Sect. 8.3, Fig. 9) from
// prm/B3-plate-manufactured.prm: the run reaches T = 3.5e-3, writes the
// sigma11 profile of the particle row X2 ~ 0.07 (particles-00035.csv), and
// its displacement error stays small against the amplitude A = 0.005 while
// the stress error shows the piecewise-constant P1 stress (journal: MPM-P1
// far from the exact stress).

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/problems/problem.h>

#include <fstream>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  auto       simulator  = make_simulator<2>("B3-plate-manufactured.prm",
                                     "subsection Output\n set Interval = 0\n"
                                            "end",
                                     "output-B3");
  const auto statistics = simulator->run();
  check(std::abs(simulator->time() - 3.5e-3) < 1e-15, "did not reach T");

  // The sigma11 profile: rows of particles-00035.csv with Y = 0.06640625.
  std::ifstream csv("output-B3/particles-00035.csv");
  std::string   line;
  std::getline(csv, line);
  check(line == "id,X,Y,x,y,ux,uy,vx,vy,sxx,syy,sxy,volume,mass",
        "unexpected CSV header " + line);
  unsigned int n_row = 0;
  double       worst = 0, largest = 0;
  while (std::getline(csv, line))
    {
      std::vector<double> values;
      std::stringstream   fields(line);
      std::string         field;
      while (std::getline(fields, field, ','))
        values.push_back(std::stod(field));
      if (std::abs(values[2] - 0.06640625) > 1e-9)
        continue;
      const Point<2> X(values[1], values[2]);
      const double   exact = simulator->problem().exact_stress(X, 3.5e-3)[0][0];
      worst                = std::max(worst, std::abs(values[9] - exact));
      largest              = std::max(largest, std::abs(exact));
      ++n_row;
    }
  check(n_row == 128, "the profile row should hold 128 particles");
  check(statistics.displacement_rms_error < 0.03 * 0.005,
        "displacement error above 3 % of the amplitude");
  check(worst < 0.5 * largest, "sigma11 deviates by more than 50 %");
  deallog << "sigma11 profile: " << n_row << " points, largest deviation "
          << std::fixed << std::setprecision(0) << 100. * worst / largest
          << " % of the largest exact stress" << std::endl;
  deallog << "RMS displacement error / A: " << std::setprecision(1)
          << 100. * statistics.displacement_rms_error / 0.005 << " %"
          << std::endl;
}
