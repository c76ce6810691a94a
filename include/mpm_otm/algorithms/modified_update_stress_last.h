#ifndef mpm_otm_algorithms_modified_update_stress_last_h
#define mpm_otm_algorithms_modified_update_stress_last_h

#include <mpm_otm/algorithms/nodal_update.h>

namespace MpmOtm
{
  /**
   * Modified update stress last (MUSL, thesis Sect. 2.4.3 and Fig. 2.5,
   * steps 3-4): the advanced particle velocities are projected back onto the
   * grid, M v^{s+1} = sum_p m_p phi_i v_p^{s+1} (thesis Eqs. 2.37-2.38).
   */
  template <int dim>
  class ModifiedUpdateStressLast : public NodalUpdate<dim>
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

    typename NodalUpdate<dim>::ParticleVelocity
    particle_velocity() const override;
  };
} // namespace MpmOtm

#endif
