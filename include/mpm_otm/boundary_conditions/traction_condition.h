#ifndef mpm_otm_boundary_conditions_traction_condition_h
#define mpm_otm_boundary_conditions_traction_condition_h

#include <deal.II/lac/la_parallel_vector.h>

#include <mpm_otm/base/parsed_expression.h>
#include <mpm_otm/boundary_conditions/condition.h>

#include <memory>

namespace MpmOtm
{
  /**
   * Type = traction: the traction 'Traction' (a Cauchy traction, force per
   * current area of the side; dim functions of time) on a side of the grid,
   * a surcharge or a pressure. Each node of the side gets the force of its
   * share of the side, the integral of its function over the side's faces
   * (ShapeFunctions::boundary_integrals(); on a moving grid recomputed in
   * every step from the faces as they are). On a moving grid (the unified
   * approach) the side is the material's boundary; on MPM's fixed grid the
   * side's nodes carry the load only where material is next to them. Its
   * work at the nodal velocities of the previous step counts as supplied
   * work, and the load is the condition's reaction.
   */
  template <int dim>
  class TractionCondition : public Condition<dim>
  {
  public:
    /**
     * Declare "Traction".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * False: its reaction is its load.
     */
    bool
    holds_nodes() const override;

    void
    initialize(const ShapeFunctions<dim> &shape_functions) override;

    Tensor<1, dim>
    add_loads(NodalSystem<dim> &system,
              const double      time,
              const double      dt) override;

  private:
    /**
     * Set #shares to the integrals of the functions over the side.
     * Collective.
     */
    void
    find_shares();

    std::unique_ptr<ParsedExpression<dim>> traction;
    /// The family, for the nodes' shares of the side.
    const ShapeFunctions<dim> *functions = nullptr;
    /// The integral of each function over the side.
    LinearAlgebra::distributed::Vector<double> shares;
  };
} // namespace MpmOtm

#endif
