#include <deal.II/dofs/dof_tools.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/fe_powell_sabin.h>
#include <mpm_otm/shape_functions/powell_sabin.h>

namespace MpmOtm
{
  namespace
  {
    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }
  } // namespace



  template <int dim>
  void
  PowellSabin<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  PowellSabin<dim>::parse_parameters(ParameterHandler &)
  {
    AssertThrow(dim == 2,
                ExcMessage(
                  "Shape functions = Powell-Sabin needs Dimension = 2: "
                  "quadratic Powell-Sabin splines are defined on "
                  "triangulations (thesis Sect. 3.5). In 1D use Shape "
                  "functions = B-spline with B-spline degree = 2, their 1D "
                  "counterpart; 3D is not implemented."));
  }



  template <int dim>
  void
  PowellSabin<dim>::initialize(const BackgroundGrid<dim> &grid)
  {
    AssertThrow(grid.is_simplex(),
                ExcMessage("Shape functions = Powell-Sabin need Mesh/Cell "
                           "type = simplex (triangles), or a Mesh/Mesh file "
                           "of triangles."));
    initialize(grid.triangulation());
  }



  template <int dim>
  void
  PowellSabin<dim>::initialize(const Triangulation<dim> &)
  {
    AssertThrow(false, ExcNotImplemented());
  }



  template <>
  void
  PowellSabin<2>::initialize(const Triangulation<2> &triangulation)
  {
    splines                   = std::make_shared<PowellSabinGeometry>();
    const std::string problem = splines->reinit(triangulation);
    AssertThrow(problem.empty(),
                ExcMessage("Shape functions = Powell-Sabin: " + problem));
    function_element = std::make_unique<FE_PowellSabin>(splines);
    function_dofs.reinit(triangulation);
    function_dofs.distribute_dofs(*function_element);

    // functions_per_node() promises that a vertex's functions are
    // consecutive from a multiple of three; DoFHandler numbers a vertex's
    // degrees of freedom together.
    functions_of_cell.resize(triangulation.n_active_cells());
    std::vector<types::global_dof_index> dofs(n_cell_functions);
    for (const auto &cell : function_dofs.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < n_cell_functions; ++i)
            {
              AssertThrow(dofs[i] == dofs[i - i % 3] + i % 3 &&
                            dofs[i - i % 3] % 3 == 0,
                          ExcInternalError());
              functions_of_cell[cell->active_cell_index()][i] = dofs[i];
            }
        }
  }



  template <int dim>
  types::global_dof_index
  PowellSabin<dim>::n_functions() const
  {
    return function_dofs.n_dofs();
  }



  template <int dim>
  IndexSet
  PowellSabin<dim>::locally_owned_functions() const
  {
    Assert(function_dofs.locally_owned_dofs().is_contiguous(),
           ExcInternalError());
    return function_dofs.locally_owned_dofs();
  }



  template <int dim>
  IndexSet
  PowellSabin<dim>::locally_relevant_functions() const
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(function_dofs, relevant);
    return relevant;
  }



  template <int dim>
  void
  PowellSabin<dim>::evaluate(const MaterialPoints<dim>         &material_points,
                             const Utilities::MPI::Partitioner &partitioner,
                             ParticleShapeData<dim>            &data) const
  {
    const auto        &particles   = material_points.particle_handler();
    const unsigned int n_particles = particles.n_locally_owned_particles();

    data.reinit(n_particles, n_cell_functions);

    std::array<unsigned int, n_cell_functions>        local_indices;
    typename Triangulation<dim>::active_cell_iterator current_cell;
    for (const auto &particle : particles)
      {
        const auto cell = particle.get_surrounding_cell();
        if (cell != current_cell)
          {
            current_cell          = cell;
            const auto &functions = cell_functions(cell);
            for (unsigned int i = 0; i < n_cell_functions; ++i)
              local_indices[i] = partitioner.global_to_local(functions[i]);
            data.start_batch(local_indices.data(), n_cell_functions);
          }
        const std::size_t offset = data.add_particle();
        if constexpr (dim == 2)
          splines->cell_values(cell,
                               particle.get_reference_location(),
                               &data.values[offset],
                               &data.gradients[offset]);
      }
    data.finish();
  }



  template <int dim>
  const std::array<types::global_dof_index, PowellSabin<dim>::n_cell_functions>
    &
    PowellSabin<dim>::cell_functions(
      const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    return functions_of_cell[cell->active_cell_index()];
  }



  template <int dim>
  void
  PowellSabin<dim>::for_each_side_control_point(
    const types::boundary_id,
    const std::function<void(const types::global_dof_index,
                             const Point<dim> &,
                             const Point<dim> &,
                             const Tensor<1, dim> &)> &) const
  {
    AssertThrow(false, ExcNotImplemented());
  }



  template <>
  void
  PowellSabin<2>::for_each_side_control_point(
    const types::boundary_id                         boundary_id,
    const std::function<void(const types::global_dof_index,
                             const Point<2> &,
                             const Point<2> &,
                             const Tensor<1, 2> &)> &action) const
  {
    // The vertices of this rank's cells, whose control triangles are
    // complete: all cells around them are its own or ghost cells.
    const auto       &triangulation = function_dofs.get_triangulation();
    std::vector<bool> of_own_cell(triangulation.n_vertices(), false);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          of_own_cell[cell->vertex_index(v)] = true;
    for (const auto &cell : function_dofs.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary_id)
            {
              const auto        &face = cell->face(f);
              const Tensor<1, 2> tangent =
                (face->vertex(1) - face->vertex(0)) / face->measure();
              for (unsigned int i = 0; i < 2; ++i)
                {
                  const unsigned int v = face->vertex_index(i);
                  if (!of_own_cell[v])
                    continue;
                  const auto  &control = splines->control_triangle(v);
                  unsigned int on_line = 0;
                  for (unsigned int q = 0; q < 3; ++q)
                    if (std::abs(
                          cross(tangent, control[q] - face->vertex(i))) <=
                        1e-10 * face->measure())
                      {
                        action(face->vertex_dof_index(i, q),
                               face->vertex(i),
                               control[q],
                               tangent);
                        ++on_line;
                      }
                  AssertThrow(
                    on_line >= 2,
                    ExcMessage("The Powell-Sabin control triangle of the "
                               "boundary vertex at " +
                               Utilities::to_string(face->vertex(i)[0]) + ", " +
                               Utilities::to_string(face->vertex(i)[1]) +
                               " has fewer than two points on boundary " +
                               Utilities::to_string(boundary_id) +
                               ": the value and tangential derivative there "
                               "cannot be imposed through its coefficients."));
                }
            }
  }



  template <int dim>
  IndexSet
  PowellSabin<dim>::boundary_functions(const types::boundary_id) const
  {
    AssertThrow(false, ExcNotImplemented());
    return IndexSet();
  }



  template <>
  IndexSet
  PowellSabin<2>::boundary_functions(const types::boundary_id boundary_id) const
  {
    IndexSet functions(n_functions());
    for_each_side_control_point(boundary_id,
                                [&](const types::global_dof_index function,
                                    const Point<2> &,
                                    const Point<2> &,
                                    const Tensor<1, 2> &) {
                                  functions.add_index(function);
                                });
    functions.compress();
    return functions;
  }



  template <int dim>
  void
  PowellSabin<dim>::make_boundary_constraints(
    const types::boundary_id   boundary_id,
    const Function<dim>       &g,
    AffineConstraints<double> &constraints) const
  {
    for_each_side_control_point(boundary_id,
                                [&](const types::global_dof_index function,
                                    const Point<dim>             &vertex,
                                    const Point<dim>             &control_point,
                                    const Tensor<1, dim>         &tangent) {
                                  if (constraints.is_constrained(function))
                                    return;
                                  constraints.add_line(function);
                                  constraints.set_inhomogeneity(
                                    function,
                                    g.value(vertex) +
                                      (g.gradient(vertex) * tangent) *
                                        ((control_point - vertex) * tangent));
                                });
  }



  template <int dim>
  bool
  PowellSabin<dim>::is_linearly_complete() const
  {
    return true;
  }



  template <int dim>
  typename ShapeFunctions<dim>::MovingGrid
  PowellSabin<dim>::moving_grid() const
  {
    return ShapeFunctions<dim>::MovingGrid::rebuilt;
  }



  template <int dim>
  void
  PowellSabin<dim>::vertex_interpolation(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const unsigned int                                       v,
    std::vector<types::global_dof_index>                    &functions,
    std::vector<double>                                     &weights) const
  {
    const auto &functions_of_this_cell = cell_functions(cell);
    functions.assign(functions_of_this_cell.begin() + 3 * v,
                     functions_of_this_cell.begin() + 3 * v + 3);
    const auto &alpha = splines->vertex_values(cell->vertex_index(v));
    weights.assign(alpha.begin(), alpha.end());
  }



  template <int dim>
  std::string
  PowellSabin<dim>::rebuild_on_moved_grid()
  {
    if constexpr (dim == 2)
      return splines->reinit(function_dofs.get_triangulation());
    else
      return "Powell-Sabin splines are defined in 2D only.";
  }



  template <int dim>
  unsigned int
  PowellSabin<dim>::functions_per_node() const
  {
    return 3;
  }



  template <int dim>
  void
  PowellSabin<dim>::functions_on_cell(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>                    &functions) const
  {
    const auto &cell_functions_of_cell = cell_functions(cell);
    functions.assign(cell_functions_of_cell.begin(),
                     cell_functions_of_cell.end());
  }



  template <int dim>
  bool
  PowellSabin<dim>::functions_in_box(
    const BoundingBox<dim> &,
    std::vector<types::global_dof_index> &functions) const
  {
    functions.clear();
    return false;
  }



  template <int dim>
  types::global_dof_index
  PowellSabin<dim>::vertex_function(
    const typename Triangulation<dim>::active_cell_iterator &,
    const unsigned int) const
  {
    return numbers::invalid_dof_index;
  }



  template <int dim>
  const DoFHandler<dim> &
  PowellSabin<dim>::dof_handler() const
  {
    return function_dofs;
  }



  template <int dim>
  void
  PowellSabin<dim>::to_cell_dofs(const VectorType &coefficients,
                                 VectorType       &values) const
  {
    values.reinit(coefficients.get_partitioner());
    values.copy_locally_owned_data_from(coefficients);
    values.update_ghost_values();
  }



  template <int dim>
  const PowellSabinGeometry &
  PowellSabin<dim>::geometry() const
  {
    Assert(splines != nullptr, ExcNotInitialized());
    return *splines;
  }



  template class PowellSabin<1>;
  template class PowellSabin<2>;
  template class PowellSabin<3>;
} // namespace MpmOtm

#define MPM_OTM_POWELL_SABIN_DESCRIPTION                                     \
  "quadratic Powell-Sabin splines, three per vertex of a triangle grid, C1 " \
  "(2D, Mesh/Cell type = simplex, Method = MPM or Unified)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<1>,
                        MpmOtm::PowellSabin<1>,
                        "Powell-Sabin",
                        MPM_OTM_POWELL_SABIN_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<2>,
                        MpmOtm::PowellSabin<2>,
                        "Powell-Sabin",
                        MPM_OTM_POWELL_SABIN_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<3>,
                        MpmOtm::PowellSabin<3>,
                        "Powell-Sabin",
                        MPM_OTM_POWELL_SABIN_DESCRIPTION)
