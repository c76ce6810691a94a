#ifndef mpm_otm_algorithms_update_stress_last_h
#define mpm_otm_algorithms_update_stress_last_h

#include <mpm_otm/algorithms/nodal_update.h>

namespace MpmOtm
{
  /**
   * Update stress last (USL, journal Alg. 1, step 6): v_i^s = M^-1 q^s
   * (Eq. 23) and v_i^{s+1} = v_i^s + dt a_i^s (Eq. 24).
   */
  template <int dim>
  class UpdateStressLast : public NodalUpdate<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    compute_nodal_velocities(NodalSystem<dim>             &system,
                             const MassMatrix<dim>        &mass_matrix,
                             const MaterialPoints<dim>    &material_points,
                             const ParticleShapeData<dim> &shape_data,
                             const double                  dt,
                             const double previous_dt) const override;
  };
} // namespace MpmOtm

#endif
