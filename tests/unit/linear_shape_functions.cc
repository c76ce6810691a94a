// The closed-form linear functions: equal to deal.II's FE_Q(1) and
// FE_SimplexP(1) at random reference points, partition of unity, and linear
// reproduction (values and gradients) at the material points of real grids
// (1D, quadrilaterals, hexahedra, triangles, tetrahedra), both on the initial
// grid and on a grid that OTM has moved and distorted (the isoparametric
// functions reproduce linear fields on any non-inverted cell).

#include <deal.II/base/partitioner.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/linear_lagrange.h>

#include <random>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

template <int dim>
void
test_reference(const bool simplex)
{
  std::unique_ptr<FiniteElement<dim>> fe;
  if (simplex)
    fe = std::make_unique<FE_SimplexP<dim>>(1);
  else
    fe = std::make_unique<FE_Q<dim>>(1);
  const unsigned int                     n = fe->n_dofs_per_cell();
  std::mt19937                           random(42);
  std::uniform_real_distribution<double> uniform(0., 1.);
  double                                 max_error = 0;
  for (unsigned int trial = 0; trial < 100; ++trial)
    {
      Point<dim> xi;
      double     sum = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          xi[d] = uniform(random) * (simplex ? 1. - sum : 1.);
          sum += xi[d];
        }
      std::vector<double>         values(n);
      std::vector<Tensor<1, dim>> gradients(n);
      LinearLagrange<dim>::reference_values(simplex,
                                            xi,
                                            values.data(),
                                            gradients.data());
      double         unity = 0;
      Tensor<1, dim> gradient_sum;
      for (unsigned int i = 0; i < n; ++i)
        {
          max_error =
            std::max(max_error, std::abs(values[i] - fe->shape_value(i, xi)));
          max_error =
            std::max(max_error, (gradients[i] - fe->shape_grad(i, xi)).norm());
          unity += values[i];
          gradient_sum += gradients[i];
          check(values[i] >= -1e-15, "negative linear function");
        }
      check(std::abs(unity - 1.) < 1e-14, "no partition of unity");
      check(gradient_sum.norm() < 1e-14, "gradients do not sum to zero");
    }
  check(max_error < 1e-14, "closed form differs from " + fe->get_name());
  deallog << dim << "D " << fe->get_name()
          << ": closed form equals deal.II's element, partition of unity"
          << std::endl;
}

