#ifndef mpm_otm_algorithms_nodal_update_h
#define mpm_otm_algorithms_nodal_update_h

#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/grid_system/mass_matrix.h>

namespace MpmOtm
{
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class ParticleTransfer;

  /**
   * The form of the nodal update: how the nodal velocities v_i^{s+1} that
   * move the material points (and, in OTM and the unified approach, the
   * nodes) are obtained once the nodal accelerations are known, and how the
   * particle velocities follow (the step in which USL, MUSL and OTM differ;
   * see ARCHITECTURE.md). The nodal displacement of the step is dt v_i^{s+1}.
   */
  template <int dim>
  class NodalUpdate
  {
  public:
    /**
     * How a material point's velocity is advanced.
     */
    enum class ParticleVelocity
    {
      /**
       * v_p^{s+1} = v_p^s + dt sum_i phi_i a_i (journal Eq. 27), in the
       * same pass over the points that moves them (the nodal velocities do
       * not depend on it: USL).
       */
      from_acceleration,
      /**
       * The same update, in a pass of its own before the nodal velocities
       * are computed, since they project the result (MUSL).
       */
      from_acceleration_before_projection,
      /**
       * v_p^{s+1} = (x_p^{s+1} - x_p^s) / dt, the velocity that OTM's
       * momentum (Eq. 49) implies, after the point has moved.
       */
      from_displacement
    };

    virtual ~NodalUpdate() = default;

    /**
     * Read the update's own parameters (declared by the plugin's static
     * declare_parameters()).
     */
    virtual void
    parse_parameters(ParameterHandler &)
    {}

    /**
     * Fill system.velocity (locally owned entries) for the step @p dt,
     * subject to @p constraints, one per component, on the velocities at
     * the end of the step (the system's own and the boundary conditions'
     * prescribed values: with a consistent mass matrix the free
     * coefficients feel the prescribed ones); @p previous_dt is the length
     * of the step before (equal to @p dt in the first step, where OTM sets
     * x_p^{-1} = x_p^0 - dt v_p^0). A projection of the points' momenta
     * (MUSL) adds the affine momenta of @p particle_transfer (APIC).
     */
    virtual void
    compute_nodal_velocities(
      NodalSystem<dim>                             &system,
      const MassMatrix<dim>                        &mass_matrix,
      const MaterialPoints<dim>                    &material_points,
      const ParticleTransfer<dim>                  &particle_transfer,
      const ParticleShapeData<dim>                 &shape_data,
      const typename NodalSystem<dim>::Constraints &constraints,
      const double                                  dt,
      const double                                  previous_dt) const = 0;

    /**
     * True if the time step must solve the nodal accelerations
     * a = M^-1 f before the nodal update (journal Alg. 1, step 5); OTM
     * folds the force into its single solve (Alg. 2, Eq. 51) and needs no
     * separate accelerations.
     */
    virtual bool
    needs_nodal_accelerations() const
    {
      return true;
    }

    /**
     * The particle-velocity update that belongs to this nodal update.
     */
    virtual ParticleVelocity
    particle_velocity() const
    {
      return ParticleVelocity::from_acceleration;
    }
  };
} // namespace MpmOtm

#endif
