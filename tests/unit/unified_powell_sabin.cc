// The unified approach with Powell-Sabin splines (issue 18, item 3) on a
// rigid translation: a unit square of material (4 x 4 blocks of four
// triangles, 6 x 6 points per block, consistent mass matrix, linear
// elastic) that moves at v = (1, 0.5) without load. Every step the
// triangulation's vertices move with the field's values there, sum_q
// alpha_v^q c_v^q, and the splines are rebuilt on the moved grid. After 10
// steps of dt = 1e-3:
// - every vertex is at X + v t and every point at X_p + v t, to 1e-12;
// - every control triangle is its initial one translated by v t, with the
//   same labels (the rebuild keeps them), to 1e-12;
// - the stress is zero to round-off (1e-9 of E |v| dt / h);
// - every point lies in its triangle (barycentric coordinates in [0, 1])
//   at the location its reference coordinates give.

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/shape_functions/powell_sabin.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  auto        simulator = make_simulator<2>("",
                                     R"(
set Dimension = 2
set Problem = custom
set Method = Unified
set Shape functions = Powell-Sabin
set Mass matrix = consistent
subsection Mesh
  set Cell type = simplex
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 4, 4
end
subsection Particles
  set Particles per cell = 6, 6
end
subsection Material
  set Young's modulus = 1000
  set Density = 1
end
subsection Custom problem
  set Initial velocity = 1; 0.5
end
subsection Time
  set End time = 1e-2
  set Time step = 1e-3
end
)",
                                     "output-unified-powell-sabin");
  const auto &splines =
    dynamic_cast<const PowellSabin<2> &>(simulator->shape_function_family());
  const Triangulation<2> &triangulation =
    simulator->background_grid().triangulation();
  const std::vector<Point<2>>          initial = triangulation.get_vertices();
  std::vector<std::array<Point<2>, 3>> initial_control;
  for (unsigned int v = 0; v < initial.size(); ++v)
    initial_control.push_back(splines.geometry().control_triangle(v));

  simulator->run();
  const Tensor<1, 2> shift({1e-2, 0.5e-2});

  double vertex_error = 0, control_error = 0;
  for (unsigned int v = 0; v < initial.size(); ++v)
    {
      vertex_error =
        std::max(vertex_error,
                 (triangulation.get_vertices()[v] - initial[v] - shift).norm());
      for (unsigned int q = 0; q < 3; ++q)
        control_error = std::max(control_error,
                                 (splines.geometry().control_triangle(v)[q] -
                                  initial_control[v][q] - shift)
                                   .norm());
    }
  check(vertex_error < 1e-12,
        "vertices at X + v t: " + rounded(vertex_error, 2));
  check(control_error < 1e-12,
        "control triangles translated with their labels: " +
          rounded(control_error, 2));

  double       point_error = 0, stress = 0, outside = 0, mapping_error = 0;
  unsigned int n_points = 0;
  for (const auto &particle : simulator->material_points().particle_handler())
    {
      const auto properties = particle.get_properties();
      Point<2>   start;
      for (unsigned int d = 0; d < 2; ++d)
        start[d] = properties[PropertyLayout<2>::initial_position + d];
      point_error =
        std::max(point_error, (particle.get_location() - start - shift).norm());
      for (unsigned int i = 0; i < 3; ++i)
        stress =
          std::max(stress, std::abs(properties[PropertyLayout<2>::stress + i]));
      const Point<2> xi   = particle.get_reference_location();
      const auto     cell = particle.get_surrounding_cell();
      outside = std::max({outside, -xi[0], -xi[1], xi[0] + xi[1] - 1.});
      const Point<2> x = cell->vertex(0) +
                         xi[0] * (cell->vertex(1) - cell->vertex(0)) +
                         xi[1] * (cell->vertex(2) - cell->vertex(0));
      mapping_error =
        std::max(mapping_error, x.distance(particle.get_location()));
      ++n_points;
    }
  check(n_points == 16 * 36, "576 points");
  check(point_error < 1e-12, "points at X_p + v t: " + rounded(point_error, 2));
  check(stress < 1e-9 * 1000 * 1.2 * 1e-3 / 0.25,
        "no stress: " + rounded(stress, 2));
  check(outside < 1e-12 && mapping_error < 1e-12,
        "points in their triangles: " + rounded(outside, 2) + ", " +
          rounded(mapping_error, 2));
  deallog << "Unified Powell-Sabin, rigid translation by v t = (0.01, "
             "0.005): vertices, control triangles (labels kept) and "
          << n_points
          << " points translated within 1e-12, no stress, every point in "
             "its triangle"
          << std::endl;
}
