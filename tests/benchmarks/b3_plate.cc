// B3 with MPM-P1, OTM-P1, BSMPM and the unified approach (journal Sect. 8.3,
// Fig. 9) from prm/B3-plate-manufactured{,-otm,-bsmpm,-unified}.prm: each
// run reaches T = 3.5e-3, writes the sigma11 profile of the particle row
// X2 ~ 0.07 (particles-00035.csv), and its displacement error stays small
// against the amplitude A = 0.005. Published behaviour: P1 gives a
// piecewise-constant stress, MPM-P1 far off because of grid crossing, OTM-P1
// without grid-crossing errors; BSMPM and unified (quadratic B-splines)
// smoothest and closest.

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/problems/problem.h>

#include <fstream>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  struct Profile
  {
    unsigned int n_points           = 0;
    double       largest_deviation  = 0;
    double       largest_exact      = 0;
    double       displacement_error = 0;
  };

  // Run @p prm to T and read the sigma11 profile of the row Y = 0.06640625
  // from its particles-00035.csv.
  Profile
  run(const std::string &prm, const std::string &directory)
  {
    auto    simulator = make_simulator<2>(prm,
                                       "subsection Output\n set Interval = 0\n"
                                          "end",
                                       directory);
    Profile profile;
    profile.displacement_error = simulator->run().displacement_rms_error;
    check(std::abs(simulator->time() - 3.5e-3) < 1e-15, "did not reach T");

    std::ifstream csv(directory + "/particles-00035.csv");
    std::string   line;
    std::getline(csv, line);
    check(line.rfind("id,X,Y,x,y,ux,uy,vx,vy,sxx,syy,sxy,volume,mass,", 0) == 0,
          "unexpected CSV header " + line);
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
        const double exact = simulator->problem().exact_stress(X, 3.5e-3)[0][0];
        profile.largest_deviation =
          std::max(profile.largest_deviation, std::abs(values[9] - exact));
        profile.largest_exact =
          std::max(profile.largest_exact, std::abs(exact));
        ++profile.n_points;
      }
    check(profile.n_points == 128, "the profile row should hold 128 particles");
    deallog << prm << ": sigma11 profile of " << profile.n_points
            << " points, largest deviation " << std::fixed
            << std::setprecision(1)
            << 100. * profile.largest_deviation / profile.largest_exact
            << " % of the largest exact stress; RMS displacement error / A "
            << std::setprecision(2) << 100. * profile.displacement_error / 0.005
            << " %" << std::defaultfloat << std::endl;
    return profile;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const Profile mpm = run("B3-plate-manufactured.prm", "output-B3");
  check(mpm.displacement_error < 0.03 * 0.005,
        "MPM-P1: displacement error above 3 % of the amplitude");
  check(mpm.largest_deviation < 0.5 * mpm.largest_exact,
        "MPM-P1: sigma11 deviates by more than 50 %");

  // OTM-P1: no grid crossing, so only the piecewise-constant P1 stress is
  // left. Over a cell of width h = 1/32 the exact sigma11 ~ cos(2 pi X1)
  // changes by at most 2 pi h = 20 % of its amplitude, so a cell-wise
  // constant stress deviates from it by at most about half of that.
  const Profile otm = run("B3-plate-manufactured-otm.prm", "output-B3-otm");
  check(otm.largest_deviation < 0.1 * otm.largest_exact,
        "OTM-P1: sigma11 deviates by more than the P1 bound of 10 %");
  check(otm.largest_deviation < 0.5 * mpm.largest_deviation,
        "OTM-P1 stress should be far closer than MPM-P1's");
  check(otm.displacement_error < 0.5 * mpm.displacement_error,
        "OTM-P1 displacement error should be below MPM-P1's");

  // Quadratic B-splines (consistent mass): smooth stress, the closest to the
  // exact one, with and without moving knots.
  for (const std::string method : {"bsmpm", "unified"})
    {
      const Profile spline =
        run("B3-plate-manufactured-" + method + ".prm", "output-B3-" + method);
      check(spline.largest_deviation < 0.5 * otm.largest_deviation,
            method + ": sigma11 should be far closer than OTM-P1's");
      check(spline.displacement_error < 0.2 * otm.displacement_error,
            method + ": displacement error should be far below OTM-P1's");
    }
}
