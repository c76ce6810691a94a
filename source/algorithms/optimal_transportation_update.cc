#include <mpm_otm/algorithms/optimal_transportation_update.h>

namespace MpmOtm
{
  template <int dim>
  void
  OptimalTransportationUpdate<dim>::compute_nodal_velocities(
    NodalSystem<dim>      &system,
    const MassMatrix<dim> &mass_matrix,
    const MaterialPoints<dim> &,
    const ParticleShapeData<dim> &shape_data,
    const double                  dt,
    const double                  previous_dt) const
  {
    this->momentum_plus_acceleration(system,
                                     mass_matrix,
                                     shape_data,
                                     0.5 * (dt + previous_dt));
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
