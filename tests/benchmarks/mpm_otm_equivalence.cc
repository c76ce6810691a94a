// The journal's Sect. 5 (and the conference paper): for a constant time step
// and linear shape functions, one step of OTM (Alg. 2) and of MPM-USL
// (Alg. 1) computes the same nodal displacement, and on B1a
// (BENCHMARKS.md) the two methods stay close over the first 20 steps
// (published RMS stress errors 3.8693 MPM and 3.8684 OTM).
//
// 1. First step, in 1D (B1a), 2D quadrilaterals and 2D triangles (B5): the
//    displacement of every vertex of OTM's moved grid equals dt times MPM's
//    nodal velocity v_i^{s+1} of Eqs. 24-25 to round-off (of the vertex
//    coordinates the displacement is read from).
// 2. B1a, 20 steps: the only difference left is the grid the gradients are
//    taken on (initial in MPM, moved in OTM). A cell stretched by the strain
//    eps changes a gradient by the relative amount eps, so the two stress
//    fields, and hence their RMS errors, differ by at most
//    eps_max(t) * RMS(sigma_exact(t)) at every step.

#include <deal.II/base/mpi.h>

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <algorithm>
#include <fstream>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  template <int dim>
  void
  check_first_step(const std::string &prm,
                   const std::string &changes,
                   const double       dt,
                   const std::string &name)
  {
    const std::string one_step =
      changes + "\nsubsection Time\n set End time = " + std::to_string(dt) +
      "\nend\n";
    auto                          mpm = make_simulator<dim>(prm,
                                   one_step + "set Method = MPM\n"
                                                                       "set Update scheme = USL\n",
                                   "output-first-step-mpm-" + name);
    auto                          otm = make_simulator<dim>(prm,
                                   one_step + "set Method = OTM\n"
                                                                       "set Update scheme = automatic\n",
                                   "output-first-step-otm-" + name);
    const std::vector<Point<dim>> initial =
      otm->background_grid().triangulation().get_vertices();
    mpm->run();
    otm->run();

    const auto &velocity   = mpm->nodal_system().velocity;
    double      difference = 0;
    double      largest    = 0;
    double      extent     = 0;
    for (const auto &cell :
         otm->shape_function_family().dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const types::global_dof_index i = cell->vertex_dof_index(v, 0);
          const Tensor<1, dim>          moved =
            cell->vertex(v) - initial[cell->vertex_index(v)];
          for (unsigned int c = 0; c < dim; ++c)
            {
              difference =
                std::max(difference, std::abs(moved[c] - dt * velocity[c](i)));
              largest = std::max(largest, std::abs(moved[c]));
              extent  = std::max(extent, std::abs(cell->vertex(v)[c]));
            }
        }
    deallog << name << ": largest vertex displacement " << rounded(largest, 2)
            << std::endl;
    check(largest > 0, name + ": OTM did not move the grid");
    // Round-off: a displacement read off as (x + dt v) - x carries the
    // rounding error of the coordinates x.
    check(difference <= 1e-14 * extent,
          name + ": OTM and MPM-USL nodal displacements differ by " +
            std::to_string(difference / largest) + " (relative)");
  }



  std::vector<double>
  stress_errors(const std::string &directory)
  {
    std::ifstream       file(directory + "/statistics.csv");
    std::string         line;
    std::vector<double> errors;
    std::getline(file, line);
    const auto header = Utilities::split_string_list(line);
    const auto column =
      std::find(header.begin(), header.end(), "stress_rms_error");
    check(column != header.end(), "no stress_rms_error in " + line);
    while (std::getline(file, line))
      errors.push_back(
        std::stod(Utilities::split_string_list(line)[column - header.begin()]));
    return errors;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const std::string consistent =
    "set Mass matrix = consistent\n"
    "subsection Output\n set Write particle CSV = false\nend\n";
  check_first_step<1>("B1a-bar-fixed-ends-conference.prm",
                      consistent,
                      1e-4,
                      "1D");
  check_first_step<1>("B1a-bar-fixed-ends-conference.prm",
                      "set Mass matrix = lumped\n",
                      1e-4,
                      "1D lumped");
  check_first_step<2>("B5-bar-2d-small.prm",
                      consistent +
                        "subsection Mesh\n set Cell type = hypercube\nend\n",
                      1e-5,
                      "2D quadrilaterals");
  check_first_step<2>("B5-bar-2d-small.prm", consistent, 1e-5, "2D triangles");

  // B1a over 20 steps, consistent mass matrix as in the conference paper.
  for (const std::string method : {"MPM", "OTM"})
    make_simulator<1>("B1a-bar-fixed-ends-conference.prm",
                      consistent + "set Method = " + method +
                        (method == "MPM" ? "\nset Update scheme = USL\n" :
                                           "\n"),
                      "output-b1a-" + method)
      ->run();
  const std::vector<double> mpm = stress_errors("output-b1a-MPM");
  const std::vector<double> otm = stress_errors("output-b1a-OTM");
  check(mpm.size() == 21 && otm.size() == 21, "expected 21 rows");

  const double E = 4e4, rho = 2e3, v0 = 0.8, dt = 1e-4;
  const double omega = numbers::PI * std::sqrt(E / rho);
  for (unsigned int step = 1; step <= 20; ++step)
    {
      // sigma = v0 sqrt(E rho) sin(omega t) cos(pi X): its largest strain
      // sigma/E and its RMS over the bar, amplitude / sqrt(2).
      const double amplitude =
        v0 * std::sqrt(E * rho) * std::sin(omega * step * dt);
      const double bound = amplitude / E * amplitude / std::sqrt(2.);
      check(std::abs(otm[step] - mpm[step]) <= bound,
            "MPM and OTM stress errors differ by more than the strain "
            "bound at step " +
              std::to_string(step));
    }
  deallog << "B1a after 20 steps: RMS stress error MPM " << rounded(mpm[20], 4)
          << ", OTM " << rounded(otm[20], 4) << ", relative difference "
          << rounded((mpm[20] - otm[20]) / mpm[20], 2)
          << " (published 3.8693, 3.8684: 2.3e-04)" << std::endl;
}
