// B1b (journal Sect. 8.1, Fig. 6) with OTM-P1 (Alg. 2, consistent mass
// matrix of Eq. 48) and the unified approach with P1 (Alg. 3): RMS
// displacement error at T against the exact solution for 8, ..., 512 nodes.
// Published behaviour: second-order convergence kept on the fine grids where
// MPM-P1 loses it (grid crossing; tests/benchmarks/b1b_convergence.cc),
// because the grid moves with the material and no point crosses a cell
// boundary. With P1 functions and a consistent mass matrix the unified
// approach gives OTM's result: the points keep their reference coordinates,
// so q = M v holds exactly and the particle-velocity updates of Eqs. 57 and
// 97 coincide.

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
      const std::string mesh =
        "subsection Mesh\n set Subdivisions = " + std::to_string(nodes - 1) +
        "\nend\n";
      const double otm =
        make_simulator<1>("B1b-bar-fixed-ends-otm.prm",
                          mesh,
                          "output-otm-" + std::to_string(nodes))
          ->run()
          .displacement_rms_error;
      const double unified =
        make_simulator<1>("B1b-bar-fixed-ends-otm.prm",
                          mesh + "set Method = Unified\n",
                          "output-unified-" + std::to_string(nodes))
          ->run()
          .displacement_rms_error;
      check(std::abs(unified - otm) <= 1e-6 * otm,
            "unified P1 with a consistent mass matrix differs from OTM");
      errors.push_back(otm);
      deallog << nodes << " nodes: OTM-P1 RMS displacement error "
              << rounded(otm, 2);
      if (errors.size() > 1)
        deallog << ", rate " << std::fixed << std::setprecision(1)
                << std::log2(errors[errors.size() - 2] / errors.back())
                << std::defaultfloat;
      deallog << std::endl;
    }
  // Second order on every refinement, the finest included.
  for (unsigned int i = 1; i < errors.size(); ++i)
    check(std::log2(errors[i - 1] / errors[i]) > 1.8,
          "OTM-P1 loses second-order convergence at " +
            std::to_string(8u << i) + " nodes");
}
