// B2 convergence study (journal Sect. 8.2, Fig. 8): RMS displacement error
// at T = 0.1 with 12 points per cell against the number of nodes in the
// material domain, for MPM-P1 and BSMPM (fixed grid 1.25 times the bar,
// prm/B2-traction-bar-convergence.prm) and for OTM-P1 and the unified
// approach with quadratic B-splines (material domain only). Published
// behaviour: the unified approach and BSMPM have the lowest errors, the
// unified approach the highest rate; rates are below the B-splines' order
// because the stress pulse has kinks.
// Max-ent (d_max = 2; prm/B2-traction-bar-{mpm,otm}-maxent.prm with the
// same changes): the published ranking puts BSMPM below MPM-maxent and the
// unified approach below OTM-maxent (required at 33 nodes; at 65 nodes
// OTM-maxent comes within 10 % of the unified error, see
// doc/benchmarks.md). OTM-maxent's smooth functions on the moving nodes
// must beat OTM-P1 on both grids and converge at least at second order,
// like the unified approach (measured 3.0 from 33 to 65 nodes).
// MPM-maxent uses a lumped mass matrix, whose O(h^2) error and the kinks
// of the pulse give rates near the P1 methods' 1.6-1.7: it must converge
// faster than order 1.4 (measured 1.6).

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

  std::vector<double> unified_errors, mpm_maxent_errors, otm_maxent_errors;
  for (const unsigned int nodes : {33u, 65u})
    {
      const std::string fixed_grid = "subsection Mesh\n set Subdivisions = " +
                                     std::to_string(5 * (nodes - 1) / 4) +
                                     "\nend\n";
      const std::string material_grid =
        "subsection Mesh\n set Subdivisions = " + std::to_string(nodes - 1) +
        "\nend\n";
      const std::string tag        = std::to_string(nodes);
      const double      mpm        = error("B2-traction-bar-convergence.prm",
                               fixed_grid,
                               "output-mpm" + tag);
      const double      bsmpm      = error("B2-traction-bar-convergence.prm",
                                 fixed_grid + splines,
                                 "output-bsmpm" + tag);
      const double      otm        = error("B2-traction-bar-otm.prm",
                               short_run + material_grid,
                               "output-otm" + tag);
      const double      unified    = error("B2-traction-bar-unified.prm",
                                   short_run + material_grid,
                                   "output-unified" + tag);
      const double      mpm_maxent = error("B2-traction-bar-mpm-maxent.prm",
                                      "subsection Mesh\n set Upper corner = "
                                           "1.25\nend\n" +
                                        short_run + fixed_grid,
                                      "output-mpm-maxent" + tag);
      const double      otm_maxent = error("B2-traction-bar-otm-maxent.prm",
                                      short_run + material_grid,
                                      "output-otm-maxent" + tag);
      unified_errors.push_back(unified);
      mpm_maxent_errors.push_back(mpm_maxent);
      otm_maxent_errors.push_back(otm_maxent);
      deallog << nodes << " material nodes: MPM-P1 " << rounded(mpm, 2)
              << ", OTM-P1 " << rounded(otm, 2) << ", BSMPM "
              << rounded(bsmpm, 2) << ", unified " << rounded(unified, 2)
              << std::endl;
      check(unified < otm && otm < mpm,
            "expected unified < OTM-P1 < MPM-P1 at " + tag + " nodes");
      check(bsmpm < otm, "expected BSMPM below OTM-P1 at " + tag + " nodes");
      deallog << nodes << " material nodes: MPM-maxent "
              << rounded(mpm_maxent, 2) << ", OTM-maxent "
              << rounded(otm_maxent, 2) << std::endl;
      check(bsmpm < mpm_maxent,
            "expected BSMPM below MPM-maxent at " + tag + " nodes");
      check(otm_maxent < otm,
            "expected OTM-maxent below OTM-P1 at " + tag + " nodes");
      if (nodes == 33)
        check(unified < otm_maxent,
              "expected the unified approach below OTM-maxent at 33 nodes");
    }
  const double rate = std::log2(unified_errors[0] / unified_errors[1]);
  deallog << "unified rate from 33 to 65 nodes " << std::fixed
          << std::setprecision(1) << rate << std::endl;
  check(rate > 1.8, "unified approach below second order");
  const double otm_maxent_rate =
    std::log2(otm_maxent_errors[0] / otm_maxent_errors[1]);
  const double mpm_maxent_rate =
    std::log2(mpm_maxent_errors[0] / mpm_maxent_errors[1]);
  deallog << "max-ent rates from 33 to 65 nodes: MPM-maxent " << std::fixed
          << std::setprecision(1) << mpm_maxent_rate << ", OTM-maxent "
          << otm_maxent_rate << std::endl;
  check(otm_maxent_rate > 1.8, "OTM-maxent below second order");
  check(mpm_maxent_rate > 1.4, "MPM-maxent converges too slowly");
}
