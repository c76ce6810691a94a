// B2 convergence study (journal Sect. 8.2, Fig. 8): RMS displacement error
// at T = 0.1 with 12 points per cell against the number of nodes in the
// material domain, for MPM-P1 and BSMPM (fixed grid 1.25 times the bar,
// prm/B2-traction-bar-convergence.prm) and for OTM-P1 and the unified
// approach with quadratic B-splines (material domain only). Published
// behaviour: the unified approach and BSMPM have the lowest errors, the
// unified approach the highest rate; rates are below the B-splines' order
// because the stress pulse has kinks.

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string short_run = "subsection Time\n set End time = 0.1\nend\n"
                                "subsection Particles\n"
                                " set Particles per cell = 12\nend\n";
  const std::string splines   = "set Shape functions = B-spline\n"
                                "set B-spline degree = 2\n"
                                "set Mass matrix = consistent\n";
  const auto        error     = [](const std::string &prm,
                        const std::string &changes,
                        const std::string &directory) {
    return make_simulator<1>(prm,
                             changes + "subsection Output\n"
                                                  " set Write particle CSV = false\nend\n",
                             directory)
      ->run()
      .displacement_rms_error;
  };

  std::vector<double> unified_errors;
  for (const unsigned int nodes : {33u, 65u})
    {
      const std::string fixed_grid = "subsection Mesh\n set Subdivisions = " +
                                     std::to_string(5 * (nodes - 1) / 4) +
                                     "\nend\n";
      const std::string material_grid =
        "subsection Mesh\n set Subdivisions = " + std::to_string(nodes - 1) +
        "\nend\n";
      const std::string tag     = std::to_string(nodes);
      const double      mpm     = error("B2-traction-bar-convergence.prm",
                               fixed_grid,
                               "output-mpm" + tag);
      const double      bsmpm   = error("B2-traction-bar-convergence.prm",
                                 fixed_grid + splines,
                                 "output-bsmpm" + tag);
      const double      otm     = error("B2-traction-bar-otm.prm",
                               short_run + material_grid,
                               "output-otm" + tag);
      const double      unified = error("B2-traction-bar-unified.prm",
                                   short_run + material_grid,
                                   "output-unified" + tag);
      unified_errors.push_back(unified);
      deallog << nodes << " material nodes: MPM-P1 " << rounded(mpm, 2)
              << ", OTM-P1 " << rounded(otm, 2) << ", BSMPM "
              << rounded(bsmpm, 2) << ", unified " << rounded(unified, 2)
              << std::endl;
      check(unified < otm && otm < mpm,
            "expected unified < OTM-P1 < MPM-P1 at " + tag + " nodes");
      check(bsmpm < otm, "expected BSMPM below OTM-P1 at " + tag + " nodes");
    }
  const double rate = std::log2(unified_errors[0] / unified_errors[1]);
  deallog << "unified rate from 33 to 65 nodes " << std::fixed
          << std::setprecision(1) << rate << std::endl;
  check(rate > 1.8, "unified approach below second order");
}
