// G3 (BENCHMARKS.md): the smooth strip footing of prm/G3-prandtl-footing.prm
// on a weightless Tresca soil (von Mises, yield stress sqrt(3) c), whose
// limit load is Prandtl's q_u = (2 + pi) c, 25.71 kN/m on the half model.
// To keep the Debug run short the footing moves at 0.2 m/s (ramped over
// 0.1 s; the inertia of the soil is then below 1e-3 of the load after the
// ramp) to 0.3 s, on 20 x 24 and 40 x 48 cells (the prm file's grid), with
// dt = 0.83 of the CFL bound. doc/benchmarks.md has the prm file's runs and
// 80 x 96 cells, where the load levels off 6 % above q_u.
// Linear MPM locks under the isochoric plastic flow, so the discrete limit
// loads lie above q_u and fall towards it under refinement. Asserted, for
// the load averaged over the settlement 0.03-0.05 (t = 0.2-0.3 s):
//  - on each grid it lies above q_u and it levels off: its means over
//    t = 0.2-0.25 and 0.25-0.3 differ by less than 5 %;
//  - its excess over q_u falls by at least a third from the coarse to the
//    fine grid (first-order convergence would halve it).

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  /**
   * Mean load of the footing over [0.2, 0.25] and [0.25, 0.3] on a grid of
   * @p n x 1.2 n cells.
   */
  std::array<double, 2>
  plateau(const unsigned int n)
  {
    const double       h  = 2.5 / n;
    const double       dt = 0.83 * h / 86.5;
    std::ostringstream changes;
    changes << std::setprecision(10)
            << "subsection Mesh\n set Subdivisions = " << n << ", " << 6 * n / 5
            << "\nend\nsubsection Time\n"
            << " set Time step = " << 0.3 / std::ceil(0.3 / dt)
            << "\n set End time = 0.3\nend\n"
            << "subsection Boundary footing\n"
            << " set Velocity = 0; -0.2*min(t/0.1, 1)\n"
            << " set Box lower corner = 0, " << 2.5 - 0.5 * h + 1e-6
            << "\n set Box upper corner = 0.5001, " << 2.5 + 0.5 * h - 1e-6
            << "\nend\nsubsection Output\n set Interval = "
            << static_cast<unsigned int>(std::ceil(0.3 / dt) / 12) << "\nend\n";
    auto simulator =
      make_simulator<2>("G3-prandtl-footing.prm", changes.str(), "output-G3");
    std::array<double, 2> sum{{0, 0}}, weight{{0, 0}};
    double                previous_time = 0;
    simulator->run(
      [&](const unsigned int step, const Statistics<2> &statistics) {
        const double t = simulator->time();
        if (step > 0 && t > 0.2 + 1e-9)
          {
            // The reaction is the mean over the steps since the last output.
            const unsigned int half = (t > 0.25 + 1e-9) ? 1 : 0;
            sum[half] -=
              statistics.boundary_reactions[0].first[1] * (t - previous_time);
            weight[half] += t - previous_time;
          }
        previous_time = t;
      });
    return {{sum[0] / weight[0], sum[1] / weight[1]}};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double        limit = (2. + numbers::PI) * 10e3 * 0.5;
  std::vector<double> excess;
  for (const unsigned int n : {20u, 40u})
    {
      const auto   load = plateau(n);
      const double mean = 0.5 * (load[0] + load[1]);
      deallog << n << " x " << 6 * n / 5 << " cells: load " << rounded(load[0])
              << ", " << rounded(load[1]) << " N/m (Prandtl " << rounded(limit)
              << "), " << std::fixed << std::setprecision(1)
              << 100. * (mean / limit - 1.) << " % above" << std::defaultfloat
              << std::endl;
      check(mean > limit, "the discrete limit load lies below Prandtl's");
      check(std::abs(load[1] / load[0] - 1.) < 0.05,
            "the load does not level off");
      excess.push_back(mean - limit);
    }
  check(excess[1] < 2. / 3. * excess[0],
        "the limit load does not approach Prandtl's under refinement");
}
