#ifndef mpm_otm_shape_functions_shape_functions_h
#define mpm_otm_shape_functions_shape_functions_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/shape_functions/particle_shape_data.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class MaterialPoints;

  /**
   * A family of shape functions on the background grid (linear Lagrange,
   * B-splines, max-ent, Powell-Sabin). The rest of the code only asks
   * it "for each material point: the indices, values and gradients of the
   * functions that do not vanish there" (journal Alg. 1, step 3), how the
   * functions are numbered and distributed over the MPI ranks, and which
   * functions carry a Dirichlet condition on a boundary.
   *
   * Every cell of the grid carries a deal.II finite element (FE_Q(1),
   * FE_SimplexP(1), FE_Bernstein(p), FE_PowellSabin): for the linear and
   * Powell-Sabin families its degrees of freedom are the functions; for
   * B-splines the functions restricted to a cell are a fixed combination of
   * that element's Bernstein polynomials; max-ent writes its values at the
   * vertices in FE_Q(1) / FE_SimplexP(1). Grid output writes fields in the
   * cells' element.
   */
  template <int dim>
  class ShapeFunctions
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    virtual ~ShapeFunctions() = default;

    /**
     * Read the family's own parameters (declared by the plugin's static
     * declare_parameters()).
     */
    virtual void
    parse_parameters(ParameterHandler &)
    {}

    /**
     * Set up the functions on @p grid.
     */
    virtual void
    initialize(const BackgroundGrid<dim> &grid) = 0;

    /**
     * Number of functions on all ranks.
     */
    virtual types::global_dof_index
    n_functions() const = 0;

    /**
     * The functions whose coefficients this rank owns; a contiguous range.
     */
    virtual IndexSet
    locally_owned_functions() const = 0;

    /**
     * The locally owned functions and those that do not vanish on some
     * locally owned cell.
     */
    virtual IndexSet
    locally_relevant_functions() const = 0;

    /**
     * Evaluate the functions at every locally owned material point; indices
     * are local indices of @p partitioner.
     */
    virtual void
    evaluate(const MaterialPoints<dim>         &material_points,
             const Utilities::MPI::Partitioner &partitioner,
             ParticleShapeData<dim>            &data) const = 0;

    /**
     * The functions whose coefficient is fixed by a Dirichlet condition on
     * boundary @p boundary_id.
     */
    virtual IndexSet
    boundary_functions(const types::boundary_id boundary_id) const = 0;

    /**
     * True if the functions reproduce linear fields, sum_i phi_i(x) x_i = x
     * (journal Eq. 47); OTM's incremental map (Eq. 52) needs it.
     */
    virtual bool
    is_linearly_complete() const = 0;

    /**
     * True if the gradients of the functions are constant on each cell
     * (linear functions on triangles/tetrahedra), so that all points of a
     * cell have the same velocity gradient. False by default.
     */
    virtual bool
    gradients_constant_on_cells() const
    {
      return false;
    }

    /**
     * How the functions follow the material when the grid moves with it
     * (OTM and the unified approach, journal Algs. 2 and 3).
     */
    enum class MovingGrid
    {
      /**
       * One function per vertex, which moves with it (vertex_function()).
       */
      vertices,
      /**
       * Tensor-product functions whose knots move per direction with the
       * direction-averaged velocities (B-splines).
       */
      knots,
      /**
       * Functions of a triangulation whose vertices move with the field's
       * values there (vertex_interpolation()), rebuilt on the moved grid
       * (rebuild_on_moved_grid()); the material points are then located
       * anew (Powell-Sabin splines).
       */
      rebuilt,
      /**
       * The functions cannot follow a moving grid;
       * moving_grid_limitation() says why.
       */
      not_supported
    };

    /**
     * How the functions follow a moving grid; MovingGrid::vertices unless a
     * family says otherwise.
     */
    virtual MovingGrid
    moving_grid() const
    {
      return MovingGrid::vertices;
    }

    /**
     * The field's value at vertex @p v of @p cell as a combination of
     * coefficients: the functions @p functions (global indices) with the
     * weights @p weights. For families whose grid moves with its vertices
     * (MovingGrid::vertices and rebuilt); by default vertex_function() with
     * weight 1.
     */
    virtual void
    vertex_interpolation(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const unsigned int                                       v,
      std::vector<types::global_dof_index>                    &functions,
      std::vector<double>                                     &weights) const
    {
      functions.assign(1, vertex_function(cell, v));
      weights.assign(1, 1.);
    }

    /**
     * For MovingGrid::rebuilt: build the functions anew on the grid's moved
     * vertices (numbering, distribution and supports stay). Not
     * collective. Returns an empty string, or what made the functions
     * impossible to build (a vertex and why), for a message.
     */
    virtual std::string
    rebuild_on_moved_grid()
    {
      return {};
    }

    /**
     * For MovingGrid::not_supported: why, and what to use instead, for the
     * message of a run that asks for a moving grid.
     */
    virtual std::string
    moving_grid_limitation() const
    {
      return {};
    }

    /**
     * Whether the family draws a picture of its functions
     * (write_basis_picture()); false unless a family says otherwise.
     */
    virtual bool
    has_basis_picture() const
    {
      return false;
    }

    /**
     * For families with has_basis_picture(): write a picture of the
     * functions near @p point as the VTU file @p file_name. Not collective.
     */
    virtual void
    write_basis_picture(const Point<dim> &, const std::string &) const
    {
      Assert(false, ExcNotImplemented());
    }

    /**
     * Number of functions that belong to one node and share its support:
     * functions n k, ..., n k + n - 1 (global indices) are node k's and have
     * one owner. They are strongly coupled in the mass matrix, and the
     * consistent-mass solves precondition with the inverse of their diagonal
     * blocks. 1 unless a family says otherwise.
     */
    virtual unsigned int
    functions_per_node() const
    {
      return 1;
    }

    /**
     * Global indices of the functions that do not vanish everywhere on
     * @p cell (a locally owned or ghost cell); with or without material.
     * Partial lumping (thesis Sect. 5.4) finds the functions at the edge of
     * the material with it.
     */
    virtual void
    functions_on_cell(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      std::vector<types::global_dof_index> &functions) const = 0;

    /**
     * The function that belongs to vertex @p v of @p cell, for families with
     * one function per vertex that moves with it (OTM and the unified
     * approach on a moving grid); numbers::invalid_dof_index otherwise.
     */
    virtual types::global_dof_index
    vertex_function(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const unsigned int                                       v) const = 0;

    /**
     * The locally owned functions (global indices, sorted) that belong to a
     * point inside @p box, for a condition on a box of nodes (a footing, a
     * platen) that prescribes their coefficients. By default the functions
     * of the locally owned cells' vertices in the box (vertex_function()).
     * Returns false (on every rank) if the family's functions do not belong
     * to points.
     */
    virtual bool
    functions_in_box(const BoundingBox<dim>               &box,
                     std::vector<types::global_dof_index> &functions) const;

    /**
     * The point x_i each locally relevant function belongs to, in the order
     * of @p partitioner's local indices, such that sum_i phi_i(x) x_i = x
     * for a linearly complete family: the vertices of vertex_function() by
     * default (linear functions, max-ent nodes), the Greville points of
     * B-splines. APIC transfers the points' affine velocity with them.
     * Returns false if the family's functions do not belong to points or
     * the points of some relevant function are not known on this rank. Not
     * collective.
     */
    virtual bool
    function_points(const Utilities::MPI::Partitioner &partitioner,
                    std::vector<Point<dim>>           &points) const;

    /**
     * Add to @p integrals (a vector with the system's partitioner) the
     * integral of each function over the grid's faces with boundary id
     * @p boundary_id, on the grid as it is now: a node's share of a side,
     * for loads on the side. By default each face gives its vertices'
     * functions (vertex_function()) the same share, its measure over its
     * number of vertices: exact for linear functions on segments, triangles
     * and parallelograms, close on other quadrilaterals (a moving grid's)
     * and for max-ent's functions on the side. Returns false,
     * on every rank, if the family's functions do not belong to vertices
     * and it does not override this. Collective.
     */
    virtual bool
    boundary_integrals(const types::boundary_id boundary_id,
                       VectorType              &integrals) const;

    /**
     * The DoFHandler of the finite element the cells carry.
     */
    virtual const DoFHandler<dim> &
    dof_handler() const = 0;

    /**
     * The field sum_i c_i phi_i with coefficients @p coefficients (ghost
     * values up to date) written in the cells' finite element: @p values is
     * set up here on the locally relevant degrees of freedom of
     * dof_handler(), with up-to-date ghost values.
     */
    virtual void
    to_cell_dofs(const VectorType &coefficients, VectorType &values) const = 0;

    /**
     * Save what the functions carry from one time step to the next (e.g.
     * the starting values of an iteration per point) into @p state, for a
     * checkpoint. Most families carry nothing.
     */
    virtual void
    save(CheckpointState &) const
    {}

    /**
     * Restore what save() saved from @p state.
     */
    virtual void
    load(const CheckpointState &)
    {}
  };
} // namespace MpmOtm

#endif
