// A free body (no boundary conditions, no body force) spinning and
// translating on a 2D grid, quadrilaterals and triangles, lumped and
// consistent mass, USL and MUSL: the total mass stays exactly constant and
// the linear momentum is conserved to round-off (the forces sum to zero
// because the shape functions are a partition of unity). Then the same body
// under gravity g and a traction tau(t) = (3 t, 0) on its side x = 3 (length
// 2): the momentum must be M g t + (2 * 3 t^2 / 2, 0) after each step, where
// the traction of a step is the one at its start, so after n steps of dt
// the traction impulse is 2 * 3 dt^2 n (n - 1) / 2.

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

  const double        dt      = 1e-3;
  const unsigned int  n_steps = 40;
  auto                loaded  = make_simulator<2>("",
                                  R"(
set Dimension = 2
set Problem = custom
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 4, 4
  set Subdivisions = 8, 8
end
subsection Particles
  set Particles per cell = 3
end
subsection Material
  set Young's modulus = 1e3
end
subsection Custom problem
  set Material lower corner = 1, 1
  set Material upper corner = 3, 3
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
)",
                                  "output-loaded");
  const Statistics<2> state   = loaded->run();
  const double        mass    = 4.;
  const double expected_x = 2. * 3. * dt * dt * n_steps * (n_steps - 1) / 2.;
  const double expected_y = -2. * mass * n_steps * dt;
  const double error_x    = std::abs(state.momentum[0] - expected_x);
  const double error_y    = std::abs(state.momentum[1] - expected_y);
  check(error_x < 1e-12 * std::abs(expected_x) &&
          error_y < 1e-12 * std::abs(expected_y),
        "momentum under gravity and traction: (" +
          std::to_string(state.momentum[0]) + ", " +
          std::to_string(state.momentum[1]) + "), expected (" +
          std::to_string(expected_x) + ", " + std::to_string(expected_y) + ")");
  deallog << "gravity and traction: momentum " << state.momentum[0] << ' '
          << state.momentum[1] << " as computed by hand" << std::endl;
}
