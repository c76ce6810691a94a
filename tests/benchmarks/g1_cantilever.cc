// G1 (BENCHMARKS.md): the elastic cantilever of prm/G1-cantilever-static.prm
// and prm/G1-cantilever-vibration.prm under its own weight, MPM with linear
// functions and with quadratic B-splines (MUSL, lumped mass; BENCHMARKS.md
// expects both) on 4 cells across the depth h (48 x 16 cells, half the prm
// files' resolution, to keep the Debug run short; dt scaled with h).
//  - Static: the mean tip deflection (the last column of points) must be
//    within 2 % of Timoshenko's 1.0080e-2 (BENCHMARKS.md:
//    rho g L^4 3 / (2 E h^2) + rho g L^2 / (2 kappa G)), and the clamp's
//    vertical reaction must carry the weight rho g L h = 981 N/m within 1 %.
//    Linear functions come to rest with local damping (0.15 for 0.4 s: the
//    tip is then within 0.3 % of where it stays). Quadratic B-splines creep
//    towards rest from below under local damping (with 0.15 the clamp still
//    carries 0.4 % less than the weight at t = 1 s), so their static state
//    is the mean over one period after gravity ramped up over two periods
//    (Gravity/Ramp time = 0.33 s; a linear ramp over whole periods leaves
//    the first mode at rest), undamped: this also tests the ramp.
//  - Vibration: undamped, gravity switched on at t = 0; the period of the
//    tip between two up-crossings of the static deflection must be within
//    2 % of Timoshenko's 0.1624 s (Euler-Bernoulli: 0.1614 s), and the
//    total energy, kinetic + strain + gravitational, must stay within 1 %
//    of the largest strain energy of its initial 0 (the energy that passes
//    from the gravitational to the strain energy: without the
//    gravitational part the total would grow by 100 % of it).

#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  const std::string coarse =
    "subsection Mesh\n set Subdivisions = 48, 16\nend\n"
    "subsection Time\n set Time step = 5e-5\nend\n";

  /**
   * A family of shape functions: its name, its entries, and how the static
   * run reaches rest, with the time from which the tip and the reaction
   * are averaged.
   */
  struct Family
  {
    std::string name;
    std::string entries;
    std::string static_run;
    double      averaged_from;
  };

  const std::vector<Family> families = {
    {"linear",
     "set Shape functions = linear\n",
     "subsection Time\n set End time = 0.4\nend\n"
     "subsection Damping\n set Local damping coefficient = 0.15\nend\n",
     0.3},
    {"quadratic B-splines",
     "set Shape functions = B-spline\nset B-spline degree = 2\n",
     "subsection Time\n set End time = 0.494\nend\n"
     "subsection Damping\n set Local damping coefficient = 0\nend\n"
     "subsection Gravity\n set Ramp time = 0.33\nend\n",
     0.33}};

  /**
   * Mean vertical displacement of the points with X > 0.99 (the last
   * column of points, at X = 0.99375).
   */
  double
  tip_deflection(const MaterialPoints<2> &points)
  {
    using Layout     = PropertyLayout<2>;
    double       sum = 0;
    unsigned int n   = 0;
    for (const auto &particle : points.particle_handler())
      {
        const auto properties = particle.get_properties();
        if (properties[Layout::initial_position] > 0.99)
          {
            sum += particle.get_location()[1] -
                   properties[Layout::initial_position + 1];
            ++n;
          }
      }
    return sum / n;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const double timoshenko_deflection = 1.0080e-2;
  const double timoshenko_period     = 0.1624;
  for (const auto &family : families)
    {
      deallog << family.name << ":" << std::endl;
      double static_deflection = 0;
      {
        auto simulator =
          make_simulator<2>("G1-cantilever-static.prm",
                            coarse + family.entries + family.static_run +
                              "subsection Output\n set Interval = 20\n"
                              " set Write particle CSV = false\nend\n",
                            "output-G1-static");
        double       reaction   = 0;
        unsigned int n_averaged = 0;
        static_deflection       = 0;
        simulator->run([&](const unsigned int,
                           const Statistics<2> &statistics) {
          if (simulator->time() >= family.averaged_from - 1e-12)
            {
              static_deflection -= tip_deflection(simulator->material_points());
              reaction += statistics.boundary_reactions[0].first[1];
              ++n_averaged;
            }
        });
        check(n_averaged > 0, "no step to average over");
        static_deflection /= n_averaged;
        reaction /= n_averaged;
        const double weight = 1000. * 9.81 * 1. * 0.1;
        deallog << "static tip deflection " << rounded(static_deflection)
                << " (Timoshenko 1.008e-02), clamp reaction "
                << rounded(reaction) << " N/m (weight " << rounded(weight)
                << ")" << std::endl;
        check(std::abs(static_deflection / timoshenko_deflection - 1.) < 0.02,
              "static tip deflection not within 2 % of Timoshenko's");
        check(std::abs(reaction / weight - 1.) < 0.01,
              "the clamp does not carry the weight");
      }
      {
        auto simulator =
          make_simulator<2>("G1-cantilever-vibration.prm",
                            coarse + family.entries +
                              "subsection Time\n set End time = 0.25\nend\n"
                              "subsection Output\n set Interval = 20\n"
                              " set Write particle CSV = false\nend\n",
                            "output-G1-vibration");
        std::vector<double> crossings;
        double              previous_time = 0, previous_tip = 0;
        double              largest_strain = 0, largest_total = 0;
        simulator->run(
          [&](const unsigned int, const Statistics<2> &statistics) {
            largest_strain = std::max(largest_strain, statistics.strain_energy);
            largest_total  = std::max(largest_total,
                                     std::abs(statistics.kinetic_energy +
                                              statistics.strain_energy +
                                              statistics.gravitational_energy));
            const double t = simulator->time();
            const double tip = -tip_deflection(simulator->material_points());
            if (t > 0 && previous_tip < static_deflection &&
                tip >= static_deflection)
              crossings.push_back(previous_time +
                                  (static_deflection - previous_tip) /
                                    (tip - previous_tip) * (t - previous_time));
            previous_time = t;
            previous_tip  = tip;
          });
        check(crossings.size() >= 2, "fewer than two up-crossings");
        const double period = crossings[1] - crossings[0];
        deallog << "period " << rounded(period) << " s (Timoshenko 1.624e-01)"
                << std::endl;
        check(std::abs(period / timoshenko_period - 1.) < 0.02,
              "period not within 2 % of Timoshenko's");
        deallog << "largest |total energy| / largest strain energy "
                << rounded(largest_total / largest_strain, 1) << std::endl;
        check(largest_total < 0.01 * largest_strain,
              "the total energy is not conserved");
      }
    }
}
