#ifndef mpm_otm_algorithms_optimal_transportation_update_h
#define mpm_otm_algorithms_optimal_transportation_update_h

#include <mpm_otm/algorithms/update_stress_last.h>

namespace MpmOtm
{
  /**
   * The nodal update of the optimal transportation meshfree method (journal
   * Alg. 2, step 5, Eq. 51):
   *
   *   x_i^{s+1} = x_i^s + dt M^-1 (q^s + (dt + dt_prev) / 2 f^s),
   *
   * with the momentum q^s of Eq. 49 built from the particle velocities
   * (x_p^s - x_p^{s-1}) / dt_prev. It is written as the nodal velocity
   * v_i^{s+1} = M^-1 q^s + (dt + dt_prev) / 2 a^s, so that the nodal
   * displacement is dt v_i^{s+1} as for the other updates; for a constant
   * time step this is the USL update (Eqs. 58-59). The particle velocity is
   * not advanced by the acceleration but follows from the displacement of
   * the point (Eq. 57). It is therefore a USL update with the centred step
   * and the other particle-velocity rule.
   */
  template <int dim>
  class OptimalTransportationUpdate : public UpdateStressLast<dim>
  {
  public:
    void
    compute_nodal_velocities(NodalSystem<dim>             &system,
                             const MassMatrix<dim>        &mass_matrix,
                             const MaterialPoints<dim>    &material_points,
                             const ParticleShapeData<dim> &shape_data,
                             const double                  dt,
                             const double previous_dt) const override;

    typename NodalUpdate<dim>::ParticleVelocity
    particle_velocity() const override;
  };
} // namespace MpmOtm

#endif
