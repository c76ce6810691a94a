#ifndef mpm_otm_shape_functions_b_splines_h
#define mpm_otm_shape_functions_b_splines_h

#include <deal.II/fe/fe.h>

#include <mpm_otm/shape_functions/shape_functions.h>

#include <array>
#include <memory>
#include <vector>

namespace MpmOtm
{
  /**
   * Tensor-product B-splines of degree p on open knot vectors (journal
   * Sect. 6.2): the knot spans are the cells of an axis-parallel box grid,
   * the first and last knot are repeated p + 1 times, so the functions are
   * interpolatory at the boundary, and direction d carries n_d = (number of
   * cells in d) + p functions. Knots may be non-uniform.
   *
   * The functions are evaluated by Bezier extraction: every cell carries
   * FE_Bernstein(p), and on the span j of direction d the p + 1 splines that
   * do not vanish are N_{j+a}(x) = sum_b C^d_j[a][b] B_b(t), t the cell's
   * reference coordinate, with the (p+1) x (p+1) extraction operator C^d_j;
   * in dim > 1 the cell's operator is the tensor product of the directions'.
   * Moving the knots (unified approach, journal Alg. 3) only recomputes the
   * extraction operators; numbering and sparsity stay.
   *
   * Function (i_0, ..., i_{dim-1}) has the tensor-product (lexicographic)
   * index i_0 + n_0 (i_1 + n_1 i_2). It belongs to the rank that owns its
   * anchor cell, the cell of the spans (a(i_0), ..., a(i_{dim-1})) with
   * a(i) = i - floor(p / 2) clamped to the spans of its direction: the
   * middle of the function's support, which holds its Greville point on
   * uniform knots. The global indices number each rank's functions
   * contiguously, in lexicographic order, rank after rank; on one rank they
   * are the lexicographic indices. A rank's relevant functions are those
   * that do not vanish on its cells.
   */
  template <int dim>
  class BSplines : public ShapeFunctions<dim>
  {
  public:
    using typename ShapeFunctions<dim>::VectorType;

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * B-splines of degree @p degree (the parameter file's "B-spline degree"
     * replaces it in parse_parameters()).
     */
    explicit BSplines(const unsigned int degree = 2);

    ~BSplines() override;

    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * Take the knots from the vertices of @p grid's axis-parallel box cells.
     */
    void
    initialize(const BackgroundGrid<dim> &grid) override;

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
     * Functions with a non-zero trace on side @p boundary_id (2 d lower,
     * 2 d + 1 upper end of direction d): the first or last layer.
     */
    IndexSet
    boundary_functions(const types::boundary_id boundary_id) const override;

    /**
     * True for p = 1 only (journal Sect. 7).
     */
    bool
    is_linearly_complete() const override;

    /**
     * MovingGrid::knots: the knots move per direction (AdvectedKnots).
     */
    typename ShapeFunctions<dim>::MovingGrid
    moving_grid() const override;

    /**
     * The (p+1)^dim functions of @p cell, local function
     * a_0 + (p+1) (a_1 + (p+1) a_2) first.
     */
    void
    functions_on_cell(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      std::vector<types::global_dof_index> &functions) const override;

    /**
     * Always numbers::invalid_dof_index: the functions belong to knots, not
     * vertices.
     */
    types::global_dof_index
    vertex_function(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const unsigned int v) const override;

    /**
     * The locally owned functions whose Greville point (the average of the
     * p inner knots of each direction, at the middle of the function's
     * support: the point a control coefficient belongs to) lies in @p box.
     */
    bool
    functions_in_box(
      const BoundingBox<dim>               &box,
      std::vector<types::global_dof_index> &functions) const override;

    /**
     * The integrals over a side of the box grid (boundary id 2 d or 2 d + 1
     * for direction d): only the functions of the first or last layer in
     * direction d do not vanish there, and each is the product of the
     * integrals of its 1D functions along the side, (U_{i+p+1} - U_i) /
     * (p + 1) on the open knot vector U.
     */
    bool
    boundary_integrals(const types::boundary_id boundary_id,
                       VectorType              &integrals) const override;

