#ifndef mpm_otm_shape_functions_powell_sabin_h
#define mpm_otm_shape_functions_powell_sabin_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/affine_constraints.h>

#include <mpm_otm/shape_functions/shape_functions.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace MpmOtm
{
  /**
   * Quadratic Powell-Sabin splines on a conforming triangulation (thesis
   * Sect. 3.5, after Dierckx): C1 piecewise quadratics on the Powell-Sabin
   * refinement, three functions per vertex.
   *
   * Every triangle is split into six sub-triangles T_{k,0} = (V_k, R_k, Z),
   * T_{k,1} = (R_k, V_{k+1}, Z) (k = 0, 1, 2) by its incentre Z and one
   * point R_k on each edge k = (V_k, V_{k+1}): where the segment between the
   * incentres of the two triangles at the edge crosses it, or the edge's
   * midpoint on the domain boundary (thesis 3.5.1). Each vertex V gets a
   * control triangle Q^0 Q^1 Q^2 that contains its Powell-Sabin points (V,
   * the midpoints between V and the split points of its edges and the
   * incentres of its triangles), chosen by the thesis's near-optimal rule
   * (3.5.2: the smallest triangle among those formed by three edges of the
   * points' convex hull, or by two and a third edge orthogonal to their
   * bisector), with one restriction: a candidate must use every hull edge
   * that passes through V, so at a boundary vertex on a straight side two
   * control points lie on that side and at a convex corner V itself is one
   * (homogeneous Dirichlet conditions then fix whole coefficients). The
   * triplets of the three functions of V are the barycentric coordinates
   * lambda_q of the control triangle and their gradients (Eqs. 3.47-3.49),
   * and a function's Bezier ordinates next to V are lambda_q at the
   * Powell-Sabin points (Eqs. 3.54-3.56; the other ordinates follow from
   * C1 continuity). The functions are non-negative, a partition of unity,
   * reproduce quadratics and are C1.
   *
   * Function q of vertex v has the index 3 i + q, i the vertex's index in
   * the FE_SimplexP(1) numbering of dof_handler(): owned ranges are
   * contiguous and a vertex's three functions share an owner. Values at a
   * point come from the point's barycentric coordinates in its cell, which
   * select the sub-triangle; only per-cell numbers (incentre, split points
   * and four ordinates per function) are stored.
   *
   * Only defined for dim = 2; in 1D and 3D parse_parameters() stops with a
   * message. Grid output writes the field's values at the vertices
   * (FE_SimplexP(1)), not the piecewise quadratic between them.
   */
  template <int dim>
  class PowellSabin : public ShapeFunctions<dim>
  {
  public:
    using typename ShapeFunctions<dim>::VectorType;

    /**
     * Number of functions that do not vanish on a cell: three per vertex.
     */
    static constexpr unsigned int n_cell_functions = 9;

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Stop unless dim = 2.
     */
    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * Set up the functions on the grid's triangulation (Mesh/Cell type
     * must be simplex).
     */
    void
    initialize(const BackgroundGrid<dim> &grid) override;

    /**
     * Set up the functions on any conforming triangulation of triangles.
     */
    void
    initialize(const Triangulation<dim> &triangulation);

    types::global_dof_index
    n_functions() const override;

    IndexSet
    locally_owned_functions() const override;

    IndexSet
    locally_relevant_functions() const override;

    void
    evaluate(const MaterialPoints<dim>         &material_points,
             const Utilities::MPI::Partitioner &partitioner,
             ParticleShapeData<dim>            &data) const override;

    /**
     * The functions (v, q) of the vertices v on boundary @p boundary_id
     * whose control point Q_v^q lies on the boundary line through v. Setting
     * their coefficients to zero makes the field and its tangential
     * derivative vanish on the boundary (thesis Eqs. 3.63-3.64 in the form
     * of Sect. 3.5.4, Fig. 3.24).
     */
    IndexSet
    boundary_functions(const types::boundary_id boundary_id) const override;

    /**
     * Add to @p constraints the Dirichlet condition u = @p g on boundary
     * @p boundary_id (a straight side), imposed through the value and the
     * tangential derivative at its vertices (thesis Sect. 3.5.4): the
     * coefficient of each function of boundary_functions() is the side's
     * linear Taylor polynomial of g at the vertex V at the function's
     * control point Q, g(V) + (grad g(V) . t) ((Q - V) . t) with t the
     * side's tangent; the third function's control point is off the side,
     * where its barycentric coordinate vanishes. Along the side the field is
     * then the quadratic C1 spline interpolating g and its tangential
     * derivative at the vertices (g itself if g is quadratic). @p g must
     * implement gradient(). Lines already constrained (a corner shared
     * with another side) are kept.
     */
    void
    make_boundary_constraints(const types::boundary_id   boundary_id,
                              const Function<dim>       &g,
                              AffineConstraints<double> &constraints) const;

    /**
     * True: the functions reproduce linear (even quadratic) fields, with the
     * control points as coefficients of x (thesis Eqs. 3.41-3.46).
     */
    bool
    is_linearly_complete() const override;

    /**
     * MovingGrid::not_supported (yet): the functions would have to be
     * rebuilt on the moved triangulation every step.
     */
    typename ShapeFunctions<dim>::MovingGrid
    moving_grid() const override;

    std::string
    moving_grid_limitation() const override;

    /**
     * True: write_basis_picture() draws the three functions of a vertex.
     */
    bool
    has_basis_picture() const override;

    /**
     * Write the three functions of the vertex nearest to @p point on the
     * Powell-Sabin refinement of its cells and their neighbours as the VTU
     * file @p file_name (phi_0, phi_1, phi_2), each of the six
     * sub-triangles of a cell divided into 36 triangles. 2D only (the
     * family is).
     */
    void
    write_basis_picture(const Point<dim>  &point,
                        const std::string &file_name) const override;

    /**
     * 3: function q of vertex v has the global index 3 i + q (i the vertex's
     * index in the FE_SimplexP(1) numbering).
     */
    unsigned int
    functions_per_node() const override;

    void
    functions_on_cell(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      std::vector<types::global_dof_index> &functions) const override;

    /**
     * numbers::invalid_dof_index: three functions per vertex, none of which
     * moves with it.
     */
    types::global_dof_index
    vertex_function(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const unsigned int v) const override;

    /**
     * The FE_SimplexP(1) vertex numbering, also the output element.
     */
    const DoFHandler<dim> &
    dof_handler() const override;

    /**
     * The field's values at the vertices, sum_q c_v^q alpha_v^q (the
     * functions of the other vertices vanish there).
     */
    void
    to_cell_dofs(const VectorType &coefficients,
                 VectorType       &values) const override;

    /**
     * The global indices of the nine functions of @p cell: vertex 0's
     * functions q = 0, 1, 2, then vertex 1's and vertex 2's.
     */
    const std::array<types::global_dof_index, n_cell_functions> &
    cell_functions(
      const typename Triangulation<dim>::active_cell_iterator &cell) const;

    /**
     * Values and gradients of the nine functions of @p cell at the point
     * with reference coordinates @p xi (barycentric coordinates
     * (1 - xi_0 - xi_1, xi_0, xi_1)), in the order of cell_functions(). The
     * point's sub-triangle is found from @p xi; with @p sub_triangle
     * (2 k + half for T_{k,half}) that sub-triangle's quadratic is evaluated
     * instead, also outside it.
     */
    void
    cell_values(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const Point<dim>                                        &xi,
      double *const                                            values,
      Tensor<1, dim> *const                                    gradients,
      const unsigned int sub_triangle = numbers::invalid_unsigned_int) const;

    /**
     * The control triangle of the vertex with index @p vertex in the
     * triangulation.
     */
    const std::array<Point<dim>, 3> &
    control_triangle(const unsigned int vertex) const;

    /**
     * The point on edge @p edge (from vertex @p edge to vertex
     * @p edge + 1 mod 3) of @p cell where the Powell-Sabin refinement splits
     * it, and the cell's split point (incentre) for @p edge = 3.
     */
    Point<dim>
    split_point(const typename Triangulation<dim>::active_cell_iterator &cell,
                const unsigned int edge) const;

  private:
    /**
     * Call @p action(function, V, Q, t) for every function of every vertex
     * V of boundary @p boundary_id whose control point Q lies on the side
     * (tangent t) through V; stops if a vertex has fewer than two.
     */
    void
    for_each_side_control_point(
      const types::boundary_id                           boundary_id,
      const std::function<void(const types::global_dof_index,
                               const Point<dim> &,
                               const Point<dim> &,
                               const Tensor<1, dim> &)> &action) const;

    /**
     * What a cell needs to evaluate its functions: incentre barycentric
     * coordinates a_k, split weights rho_k (R_k = rho_k V_k + (1 - rho_k)
     * V_{k+1}), gradients of the barycentric coordinates, and per function
     * the ordinates f, Lf, Lb, Lt of the owner vertex V_j at V_j,
     * mid(V_j, R_j), mid(V_j, R_{j-1}) and mid(V_j, Z) (thesis Eqs. 3.54-3.56).
     */
    struct CellData
    {
      std::array<double, 3>                                 a;
      std::array<double, 3>                                 rho;
      std::array<Tensor<1, dim>, 3>                         zeta_gradients;
      std::array<std::array<double, 4>, n_cell_functions>   ordinates;
      std::array<types::global_dof_index, n_cell_functions> functions;
    };

    std::unique_ptr<FiniteElement<dim>> fe;
    DoFHandler<dim>                     vertex_dofs;
    std::vector<CellData>               cell_data;
    /// Control triangle of each vertex (by vertex index).
    std::vector<std::array<Point<dim>, 3>> control_triangles;
    /// alpha_v^q = lambda_q(V) of each vertex (by vertex index).
    std::vector<std::array<double, 3>> vertex_values;
  };
} // namespace MpmOtm

#endif
