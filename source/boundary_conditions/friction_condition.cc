#include <mpm_otm/base/plugins.h>
#include <mpm_otm/boundary_conditions/friction_condition.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/shape_functions/particle_shape_data.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace MpmOtm
{
  template <int dim>
  void
  FrictionCondition<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Double(),
                      "Type = friction: Coulomb coefficient mu >= 0.");
  }



  template <int dim>
  void
  FrictionCondition<dim>::parse_parameters(ParameterHandler &prm)
  {
    friction_coefficient = prm.get_double("Friction coefficient");
    AssertThrow(friction_coefficient >= 0.,
                ExcMessage(this->where.path() + "Friction coefficient = " +
                           prm.get("Friction coefficient") + " must be >= 0."));
  }



  template <int dim>
  bool
  FrictionCondition<dim>::needs_normal() const
  {
    return true;
  }



  template <int dim>
  void
  FrictionCondition<dim>::prepare(const MaterialPoints<dim>    &material_points,
                                  const ParticleShapeData<dim> &data,
                                  const NodalSystem<dim>       &system)
  {
    const auto &partitioner = system.lumped_mass.get_partitioner();
    if (gap.get_partitioner() != partitioner)
      gap.reinit(partitioner);
    double *const values = gap.get_values();
    std::fill(values,
              values + partitioner->locally_owned_size() +
                partitioner->n_ghost_indices(),
              std::numeric_limits<double>::max());
    typename ParticleShapeData<dim>::Cursor functions(data);
    for (const auto &particle : material_points.particle_handler())
      {
        const auto   point = functions.next();
        const double half_size =
          0.5 * std::pow(PropertyLayout<dim>::volume(particle.get_properties()),
                         1. / dim);
        const double point_gap = this->where.wall_offset -
                                 this->where.normal * particle.get_location() -
                                 half_size;
        for (unsigned int j = 0; j < point.n; ++j)
          if (point.values[j] != 0.)
            values[point.indices[j]] =
              std::min(values[point.indices[j]], point_gap);
      }
    gap.compress(VectorOperation::min);
  }



  template <int dim>
  void
  FrictionCondition<dim>::correct_accelerations(NodalSystem<dim> &system,
                                                const double,
                                                const double dt)
  {
    const Tensor<1, dim>            &normal    = this->where.normal;
    const std::vector<unsigned int> &functions = this->where.functions;
    in_contact.assign(functions.size(), false);
    for (unsigned int k = 0; k < functions.size(); ++k)
      {
        const unsigned int i = functions[k];
        const double       m = system.lumped_mass.local_element(i);
        if (!(m > 0.))
          continue;
        Tensor<1, dim> v, a;
        for (unsigned int c = 0; c < dim; ++c)
          {
            v[c] = system.momentum[c].local_element(i) / m;
            a[c] = system.acceleration[c].local_element(i);
          }
        const Tensor<1, dim> moved           = v + dt * a;
        const double         normal_velocity = moved * normal;
        if (!(normal_velocity > 0. &&
              gap.local_element(i) <= dt * normal_velocity))
          continue;
        in_contact[k]                   = true;
        const Tensor<1, dim> tangential = moved - normal_velocity * normal;
        const double         speed      = tangential.norm();
        const double         reduction =
          std::min(friction_coefficient * normal_velocity, speed);
        const Tensor<1, dim> corrected =
          speed > 0. ? tangential * (1. - reduction / speed) : tangential;
        for (unsigned int c = 0; c < dim; ++c)
          system.acceleration[c].local_element(i) = (corrected[c] - v[c]) / dt;
      }
  }



  template <int dim>
  void
  FrictionCondition<dim>::correct_velocities(NodalSystem<dim> &system,
                                             const double) const
  {
    const Tensor<1, dim>            &normal    = this->where.normal;
    const std::vector<unsigned int> &functions = this->where.functions;
    for (unsigned int k = 0; k < functions.size(); ++k)
      {
        const unsigned int i = functions[k];
        if (!(system.lumped_mass.local_element(i) > 0.) ||
            !(k < in_contact.size() && in_contact[k]))
          continue;
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = system.velocity[c].local_element(i);
        const Tensor<1, dim> corrected = v - (v * normal) * normal;
        for (unsigned int c = 0; c < dim; ++c)
          system.velocity[c].local_element(i) = corrected[c];
      }
  }



  template class FrictionCondition<1>;
  template class FrictionCondition<2>;
  template class FrictionCondition<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<1>,
  MpmOtm::FrictionCondition<1>,
  "friction",
  "Coulomb friction with 'Friction coefficient'; the material may separate "
  "from the wall (the boundary must be planar)")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<2>,
  MpmOtm::FrictionCondition<2>,
  "friction",
  "Coulomb friction with 'Friction coefficient'; the material may separate "
  "from the wall (the boundary must be planar)")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<3>,
  MpmOtm::FrictionCondition<3>,
  "friction",
  "Coulomb friction with 'Friction coefficient'; the material may separate "
  "from the wall (the boundary must be planar)")
