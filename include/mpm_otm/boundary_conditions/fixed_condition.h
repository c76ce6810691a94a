#ifndef mpm_otm_boundary_conditions_fixed_condition_h
#define mpm_otm_boundary_conditions_fixed_condition_h

#include <mpm_otm/boundary_conditions/condition.h>

namespace MpmOtm
{
  /**
   * Type = fixed: every velocity component zero on the condition's nodes.
   */
  template <int dim>
  class FixedCondition : public Condition<dim>
  {
  public:
    /**
     * No entries of its own.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    std::array<bool, dim>
    constrained_components() const override;

    std::vector<FixedComponents<dim>>
    fixed_components() const override;
  };
} // namespace MpmOtm

#endif
