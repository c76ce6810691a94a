#ifndef mpm_otm_shape_functions_powell_sabin_h
#define mpm_otm_shape_functions_powell_sabin_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/affine_constraints.h>

#include <mpm_otm/shape_functions/powell_sabin_geometry.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace MpmOtm
{
  /**
   * The family of quadratic Powell-Sabin splines on a conforming
   * triangulation (thesis Sect. 3.5): C1 piecewise quadratics, three
   * functions per vertex. PowellSabinGeometry builds them and evaluates
   * them; FE_PowellSabin makes them a deal.II element, whose DoFHandler
   * numbers and distributes them (function q of a vertex is its degree of
   * freedom q; owned ranges are contiguous and a vertex's three functions
   * are consecutive, start at a multiple of three and share an owner). This
   * class is what the rest of the program sees of them: the values at the
   * material points, which come from the points' barycentric coordinates in
   * their cells through the geometry's kernel, and the boundary conditions
   * on the coefficients.
   *
   * Only defined for dim = 2; in 1D and 3D parse_parameters() stops with a
   * message. Grid output writes the field with FE_PowellSabin: DataOut
   * evaluates it at the vertices and edge midpoints of every triangle.
   */
  template <int dim>
  class PowellSabin : public ShapeFunctions<dim>
  {
  public:
    using typename ShapeFunctions<dim>::VectorType;

    /**
     * Number of functions that do not vanish on a cell: three per vertex.
     */
    static constexpr unsigned int n_cell_functions =
      PowellSabinGeometry::n_cell_functions;

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
     * MovingGrid::rebuilt: on a moving grid (Method = Unified) the vertices
     * move with the field's values there and the functions are rebuilt on
     * the moved triangulation every step.
     */
    typename ShapeFunctions<dim>::MovingGrid
    moving_grid() const override;

    /**
     * The vertex's three functions with weights alpha_v^q = lambda_q(V):
     * the field's value at the vertex (the other vertices' functions vanish
     * there).
     */
    void
    vertex_interpolation(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const unsigned int                                       v,
      std::vector<types::global_dof_index>                    &functions,
      std::vector<double> &weights) const override;

    /**
     * Build split points, control triangles and ordinates anew on the moved
     * vertices (PowellSabinGeometry::reinit()); numbering and supports stay.
     */
    std::string
    rebuild_on_moved_grid() override;

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
     * 3: the functions of a vertex are its three degrees of freedom of
     * FE_PowellSabin, consecutive from a multiple of three.
     */
    unsigned int
    functions_per_node() const override;

    void
    functions_on_cell(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      std::vector<types::global_dof_index> &functions) const override;

    /**
     * False: three functions belong to each vertex.
     */
    bool
    functions_in_box(
      const BoundingBox<dim>               &box,
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
     * The DoFHandler of FE_PowellSabin: its degrees of freedom are the
     * functions, and grid output writes the field with it.
     */
    const DoFHandler<dim> &
    dof_handler() const override;

    /**
     * A copy of @p coefficients: they are the degrees of freedom of
     * dof_handler().
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
     * The refinement and the functions' numbers, with their evaluation.
     */
    const PowellSabinGeometry &
    geometry() const;

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

    std::shared_ptr<PowellSabinGeometry> splines;
    /// FE_PowellSabin on the functions, numbered by function_dofs.
    std::unique_ptr<FiniteElement<dim>> function_element;
    DoFHandler<dim>                     function_dofs;
    /// The functions of each cell (by active cell index), as the
    /// geometry's kernel orders them.
    std::vector<std::array<types::global_dof_index, n_cell_functions>>
      functions_of_cell;
  };
} // namespace MpmOtm

#endif
