// Bodies from the physical groups of a Gmsh file (Body/Shape = mesh group;
// issue 36): tests/meshes/two-groups.msh is a 4 m x 2 m block of 1 m
// squares whose lower row is the surface group "clay" (tag 1) and whose
// upper row is "sand layer" (tag 2). Two bodies, one named by the group's
// name and one by its tag, each with its own material, with a geostatic
// initial stress under gravity 10 m/s^2:
//  - every cell of a group gets its 2 x 2 points and the body's material:
//    16 clay points below y = 1 and 16 sand points above;
//  - sigma_yy is the weight of the material above, -1500 g (2 - y) in the
//    sand and -(1500 g + 2000 g (1 - y)) in the clay (to 1e-9 of the
//    largest), and sigma_xx is K0 = nu / (1 - nu) times it.
// On the file's own grid (2 x 2 points per cell: 16 points per group), and
// on a box grid [0, 4] x [0, 2.5] of 0.25 m cells with the bodies naming
// the file as their own Mesh file (Body/Mesh file: 4 x 4 cells of the box
// per square of the file, 256 points per group). On one rank and on two,
// where each rank holds part of the distributed grid but locates the
// points above its own in the file's whole mesh.

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string mesh =
    std::string(MPM_OTM_SOURCE_DIR) + "/tests/meshes/two-groups.msh";
  // The bodies' groups from the grid's Mesh file, or from their own.
  const auto check_bodies = [&](const std::string &grid,
                                const std::string &own_file,
                                const unsigned int n_expected) {
    const auto simulator = simulator_from_text<2>(R"(
set Dimension = 2
set Problem = custom
set Materials = clay, sand
set Bodies = lower, upper
subsection Mesh
)" + grid + R"(
end
subsection Particles
  set Particles per cell = 2
end
subsection Material clay
  set Model = hypo-elastic
  set Density = 2000
  set Young's modulus = 1e7
  set Poisson's ratio = 0.25
end
subsection Material sand
  set Model = hypo-elastic
  set Density = 1500
  set Young's modulus = 1e7
  set Poisson's ratio = 0.2
end
subsection Body lower
  set Shape = mesh group
  set Group = clay
  set Material = clay
  set Initial stress = geostatic
)" + own_file + R"(
end
subsection Body upper
  set Shape = mesh group
  set Group = 2
  set Material = sand
  set Initial stress = geostatic
)" + own_file + R"(
end
subsection Gravity
  set Vector = 0, -10
end
subsection Time
  set End time = 1e-4
  set Time step = 1e-5
end
subsection Output
  set Directory = output-mesh-groups
  set Format = none
  set Overwrite = true
end
)");

    using Layout = PropertyLayout<2>;
    std::map<unsigned int, unsigned int> points_per_material;
    double                               largest_error = 0;
    bool                                 in_its_group  = true;
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const auto         properties = particle.get_properties();
        const unsigned int material   = Layout::get_material_id(properties);
        const Point<2>     X          = particle.get_location();
        ++points_per_material[material];
        // Materials: 0 the default, 1 clay, 2 sand.
        in_its_group =
          in_its_group && X[1] < 2. && (material == 1 ? X[1] < 1. : X[1] > 1.);
        const double sigma_v = material == 2 ?
                                 -1500. * 10. * (2. - X[1]) :
                                 -(1500. * 10. + 2000. * 10. * (1. - X[1]));
        const double K0      = material == 2 ? 0.2 / 0.8 : 0.25 / 0.75;
        const auto   sigma   = Layout::get_stress(properties);
        largest_error =
          std::max({largest_error,
                    std::abs(sigma[1][1] - sigma_v) / 35000.,
                    std::abs(sigma[0][0] - K0 * sigma_v) / 35000.});
      }
    const unsigned int n_clay =
      Utilities::MPI::sum(points_per_material[1], MPI_COMM_WORLD);
    const unsigned int n_sand =
      Utilities::MPI::sum(points_per_material[2], MPI_COMM_WORLD);
    const unsigned int n_other =
      Utilities::MPI::sum(points_per_material[0], MPI_COMM_WORLD);
    largest_error = Utilities::MPI::max(largest_error, MPI_COMM_WORLD);
    in_its_group  = Utilities::MPI::min(in_its_group ? 1 : 0, MPI_COMM_WORLD);
    deallog << "clay: " << n_clay << " points, sand: " << n_sand
            << " points, each in its group's cells: "
            << (in_its_group ? "yes" : "NO") << std::endl;
    deallog << "geostatic stress "
            << (largest_error < 1e-9 ? "exact to 1e-9" : "WRONG") << std::endl;
    check(n_clay == n_expected && n_sand == n_expected && n_other == 0 &&
            in_its_group,
          "the groups' cells did not get their bodies' points");
    check(largest_error < 1e-9,
          "geostatic stress off by " + std::to_string(largest_error));
  };

  deallog << "groups of the grid's Mesh file" << std::endl;
  check_bodies(" set Mesh file = " + mesh, "", 16);
  deallog << "groups of the bodies' own Mesh file on a box grid" << std::endl;
  check_bodies(" set Lower corner = 0, 0\n set Upper corner = 4, 2.5\n"
               " set Subdivisions = 16, 10",
               " set Mesh file = " + mesh,
               256);
}
