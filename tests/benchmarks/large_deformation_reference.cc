// The 1D updated-Lagrangian reference solutions of the large-deformation
// benchmarks B5 (thesis Table 4.4) and B6 (Table 4.6): OTM with linear
// shape functions on a grid that moves with the material
// (prm/B5-bar-large-reference-1d.prm,
// prm/B6-soil-column-large-reference-1d.prm; doc/benchmarks.md compares
// Lagrange MPM with them). The reference is only as good as these checks:
// 1. At a strain 1000 times smaller the B5 reference set-up reproduces the
//    exact small-strain solution (BENCHMARKS.md B1/B5) at the middle of the
//    bar over half a period.
// 2. At the benchmark strains (7 % and 18 %), halving the cell size changes
//    the tracked displacement (middle of the bar, top of the column) by a
//    small fraction of its range over the whole run: the reference is
//    converged on the fine grids of the prm files, which are finer still.
// The grids and time steps are coarser than in the prm files to keep the
// test short.

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/problems/problem.h>

#include <array>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  using Layout = PropertyLayout<1>;

  // Mean displacement of the points with initial position in [from, to].
  double
  mean_displacement(const Simulator<1> &simulator,
                    const double        from,
                    const double        to)
  {
    double       sum = 0;
    unsigned int n   = 0;
    for (const auto &particle : simulator.material_points().particle_handler())
      {
        const double X = Layout::get_vector(particle.get_properties(),
                                            Layout::initial_position)[0];
        if (X >= from && X <= to)
          {
            sum += particle.get_location()[0] - X;
            ++n;
          }
      }
    check(n > 0, "no material point in the tracked range");
    return sum / n;
  }

  // Displacement of the points in [from, to] at every output step.
  std::vector<double>
  history(const std::string &prm,
          const std::string &changes,
          const std::string &directory,
          const double       from,
          const double       to)
  {
    auto simulator = make_simulator<1>(
      prm,
      changes + "subsection Output\n set Write particle CSV = false\nend\n",
      directory);
    std::vector<double> values;
    simulator->run([&](unsigned int, const Statistics<1> &) {
      values.push_back(mean_displacement(*simulator, from, to));
    });
    return values;
  }

  // Largest difference of two histories relative to the range of the first.
  double
  relative_difference(const std::vector<double> &fine,
                      const std::vector<double> &coarse)
  {
    check(fine.size() == coarse.size(), "histories of different length");
    double difference = 0, low = 0, high = 0;
    for (unsigned int i = 0; i < fine.size(); ++i)
      {
        difference = std::max(difference, std::abs(fine[i] - coarse[i]));
        low        = std::min(low, fine[i]);
        high       = std::max(high, fine[i]);
      }
    return difference / (high - low);
  }
  // A grid of a convergence check: its number of cells and the range of
  // initial positions of the tracked points.
  struct TrackedGrid
  {
    unsigned int cells;
    double       from;
    double       to;
  };

  // The largest difference between the tracked displacement histories of
  // prm/@p prm on the @p fine and the @p coarse grid, relative to the range
  // of the fine one.
  double
  halving_change(const std::string &prm,
                 const std::string &common,
                 const std::string &label,
                 const TrackedGrid &fine,
                 const TrackedGrid &coarse)
  {
    std::vector<double> histories[2];
    const TrackedGrid  *grids[2] = {&fine, &coarse};
    for (unsigned int i = 0; i < 2; ++i)
      histories[i] =
        history(prm,
                common + "subsection Mesh\n set Subdivisions = " +
                  std::to_string(grids[i]->cells) + "\nend\n",
                "output-" + label + "-" + std::to_string(grids[i]->cells),
                grids[i]->from,
                grids[i]->to);
    return relative_difference(histories[0], histories[1]);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  // 1. B5 set-up at v0 = 1e-4 (strain 7e-5), 125 cells, to T = 17.5 s (about
  //    half a period 2 L / c = 35.4 s).
  {
    const std::string         small  = "subsection Vibrating bar\n"
                                       " set Initial velocity amplitude = 1e-4\nend\n"
                                       "subsection Time\n set End time = 17.5\n"
                                       " set Time step = 1e-2\nend\n"
                                       "subsection Mesh\n set Subdivisions = 125\nend\n"
                                       "subsection Output\n set Interval = 50\nend\n";
    const std::vector<double> middle = history("B5-bar-large-reference-1d.prm",
                                               small,
                                               "output-b5-small-strain",
                                               12.4,
                                               12.6);
    const double c = std::sqrt(50. / 25.), omega = numbers::PI * c / 25.;
    double       worst = 0;
    for (unsigned int i = 0; i < middle.size(); ++i)
      {
        // u(X, t) = (v0 / w) sin(w t) sin(pi X / L) at the middle, averaged
        // over the points in [12.4, 12.6] (a relative 1e-4 below the peak).
        const double exact = 1e-4 / omega * std::sin(omega * i * 0.5);
        worst              = std::max(worst, std::abs(middle[i] - exact));
      }
    const double amplitude = 1e-4 / omega;
    deallog << "B5 reference at strain 7e-5: largest deviation from the exact "
               "solution at the middle "
            << rounded(worst / amplitude, 1) << " of the amplitude"
            << std::endl;
    check(worst < 1e-3 * amplitude,
          "the B5 reference set-up misses the small-strain exact solution");
  }

  // 2. B5 at the benchmark strain, T = 20 s, 62 and 125 cells (the two
  //    points nearest the middle on each grid).
  const double b5 =
    halving_change("B5-bar-large-reference-1d.prm",
                   "subsection Time\n set End time = 20\n"
                   " set Time step = 1e-2\nend\n"
                   "subsection Output\n set Interval = 50\nend\n",
                   "b5",
                   TrackedGrid{125, 12.4, 12.6},
                   TrackedGrid{62, 12.3, 12.7});
  deallog << "B5 reference, 62 vs 125 cells: largest difference "
          << rounded(b5, 1) << " of the displacement range" << std::endl;
  check(b5 < 0.005, "the B5 reference is not converged");

  // 3. B6 at the benchmark strain, T = 0.5 s, 50 and 100 cells: the top.
  const double b6 =
    halving_change("B6-soil-column-large-reference-1d.prm",
                   "subsection Time\n set End time = 0.5\n"
                   " set Time step = 1e-4\nend\n"
                   "subsection Output\n set Interval = 100\nend\n",
                   "b6",
                   TrackedGrid{100, 0.99, 1.},
                   TrackedGrid{50, 0.99, 1.});
  deallog << "B6 reference, 50 vs 100 cells: largest difference "
          << rounded(b6, 1) << " of the top displacement range" << std::endl;
  check(b6 < 0.005, "the B6 reference is not converged");
}
