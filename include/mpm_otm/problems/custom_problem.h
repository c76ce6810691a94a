#ifndef mpm_otm_problems_custom_problem_h
#define mpm_otm_problems_custom_problem_h

#include <deal.II/base/function_parser.h>

#include <mpm_otm/problems/problem.h>

#include <memory>

namespace MpmOtm
{
  /**
   * A problem written in the parameter file: initial velocity, body force,
   * traction and, optionally, the exact displacement as muparser expressions
   * of the initial position (x, y, z) and time t, and the fixed velocity
   * components per boundary id.
   */
  template <int dim>
  class CustomProblem : public Problem<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    void
    initialize(const Material<dim>    &material,
               const BoundingBox<dim> &grid_box) override;

    Tensor<1, dim>
    initial_velocity(const Point<dim> &X) const override;

    bool
    has_body_force() const override;

    Tensor<1, dim>
    body_force(const Point<dim> &X, const double time) const override;

    std::vector<FixedComponents<dim>>
    fixed_components() const override;

    BoundingBox<dim>
    material_region() const override;

    std::vector<types::boundary_id>
    traction_boundaries() const override;

    Tensor<1, dim>
    traction(const types::boundary_id boundary_id,
             const double             time) const override;

    bool
    has_exact_solution() const override;

    bool
    has_exact_stress() const override;

    Tensor<1, dim>
    exact_displacement(const Point<dim> &X, const double time) const override;

  private:
    std::unique_ptr<FunctionParser<dim>> velocity;
    std::unique_ptr<FunctionParser<dim>> force;
    std::unique_ptr<FunctionParser<dim>> traction_function;
    std::unique_ptr<FunctionParser<dim>> displacement;
    std::vector<FixedComponents<dim>>    fixed;
    std::vector<types::boundary_id>      traction_ids;
    std::string                          region_lower;
    std::string                          region_upper;
  };
} // namespace MpmOtm

#endif
