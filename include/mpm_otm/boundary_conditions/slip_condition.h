#ifndef mpm_otm_boundary_conditions_slip_condition_h
#define mpm_otm_boundary_conditions_slip_condition_h

#include <mpm_otm/boundary_conditions/condition.h>

namespace MpmOtm
{
  /**
   * Type = slip: the velocity along the outward normal n of a planar
   * boundary zero, the tangential velocity free. On a side normal to a
   * coordinate direction this is an affine constraint on one component; on
   * an inclined side the solved accelerations and velocities lose their
   * normal part, v* - (v* . n) n.
   */
  template <int dim>
  class SlipCondition : public Condition<dim>
  {
  public:
    /**
     * No entries of its own.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    bool
    needs_normal() const override;

    std::array<bool, dim>
    constrained_components() const override;

    std::vector<FixedComponents<dim>>
    fixed_components() const override;

    void
    correct_accelerations(NodalSystem<dim> &system,
                          const double      time,
                          const double      dt) override;

    void
    correct_velocities(NodalSystem<dim> &system,
                       const double      time) const override;

  private:
    /**
     * Whether the normal is a coordinate direction (then only the
     * constraints act).
     */
    bool
    along_axis() const;
  };
} // namespace MpmOtm

#endif
