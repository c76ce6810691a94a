// Thesis Chapter 5 with Powell-Sabin MPM: the soil column at large
// deformation (Table 4.6) on 1 x 8 blocks with an empty block on top
// (prm/B6-soil-column-large-powell-sabin-remedies.prm). As the column sinks
// the top cells empty and the consistent mass matrix becomes
// ill-conditioned (Sect. 5.1); the published behaviour of each remedy:
// - consistent: unstable at about t = 0.1 s (Sect. 5.2, Fig. 5.3): the run
//   must stop with the step, time and point; also on 2 x 16 (+1) blocks,
//   the grid of the thesis's first instability (Fig. 4.11c;
//   prm/B6-soil-column-large-powell-sabin-remedies-2x16.prm);
// - partially lumped (Sect. 5.4): stable, the displacement of the top
//   "almost indistinguishable" from the reference, the velocity close;
// - lumped (Sect. 5.3): stable, with displacement and velocity errors not
//   seen with the consistent matrix - larger than partial lumping's;
// - deactivation below M_ii = 1e-2 (Sect. 5.2): stable, with a large
//   displacement error (Fig. 5.4b) - larger than lumping's.
// - the unified approach (beyond the seeds;
//   prm/B6-soil-column-large-powell-sabin-unified.prm): the grid is the
//   column (1 x 8 blocks) and moves with it, the splines rebuilt every step,
//   so no cell empties; with the consistent matrix and no remedy it must be
//   stable and closer to the reference than partial lumping.
// The reference is the 1D updated-Lagrangian run
// prm/B6-soil-column-large-reference-1d.prm on 50 cells (within 1.1e-3
// of the range of the 100-cell run, tests/benchmarks/
// large_deformation_reference). To keep the test short the runs end at
// T = 0.25 s, after the column's deepest point (t = 0.2 s), with dt = 5e-4
// (the prm file has 1e-4; the CFL bound is 5e-3).

