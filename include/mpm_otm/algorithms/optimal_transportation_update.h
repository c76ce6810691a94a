#ifndef mpm_otm_algorithms_optimal_transportation_update_h
#define mpm_otm_algorithms_optimal_transportation_update_h

#include <mpm_otm/algorithms/nodal_update.h>

namespace MpmOtm
{
  /**
   * The nodal update of the optimal transportation meshfree method (journal
   * Alg. 2, step 5, Eq. 51):
   *
   *   x_i^{s+1} = x_i^s + dt M^-1 (q^s + (dt + dt_prev) / 2 f^s),
   *
   * with the momentum q^s of Eq. 49 built from the particle velocities
   * (x_p^s - x_p^{s-1}) / dt_prev. It is computed as the nodal velocity
   * v_i^{s+1} = M^-1 (q^s + (dt + dt_prev) / 2 f^s), one solve, so that the
   * nodal displacement is dt v_i^{s+1} as for the other updates; for a
   * constant time step this is the USL update (Eqs. 58-59). No nodal
   * accelerations are needed: the particle velocity is not advanced by them
   * but follows from the displacement of the point (Eq. 57).
   */
  template <int dim>
  class OptimalTransportationUpdate : public NodalUpdate<dim>
  {
  public:
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

    bool
    needs_nodal_accelerations() const override;

    typename NodalUpdate<dim>::ParticleVelocity
    particle_velocity() const override;
  };
} // namespace MpmOtm

#endif
