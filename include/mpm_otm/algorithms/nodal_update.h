#ifndef mpm_otm_algorithms_nodal_update_h
#define mpm_otm_algorithms_nodal_update_h

#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/grid_system/mass_matrix.h>

namespace MpmOtm
{
  template <int dim>
  class MaterialPoints;

  /**
   * The form of the nodal update: how the nodal velocities v_i^{s+1} that
   * move the material points are obtained once the nodal accelerations are
   * known and the particle velocities have been advanced (the only step in
   * which USL, MUSL and, later, OTM differ; see ARCHITECTURE.md).
   */
  template <int dim>
  class NodalUpdate
  {
  public:
    virtual ~NodalUpdate() = default;

    /**
     * Fill system.velocity (locally owned entries) for the step @p dt.
     */
    virtual void
    compute_nodal_velocities(NodalSystem<dim>             &system,
                             const MassMatrix<dim>        &mass_matrix,
                             const MaterialPoints<dim>    &material_points,
                             const ParticleShapeData<dim> &shape_data,
                             const double                  dt) const = 0;
  };
} // namespace MpmOtm

#endif
