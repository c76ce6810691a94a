#include <mpm_otm/algorithms/update_stress_last.h>
#include <mpm_otm/base/plugins.h>

namespace MpmOtm
{
  template <int dim>
  void
  UpdateStressLast<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  UpdateStressLast<dim>::compute_nodal_velocities(
    NodalSystem<dim>      &system,
    const MassMatrix<dim> &mass_matrix,
    const MaterialPoints<dim> &,
    const ParticleShapeData<dim> &shape_data,
    const double                  dt,
    const double) const
  {
    for (unsigned int c = 0; c < dim; ++c)
      {
        mass_matrix.solve(system,
                          shape_data,
                          system.momentum[c],
                          system.velocity[c],
                          system.constraints()[c]);
        system.velocity[c].add(dt, system.acceleration[c]);
      }
  }



  template class UpdateStressLast<1>;
  template class UpdateStressLast<2>;
  template class UpdateStressLast<3>;
} // namespace MpmOtm

#define MPM_OTM_USL_DESCRIPTION "update stress last, journal Alg. 1"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::NodalUpdate<1>,
                        MpmOtm::UpdateStressLast<1>,
                        "USL",
                        MPM_OTM_USL_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::NodalUpdate<2>,
                        MpmOtm::UpdateStressLast<2>,
                        "USL",
                        MPM_OTM_USL_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::NodalUpdate<3>,
                        MpmOtm::UpdateStressLast<3>,
                        "USL",
                        MPM_OTM_USL_DESCRIPTION)
