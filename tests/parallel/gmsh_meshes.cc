// Meshes of Gmsh files (tests/meshes/) run on two MPI ranks: p4est takes
// the cells of quadrilateral and hexahedral meshes as its trees, METIS
// partitions triangles and tetrahedra (a fully distributed grid), and both
// ranks own cells. The material filling the mesh has the mass density x measure
// (the trapezoid: 2 x 6; the two parallelepipeds: 2 x 2), every boundary id
// of the file is found (0, 1, 2), and a ball translated rigidly with v0
// (no forces, MPM USL, lumped mass) is at X + v0 t after every step to
// round-off, with no point lost, while points move from one rank to the
// other.

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>

#include <set>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

template <int dim>
void
test(const std::string &file,
     const double       measure,
     const std::string &ball,
     const std::string &velocity)
{
  const MPI_Comm    world = MPI_COMM_WORLD;
  const std::string mesh  = "set Dimension = " + std::to_string(dim) +
                           "\nset Problem = custom\nset Update scheme = USL\n"
                           "subsection Mesh\n  set Mesh file = " +
                           std::string(MPM_OTM_SOURCE_DIR) + "/tests/meshes/" +
                           file +
                           "\nend\n"
                           "subsection Material\n  set Young's modulus = 1e3\n"
                           "  set Density = 2\nend\n"
                           "subsection Time\n  set End time = 0.1\n"
                           "  set Time step = 0.01\nend\n"
                           "subsection Output\n  set Interval = 1\nend\n";

  // The whole mesh.
  {
    auto filled = make_simulator<dim>(
      "",
      mesh + "subsection Particles\n  set Particles per cell = 3\nend\n",
      "output-filled");
    const auto  &grid  = filled->background_grid();
    unsigned int owned = 0;
    for (const auto &cell : grid.triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        ++owned;
    check(Utilities::MPI::min(owned, world) > 0,
          file + ": a rank owns no cell");
    check(grid.boundary_ids() == std::vector<types::boundary_id>{0, 1, 2},
          file + ": boundary ids are not 0, 1, 2 on all ranks");
    Statistics<dim> initial;
    filled->run([&](const unsigned int step, const Statistics<dim> &s) {
      if (step == 0)
        initial = s;
    });
    check(std::abs(initial.total_mass - 2. * measure) < 1e-13 * measure,
          file + ": total mass " + std::to_string(initial.total_mass));
  }

  // The ball.
  auto simulator = make_simulator<dim>(
    "",
    mesh + "set Bodies = ball\nsubsection Body ball\n  set Shape = ball\n" +
      ball + "  set Initial velocity = " + velocity +
      "\nend\nsubsection Particles\n  set Particles per cell = 6\nend\n",
    "output-ball");
  Tensor<1, dim> v0;
  {
    const auto components =
      Utilities::string_to_double(Utilities::split_string_list(velocity, ';'));
    for (unsigned int d = 0; d < dim; ++d)
      v0[d] = components[d];
  }
  using Layout                              = PropertyLayout<dim>;
  const auto                     &points    = simulator->material_points();
  const auto                      n_points  = points.n_global_points();
  double                          largest   = 0;
  unsigned int                    left_rank = 0;
  std::set<types::particle_index> initial_ids;
  simulator->run([&](const unsigned int step, const Statistics<dim> &) {
    const double                    t = simulator->time();
    std::set<types::particle_index> ids;
    for (const auto &particle : points.particle_handler())
      {
        const Point<dim> X(Layout::get_vector(particle.get_properties(),
                                              Layout::initial_position));
        largest =
          std::max(largest, (particle.get_location() - X - t * v0).norm());
        ids.insert(particle.get_id());
      }
    if (step == 0)
      initial_ids = ids;
    else
      {
        left_rank = 0;
        for (const auto id : initial_ids)
          if (ids.count(id) == 0)
            ++left_rank;
      }
  });
  largest   = Utilities::MPI::max(largest, world);
  left_rank = Utilities::MPI::sum(left_rank, world);
  check(points.n_global_points() == n_points, file + ": points were lost");
  check(largest < 1e-12 * 0.1 * v0.norm(),
        file + ": translation error " + std::to_string(largest));
  check(left_rank > 0, file + ": no point moved to the other rank");
  deallog << file << " on 2 ranks: mass " << 2. * measure
          << ", boundary ids 0, 1, 2, " << n_points
          << " points translated by v0 t to round-off, some across ranks"
          << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  test<2>("trapezoid-quads.msh",
          6.,
          "  set Centre = 2, 1\n  set Radius = 0.6\n",
          "2; 3");
  test<3>("parallelepiped-hexahedra.msh",
          2.,
          "  set Centre = 1.15, 0.7, 0.5\n  set Radius = 0.3\n",
          "2; 0; 0");
  test<2>("trapezoid-triangles.msh",
          6.,
          "  set Centre = 2, 1\n  set Radius = 0.6\n",
          "2; 3");
  test<3>("cube-tetrahedra.msh",
          1.,
          "  set Centre = 0.65, 0.6, 0.5\n  set Radius = 0.25\n",
          "1; 0; 0");
}
