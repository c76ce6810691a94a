#include <mpm_otm/algorithms/optimal_transportation_update.h>

namespace MpmOtm
{
  template <int dim>
  void
  OptimalTransportationUpdate<dim>::compute_nodal_velocities(
    NodalSystem<dim>      &system,
    const MassMatrix<dim> &mass_matrix,
    const MaterialPoints<dim> &,
    const ParticleTransfer<dim> &,
    const ParticleShapeData<dim>                 &shape_data,
    const typename NodalSystem<dim>::Constraints &constraints,
    const double                                  dt,
    const double                                  previous_dt) const
  {
    const double centred_step = 0.5 * (dt + previous_dt);
    for (unsigned int c = 0; c < dim; ++c)
      {
        typename NodalSystem<dim>::VectorType right_hand_side(
          system.momentum[c]);
        right_hand_side.add(centred_step, system.force[c]);
        mass_matrix.solve(system,
                          shape_data,
                          right_hand_side,
                          system.velocity[c],
                          constraints[c]);
      }
  }



  template <int dim>
  bool
  OptimalTransportationUpdate<dim>::needs_nodal_accelerations() const
  {
    return false;
  }



  template <int dim>
  typename NodalUpdate<dim>::ParticleVelocity
  OptimalTransportationUpdate<dim>::particle_velocity() const
  {
    return NodalUpdate<dim>::ParticleVelocity::from_displacement;
  }



  template class OptimalTransportationUpdate<1>;
  template class OptimalTransportationUpdate<2>;
  template class OptimalTransportationUpdate<3>;
} // namespace MpmOtm
