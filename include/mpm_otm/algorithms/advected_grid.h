#ifndef mpm_otm_algorithms_advected_grid_h
#define mpm_otm_algorithms_advected_grid_h

#include <deal.II/grid/tria.h>

#include <mpm_otm/algorithms/grid_motion.h>

#include <array>
#include <vector>

namespace MpmOtm
{
  /**
   * The grid of OTM and the unified approach: the triangulation's vertices
   * (the nodes x_i) are advected with the nodal displacements every step,
   * x_i^{s+1} = x_i^s + dt v_i^{s+1} (journal Alg. 2, step 5; Alg. 3,
   * step 6), so that the next step's shape functions phi_i^{s+1} are those of
   * the moved grid. Only the vertex positions change: the DoF numbering,
   * partition and index sets stay.
   *
   * A vertex moves with the field's value there, a combination of
   * coefficients the family gives (ShapeFunctions::vertex_interpolation()).
   * With one function per vertex and no other (linear Lagrange) a material
   * point moved by sum_i phi_i dt v_i keeps its reference coordinates in its
   * cell (the isoparametric map of the moved cell at the same reference
   * point), so points never change cell or rank and no search is needed.
   * Families with several functions per vertex (Powell-Sabin,
   * MovingGrid::rebuilt) are rebuilt on the moved grid every step, after
   * which the points, which moved with the family's field and not with the
   * cells' affine map, are located anew; a family that cannot be rebuilt on
   * the moved vertices (no control triangle) stops the run with the grid
   * left as it was.
   *
   * Before the vertices move, every locally owned cell is checked: a cell
   * whose Jacobian would change sign at one of its vertices, or that would
   * be compressed below the size for which the time step is stable (CFL,
   * thesis Eq. 2.48), stops the run with the cell and its position, and the
   * grid is left as it was.
   *
   * The grid covers the material only, so its boundary is the material
   * boundary: a traction acts on the boundary faces of the moved grid,
   * t |face| / n_face_vertices at each vertex of the face (exact for linear
   * functions on simplex faces and parallelogram faces), with the current
   * face measure (a Cauchy traction), shared among the vertex's functions
   * with the weights of its interpolation. In 1D the end vertex carries
   * the traction, the journal's delta(x - l) of Sect. 8.2.
   */
  template <int dim>
  class AdvectedGrid : public GridMotion<dim>
  {
  public:
    /**
     * A grid whose vertices carry the functions; with @p rebuilt_functions
     * (MovingGrid::rebuilt) that family is rebuilt after every move.
     */
    explicit AdvectedGrid(ShapeFunctions<dim> *rebuilt_functions = nullptr);

    bool
    moves_vertices() const override;

    bool
    tractions_on_grid_faces() const override;

    void
    add_face_tractions(const Problem<dim> &problem,
                       const double        time,
                       NodalSystem<dim>   &system) const override;

    void
    initialize(BackgroundGrid<dim>       &grid,
               const ShapeFunctions<dim> &shape_functions,
               const NodalSystem<dim>    &system,
               const double               stable_cell_size) override;

    void
    advance(const NodalSystem<dim> &system,
            MaterialPoints<dim>    &material_points,
            const double            dt) override;

    void
    save(CheckpointState &state) const override;

    void
    load(const CheckpointState &state) override;

  private:
    /**
     * Smallest Jacobian determinant over the vertices of a cell with the
     * given corner positions (deal.II's vertex order), times @p orientation.
     */
    static double
    smallest_vertex_jacobian(const Point<dim> *const corners[],
                             const unsigned int      n_corners,
                             const double            orientation);

    /**
     * The current measure of @p face (1 in 1D).
     */
    double
    measure(const unsigned int n_vertices,
            const std::array<unsigned int, GeometryInfo<dim>::vertices_per_face>
              &vertices) const;

    Triangulation<dim>        *triangulation = nullptr;
    const BackgroundGrid<dim> *background    = nullptr;

    /**
     * c dt: the smallest stable distance between two vertices of a cell.
     */
    double stable_size = 0.;

    /**
     * The number in the coarse mesh, the same on every rank, of the vertex
     * of vertex_positions[k].
     */
    unsigned int
    vertex_index(const unsigned int k) const;

    /**
     * Read the weights of every vertex's interpolation from the family
     * (they change when it is rebuilt).
     */
    void
    read_vertex_weights();

    /**
     * For a rebuilt family on several ranks: give the vertices that belong to
     * ghost cells only the moved positions their cells' owners computed in
     * moved_positions. A rank's weights of such a vertex come from an
     * incomplete control triangle (one ghost layer holds only some of the
     * vertex's cells), the owners' from a complete one. Collective.
     */
    void
    take_ghost_vertices_from_owners();

    /**
     * Rebuild the family on the current vertices; on a problem on any rank,
     * put the vertices back to @p previous, rebuild there and stop the run.
     * Collective.
     */
    void
    rebuild_functions(const std::vector<Point<dim>> &previous);

    ShapeFunctions<dim> *rebuilt_functions;

    /**
     * Each vertex k of a locally owned or ghost cell once: where its
     * position is stored, a cell and its number there, and the local indices
     * and weights of the coefficients whose combination is the field's
     * value there (vertex_offsets[k] to vertex_offsets[k + 1]).
     */
    std::vector<Point<dim> *> vertex_positions;
    std::vector<std::pair<typename Triangulation<dim>::active_cell_iterator,
                          unsigned int>>
                              vertex_cells;
    std::vector<unsigned int> vertex_offsets;
    /// The position k of each vertex (by its index in the triangulation),
    /// and whether vertex k belongs to a locally owned cell.
    std::vector<unsigned int> position_of_vertex;
    std::vector<bool>         of_owned_cell;
    std::vector<unsigned int> vertex_functions;
    std::vector<double>       vertex_weights;

    /**
     * For each locally owned cell: its indices into vertex_positions
     * (vertices_per_cell of them), its iterator for messages and the sign of
     * its initial Jacobian.
     */
    unsigned int              vertices_per_cell = 0;
    std::vector<unsigned int> owned_cell_vertices;
    std::vector<typename Triangulation<dim>::active_cell_iterator> owned_cells;
    std::vector<double>                                            orientations;

    /**
     * A boundary face of a locally owned cell: its boundary id and its
     * vertices (indices into vertex_positions).
     */
    struct BoundaryFace
    {
      types::boundary_id boundary_id;
      unsigned int       n_vertices;
      std::array<unsigned int, GeometryInfo<dim>::vertices_per_face> vertices;
    };
    std::vector<BoundaryFace> boundary_faces;

    /**
     * Work array: the vertex positions after the step.
     */
    std::vector<Point<dim>> moved_positions;
  };
} // namespace MpmOtm

#endif
