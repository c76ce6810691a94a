#ifndef mpm_otm_shape_functions_max_ent_h
#define mpm_otm_shape_functions_max_ent_h

#include <deal.II/base/bounding_box.h>

#include <mpm_otm/shape_functions/linear_lagrange.h>
#include <mpm_otm/shape_functions/max_ent_node_cloud.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <memory>
#include <string>
#include <vector>

namespace MpmOtm
{
  /**
   * The cubic-spline prior of journal Eq. 89, w(r) = 2/3 - 4 r^2 + 4 r^3 for
   * r <= 1/2, 4/3 (1 - r)^3 for 1/2 < r < 1 and 0 beyond, at the normalised
   * distance @p r = |x - x_i| / d_i (Eq. 87): its @p value and its
   * @p derivative dw/dr.
   */
  void
  cubic_spline_prior(const double r, double &value, double &derivative);

  /**
   * Local maximum-entropy shape functions (Arroyo and Ortiz; journal
   * Sect. 6.3, Eqs. 77-89) on the node cloud of the grid's vertices: fixed
   * nodes for MPM, nodes that move with the material for OTM. At a point x
   * the functions are phi_i = w_i exp(lambda . (x - x_i)) / Z with the
   * cubic-spline prior w_i of Eq. 89 on the support radius
   * d_i = d_max zeta_i (Eq. 88, zeta_i the distance from node i to its
   * nearest other node), and lambda minimises ln Z (Eq. 83), found by
   * Newton's method with a backtracking line search. The gradients follow
   * from differentiating the constraint sum_i phi_i (x - x_i) = 0:
   * grad phi_i = phi_i (grad w_i / w_i - sum_j phi_j grad w_j / w_j
   *                     - (I + A^T) H^-1 (x - x_i)),
   * H = sum_j phi_j (x - x_j) (x - x_j)^T, A = sum_j phi_j (x - x_j)
   * (grad w_j / w_j)^T (journal Eqs. 84-86; Eq. 84 as printed has the
   * opposite sign). They are evaluated in a form that stays exact for the
   * small residual Newton's method leaves (offsets from the phi-weighted mean
   * of the nodes, see solve()), which matters at and next to a node on the
   * boundary of the nodes' convex hull. The nodes whose support contains x are
   * found with an R-tree of the supports' bounding boxes, so the cost per point
   * does not grow with the number of nodes.
   *
   * The functions reach beyond one cell's vertices, so they are not the
   * degrees of freedom of a FiniteElement; they are numbered like the
   * linear functions, one per vertex, and the numbering, the boundary sets
   * and the output element are those of a LinearLagrange object (the field
   * is written by its values at the vertices).
   *
   * Under MPI each rank works on the nodes of a MaxEntNodeCloud: those it
   * owns and the other ranks' nodes within a halo of its cells, which it
   * keeps up to date when the nodes move.
   *
   * Newton's method starts from the multipliers of the point evaluated
   * before (zero for the first point of a pass), so nothing is stored per
   * point and nothing has to move with the points between ranks.
   */
  template <int dim>
  class MaxEnt : public ShapeFunctions<dim>
  {
  public:
    using typename ShapeFunctions<dim>::VectorType;

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Support factor @p support_factor (d_max); the parameter file's
     * "Max-ent support factor" replaces it in parse_parameters().
     */
    explicit MaxEnt(const double support_factor = 2.);

    ~MaxEnt() override;

    void
    parse_parameters(ParameterHandler &prm) override;

    void
    initialize(const BackgroundGrid<dim> &grid) override;

    types::global_dof_index
    n_functions() const override;

    IndexSet
    locally_owned_functions() const override;

    IndexSet
    locally_relevant_functions() const override;

    /**
     * Rebuild the node cloud from the current vertices (they move in OTM),
     * then evaluate at every point.
     */
    void
    evaluate(const MaterialPoints<dim>         &material_points,
             const Utilities::MPI::Partitioner &partitioner,
             ParticleShapeData<dim>            &data) const override;

    IndexSet
    boundary_functions(const types::boundary_id boundary_id) const override;

    bool
    is_linearly_complete() const override;

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

