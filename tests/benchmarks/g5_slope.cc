// G5 (BENCHMARKS.md): the slope of prm/G5-slope.prm (10 m high, 1V:1.5H,
// Mohr-Coulomb phi = 30 deg, psi = 0) released from K0 with local damping,
// on 0.5 m cells with the default 2 x 2 points per cell and the default
// F-bar remedy, ended by its quasi-static end. Bishop's simplified method
// (doc/scripts/bishop_slope.py) puts the critical cohesion at 0.87 kPa;
// with c = 0 the infinite-slope factor is 0.866. Asserted, to t = 8 s:
//  - c = 0 slides: not at rest, its largest displacement above 1 m;
//  - c = 0.7 x 0.87 kPa fails and c = 1.3 x 0.87 kPa stands (at rest before
//    8 s, largest displacement below 0.5 m): the program's critical
//    cohesion lies within 30 % of Bishop's (BENCHMARKS.md, 0.5 m cells).
// (Without a remedy the c = 0 slope stood on these cells:
// doc/benchmarks.md.)

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  /**
   * Run the slope with cohesion @p cohesion (Pa) to 8 s; return whether it
   * came to rest and its largest displacement.
   */
  std::pair<bool, double>
  slope(const double cohesion)
  {
    std::ostringstream changes;
    changes
      << "subsection Material\n subsection Mohr-Coulomb\n  set Cohesion = "
      << cohesion << "\n end\nend\nsubsection Time\n set End time = 8\n"
      << "end\nsubsection Output\n set Time interval = 8\nend\n";
    auto simulator =
      make_simulator<2>("G5-slope.prm", changes.str(), "output-G5");
    simulator->run();
    double largest = 0;
    for (const auto &particle : simulator->material_points().particle_handler())
      largest = std::max(largest,
                         (particle.get_location() -
                          Point<2>(PropertyLayout<2>::get_vector(
                            particle.get_properties(),
                            PropertyLayout<2>::initial_position)))
                           .norm());
    deallog << "c = " << cohesion << " Pa: "
            << (simulator->at_rest() ? "at rest at t = " :
                                       "still moving at t = ")
            << std::setprecision(3) << simulator->time()
            << ", largest displacement " << largest << " m" << std::endl;
    return {simulator->at_rest(), largest};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double bishop = 870.;
  const auto   zero   = slope(0.);
  check(!zero.first && zero.second > 1., "the slope with c = 0 stands");
  const auto weak = slope(0.7 * bishop);
  check(!weak.first, "the slope with c = 0.7 c_Bishop stands");
  const auto strong = slope(1.3 * bishop);
  check(strong.first && strong.second < 0.5,
        "the slope with c = 1.3 c_Bishop does not come to rest");
}
