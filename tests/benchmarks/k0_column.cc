// A Mohr-Coulomb column at rest under its own weight from a geostatic start
// (prm/K0-column-at-rest.prm): 2 m x 9.8 m on 0.5 m cells, so that the soil
// surface lies inside a cell as on a user's grid, 2 x 2 points per cell,
// K0 = 1 - sin 30 deg = 0.5, damped to t = 1 s and free to t = 2 s. Exact:
// the mean stress of a point that started at height Y is
// p = -(1 + 2 K0) / 3 gamma (9.8 - Y), whatever the column's (small)
// settlement, since the weight above a point does not change. Asserted for
// the default F-bar remedy and without a remedy:
//  - every point's mean stress within 1 % of gamma H (1 + 2 K0) / 3, the
//    mean stress at the base, of the exact one;
//  - the column at rest: no point moved by more than 1e-3 m;
//  - the point-to-point oscillation of the mean stress (the largest
//    difference between points that started at the same height, and the
//    largest second difference down a column of points, both over the base
//    value) is printed for both and is below 1e-3: in a column every point of
//    a cell has the same velocity gradient, so F-bar changes nothing here
//    (the oscillation F-bar removes in a plastic flow: doc/benchmarks.md, G3).

#include <deal.II/base/mpi.h>

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>

#include <map>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using Layout        = PropertyLayout<2>;
  const double gamma  = 1900. * 9.81;
  const double height = 9.8;
  const double K0     = 0.5;
  const double base   = (1. + 2. * K0) / 3. * gamma * height;
  for (const std::string remedy : {"F-bar", "none"})
    {
      auto simulator = make_simulator<2>(
        "K0-column-at-rest.prm",
        "set Volumetric locking remedy = " + remedy +
          "\nsubsection Body column\n set Upper corner = 2, 9.8\nend\n"
          "subsection Output\n set Write particle CSV = false\nend\n",
        "output-k0-column");
      simulator->run();
      double                                     error = 0, moved = 0;
      std::map<double, std::map<double, double>> by_height;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const auto   properties = particle.get_properties();
          const auto   sigma      = Layout::get_stress(properties);
          const double p =
            (trace(sigma) + Layout::get_out_of_plane_stress(properties)) / 3.;
          const Point<2> X(
            Layout::get_vector(properties, Layout::initial_position));
          const double exact = -(1. + 2. * K0) / 3. * gamma * (height - X[1]);
          error              = std::max(error, std::abs(p - exact) / base);
          moved = std::max(moved, (particle.get_location() - X).norm());
          by_height[X[1]][X[0]] = (p - exact) / base;
        }
      double              across = 0, down = 0;
      std::vector<double> column;
      for (const auto &row : by_height)
        {
          double low = 1e300, high = -1e300;
          for (const auto &point : row.second)
            {
              low  = std::min(low, point.second);
              high = std::max(high, point.second);
            }
          across = std::max(across, high - low);
          column.push_back(row.second.begin()->second);
        }
      for (unsigned int i = 1; i + 1 < column.size(); ++i)
        down =
          std::max(down,
                   std::abs(column[i - 1] - 2 * column[i] + column[i + 1]));
      deallog << remedy << ": largest mean-stress error " << std::fixed
              << std::setprecision(2) << 100. * error
              << " % of the base value; oscillation across "
              << std::setprecision(3) << 100. * across << " %, down "
              << 100. * down << " %" << std::defaultfloat << std::endl;
      check(error < 0.01, remedy + ": the mean stress is not within 1 %");
      check(moved < 1e-3, remedy + ": the column does not stay at rest");
      check(across < 1e-3 && down < 1e-3,
            remedy + ": the mean stress oscillates from point to point");
    }
}
