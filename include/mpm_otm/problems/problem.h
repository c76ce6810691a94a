#ifndef mpm_otm_problems_problem_h
#define mpm_otm_problems_problem_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <mpm_otm/problems/surface_loads.h>

#include <string>
#include <utility>
#include <vector>

namespace MpmOtm
{
  template <int dim>
  class BackgroundGrid;
  using namespace dealii;

  template <int dim>
  class Material;
  template <int dim>
  class MaterialLibrary;

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
   * One benchmark or user problem: where the material is (its bodies, each
   * with a material, an initial velocity and an initial stress), its loads
   * (gravity, read here for every problem from subsection "Gravity", body
   * force, tractions), its Dirichlet conditions and, where known, the exact
   * displacement and stress. Quantities are functions of the initial
   * (material) position X of a point and of time. Boundary ids are those of
   * BackgroundGrid (2 d: lower side, 2 d + 1: upper side in direction d).
   * The built-in benchmarks have one body, their material region, of the
   * default material.
   */
  template <int dim>
  class Problem
  {
  public:
    virtual ~Problem() = default;

    /**
     * Declare subsection "Gravity", which every problem has.
     */
    static void
    declare_common_parameters(ParameterHandler &prm);

    /**
     * Read subsection "Gravity", remember @p materials and read the
     * problem's own entries (parse_parameters()).
     */
    void
    parse(ParameterHandler &prm, const MaterialLibrary<dim> &materials);

    /**
     * Read the problem's own subsection.
     */
    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /**
     * The gravitational acceleration at @p time (the entry Gravity/Vector,
     * ramped linearly from 0 over Gravity/Ramp time).
     */
    Tensor<1, dim>
    gravity(const double time) const;

    /**
     * Whether gravity is switched on.
     */
    bool
    has_gravity() const;

    /**
     * Let the gravitational acceleration be @p g from now on, at once (a
     * stage's Gravity; the ramp of Gravity/Ramp time ends here).
     */
    void
    set_gravity(const Tensor<1, dim> &g);

    /**
     * Number of bodies (1 unless a problem says otherwise).
     */
    virtual unsigned int
    n_bodies() const;

    /**
     * Name of body @p body (for messages and output).
     */
    virtual std::string
    body_name(const unsigned int body) const;

    /**
     * The body that contains @p X, or numbers::invalid_unsigned_int if none;
     * stops if two bodies overlap there. Default: body 0 is
     * material_region().
     */
    virtual unsigned int
    body_containing(const Point<dim> &X) const;

    /**
     * The number of the material of body @p body (default: 0, the default
     * material).
     */
    virtual unsigned int
    material_id(const unsigned int body) const;

    /**
     * Initial stress at @p X in body @p body: the in-plane components and
     * the out-of-plane one (default: none).
     */
    virtual std::pair<SymmetricTensor<2, dim>, double>
    initial_stress(const Point<dim> &X, const unsigned int body) const;

    /**
     * Which bodies are present (a stage of the run removes or adds some):
     * body_containing() finds these only, so that a geostatic initial
     * stress counts their weight and a body added later may take the place
     * of one removed before (a backfill). Default: nothing to do (one
     * body).
     */
    virtual void
    set_present_bodies(const std::vector<bool> &present);

    /**
     * Whether the problem runs on any background grid, in particular on a
     * Mesh file (default: false; the benchmarks are defined on box grids,
     * whose sides have the boundary ids 0 to 2 dim - 1).
     */
    virtual bool
    runs_on_any_grid() const;

    /**
     * Whether the problem's material is given by the bodies of the entry
     * "Bodies" (default: false; a benchmark places its own material and a
     * list of bodies is refused).
     */
    virtual bool
    defines_bodies() const;

    /**
     * Called once the material and the background grid are known (its
     * box: for a Mesh file the bounding box of its vertices).
     */
    virtual void
    initialize(const Material<dim> &material, const BackgroundGrid<dim> &grid);

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
     * fixed components; @p entry names the parameter in error messages. Any
     * boundary id is accepted here; the Simulator checks that the grid has
     * it.
     */
    static std::vector<FixedComponents<dim>>
    parse_fixed_components(const std::string &text, const std::string &entry);

    /**
     * The loads on parts of the bodies' surfaces (entry "Surface loads"),
     * read by parse().
     */
    const SurfaceLoads<dim> &
    surface_loads() const;

    /**
     * The same, to reserve their point variables and give them their
     * points.
     */
    SurfaceLoads<dim> &
    surface_loads();

  protected:
    BoundingBox<dim>            grid_box;
    const MaterialLibrary<dim> *materials = nullptr;
    Tensor<1, dim>              gravity_vector;
    double                      gravity_ramp_time = 0;
    SurfaceLoads<dim>           loads;
  };
} // namespace MpmOtm

#endif