template <int dim>
void
test_reproduction(const std::string &cell_type, const bool moved)
{
  const std::string corner = (dim == 1 ? "0" : dim == 2 ? "0, 0" : "0, 0, 0");
  const std::string upper  = (dim == 1 ? "2" :
                              dim == 2 ? "2, 1.5" :
                                         "2, 1.5, 1");
  const std::string blocks = (dim == 1 ? "5" : dim == 2 ? "5, 3" : "3, 2, 2");
  // A shearing, stretching initial velocity; 20 OTM steps distort the grid.
  const std::string velocity =
    (dim == 1 ? "0.3 * sin(x)" :
     dim == 2 ? "0.3 * sin(y) + 0.1 * x; 0.3 * sin(x)" :
                "0.3 * sin(y); 0.3 * sin(z); 0.3 * sin(x)");
  auto simulator = make_simulator<dim>("",
                                       "set Dimension = " +
                                         std::to_string(dim) + R"(
set Problem = custom
set Method = OTM
set Mass matrix = consistent
subsection Time
  set End time = 0.2
  set Time step = 0.01
end
subsection Material
  set Young's modulus = 1
  set Density = 1
end
subsection Custom problem
  set Initial velocity = )" + velocity + R"(
end
subsection Mesh
  set Cell type = )" + cell_type +
                                         R"(
  set Lower corner = )" + corner + R"(
  set Upper corner = )" + upper + R"(
  set Subdivisions = )" + blocks + R"(
end
subsection Particles
  set Particles per cell = 3
end
)",
                                       "output-" + std::to_string(dim) + "d-" +
                                         cell_type);
  if (moved)
    simulator->run();

  // The family under test, on the simulator's (possibly moved) grid; its
  // numbering is the simulator's.
  LinearLagrange<dim> shape_functions;
  shape_functions.initialize(simulator->background_grid());
  const auto &dofs        = shape_functions.dof_handler();
  const auto &partitioner = simulator->nodal_system().partitioner();
  const auto &points      = simulator->material_points();

  // Nodal values of f(x) = 1 + sum_d (d + 2) x_d at the vertices.
  std::vector<double> nodal(partitioner.locally_owned_size() +
                            partitioner.n_ghost_indices());
  Tensor<1, dim>      slope;
  for (unsigned int d = 0; d < dim; ++d)
    slope[d] = d + 2.;
  std::vector<types::global_dof_index> indices(dofs.get_fe().n_dofs_per_cell());
  for (const auto &cell : dofs.active_cell_iterators())
    {
      cell->get_dof_indices(indices);
      for (unsigned int i = 0; i < indices.size(); ++i)
        nodal[partitioner.global_to_local(indices[i])] =
          1. + slope * cell->vertex(i);
    }

  ParticleShapeData<dim> data;
  shape_functions.evaluate(points, partitioner, data);
  double                                  max_error = 0;
  typename ParticleShapeData<dim>::Cursor cursor(data);
  for (const auto &particle : points.particle_handler())
    {
      double         value = 0;
      Tensor<1, dim> gradient;
      const auto     point = cursor.next();
      for (unsigned int e = 0; e < point.n; ++e)
        {
          value += point.values[e] * nodal[point.indices[e]];
          gradient += point.gradients[e] * nodal[point.indices[e]];
        }
      max_error =
        std::max(max_error,
                 std::abs(value - 1. - slope * particle.get_location()) +
                   (gradient - slope).norm());
    }
  check(max_error < 1e-12,
        "linear function not reproduced: error " + std::to_string(max_error));

  // One batch per cell with points, holding the cell's functions once.
  unsigned int occupied_cells = 0;
  for (const auto &cell : dofs.get_triangulation().active_cell_iterators())
    if (points.particle_handler().n_particles_in_cell(cell) > 0)
      ++occupied_cells;
  check(data.n_batches() == occupied_cells &&
          data.n_particles() == points.n_global_points(),
        "expected one batch per cell with points: " +
          std::to_string(data.n_batches()) + " batches, " +
          std::to_string(occupied_cells) + " cells with points");
  for (unsigned int b = 0; b < data.n_batches(); ++b)
    check(data.n_functions(b) == dofs.get_fe().n_dofs_per_cell() &&
            data.values.size() ==
              std::size_t(data.n_particles()) * dofs.get_fe().n_dofs_per_cell(),
          "a batch without the cell's functions");
  double largest_motion = 0;
  for (const auto &particle : points.particle_handler())
    largest_motion = std::max(largest_motion,
                              (particle.get_location() -
                               Point<dim>(PropertyLayout<dim>::get_vector(
                                 particle.get_properties(),
                                 PropertyLayout<dim>::initial_position)))
                                .norm());
  check(moved == (largest_motion > 1e-2), "the grid should have moved");
  deallog << dim << "D " << cell_type
          << (moved ? ", grid moved by OTM" : ", initial grid")
          << ": linear reproduction at " << points.n_global_points()
          << " points" << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  test_reference<1>(false);
  test_reference<2>(false);
  test_reference<3>(false);
  test_reference<2>(true);
  test_reference<3>(true);
  for (const bool moved : {false, true})
    {
      test_reproduction<1>("hypercube", moved);
      test_reproduction<2>("hypercube", moved);
      test_reproduction<3>("hypercube", moved);
      test_reproduction<2>("simplex", moved);
      test_reproduction<3>("simplex", moved);
    }
}
