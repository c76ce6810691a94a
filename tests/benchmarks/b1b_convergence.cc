// B1b (journal Sect. 8.1, Fig. 6, MPM-P1 curve) from
// prm/B1b-bar-fixed-ends.prm: RMS displacement error at T against the exact
// solution for 8, ..., 512 nodes. Published behaviour: second order on coarse
// grids, loss of convergence on fine grids because of grid crossing.

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::vector<double> errors;
  for (const unsigned int nodes : {8u, 16u, 32u, 64u, 128u, 256u, 512u})
    {
      auto simulator = make_simulator<1>(
        "B1b-bar-fixed-ends.prm",
        "subsection Mesh\n set Subdivisions = " + std::to_string(nodes - 1) +
          "\nend\nsubsection Output\n set Write particle CSV = false\nend",
        "output-" + std::to_string(nodes));
      const auto statistics = simulator->run();
      errors.push_back(statistics.displacement_rms_error);
      deallog << nodes << " nodes: RMS displacement error "
              << rounded(statistics.displacement_rms_error, 2);
      if (errors.size() > 1)
        deallog << ", rate " << std::fixed << std::setprecision(1)
                << std::log2(errors[errors.size() - 2] / errors.back())
                << std::defaultfloat;
      deallog << std::endl;
    }
  // Second order from 8 to 64 nodes.
  for (unsigned int i = 1; i <= 3; ++i)
    check(std::log2(errors[i - 1] / errors[i]) > 1.9,
          "no second-order convergence on coarse grids");
  // Journal Fig. 6: the error stalls or grows on the finest grids.
  check(std::log2(errors[5] / errors[6]) < 1.0,
        "MPM-P1 should lose convergence at 512 nodes (grid crossing)");
  check(errors[6] > errors[4] / 4.,
        "MPM-P1 should not keep second order to 512 nodes");
}
