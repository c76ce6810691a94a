// A free body (no boundary conditions, no body force) spinning and
// translating on a 2D grid, quadrilaterals and triangles, lumped and
// consistent mass, USL and MUSL: the total mass stays exactly constant and
// the linear momentum is conserved to round-off (the forces sum to zero
// because the shape functions are a partition of unity). Then the same body
// under gravity g and a traction tau(t) = (3 t, 0) on its side x = 3 (length
// 2): the momentum must be M g t + (2 * 3 t^2 / 2, 0) after each step, where
// the traction of a step is the one at its start, so after n steps of dt
// the traction impulse is 2 * 3 dt^2 n (n - 1) / 2; with MPM (traction on
// the boundary points) and with OTM (traction on the moving grid's boundary
// faces, quadrilaterals and triangles; on triangles the loaded side's
// current length, which the face traction uses, changes slightly).

#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const std::string cell_type : {"hypercube", "simplex"})
    for (const std::string mass : {"lumped", "consistent"})
      for (const std::string scheme : {"USL", "MUSL"})
        {
          auto                simulator = make_simulator<2>("",
                                             R"(
set Dimension = 2
set Problem = custom
set Update scheme = )" + scheme +
                                               R"(
set Mass matrix = )" + mass + R"(
subsection Mesh
  set Cell type = )" + cell_type +
                                               R"(
  set Lower corner = 0, 0
  set Upper corner = 4, 4
  set Subdivisions = 8, 8
end
subsection Particles
  set Particles per cell = 3
end
subsection Material
  set Model = neo-Hookean
  set Young's modulus = 1e3
  set Poisson's ratio = 0.3
  set Density = 1
end
subsection Custom problem
  set Material lower corner = 1, 1
  set Material upper corner = 3, 3
  # rigid rotation about (2, 2) plus a translation and a stretch
  set Initial velocity = 0.3 - 0.5*(y-2) + 0.1*(x-2); 0.2 + 0.5*(x-2)
end
subsection Time
  set End time = 0.05
  set Time step = 1e-3
end
subsection Output
  set Interval = 0
end
)",
                                             "output-free-body");
          Statistics<2>       before;
          const Statistics<2> after = simulator->run(
            [&](const unsigned int step, const Statistics<2> &statistics) {
              if (step == 0)
                before = statistics;
            });
          const double scale =
            std::abs(before.momentum[0]) + std::abs(before.momentum[1]);
          const double momentum_change =
            std::abs(after.momentum[0] - before.momentum[0]) +
            std::abs(after.momentum[1] - before.momentum[1]);
          const std::string label = cell_type + ", " + mass + ", " + scheme;
          check(after.total_mass == before.total_mass,
                label + ": the total mass changed");
          check(momentum_change < 1e-12 * scale,
                label + ": momentum changed by " +
                  std::to_string(momentum_change / scale));
          check(simulator->material_points().n_global_points() == 4 * 4 * 9,
                label + ": material points were lost");
          deallog << label << ": mass " << after.total_mass
                  << ", momentum conserved to 1e-12, "
                  << simulator->material_points().n_global_points() << " points"
                  << std::endl;
        }

  // The loaded body: MPM with the traction on the boundary points, and OTM
  // (quadrilaterals and triangles) whose grid is the body itself and carries
  // the traction on its moving boundary faces. nu = 0 and a uniform load:
  // the side x = 3 keeps its length 2, so the traction force is 2 * 3 t.
  const double       dt      = 1e-3;
  const unsigned int n_steps = 40;
  const std::string  mpm_grid =
    "subsection Mesh\n set Upper corner = 4, 4\n set Subdivisions = 8, 8\n"
    "end\nsubsection Custom problem\n set Material lower corner = 1, 1\n"
    " set Material upper corner = 3, 3\nend\n";
  const std::string otm_grid =
    "set Method = OTM\nset Mass matrix = consistent\nsubsection Mesh\n"
    " set Lower corner = 1, 1\n set Upper corner = 3, 3\n"
    " set Subdivisions = 4, 4\nend\n";
  for (const auto &[label, grid] :
       std::vector<std::pair<std::string, std::string>>{
         {"MPM", mpm_grid},
         {"OTM quadrilaterals", otm_grid},
         {"OTM triangles",
          otm_grid + "subsection Mesh\n set Cell type = simplex\nend\n"}})
    {
      auto                loaded = make_simulator<2>("",
                                      R"(
set Dimension = 2
set Problem = custom
subsection Mesh
  set Lower corner = 0, 0
end
subsection Particles
  set Particles per cell = 3
end
subsection Material
  set Young's modulus = 1e3
  set Poisson's ratio = 0
end
subsection Custom problem
  set Body force = 0; -2
  set Traction boundary ids = 1
  set Traction = 3*t; 0
end
subsection Time
  set End time = 0.04
  set Time step = 1e-3
end
subsection Output
  set Interval = 0
end
)" + grid,
                                      "output-loaded");
      const Statistics<2> state  = loaded->run();
      const double        mass   = 4.;
      const double        expected_x =
        2. * 3. * dt * dt * n_steps * (n_steps - 1) / 2.;
      const double expected_y = -2. * mass * n_steps * dt;
      const double error_x    = std::abs(state.momentum[0] - expected_x);
      const double error_y    = std::abs(state.momentum[1] - expected_y);
      // On triangles the P1 field of the wave the traction sends through the
      // body has some lateral motion, so the loaded side's length changes by
      // a fraction of the strain, at most t_max / E = 0.12 / 1e3.
      const double tolerance = (label == "OTM triangles" ? 1.2e-4 : 1e-12);
      check(error_x < tolerance * std::abs(expected_x) &&
              error_y < 1e-12 * std::abs(expected_y),
            label + ": momentum under gravity and traction: (" +
              std::to_string(state.momentum[0]) + ", " +
              std::to_string(state.momentum[1]) + "), expected (" +
              std::to_string(expected_x) + ", " + std::to_string(expected_y) +
              "), relative errors (1e-12) " +
              std::to_string(1e12 * error_x / std::abs(expected_x)) + ", " +
              std::to_string(1e12 * error_y / std::abs(expected_y)));
      deallog << label << ", gravity and traction: momentum "
              << rounded(state.momentum[0], 4) << ' '
              << rounded(state.momentum[1], 4)
              << ", the hand computation to a relative " << tolerance
              << std::endl;
    }
}