#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  // Mean vertical displacement and velocity of the points that start above
  // @p from, at every output step.
  template <int dim>
  std::vector<std::array<double, 2>>
  top_history(Simulator<dim> &simulator, const double from)
  {
    using Layout = PropertyLayout<dim>;
    std::vector<std::array<double, 2>> result;
    simulator.run([&](unsigned int, const Statistics<dim> &) {
      double       u = 0, v = 0;
      unsigned int n = 0;
      for (const auto &particle :
           simulator.material_points().particle_handler())
        {
          const auto   properties = particle.get_properties();
          const double Y =
            Layout::get_vector(properties, Layout::initial_position)[dim - 1];
          if (Y > from)
            {
              u += particle.get_location()[dim - 1] - Y;
              v += Layout::get_vector(properties, Layout::velocity)[dim - 1];
              ++n;
            }
        }
      check(n > 0, "no point at the top");
      result.push_back({{u / n, v / n}});
    });
    return result;
  }

  const std::string common_2d = "subsection Time\n set End time = 0.25\n"
                                " set Time step = 5e-4\nend\n"
                                "subsection Output\n set Interval = 4\n"
                                " set Write particle CSV = false\nend\n";

  // Largest deviation of the top's displacement and velocity from the
  // reference, relative to the reference's largest magnitudes.
  std::array<double, 2>
  deviation(const std::vector<std::array<double, 2>> &reference,
            const std::string                        &name,
            const std::string                        &changes)
  {
    auto simulator =
      make_simulator<2>("B6-soil-column-large-powell-sabin-remedies.prm",
                        common_2d + changes,
                        "output-" + name);
    // The top row of points starts at y = 1 - 0.125 / 18.
    const auto history = top_history(*simulator, 0.99);
    check(history.size() == reference.size(),
          name + ": the run did not reach the end time");
    std::array<double, 2> largest{{0, 0}}, deviation{{0, 0}};
    for (unsigned int i = 0; i < history.size(); ++i)
      for (unsigned int c = 0; c < 2; ++c)
        {
          largest[c] = std::max(largest[c], std::abs(reference[i][c]));
          deviation[c] =
            std::max(deviation[c], std::abs(history[i][c] - reference[i][c]));
        }
    for (unsigned int c = 0; c < 2; ++c)
      deviation[c] /= largest[c];
    deallog << name << ": largest deviation of the top from the reference: "
            << "displacement " << rounded(deviation[0], 1) << ", velocity "
            << rounded(deviation[1], 1) << std::endl;
    return deviation;
  }


  // The time at which the consistent run of prm/@p prm_file on @p grid stops
  // as unstable; the test fails if it does not stop, or without step and
  // point.
  double
  consistent_stop_time(const std::string &grid, const std::string &prm_file)
  {
    auto simulator =
      make_simulator<2>(prm_file,
                        common_2d + "set Mass matrix = consistent\n",
                        "output-consistent");
    std::string message;
    try
      {
        simulator->run();
      }
    catch (const std::exception &error)
      {
        // deal.II wraps the text of an exception: join it into one line.
        std::istringstream words(error.what());
        for (std::string word; words >> word;)
          message += word + " ";
      }
    check(message.find("Stopped in time step") != std::string::npos &&
            message.find("became unstable: material point") !=
              std::string::npos,
          "the consistent run on " + grid +
            " must stop as unstable, naming step and point; it said: '" +
            message + "'");
    const double time = std::stod(message.substr(message.find("(t = ") + 5));
    deallog << "consistent, " << grid
            << ": stopped as unstable at t = " << rounded(time, 1) << " s"
            << std::endl;
    return time;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  // The reference at the output times of the 2D runs (every 2e-3 s); its
  // top cell's points.
  auto reference_run =
    make_simulator<1>("B6-soil-column-large-reference-1d.prm",
                      "subsection Time\n set End time = 0.25\n"
                      " set Time step = 2e-4\nend\n"
                      "subsection Mesh\n set Subdivisions = 50\nend\n"
                      "subsection Output\n set Interval = 10\n"
                      " set Write particle CSV = false\nend\n",
                      "output-reference");
  const auto reference = top_history(*reference_run, 0.99);

  // Consistent: the run must stop, naming the step, the time and the point,
  // on 1 x 8 (+1) blocks and on 2 x 16 (+1) blocks (6 x 6 points per block).
  const double time_1x8 =
    consistent_stop_time("1 x 8 (+1) blocks",
                         "B6-soil-column-large-powell-sabin-remedies.prm");
  check(time_1x8 > 0.05 && time_1x8 < 0.2,
        "the consistent run on 1 x 8 blocks must become unstable near "
        "t = 0.1 s (thesis Sect. 5.2), not at t = " +
          std::to_string(time_1x8));
  const double time_2x16 =
    consistent_stop_time("2 x 16 (+1) blocks",
                         "B6-soil-column-large-powell-sabin-remedies-2x16.prm");
  check(time_2x16 < 0.2,
        "the consistent run on 2 x 16 blocks must become unstable while the "
        "column first sinks (thesis Fig. 4.11c), not at t = " +
          std::to_string(time_2x16));

  const auto partial = deviation(reference, "partially-lumped", "");
  check(partial[0] < 0.02 && partial[1] < 0.1,
        "partial lumping must follow the reference (2 % in displacement, "
        "10 % in velocity)");
  const auto lumped =
    deviation(reference, "lumped", "set Mass matrix = lumped\n");
  check(lumped[0] > partial[0] && lumped[1] > partial[1],
        "lumping must be less accurate than partial lumping (thesis 5.3)");
  const auto deactivated = deviation(reference,
                                     "deactivated",
                                     "set Mass matrix = consistent\n"
                                     "set Deactivation threshold = 1e-2\n");
  check(deactivated[0] > lumped[0],
        "deactivation must cost more displacement accuracy than lumping "
        "(thesis 5.2, Fig. 5.4b)");

  // The unified approach: the grid is the column (1 x 8 blocks) and moves
  // with it, so no cell empties and the consistent matrix needs no remedy.
  const auto unified = deviation(reference,
                                 "unified, consistent",
                                 "set Method = Unified\n"
                                 "set Mass matrix = consistent\n"
                                 "subsection Mesh\n"
                                 " set Upper corner = 0.1, 1\n"
                                 " set Subdivisions = 1, 8\nend\n");
  check(unified[0] < partial[0] && unified[1] < partial[1],
        "the unified approach must follow the reference more closely than "
        "partial lumping, the best remedy");
}
