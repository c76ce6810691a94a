#ifndef mpm_otm_algorithms_grid_motion_h
#define mpm_otm_algorithms_grid_motion_h

#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/grid_system/nodal_system.h>

namespace MpmOtm
{
  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class Problem;
  template <int dim>
  class ShapeFunctions;

  /**
   * Where the shape functions live, the first of the two differences
   * between MPM and OTM/the unified approach (journal Sect. 5, step 3): on
   * the initial grid, which stays fixed while the material points move
   * through it (MPM, FixedGrid), or on nodes that are advected with the
   * material every step (OTM and unified, AdvectedGrid). Called at the end
   * of each time step, after the material points have moved, to bring the
   * grid and the points' cell bookkeeping to the new configuration.
   */
  template <int dim>
  class GridMotion
  {
  public:
    virtual ~GridMotion() = default;

    /**
     * True if the grid's vertices move (the grid then needs a mapping that
     * is not restricted to axis-parallel boxes).
     */
    virtual bool
    moves_vertices() const = 0;

    /**
     * True if the grid's boundary is the material's (the grid moves with the
     * material), so that tractions act on the grid's boundary faces; false
     * if the boundary material points carry them (thesis Sect. 2.4.1).
     */
    virtual bool
    tractions_on_grid_faces() const = 0;

    /**
     * If tractions_on_grid_faces(): add the tractions of @p problem at
     * @p time on the locally owned boundary faces to system.force, before
     * NodalSystem::finish_assembly().
     */
    virtual void
    add_face_tractions(const Problem<dim> &problem,
                       const double        time,
                       NodalSystem<dim>   &system) const = 0;

    /**
     * Prepare for @p grid with the functions @p shape_functions, numbered
     * as in @p system (called once, after the nodal system is set up).
     * @p stable_cell_size = h_min dt / dt_stable is the smallest distance
     * between two vertices of a cell for which the time step stays stable:
     * the stable time step dt_stable found at the start for the smallest
     * cell size h_min scales with the cell size (as the CFL bound h / c of
     * thesis Eq. 2.48, which it equals for linear functions with lumped
     * mass); a moving grid must not compress a cell below it.
     */
    virtual void
    initialize(BackgroundGrid<dim>       &grid,
               const ShapeFunctions<dim> &shape_functions,
               const NodalSystem<dim>    &system,
               const double               stable_cell_size) = 0;

    /**
     * Move the grid by dt times the nodal velocities of @p system (ghost
     * values up to date) and find the cells of the moved material points.
     */
    virtual void
    advance(const NodalSystem<dim> &system,
            MaterialPoints<dim>    &material_points,
            const double            dt) = 0;

    /**
     * Save where the grid has moved (vertices, knots) into @p state, for a
     * checkpoint. Collective. A fixed grid saves nothing.
     */
    virtual void
    save(CheckpointState &) const
    {}

    /**
     * Move the grid to where save() found it, from @p state (of a run on
     * any number of ranks), before the points are read.
     */
    virtual void
    load(const CheckpointState &)
    {}
  };
} // namespace MpmOtm

#endif
