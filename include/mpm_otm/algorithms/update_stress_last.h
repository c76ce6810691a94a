#ifndef mpm_otm_algorithms_update_stress_last_h
#define mpm_otm_algorithms_update_stress_last_h

#include <mpm_otm/algorithms/nodal_update.h>

namespace MpmOtm
{
  /**
   * Update stress last (USL, journal Alg. 1, step 6): v_i^s = M^-1 q^s
   * (Eq. 23) and v_i^{s+1} = v_i^s + dt a_i^s (Eq. 24). A constraint
   * v_i^{s+1} = g_i on the velocity at the end of the step becomes
   * v_i^s = g_i - dt a_i^s in the solve for v^s.
   */
  template <int dim>
  class UpdateStressLast : public NodalUpdate<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    compute_nodal_velocities(
      NodalSystem<dim>                             &system,
      const MassMatrix<dim>                        &mass_matrix,
      const MaterialPoints<dim>                    &material_points,
      const ParticleTransfer<dim>                  &particle_transfer,
      const ParticleShapeData<dim>                 &shape_data,
      const typename NodalSystem<dim>::Constraints &constraints,
      const double                                  dt,
      const double                                  previous_dt) const override;

  private:
    /// The constraints of the solve for v^s (scratch of each step).
    mutable typename NodalSystem<dim>::Constraints start_constraints;
  };
} // namespace MpmOtm

#endif
