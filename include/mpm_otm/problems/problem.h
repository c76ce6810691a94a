#ifndef mpm_otm_problems_problem_h
#define mpm_otm_problems_problem_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class Material;

  /**
   * A boundary on which some velocity components are fixed to zero
   * (homogeneous Dirichlet conditions, thesis Sect. 2.5).
   */
  template <int dim>
  struct FixedComponents
  {
    types::boundary_id    boundary_id;
    std::array<bool, dim> fixed;

    /**
     * Every component fixed on side @p side (a clamped end).
     */
    static FixedComponents
    all(const types::boundary_id side)
    {
      FixedComponents condition{side, {}};
      condition.fixed.fill(true);
      return condition;
    }

    /**
     * Only the component normal to side @p side fixed (a roller); the
     * normal of side 2 d or 2 d + 1 is direction d.
     */
    static FixedComponents
    normal(const types::boundary_id side)
    {
      FixedComponents condition{side, {}};
      condition.fixed.fill(false);
      condition.fixed[side / 2] = true;
      return condition;
    }
  };

  /**
   * One benchmark or user problem: where the material is, its initial
   * velocity, body force, Dirichlet and traction conditions and, where
   * known, the exact displacement and stress. Quantities are functions of the
   * initial (material) position X of a point and of time. Boundary ids are
   * those of BackgroundGrid (2 d: lower side, 2 d + 1: upper side in
   * direction d).
   */
  template <int dim>
  class Problem
  {
  public:
    virtual ~Problem() = default;

    /**
     * Read the problem's own subsection.
     */
    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /**
     * Called once the material and the background box are known.
     */
    virtual void
    initialize(const Material<dim> &material, const BoundingBox<dim> &grid_box);

    /**
     * The box filled with material at t = 0 (default: the whole grid).
     */
    virtual BoundingBox<dim>
    material_region() const;

    /**
     * v(X, 0).
     */
    virtual Tensor<1, dim>
    initial_velocity(const Point<dim> &X) const = 0;

    /**
     * Whether body_force() is not identically zero.
     */
    virtual bool
    has_body_force() const;

    /**
     * Body force per unit mass b(X, t) (gravity included).
     */
    virtual Tensor<1, dim>
    body_force(const Point<dim> &X, const double time) const;

    /**
     * Boundaries and the velocity components fixed on them.
     */
    virtual std::vector<FixedComponents<dim>>
    fixed_components() const = 0;

    /**
     * Boundaries that carry a traction.
     */
    virtual std::vector<types::boundary_id>
    traction_boundaries() const;

    /**
     * Traction (force per unit boundary measure) on @p boundary_id at
     * @p time.
     */
    virtual Tensor<1, dim>
    traction(const types::boundary_id boundary_id, const double time) const;

    /**
     * Whether exact_displacement() and exact_stress() are available.
     */
    virtual bool
    has_exact_solution() const;

    /**
     * Whether exact_stress() is available (default: has_exact_solution()).
     */
    virtual bool
    has_exact_stress() const;

    /**
     * u(X, t).
     */
    virtual Tensor<1, dim>
    exact_displacement(const Point<dim> &X, const double time) const;

    /**
     * sigma(X, t).
     */
    virtual SymmetricTensor<2, dim>
    exact_stress(const Point<dim> &X, const double time) const;

    /**
     * Parse "id: components; id: components", e.g. "0: x, y; 2: y", into
     * fixed components; @p entry names the parameter in error messages.
     */
    static std::vector<FixedComponents<dim>>
    parse_fixed_components(const std::string &text, const std::string &entry);

  protected:
    BoundingBox<dim> grid_box;
  };
} // namespace MpmOtm

#endif
