// The inverse cell maps of the point location (ReferenceMap): on a
// quadrilateral and a hexahedron that are not parallelograms
// (parallelepipeds), on a parallelogram and on a triangle, reference points
// mapped to the cell by deal.II's MappingQ1 (the mapping of the shape
// functions) come back to within 1e-12; the points of a grid of reference
// coordinates from -0.5 to 1.5 are inside exactly when their reference
// coordinates are in the reference cell; a point far outside a distorted
// cell, where Newton's method may not converge, is not inside.

#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <mpm_otm/material_points/reference_map.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

template <int dim>
void
test(const std::string             &name,
     const std::vector<Point<dim>> &vertices,
     const bool                     simplex)
{
  Triangulation<dim> triangulation;
  GridGenerator::reference_cell(triangulation,
                                simplex ? ReferenceCells::get_simplex<dim>() :
                                          ReferenceCells::get_hypercube<dim>());
  for (unsigned int v = 0; v < vertices.size(); ++v)
    triangulation.begin_active()->vertex(v) = vertices[v];
  const auto cell = triangulation.begin_active();

  ReferenceMap<dim> map;
  map.reinit(cell);
  const Mapping<dim> &mapping =
    cell->reference_cell().template get_default_linear_mapping<dim>();

  double             largest_error = 0;
  unsigned int       n_points = 0, n_inside = 0, wrong = 0;
  const unsigned int n  = 8;
  const unsigned int n3 = dim == 3 ? n + 1 : 1;
  for (unsigned int i = 0; i <= n; ++i)
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int k = 0; k < n3; ++k)
        {
          Point<dim> xi;
          xi[0] = -0.5 + 2. * i / n;
          xi[1] = -0.5 + 2. * j / n;
          if (dim == 3)
            xi[2] = -0.5 + 2. * k / n;
          bool   inside = true;
          double sum    = 0;
          for (unsigned int d = 0; d < dim; ++d)
            {
              inside = inside && xi[d] >= 0. && xi[d] <= 1.;
              sum += xi[d];
            }
          if (simplex)
            inside = inside && sum <= 1.;
          const Point<dim> x = mapping.transform_unit_to_real_cell(cell, xi);
          const Point<dim> found = map.reference_point(x);
          if (inside)
            {
              largest_error = std::max(largest_error, (found - xi).norm());
              ++n_inside;
            }
          if (map.contains(found) != inside)
            ++wrong;
          ++n_points;
        }
  check(largest_error < 1e-12,
        name + ": reference coordinates off by " +
          std::to_string(largest_error));
  check(wrong == 0,
        name + ": " + std::to_string(wrong) +
          " points inside or outside wrongly");

  // Far outside.
  Point<dim> far;
  for (unsigned int d = 0; d < dim; ++d)
    far[d] = 1e3 * (d + 1);
  check(!map.contains(map.reference_point(far)),
        name + ": a point far outside is inside");
  deallog << name << ": " << n_inside << " of " << n_points
          << " points inside, reference coordinates within 1e-12" << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  test<2>(
    "quadrilateral",
    {Point<2>(0, 0), Point<2>(2, 0.3), Point<2>(-0.2, 1), Point<2>(1.4, 1.7)},
    false);
  test<2>(
    "parallelogram",
    {Point<2>(0, 0), Point<2>(2, 0.5), Point<2>(0.5, 1), Point<2>(2.5, 1.5)},
    false);
  test<2>("triangle",
          {Point<2>(0.1, 0), Point<2>(2, 0.3), Point<2>(0.4, 1.2)},
          true);
  test<3>("hexahedron",
          {Point<3>(0, 0, 0),
           Point<3>(1, 0.1, 0),
           Point<3>(0.1, 1.2, 0.1),
           Point<3>(1.3, 1, -0.1),
           Point<3>(0, 0.1, 1),
           Point<3>(1.1, 0, 1.2),
           Point<3>(-0.1, 1, 0.9),
           Point<3>(1.2, 1.3, 1.4)},
          false);
}
