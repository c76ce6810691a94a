// The mass-matrix remedies of thesis Chapter 5 against hand computations:
// partial lumping (Sect. 5.4) and deactivation (Sect. 5.2).
//
// 1D grid [0, 4] with four cells, material in [0, 2] only: two points per
// filled cell at X = 0.25, 0.75, 1.25, 1.75 with m = 0.5, at rest, body
// force b = x. Linear functions phi_0 .. phi_4; phi_3 and phi_4 have no
// material, phi_2 is the one at the edge of the material (on a filled and an
// empty cell). In the first step the stress is zero, so f_i = sum_p m_p
// phi_i(X_p) X_p = (3/16, 1, 13/16) and
//   M = [5/16 3/16 0; 3/16 5/8 3/16; 0 3/16 5/16], lumped m = (1/2, 1, 1/2).
// - consistent: M a = f gives a = x at the nodes, (0, 1, 2);
// - lumped: a = f / m = (3/8, 1, 13/8);
// - partially lumped: a_2 = f_2 / m_2 = 13/8, then
//   [5/16 3/16; 3/16 5/8] (a_0, a_1) = (3/16, 1 - 3/16 13/8) gives
//   a = (-27/328, 373/328, 13/8);
// - consistent with deactivation below 0.32: M_00 = M_22 = 5/16 < 0.32 are
//   deactivated, so a_0 = a_2 = 0 and a_1 = f_1 / M_11 = 8/5.

#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

const std::string parameters = R"(
set Dimension = 1
set Problem = custom
set Update scheme = USL
subsection Time
  set End time = 0.1
  set Time step = 0.1
end
subsection Mesh
  set Lower corner = 0
  set Upper corner = 4
  set Subdivisions = 4
end
subsection Particles
  set Particles per cell = 2
end
subsection Material
  set Young's modulus = 1
  set Density = 1
end
subsection Custom problem
  set Body force = x
  set Material lower corner = 0
  set Material upper corner = 2
end
)";

/**
 * Run one step with @p changes and check the nodal accelerations against
 * @p exact (nodes 0 to 4).
 */
void
check_accelerations(const std::string               &name,
                    const std::string               &changes,
                    const std::array<double, 5>      exact,
                    const std::vector<unsigned int> &deactivated = {})
{
  auto simulator =
    make_simulator<1>("", parameters + changes, "output-" + name);
  const auto &system  = simulator->nodal_system();
  bool        checked = false;
  simulator->run([&](const unsigned int step, const Statistics<1> &) {
    if (step != 1)
      return;
    checked = true;
    for (unsigned int i = 0; i < 5; ++i)
      {
        const double a = system.acceleration[0].local_element(i);
        check(std::abs(a - exact[i]) < 1e-13,
              name + ": acceleration at node " + std::to_string(i) + " = " +
                std::to_string(a) + ", by hand " + std::to_string(exact[i]));
        deallog << name << ": a_" << i << " = "
                << rounded(std::abs(a) < 1e-12 ? 0. : a, 6) << std::endl;
      }
    check(system.deactivated_functions() == deactivated,
          name + ": wrong deactivated functions");
  });
  check(checked, name + ": step 1 was not checked");
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  {
    // The points, masses and the edge of the material the hand values use.
    auto simulator = make_simulator<1>("", parameters, "output-points");
    std::vector<double> positions;
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        positions.push_back(particle.get_location()[0]);
        check(std::abs(particle.get_properties()[PropertyLayout<1>::mass] -
                       0.5) < 1e-14,
              "point mass must be 0.5");
      }
    std::sort(positions.begin(), positions.end());
    check(positions == std::vector<double>({0.25, 0.75, 1.25, 1.75}),
          "points must be at 0.25, 0.75, 1.25, 1.75");
    deallog << "points at 0.25, 0.75, 1.25, 1.75 with m = 0.5" << std::endl;
  }

  check_accelerations("consistent",
                      "set Mass matrix = consistent\n",
                      {{0., 1., 2., 0., 0.}});
  check_accelerations("lumped",
                      "set Mass matrix = lumped\n",
                      {{3. / 8., 1., 13. / 8., 0., 0.}});
  check_accelerations("partially-lumped",
                      "set Mass matrix = partially lumped\n",
                      {{-27. / 328., 373. / 328., 13. / 8., 0., 0.}});
  check_accelerations("deactivated",
                      "set Mass matrix = consistent\n"
                      "set Deactivation threshold = 0.32\n",
                      {{0., 8. / 5., 0., 0., 0.}},
                      {0, 2});
  check_accelerations("threshold-below-all",
                      "set Mass matrix = consistent\n"
                      "set Deactivation threshold = 0.3\n",
                      {{0., 1., 2., 0., 0.}});
}
