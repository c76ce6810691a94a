// Prescribed velocities through AffineConstraints on two ranks: a block of
// soil (hypo-elastic) on a fixed bottom between slip walls, pressed by a
// smooth footing - the grid nodes in a box on its surface moving down at
// 0.1 m/s (Boundaries, Type = velocity, as in G3) - with a lumped and with a
// consistent mass matrix (where the constrained nodes couple to the free
// ones in the solve). The grid's 8 x 8 cells split into the lower and the
// upper half between the ranks; the surface (y = 0.625) and the footing lie
// in the upper half, the soil in both. Each case runs on both ranks and on
// rank 0 alone: the footing's reaction and the kinetic and strain energies
// agree to round-off, and the footing has moved down by 30 dt x 0.1 m/s.

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

const std::string parameters = R"(
set Dimension = 2
set Problem = custom
set Update scheme = MUSL
set Bodies = soil
set Boundaries = footing, left, right, bottom
subsection Time
  set End time = 0.03
  set Time step = 1e-3
end
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 8, 8
end
subsection Material
  set Young's modulus = 1e6
  set Poisson's ratio = 0.3
  set Density = 1000
end
subsection Body soil
  set Shape = box
  set Lower corner = 0, 0
  set Upper corner = 1, 0.625
end
subsection Boundary footing
  set Type = velocity
  set Box lower corner = 0, 0.6
  set Box upper corner = 0.3751, 0.65
  set Velocity = 0; -0.1
  set Velocity components = y
end
subsection Boundary left
  set Type = slip
  set Boundary ids = 0
end
subsection Boundary right
  set Type = slip
  set Boundary ids = 1
end
subsection Boundary bottom
  set Type = fixed
  set Boundary ids = 2
end
subsection Output
  set Interval = 30
end
)";

void
compare(const std::string &mass_matrix)
{
  const MPI_Comm    world   = MPI_COMM_WORLD;
  const std::string changes = "set Mass matrix = " + mass_matrix + "\n";
  const auto        parallel =
    make_simulator<2>("", parameters + changes, "output-" + mass_matrix)->run();
  Statistics<2> serial;
  if (Utilities::MPI::this_mpi_process(world) == 0)
    serial = make_simulator<2>("",
                               parameters + changes,
                               "output-" + mass_matrix + "-serial",
                               MPI_COMM_SELF)
               ->run();
  const std::vector<double> serial_values = {
    serial.boundary_reactions.empty() ? 0. :
                                        serial.boundary_reactions[0].first[1],
    serial.kinetic_energy,
    serial.strain_energy};
  const std::vector<double> parallel_values = {
    parallel.boundary_reactions[0].first[1],
    parallel.kinetic_energy,
    parallel.strain_energy};
  const auto  reference = Utilities::MPI::broadcast(world, serial_values, 0);
  const char *names[] = {"footing reaction", "kinetic energy", "strain energy"};
  for (unsigned int i = 0; i < 3; ++i)
    check(std::abs(parallel_values[i] - reference[i]) <=
              1e-10 * std::abs(reference[i]) &&
            reference[i] != 0.,
          mass_matrix + ": " + names[i] + " on 2 ranks " +
            std::to_string(parallel_values[i]) + ", on 1 rank " +
            std::to_string(reference[i]));
  const Tensor<1, 2> moved = parallel.boundary_reactions[0].second;
  check(std::abs(moved[0]) < 1e-15 && std::abs(moved[1] + 0.03 * 0.1) < 1e-15,
        mass_matrix + ": the footing did not move down by 3e-3");
  deallog << mass_matrix << ": 1 and 2 ranks agree; footing reaction "
          << rounded(parallel_values[0], 4) << " N/m, kinetic energy "
          << rounded(parallel_values[1], 4) << " J/m, strain energy "
          << rounded(parallel_values[2], 4) << " J/m" << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  compare("lumped");
  compare("consistent");
}