    /**
     * The field's values at the vertices.
     */
    void
    to_cell_dofs(const VectorType &coefficients,
                 VectorType       &values) const override;

    /**
     * Bring the node positions and support radii up to date with the
     * current vertices and rebuild the search structures if they moved.
     * Collective under MPI. With @p material_points, their positions enter
     * the check that the cloud still holds every node that can reach them.
     */
    void
    update_nodes(const MaterialPoints<dim> *material_points = nullptr) const;

    /**
     * The functions that do not vanish at @p x, their values and gradients
     * (global indices; x must lie where this rank's cloud of nodes reaches,
     * e.g. in one of its locally owned cells). Returns an empty string, or a
     * message naming @p x and what to change if fewer than dim + 1 nodes reach
     * x or Newton's method does not converge (x outside the convex hull of the
     * nodes).
     */
    std::string
    evaluate_at(const Point<dim>                     &x,
                std::vector<types::global_dof_index> &indices,
                std::vector<double>                  &values,
                std::vector<Tensor<1, dim>>          &gradients) const;

    /**
     * The nodes of the relevant functions.
     */
    bool
    function_points(const Utilities::MPI::Partitioner &partitioner,
                    std::vector<Point<dim>>           &points) const override;

    /**
     * The current position of the node of function @p i.
     */
    const Point<dim> &
    node(const types::global_dof_index i) const;

    /**
     * The support radius d_i = d_max zeta_i of function @p i (Eq. 88).
     */
    double
    support_radius(const types::global_dof_index i) const;

  private:
    double support_factor;
    /// Halo of the cloud of other ranks' nodes, as a multiple of the
    /// largest support radius at set-up.
    double halo_factor;

    /// The numbering of the nodes (one function per vertex, as for linear
    /// functions), their boundary sets and the output element.
    LinearLagrange<dim> vertex_numbering;

    /// The nodes this rank owns and those of its cloud, with their
    /// positions and radii; node arrays below are indexed by the local
    /// numbers of its partition (owned first).
    mutable MaxEntNodeCloud<dim> cloud;
    mutable std::vector<double>  inverse_radii;
    /// Bounding boxes of the supports and their R-tree.
    mutable std::vector<BoundingBox<dim>> supports;
    struct SearchTree;
    mutable std::unique_ptr<SearchTree> search_tree;
    /// Each locally owned cell's bounding box and the nodes whose support
    /// meets it (cell c's nodes are cell_nodes[cell_node_offsets[c]]
    /// onwards; local indices), by active cell index.
    mutable std::vector<BoundingBox<dim>> cell_boxes;
    mutable std::vector<unsigned int>     cell_node_offsets;
    mutable std::vector<unsigned int>     cell_nodes;
    /// Multipliers of the last point solved: the next one's first guess.
    mutable Tensor<1, dim> previous_lambda;
    /// Work arrays of one point, kept to avoid allocation per point.
    mutable std::vector<unsigned int> candidates;
    /// The first n_reached entries of reached are the candidates whose
    /// support contains the last point solve() was called for.
    mutable std::vector<unsigned int>            reached;
    mutable unsigned int                         n_reached = 0;
    mutable std::vector<Tensor<1, dim>>          offsets;
    mutable std::vector<double>                  weights;
    mutable std::vector<Tensor<1, dim>>          log_weight_gradients;
    mutable std::vector<double>                  phi_current;
    mutable std::vector<double>                  phi_trial;
    mutable std::vector<types::global_dof_index> point_indices;
    mutable std::vector<double>                  point_values;
    mutable std::vector<Tensor<1, dim>>          point_gradients;

    /**
     * The values and gradients at @p x of the functions of the
     * @p n_candidates nodes @p candidate_nodes (zero for those whose support
     * does not contain x), by Newton's method from the multipliers
     * @p lambda, which return the solution. Returns an empty string or what
     * went wrong (see evaluate_at()).
     */
    std::string
    solve(const Point<dim>         &x,
          const unsigned int *const candidate_nodes,
          const unsigned int        n_candidates,
          Tensor<1, dim>           &lambda,
          double *const             values,
          Tensor<1, dim> *const     gradients) const;
  };
} // namespace MpmOtm

#endif
