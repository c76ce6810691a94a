#include <mpm_otm/algorithms/modified_update_stress_last.h>
#include <mpm_otm/algorithms/particle_transfer.h>
#include <mpm_otm/base/plugins.h>

namespace MpmOtm
{
  template <int dim>
  void
  ModifiedUpdateStressLast<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  ModifiedUpdateStressLast<dim>::compute_nodal_velocities(
    NodalSystem<dim>                             &system,
    const MassMatrix<dim>                        &mass_matrix,
    const MaterialPoints<dim>                    &material_points,
    const ParticleTransfer<dim>                  &particle_transfer,
    const ParticleShapeData<dim>                 &shape_data,
    const typename NodalSystem<dim>::Constraints &constraints,
    const double,
    const double) const
  {
    system.assemble_momentum(material_points, shape_data);
    if (particle_transfer.is_affine())
      {
        particle_transfer.add_affine_momentum(material_points,
                                              shape_data,
                                              system);
        for (unsigned int c = 0; c < dim; ++c)
          system.momentum[c].compress(VectorOperation::add);
      }
    for (unsigned int c = 0; c < dim; ++c)
      mass_matrix.solve(system,
                        shape_data,
                        system.momentum[c],
                        system.velocity[c],
                        constraints[c]);
  }



  template <int dim>
  typename NodalUpdate<dim>::ParticleVelocity
  ModifiedUpdateStressLast<dim>::particle_velocity() const
  {
    return NodalUpdate<
      dim>::ParticleVelocity::from_acceleration_before_projection;
  }



  template class ModifiedUpdateStressLast<1>;
  template class ModifiedUpdateStressLast<2>;
  template class ModifiedUpdateStressLast<3>;
} // namespace MpmOtm

#define MPM_OTM_MUSL_DESCRIPTION \
  "modified update stress last, thesis Sect. 2.4.3"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::NodalUpdate<1>,
                        MpmOtm::ModifiedUpdateStressLast<1>,
                        "MUSL",
                        MPM_OTM_MUSL_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::NodalUpdate<2>,
                        MpmOtm::ModifiedUpdateStressLast<2>,
                        "MUSL",
                        MPM_OTM_MUSL_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::NodalUpdate<3>,
                        MpmOtm::ModifiedUpdateStressLast<3>,
                        "MUSL",
                        MPM_OTM_MUSL_DESCRIPTION)
