#ifndef mpm_otm_problems_custom_problem_h
#define mpm_otm_problems_custom_problem_h

#include <mpm_otm/base/parsed_expression.h>
#include <mpm_otm/problems/body.h>
#include <mpm_otm/problems/problem.h>

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace MpmOtm
{
  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class MeshGroups;
  /**
   * A problem written in the parameter file. The material is either the
   * bodies listed in the entry "Bodies" (each of any shape, with its own
   * material, initial velocity and initial stress, given or geostatic), or
   * one box of the default material given by "Material lower corner" and
   * "Material upper corner" with the "Initial velocity" of subsection
   * "Custom problem". Body force, traction and, optionally, the exact
   * displacement are muparser expressions of the initial position (x, y, z)
   * and time t; the fixed velocity components per boundary id are listed in
   * "Fixed components" (further boundary conditions: BoundaryConditions).
   */
  template <int dim>
  class CustomProblem : public Problem<dim>
  {
  public:
    ~CustomProblem() override;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * True: the conditions are expressions and boundary ids, which any
     * grid, also a Mesh file, can take.
     */
    bool
    runs_on_any_grid() const override;

    bool
    defines_bodies() const override;

    void
    initialize(const Material<dim>       &material,
               const BackgroundGrid<dim> &grid) override;

    Tensor<1, dim>
    initial_velocity(const Point<dim> &X) const override;

    unsigned int
    n_bodies() const override;

    std::string
    body_name(const unsigned int body) const override;

    unsigned int
    body_containing(const Point<dim> &X) const override;

    unsigned int
    material_id(const unsigned int body) const override;

    std::pair<SymmetricTensor<2, dim>, double>
    initial_stress(const Point<dim> &X, const unsigned int body) const override;

    void
    set_present_bodies(const std::vector<bool> &present) override;

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
    /**
     * The weight per unit area of the material above @p X: the integral of
     * the density over the vertical line from X to the top of the grid
     * (of the present bodies), times the vertical component of gravity
     * (negative: compression).
     */
    double
    vertical_stress(const Point<dim> &X) const;

    std::vector<Body<dim>> bodies;
    /// Whether each body is present (set_present_bodies(); empty: all).
    std::vector<bool> present_bodies;
    /// The physical groups of the Mesh files the bodies are groups of, by
    /// the bodies' entry Mesh file (empty: the grid's).
    std::map<std::string, std::unique_ptr<MeshGroups<dim>>> mesh_groups;
    std::unique_ptr<ParsedExpression<dim>>                  velocity;
    std::unique_ptr<ParsedExpression<dim>>                  force;
    std::unique_ptr<ParsedExpression<dim>>                  traction_function;
    std::unique_ptr<ParsedExpression<dim>>                  displacement;
    std::vector<FixedComponents<dim>>                       fixed;
    std::vector<types::boundary_id>                         traction_ids;
    /// The box material region, if given (else the grid's box).
    std::optional<BoundingBox<dim>> region;
  };
} // namespace MpmOtm

#endif
