#ifndef mpm_otm_shape_functions_linear_lagrange_h
#define mpm_otm_shape_functions_linear_lagrange_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/fe.h>

#include <mpm_otm/shape_functions/shape_functions.h>

#include <memory>
#include <vector>

namespace MpmOtm
{
  /**
   * Piecewise-linear Lagrange functions (journal Sect. 6.1): FE_Q(1) on
   * quadrilaterals/hexahedra, FE_SimplexP(1) on triangles/tetrahedra. Values
   * and gradients are computed in closed form from the particle's reference
   * coordinates (tensor products of 1 - xi and xi, or barycentric
   * coordinates) and the isoparametric Jacobian of its cell, so they are right
   * on fixed and on moving grids.
   */
  template <int dim>
  class LinearLagrange : public ShapeFunctions<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    initialize(const BackgroundGrid<dim> &grid) override;

    types::global_dof_index
    n_functions() const override;

    IndexSet
    locally_owned_functions() const override;

    IndexSet
    locally_relevant_functions() const override;

    void
    functions_on_cell(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      std::vector<types::global_dof_index> &functions) const override;

    types::global_dof_index
    vertex_function(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const unsigned int v) const override;

    const DoFHandler<dim> &
    dof_handler() const override;

    void
    to_cell_dofs(
      const typename ShapeFunctions<dim>::VectorType &coefficients,
      typename ShapeFunctions<dim>::VectorType       &values) const override;

    void
    evaluate(const MaterialPoints<dim>         &material_points,
             const Utilities::MPI::Partitioner &partitioner,
             ParticleShapeData<dim>            &data) const override;

    IndexSet
    boundary_functions(const types::boundary_id boundary_id) const override;

    bool
    is_linearly_complete() const override;

    /**
     * True on triangles/tetrahedra.
     */
    bool
    gradients_constant_on_cells() const override;

    /**
     * Whether the hypercube cell with @p vertices (in deal.II's order) is
     * the affine image of the reference cell (a parallelogram or a
     * parallelepiped), to round-off: then its Jacobian is constant.
     */
    static bool
    is_affine(const std::vector<Point<dim>> &vertices);

    /**
     * Values and reference-cell gradients of the 2^dim (hypercube) or dim + 1
     * (simplex) functions at reference point @p xi, in the order of the
     * cell's vertices.
     */
    static void
    reference_values(const bool        simplex,
                     const Point<dim> &xi,
                     double           *values,
                     Tensor<1, dim>   *reference_gradients);

  private:
    bool                                simplex = false;
    std::unique_ptr<FiniteElement<dim>> fe;
    DoFHandler<dim>                     dofs;
  };
} // namespace MpmOtm

#endif
