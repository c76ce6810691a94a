#ifndef mpm_otm_boundary_conditions_velocity_condition_h
#define mpm_otm_boundary_conditions_velocity_condition_h

#include <mpm_otm/base/parsed_expression.h>
#include <mpm_otm/boundary_conditions/condition.h>

#include <memory>

namespace MpmOtm
{
  /**
   * Type = velocity: the components 'Velocity components' prescribed to
   * 'Velocity' (functions of time; the condition's nodes move as one), the
   * others free. A box of prescribed velocity moves with the displacement it
   * prescribes (a settling footing, a moving platen): every step it acts on
   * the nodes inside the moved box. The work it does is counted in the
   * energy balance.
   */
  template <int dim>
  class VelocityCondition : public Condition<dim>
  {
  public:
    /**
     * Declare "Velocity" and "Velocity components".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * Refuse a condition on grid sides whose prescribed motion takes it
     * more than half a cell into the grid before @p end_time: MPM's grid
     * stays where it is, so the material leaves the side's nodes, which then
     * hold less and less of it, and the condition's reaction stops being the
     * load on the material (a platen on the grid's top side lost the
     * specimen of the biaxial test after 0.04 m of travel on 0.05 m cells).
     * A condition on a box follows its displacement; on a moving grid the
     * side moves with its nodes.
     */
    void
    check_run(const double end_time) const override;

    std::array<bool, dim>
    constrained_components() const override;

    Tensor<1, dim>
    target_velocity(const double time) const override;

    bool
    moves() const override;

    /**
     * Move the nodes by the prescribed velocity at the end of the step and
     * return the positive part of the work the reaction did.
     */
    double
    advance(const Tensor<1, dim> &reaction,
            const double          time,
            const double          dt) override;

  private:
    std::array<bool, dim>                  components{};
    std::unique_ptr<ParsedExpression<dim>> velocity;
  };
} // namespace MpmOtm

#endif
