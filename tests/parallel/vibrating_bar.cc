// Parallel runs with two MPI ranks give the serial result: the 2D bar of B5
// on quadrilaterals and a 3D bar on hexahedra (p4est-distributed grids),
// with MPM and with the moving grid of OTM (2D) and the unified approach
// (3D), with quadratic B-splines (BSMPM in 2D and 3D, the unified approach
// with moving knots in 2D), and on fully distributed grids: triangles
// (MPM, OTM, and MPM and the unified approach with Powell-Sabin splines),
// tetrahedra (MPM) and 1D
// intervals (MPM, OTM, the unified approach with moving B-spline knots), and
// with max-ent functions, whose supports reach beyond the ghost cells
// (MPM, OTM and the unified approach on quadrilaterals, MPM on triangles,
// hexahedra and tetrahedra, OTM in 1D; wide ones with the consistent mass
// matrix preconditioned by algebraic multigrid and by a direct solve per rank).
// Each runs once on MPI_COMM_WORLD (2 ranks) and once on rank 0 alone; the
// error norms against the exact solution and the energies agree to round-off,
// and the errors are small.

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

template <int dim>
void
compare(const std::string &label, const std::string &changes)
{
  const MPI_Comm world    = MPI_COMM_WORLD;
  auto       parallel_run = make_simulator<dim>("", changes, "output-" + label);
  const auto parallel     = parallel_run->run();

  Statistics<dim> serial;
  if (Utilities::MPI::this_mpi_process(world) == 0)
    {
      auto serial_run = make_simulator<dim>("",
                                            changes,
                                            "output-" + label + "-serial",
                                            MPI_COMM_SELF);
      serial          = serial_run->run();
    }
  const double serial_values[3] = {serial.displacement_l2_error,
                                   serial.kinetic_energy,
                                   serial.strain_energy};
  double       broadcast[3];
  for (unsigned int i = 0; i < 3; ++i)
    broadcast[i] = Utilities::MPI::broadcast(world, serial_values[i], 0);

  const double parallel_values[3] = {parallel.displacement_l2_error,
                                     parallel.kinetic_energy,
                                     parallel.strain_energy};
  for (unsigned int i = 0; i < 3; ++i)
    check(std::abs(parallel_values[i] - broadcast[i]) <=
            1e-10 * std::abs(broadcast[i]),
          label + ": 2 ranks differ from 1 rank");
  check(parallel.displacement_rms_error < 0.01 * 0.1 / (3.14159 / 25.),
        label + ": error above 1 % of the amplitude");
  deallog << label << ": 1 and 2 ranks agree, L2 displacement error "
          << rounded(parallel.displacement_l2_error, 2) << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string common = R"(
set Problem = vibrating bar
set Update scheme = MUSL
set Mass matrix = consistent
subsection Time
  set End time = 0.02
  set Time step = 1e-4
end
subsection Material
  set Young's modulus = 100
  set Density = 1
end
subsection Vibrating bar
  set Initial velocity amplitude = 0.1
end
)";
  const std::string bar_2d = R"(
set Dimension = 2
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 25, 2
  set Subdivisions = 16, 2
end
subsection Particles
  set Particles per cell = 4
end
)";
  const std::string bar_3d = R"(
set Dimension = 3
subsection Mesh
  set Lower corner = 0, 0, 0
  set Upper corner = 25, 2, 2
  set Subdivisions = 8, 1, 1
end
subsection Particles
  set Particles per cell = 3
end
)";
  const std::string otm = "set Method = OTM\nset Update scheme = automatic\n";
  compare<2>("2D", common + bar_2d);
  compare<3>("3D", common + bar_3d);
  compare<2>("2D OTM", common + bar_2d + otm);
  compare<3>("3D Unified", common + bar_3d + "set Method = Unified\n");
  // Quadratic B-splines: functions reach over several cells, so the ranks
  // exchange more than the shared vertices; the knots move on every rank.
  const std::string splines =
    "set Shape functions = B-spline\nset B-spline degree = 2\n";
  compare<2>("2D BSMPM", common + bar_2d + splines);
  compare<2>("2D Unified B-spline",
             common + bar_2d + splines + "set Method = Unified\n");
  compare<3>("3D BSMPM", common + bar_3d + splines);
  // Triangles and tetrahedra: a fully distributed grid partitioned by
  // METIS.
  const std::string simplices =
    "subsection Mesh\n  set Cell type = simplex\nend\n";
  compare<2>("2D simplex", common + bar_2d + simplices);
  compare<2>("2D simplex OTM", common + bar_2d + simplices + otm);
  compare<3>("3D simplex", common + bar_3d + simplices);
  // Powell-Sabin splines: each rank builds the functions of its cells'
  // vertices from its own and its ghost cells.
  compare<2>("2D Powell-Sabin",
             common + bar_2d + simplices +
               "set Shape functions = Powell-Sabin\n");
  // The unified approach with Powell-Sabin splines: the vertices of ghost
  // cells only take the positions their owners computed.
  compare<2>("2D Unified Powell-Sabin",
             common + bar_2d + simplices +
               "set Shape functions = Powell-Sabin\n"
               "set Method = Unified\n");
  // Max-ent: each rank keeps the nodes within the halo of its cells; with
  // OTM their positions and radii are exchanged every step.
  const std::string max_ent = "set Shape functions = max-ent\n";
  compare<2>("2D max-ent", common + bar_2d + max_ent);
  compare<2>("2D max-ent OTM", common + bar_2d + max_ent + otm);
  compare<2>("2D simplex max-ent", common + bar_2d + simplices + max_ent);
  compare<3>("3D max-ent", common + bar_3d + max_ent);
  compare<3>("3D simplex max-ent", common + bar_3d + simplices + max_ent);
  compare<2>("2D max-ent Unified",
             common + bar_2d + max_ent + "set Method = Unified\n");
  // The other preconditioners of the consistent mass matrix: algebraic
  // multigrid with wide max-ent functions, which make the matrix
  // ill-conditioned, and a direct factorisation of each rank's rows. (With
  // d_max = 3 the latter is only block Jacobi between two ranks, and 1 and 2
  // ranks differ by the CG tolerance times the condition number, 5e-10.)
  compare<2>("2D max-ent d_max = 3, multigrid",
             common + bar_2d + max_ent +
               "set Max-ent support factor = 3\n"
               "set Mass matrix preconditioner = algebraic multigrid\n");
  compare<2>("2D max-ent, direct per rank",
             common + bar_2d + max_ent +
               "set Mass matrix preconditioner = direct per rank\n");
  // 1D: a fully distributed line of intervals.
  const std::string bar_1d = R"(
set Dimension = 1
subsection Mesh
  set Lower corner = 0
  set Upper corner = 25
  set Subdivisions = 16
end
subsection Particles
  set Particles per cell = 4
end
)";
  compare<1>("1D", common + bar_1d);
  compare<1>("1D OTM", common + bar_1d + otm);
  compare<1>("1D max-ent OTM", common + bar_1d + max_ent + otm);
  compare<1>("1D Unified B-spline",
             common + bar_1d + splines + "set Method = Unified\n");
}
