#ifndef mpm_otm_shape_functions_shape_functions_h
#define mpm_otm_shape_functions_shape_functions_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>

#include <mpm_otm/shape_functions/particle_shape_data.h>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class MaterialPoints;

  /**
   * A family of shape functions on the background grid (linear Lagrange;
   * later B-splines, max-ent, Powell-Sabin). The rest of the code only asks
   * it "for each material point: the indices, values and gradients of the
   * functions that do not vanish there" (journal Alg. 1, step 3) and which
   * functions carry a Dirichlet condition on a boundary. The functions are
   * numbered by a DoFHandler of the family's finite element, which also gives
   * the parallel partition.
   */
  template <int dim>
  class ShapeFunctions
  {
  public:
    virtual ~ShapeFunctions() = default;

    /**
     * Set up the functions on @p grid (distribute the degrees of freedom).
     */
    virtual void
    initialize(const BackgroundGrid<dim> &grid) = 0;

    /**
     * The numbering of the functions.
     */
    virtual const DoFHandler<dim> &
    dof_handler() const = 0;

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
  };
} // namespace MpmOtm

#endif
