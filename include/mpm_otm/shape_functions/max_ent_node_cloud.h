#ifndef mpm_otm_shape_functions_max_ent_node_cloud_h
#define mpm_otm_shape_functions_max_ent_node_cloud_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialPoints;

  /**
   * The squared distance from @p x to the box @p box (0 inside).
   */
  template <int dim>
  double
  squared_distance_to_box(const Point<dim> &x, const BoundingBox<dim> &box);

  /**
   * The nodes of max-ent functions (one per vertex) that one MPI rank
   * needs, with their current positions and support radii
   * d_i = d_max zeta_i (journal Eq. 88). Max-ent supports reach d_max zeta,
   * several cells, beyond the one ghost layer of deal.II's distributed
   * grids, so each rank owns the nodes of its vertex degrees of freedom and
   * keeps a cloud of other ranks' nodes: the vertices of its ghost cells and
   * every node within the halo H = (halo factor) max_i d_i (over all nodes,
   * at set-up) of its cells.
   *
   * The cloud is found once, in initialize(), with one point-to-point
   * exchange of node positions (Utilities::MPI::some_to_some) wide enough
   * that each rank also receives the nearest neighbours of its own nodes,
   * so that zeta_i, computed by node i's owner, is that of one rank exactly.
   * The cloud is the ghost set of partition(). When the nodes move (OTM,
   * the unified approach), update() sends their positions and radii to the
   * clouds by ghost exchanges and checks, with a bound on how far any node
   * has moved relative to the others, that no node outside a cloud can
   * reach a rank's cells and points; otherwise the run stops on all ranks
   * and names the halo factor. On one rank the cloud is every node.
   */
  template <int dim>
  class MaxEntNodeCloud
  {
  public:
    /**
     * Find the cloud of the nodes of @p vertex_dofs (an FE_Q(1) or
     * FE_SimplexP(1) DoFHandler; @p ghost_cell_vertices its locally
     * relevant dofs) for the support factor @p support_factor (d_max) and
     * the halo factor @p halo_factor, and compute the positions and radii.
     * Collective.
     */
    void
    initialize(const DoFHandler<dim> &vertex_dofs,
               const IndexSet        &ghost_cell_vertices,
               const double           support_factor,
               const double           halo_factor);

    /**
     * Bring the positions and radii up to date with the current vertices.
     * Returns whether any node moved on any rank (always true the first
     * time). Collective under MPI. With @p material_points, their positions
     * enter the check that the cloud still holds every node that can reach
     * them.
     */
    bool
    update(const MaterialPoints<dim> *material_points);

    /**
     * The owned nodes and the cloud, as a partition of the function
     * indices; positions() and radii() are indexed by its local numbers
     * (owned first).
     */
    const Utilities::MPI::Partitioner &
    partition() const;

    /**
     * Current node positions, by local index.
     */
    const std::vector<Point<dim>> &
    positions() const;

    /**
     * Current support radii, by local index.
     */
    const std::vector<double> &
    radii() const;

  private:
    const DoFHandler<dim> *dofs           = nullptr;
    double                 support_factor = 2.;
    double                 halo_factor    = 1.5;

    std::shared_ptr<Utilities::MPI::Partitioner> node_partition;
    /// Whether the cloud holds every node (one rank, or a small grid).
    bool                    complete = true;
    std::vector<Point<dim>> node_positions;
    std::vector<double>     node_radii;

    /// For the check when the nodes move: the halo H, the owned nodes'
    /// positions and the owned cells' bounding boxes at set-up (by active
    /// cell index).
    double                        halo = 0;
    std::vector<Point<dim>>       initial_owned_nodes;
    std::vector<BoundingBox<dim>> initial_cell_boxes;
    /// What the last update of moving nodes found: the largest support
    /// radius on all ranks and the centre and half diagonal of the box of
    /// all nodes' displacements since set-up; and whether it checked the
    /// cloud without the material points (for grid output), so that the
    /// next update with points checks them.
    double         largest_radius = 0;
    Tensor<1, dim> displacement_centre;
    double         displacement_spread = 0;
    bool           points_unchecked    = false;

    /**
     * Under MPI: stop the run on all ranks if on some rank with a partial
     * cloud a locally owned cell (with its points, if @p material_points)
     * moved so far relative to the nodes outside the cloud that one of them
     * could reach it. Collective.
     */
    void
    stop_if_cloud_too_small(const MaterialPoints<dim> *material_points);

    /**
     * The local part of stop_if_cloud_too_small(): a description of the
     * first locally owned cell that fails the check, or an empty string.
     */
    std::string
    cloud_problem(const MaterialPoints<dim> *material_points) const;
  };
} // namespace MpmOtm

#endif