    /**
     * The Greville points of the relevant functions: the coefficients of
     * the field x (B-splines reproduce linear fields).
     */
    bool
    function_points(const Utilities::MPI::Partitioner &partitioner,
                    std::vector<Point<dim>>           &points) const override;

    /**
     * The DoFHandler of FE_Bernstein(p) on the grid.
     */
    const DoFHandler<dim> &
    dof_handler() const override;

    /**
     * Bernstein coefficients of the spline field on every locally owned
     * cell (the transpose of the extraction operator applied to the
     * coefficients).
     */
    void
    to_cell_dofs(const VectorType &coefficients,
                 VectorType       &values) const override;

    /**
     * Degree p.
     */
    unsigned int
    degree() const;

    /**
     * The distinct knots (cell boundaries) of direction @p d.
     */
    const std::vector<double> &
    breakpoints(const unsigned int d) const;

    /**
     * The multi-index (i_0, ..., i_{dim-1}) of the function with global
     * index @p global (owned or relevant on this rank).
     */
    std::array<unsigned int, dim>
    multi_index(const types::global_dof_index global) const;

    /**
     * Number of functions of direction @p d.
     */
    unsigned int
    n_functions_in_direction(const unsigned int d) const;

    /**
     * Replace the distinct knots (same number, increasing) and rebuild the
     * extraction operators. The caller moves the grid's vertices alike.
     */
    void
    move_breakpoints(const std::array<std::vector<double>, dim> &breaks);

    /**
     * Index of the first of the p + 1 functions of @p cell in each direction
     * (equal to the cell's span index).
     */
    const std::array<unsigned int, dim> &
    first_function(
      const typename Triangulation<dim>::active_cell_iterator &cell) const;

    /**
     * Values and gradients (real coordinates) of the (p+1)^dim functions of
     * @p cell at the reference point @p xi, in the order of
     * functions_on_cell().
     */
    void
    cell_values(const typename Triangulation<dim>::active_cell_iterator &cell,
                const Point<dim>                                        &xi,
                double                                                  *values,
                Tensor<1, dim> *gradients) const;

    /**
     * Values and x-derivatives of the p + 1 functions of span @p span in
     * direction @p d at its reference coordinate @p t in [0, 1].
     */
    void
    values_1d(const unsigned int d,
              const unsigned int span,
              const double       t,
              double            *values,
              double            *derivatives) const;

  private:
    /**
     * Give each function to the rank that owns its anchor cell and number
     * the functions rank after rank (owned, global_of_lexicographic,
     * lexicographic_of_global). Collective.
     */
    void
    distribute_functions();

    /**
     * The Greville point of function @p global (owned or relevant): the
     * average of its p inner knots in each direction.
     */
    Point<dim>
    greville_point(const types::global_dof_index global) const;

    /**
     * Extraction operators of direction @p d from the current knots, by
     * Cox-de Boor evaluation at p + 1 points of every span.
     */
    void
    compute_extraction(const unsigned int d);

    unsigned int p;

    const Triangulation<dim>                  *triangulation = nullptr;
    std::array<std::vector<double>, dim>       knots;
    std::array<unsigned int, dim>              n_per_direction;
    std::array<std::vector<double>, dim>       extraction;
    std::vector<std::array<unsigned int, dim>> span_of_cell;
    IndexSet                                   owned;
    IndexSet                                   relevant;
    /// The global index of each lexicographic index and the inverse; empty
    /// on one rank, where both are the identity.
    std::vector<types::global_dof_index> global_of_lexicographic;
    std::vector<types::global_dof_index> lexicographic_of_global;
    std::vector<double>                  binomial;
    /// (a_0, ..., a_{dim-1}) of each of the (p+1)^dim local functions.
    std::vector<std::array<unsigned int, dim>> local_multi_index;

    std::unique_ptr<FiniteElement<dim>> fe;
    DoFHandler<dim>                     dofs;
    /// FE_Bernstein's degree of freedom of each tensor-product index.
    std::vector<unsigned int> hierarchic_of_lexicographic;
  };
} // namespace MpmOtm

#endif
