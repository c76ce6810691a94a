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
    const ParticleTransfer<dim> &,
    const ParticleShapeData<dim>                 &shape_data,
    const typename NodalSystem<dim>::Constraints &constraints,
    const double                                  dt,
    const double) const
  {
    const Utilities::MPI::Partitioner &partitioner = system.partitioner();
    for (unsigned int c = 0; c < dim; ++c)
      {
        start_constraints[c].copy_from(constraints[c]);
        for (const auto &line : constraints[c].get_lines())
          start_constraints[c].set_inhomogeneity(
            line.index,
            line.inhomogeneity -
              dt * system.acceleration[c].local_element(
                     partitioner.global_to_local(line.index)));
        mass_matrix.solve(system,
                          shape_data,
                          system.momentum[c],
                          system.velocity[c],
                          start_constraints[c]);
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
