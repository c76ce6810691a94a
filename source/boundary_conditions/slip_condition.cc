#include <mpm_otm/base/plugins.h>
#include <mpm_otm/boundary_conditions/slip_condition.h>
#include <mpm_otm/grid_system/nodal_system.h>

#include <algorithm>
#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  SlipCondition<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  SlipCondition<dim>::parse_parameters(ParameterHandler &)
  {}



  template <int dim>
  bool
  SlipCondition<dim>::needs_normal() const
  {
    return true;
  }



  template <int dim>
  std::array<bool, dim>
  SlipCondition<dim>::constrained_components() const
  {
    std::array<bool, dim> result{};
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = std::abs(std::abs(this->where.normal[d]) - 1.) < 1e-12;
    return result;
  }



  template <int dim>
  bool
  SlipCondition<dim>::along_axis() const
  {
    const std::array<bool, dim> components = constrained_components();
    return std::any_of(components.begin(), components.end(), [](bool b) {
      return b;
    });
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  SlipCondition<dim>::fixed_components() const
  {
    std::vector<FixedComponents<dim>> result;
    const std::array<bool, dim>       components = constrained_components();
    for (const auto id : this->where.boundary_ids)
      for (unsigned int d = 0; d < dim; ++d)
        if (components[d])
          {
            FixedComponents<dim> fixed{id, {}};
            fixed.fixed.fill(false);
            fixed.fixed[d] = true;
            result.push_back(fixed);
          }
    return result;
  }



  template <int dim>
  void
  SlipCondition<dim>::correct_accelerations(NodalSystem<dim> &system,
                                            const double,
                                            const double dt)
  {
    if (along_axis())
      return;
    const Tensor<1, dim> &normal = this->where.normal;
    for (const unsigned int i : this->where.functions)
      {
        const double m = system.lumped_mass.local_element(i);
        if (!(m > 0.))
          continue;
        Tensor<1, dim> v, a;
        for (unsigned int c = 0; c < dim; ++c)
          {
            v[c] = system.momentum[c].local_element(i) / m;
            a[c] = system.acceleration[c].local_element(i);
          }
        const Tensor<1, dim> moved     = v + dt * a;
        const Tensor<1, dim> corrected = moved - (moved * normal) * normal;
        for (unsigned int c = 0; c < dim; ++c)
          system.acceleration[c].local_element(i) = (corrected[c] - v[c]) / dt;
      }
  }



  template <int dim>
  void
  SlipCondition<dim>::correct_velocities(NodalSystem<dim> &system,
                                         const double) const
  {
    if (along_axis())
      return;
    const Tensor<1, dim> &normal = this->where.normal;
    for (const unsigned int i : this->where.functions)
      {
        if (!(system.lumped_mass.local_element(i) > 0.))
          continue;
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = system.velocity[c].local_element(i);
        const Tensor<1, dim> corrected = v - (v * normal) * normal;
        for (unsigned int c = 0; c < dim; ++c)
          system.velocity[c].local_element(i) = corrected[c];
      }
  }



  template class SlipCondition<1>;
  template class SlipCondition<2>;
  template class SlipCondition<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<1>,
  MpmOtm::SlipCondition<1>,
  "slip",
  "normal velocity zero, tangential free (the boundary must be planar)")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<2>,
  MpmOtm::SlipCondition<2>,
  "slip",
  "normal velocity zero, tangential free (the boundary must be planar)")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<3>,
  MpmOtm::SlipCondition<3>,
  "slip",
  "normal velocity zero, tangential free (the boundary must be planar)")
