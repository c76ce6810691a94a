#include <mpm_otm/base/plugins.h>
#include <mpm_otm/boundary_conditions/fixed_condition.h>

namespace MpmOtm
{
  template <int dim>
  void
  FixedCondition<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  FixedCondition<dim>::parse_parameters(ParameterHandler &)
  {}



  template <int dim>
  std::array<bool, dim>
  FixedCondition<dim>::constrained_components() const
  {
    std::array<bool, dim> result;
    result.fill(true);
    return result;
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  FixedCondition<dim>::fixed_components() const
  {
    std::vector<FixedComponents<dim>> result;
    for (const auto id : this->where.boundary_ids)
      result.push_back(FixedComponents<dim>::all(id));
    return result;
  }



  template class FixedCondition<1>;
  template class FixedCondition<2>;
  template class FixedCondition<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(MpmOtm::Condition<1>,
                        MpmOtm::FixedCondition<1>,
                        "fixed",
                        "velocity zero")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Condition<2>,
                        MpmOtm::FixedCondition<2>,
                        "fixed",
                        "velocity zero")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Condition<3>,
                        MpmOtm::FixedCondition<3>,
                        "fixed",
                        "velocity zero")
