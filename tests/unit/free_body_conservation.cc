// A free body (no boundary conditions, no body force) spinning and
// translating on a 2D grid, quadrilaterals and triangles, lumped and
// consistent mass, USL and MUSL: the total mass stays exactly constant and
// the linear momentum is conserved to round-off (the forces sum to zero
// because the shape functions are a partition of unity).

#include <mpm_otm/io/statistics.h>

#include "components.h"

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
          Components<2> setup(R"(
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
)");
          Statistics<2> before, after;
          before.compute(setup.points, *setup.material, *setup.problem, 0.);
          for (unsigned int step = 0; step < 50; ++step)
            setup.stepper->advance(step * 1e-3, 1e-3);
          after.compute(setup.points, *setup.material, *setup.problem, 0.05);
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
          check(setup.points.n_global_points() == 4 * 4 * 9,
                label + ": material points were lost");
          deallog << label << ": mass " << after.total_mass
                  << ", momentum conserved to 1e-12, "
                  << setup.points.n_global_points() << " points" << std::endl;
        }
}
