#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/linear_lagrange.h>

#include <bitset>

namespace MpmOtm
{
  template <int dim>
  void
  LinearLagrange<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  LinearLagrange<dim>::initialize(const BackgroundGrid<dim> &grid)
  {
    simplex = grid.is_simplex();
    if (simplex)
      fe = std::make_unique<FE_SimplexP<dim>>(1);
    else
      fe = std::make_unique<FE_Q<dim>>(1);
    dofs.reinit(grid.triangulation());
    dofs.distribute_dofs(*fe);
  }



  template <int dim>
  types::global_dof_index
  LinearLagrange<dim>::n_functions() const
  {
    return dofs.n_dofs();
  }



  template <int dim>
  IndexSet
  LinearLagrange<dim>::locally_owned_functions() const
  {
    return dofs.locally_owned_dofs();
  }



  template <int dim>
  IndexSet
  LinearLagrange<dim>::locally_relevant_functions() const
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    return relevant;
  }



  template <int dim>
  void
  LinearLagrange<dim>::functions_on_cell(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>                    &functions) const
  {
    functions.resize(dofs.get_fe().n_dofs_per_cell());
    typename DoFHandler<dim>::active_cell_iterator(&cell->get_triangulation(),
                                                   cell->level(),
                                                   cell->index(),
                                                   &dofs)
      ->get_dof_indices(functions);
  }



  template <int dim>
  types::global_dof_index
  LinearLagrange<dim>::vertex_function(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const unsigned int                                       v) const
  {
    return
      typename DoFHandler<dim>::active_cell_iterator(&cell->get_triangulation(),
                                                     cell->level(),
                                                     cell->index(),
                                                     &dofs)
        ->vertex_dof_index(v, 0);
  }



  template <int dim>
  const DoFHandler<dim> &
  LinearLagrange<dim>::dof_handler() const
  {
    return dofs;
  }



  template <int dim>
  void
  LinearLagrange<dim>::to_cell_dofs(
    const typename ShapeFunctions<dim>::VectorType &coefficients,
    typename ShapeFunctions<dim>::VectorType       &values) const
  {
    values.reinit(coefficients.get_partitioner());
    values = coefficients;
    values.update_ghost_values();
  }



  template <int dim>
  void
  LinearLagrange<dim>::reference_values(const bool        simplex,
                                        const Point<dim> &xi,
                                        double           *values,
                                        Tensor<1, dim>   *reference_gradients)
  {
    if (simplex)
      {
        values[0] = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            values[0] -= xi[d];
            values[d + 1]             = xi[d];
            reference_gradients[0][d] = -1.;
            for (unsigned int e = 0; e < dim; ++e)
              reference_gradients[d + 1][e] = (d == e ? 1. : 0.);
          }
        return;
      }

    // Vertex i of a hypercube sits at xi_d = bit d of i; its function is the
    // product over d of xi_d or 1 - xi_d.
    for (unsigned int i = 0; i < (1u << dim); ++i)
      {
        double factors[dim];
        double signs[dim];
        for (unsigned int d = 0; d < dim; ++d)
          {
            const bool upper = (i >> d) & 1u;
            factors[d]       = upper ? xi[d] : 1. - xi[d];
            signs[d]         = upper ? 1. : -1.;
          }
        double value = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          value *= factors[d];
        values[i] = value;
        for (unsigned int e = 0; e < dim; ++e)
          {
            double derivative = signs[e];
            for (unsigned int d = 0; d < dim; ++d)
              if (d != e)
                derivative *= factors[d];
            reference_gradients[i][e] = derivative;
          }
      }
  }



  template <int dim>
  bool
  LinearLagrange<dim>::is_affine(const std::vector<Point<dim>> &vertices)
  {
    // The map sum_i x_i N_i(xi) of a hypercube is affine if the coefficients
    // of its products xi_a xi_b (xi_c) vanish: for every set S of two or
    // more directions, sum over the vertices T in S of (-1)^(|S| - |T|) x_T,
    // vertex T sitting at xi_d = 1 for d in T (bit d of its number).
    const double scale = vertices.back().distance(vertices.front());
    for (unsigned int S = 0; S < vertices.size(); ++S)
      {
        if (S == 0 || (S & (S - 1)) == 0)
          continue;
        Tensor<1, dim> coefficient;
        for (unsigned int T = 0; T < vertices.size(); ++T)
          if ((T & S) == T)
            {
              const bool even = std::bitset<3>(S ^ T).count() % 2 == 0;
              coefficient += (even ? 1. : -1.) * vertices[T];
            }
        if (coefficient.norm() > 1e-12 * scale)
          return false;
      }
    return true;
  }



  template <int dim>
  void
  LinearLagrange<dim>::evaluate(const MaterialPoints<dim> &material_points,
                                const Utilities::MPI::Partitioner &partitioner,
                                ParticleShapeData<dim>            &data) const
  {
    const auto        &particles   = material_points.particle_handler();
    const unsigned int n_functions = fe->n_dofs_per_cell();
    const unsigned int n_particles = particles.n_locally_owned_particles();

    data.reinit(n_particles, n_functions);

    std::vector<types::global_dof_index> dof_indices(n_functions);
    std::vector<unsigned int>            local_indices(n_functions);
    std::vector<Point<dim>>              vertices(n_functions);
    std::vector<Tensor<1, dim>>          reference_gradients(n_functions);
    typename Triangulation<dim>::active_cell_iterator current_cell;
    // On an affine cell (a simplex, a parallelogram, a parallelepiped) the
    // Jacobian is the same at every point: its columns are the edges from
    // vertex 0 along the reference axes, inverted once per cell.
    bool           affine = false;
    Tensor<2, dim> inverse_transpose;

    for (const auto &particle : particles)
      {
        const auto cell = particle.get_surrounding_cell();
        if (cell != current_cell)
          {
            current_cell = cell;
            typename DoFHandler<dim>::active_cell_iterator dof_cell(
              &cell->get_triangulation(),
              cell->level(),
              cell->index(),
              &dofs);
            dof_cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < n_functions; ++i)
              {
                local_indices[i] = partitioner.global_to_local(dof_indices[i]);
                vertices[i]      = cell->vertex(i);
              }
            affine = simplex || is_affine(vertices);
            if (affine)
              {
                Tensor<2, dim> jacobian;
                for (unsigned int b = 0; b < dim; ++b)
                  {
                    const Tensor<1, dim> edge =
                      vertices[simplex ? b + 1 : 1u << b] - vertices[0];
                    for (unsigned int a = 0; a < dim; ++a)
                      jacobian[a][b] = edge[a];
                  }
                inverse_transpose = transpose(invert(jacobian));
              }
            data.start_batch(local_indices.data(), n_functions);
          }

        const std::size_t offset    = data.add_particle();
        double           *values    = &data.values[offset];
        Tensor<1, dim>   *gradients = &data.gradients[offset];
        reference_values(simplex,
                         particle.get_reference_location(),
                         values,
                         reference_gradients.data());

        if (!affine)
          {
            // Isoparametric Jacobian J_ab = sum_i x_i,a dN_i/dxi_b.
            Tensor<2, dim> jacobian;
            for (unsigned int i = 0; i < n_functions; ++i)
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  jacobian[a][b] += vertices[i][a] * reference_gradients[i][b];
            inverse_transpose = transpose(invert(jacobian));
          }
        for (unsigned int i = 0; i < n_functions; ++i)
          gradients[i] = inverse_transpose * reference_gradients[i];
      }
    data.finish();
  }



  template <int dim>
  IndexSet
  LinearLagrange<dim>::boundary_functions(
    const types::boundary_id boundary_id) const
  {
    return DoFTools::extract_boundary_dofs(dofs,
                                           ComponentMask(),
                                           std::set<types::boundary_id>{
                                             boundary_id});
  }



  template <int dim>
  bool
  LinearLagrange<dim>::gradients_constant_on_cells() const
  {
    return simplex;
  }



  template <int dim>
  bool
  LinearLagrange<dim>::is_linearly_complete() const
  {
    return true;
  }



  template class LinearLagrange<1>;
  template class LinearLagrange<2>;
  template class LinearLagrange<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<1>,
                        MpmOtm::LinearLagrange<1>,
                        "linear",
                        "piecewise-linear Lagrange (FE_Q(1) / FE_SimplexP(1))")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<2>,
                        MpmOtm::LinearLagrange<2>,
                        "linear",
                        "piecewise-linear Lagrange (FE_Q(1) / FE_SimplexP(1))")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<3>,
                        MpmOtm::LinearLagrange<3>,
                        "linear",
                        "piecewise-linear Lagrange (FE_Q(1) / FE_SimplexP(1))")
