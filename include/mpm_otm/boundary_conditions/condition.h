#ifndef mpm_otm_boundary_conditions_condition_h
#define mpm_otm_boundary_conditions_condition_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <mpm_otm/problems/problem.h>

#include <array>
#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class BoundaryConditions;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class NodalSystem;
  template <int dim>
  class ShapeFunctions;
  template <int dim>
  struct ParticleShapeData;

  /**
   * Where a condition acts: the grid sides of some boundary ids, or the grid
   * vertices (B-splines: Greville points) inside a box, and what the manager
   * BoundaryConditions found there on the grid.
   */
  template <int dim>
  struct ConditionNodes
  {
    /// The name in the entry "Boundaries".
    std::string name;
    /// The boundary ids; empty for a box.
    std::vector<types::boundary_id> boundary_ids;
    /// Whether the condition acts on the nodes in #box.
    bool on_box = false;
    /// The box at the start, before #displacement.
    BoundingBox<dim> box;
    /// The outward normal of a planar boundary (zero on a box or where the
    /// faces of the ids face each other).
    Tensor<1, dim> normal;
    /// normal * x for the points x of a planar boundary.
    double wall_offset = 0;
    /// The least depth, along the normal, of the cells at the sides.
    double cell_depth = 0;
    /// Local indices of the locally owned functions it acts on.
    std::vector<unsigned int> functions;
    /// The displacement of the nodes since the start (a box follows it).
    Tensor<1, dim> displacement;
    /// Whether the grid stays where it is (MPM). On a moving grid (the
    /// unified approach) a side's nodes move with the material: a velocity
    /// condition moves its side with them, and the plane of a slip or
    /// friction condition stays where the side was at the start.
    bool fixed_grid = true;

    /**
     * "Boundary <name>/", to begin the messages about its entries.
     */
    std::string
    path() const
    {
      return "Boundary " + name + "/";
    }
  };



  /**
   * One type of condition on the nodal velocities of the grid, a plugin
   * of the nodal pipeline that BoundaryConditions runs (Bardenhagen,
   * Brackbill & Sulsky 2000; Bardenhagen et al. 2001). Each type registers
   * its name (the entry "Type" of a subsection "Boundary <name>") with
   * MPM_OTM_REGISTER_PLUGIN, declares and reads its own entries, and
   * implements what it needs of the phases of a step:
   *
   * - loads: forces added to the nodes in particle-to-grid (add_loads());
   * - constraints: the components it fixes by an affine constraint and their
   *   target velocity at each node, which the manager adds as a_i = (v_target -
   * v_i) / dt to the solve for the accelerations and as v_i = v_target to the
   * solves for the velocities of the end of the step;
   * - prepare(): what it measures before the corrections (friction: the gap
   *   between wall and material);
   * - correct_accelerations() and correct_velocities(): what is not affine
   *   in one component (friction, slip on an inclined side), applied to the
   *   solved nodal values;
   * - advance(): its state after the step, given its reaction (a prescribed
   *   velocity moves its nodes and does work).
   *
   * Where it acts (ConditionNodes) is read and found on the grid by the
   * manager, so a new type is its own two files.
   */
  template <int dim>
  class Condition
  {
  public:
    virtual ~Condition() = default;

    /**
     * Read the type's own entries in subsection "Boundary <name>" (entered).
     * Where the condition acts is known (nodes()); the normal is not yet.
     */
    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /**
     * Whether the condition needs the normal of a planar boundary (and so
     * cannot act on a box of nodes).
     */
    virtual bool
    needs_normal() const;

    /**
     * Whether the condition holds its nodes (fixes components or corrects
     * the solved values), so that what the equations of motion leave over
     * there, (M a - f)_i, is part of its reaction. A condition that only
     * adds loads has them as its reaction.
     */
    virtual bool
    holds_nodes() const;

    /**
     * Whether the condition needs a lumped mass matrix (it acts on each
     * node with its own mass).
     */
    virtual bool
    needs_lumped_mass() const;

    /**
     * Take what the condition needs of the family @p shape_functions, once
     * its nodes are known (nodes()).
     */
    virtual void
    initialize(const ShapeFunctions<dim> &shape_functions);

    /**
     * Add the condition's loads to the nodal forces (locally owned entries
     * of system.force, assembled from the points) for the step from
     * @p time to @p time + @p dt, before the solve. Returns their sum on
     * this rank, which is part of the condition's reaction. Collective
     * where it reduces.
     */
    virtual Tensor<1, dim>
    add_loads(NodalSystem<dim> &system, const double time, const double dt);

    /**
     * Stop before the first step if the condition cannot hold until
     * @p end_time. Collective where it reduces.
     */
    virtual void
    check_run(const double end_time) const;

    /**
     * The components the condition fixes by an affine constraint.
     */
    virtual std::array<bool, dim>
    constrained_components() const;

    /**
     * The velocity of the constrained components at @p time at each of the
     * condition's nodes: @p targets[k] for the function where.functions[k]
     * (@p targets has that size).
     */
    virtual void
    target_velocities(const double                 time,
                      std::vector<Tensor<1, dim>> &targets) const;

    /**
     * The components fixed to zero on whole grid sides, for the
     * NodalSystem's homogeneous constraints (as the problems' own
     * FixedComponents).
     */
    virtual std::vector<FixedComponents<dim>>
    fixed_components() const;

    /**
     * Whether a condition on a box finds its nodes anew in every step (it
     * follows its displacement).
     */
    virtual bool
    moves() const;

    /**
     * Measure what the corrections need from the points of the step.
     * Collective.
     */
    virtual void
    prepare(const MaterialPoints<dim>    &material_points,
            const ParticleShapeData<dim> &data,
            const NodalSystem<dim>       &system);

    /**
     * Correct the solved accelerations of the step from @p time to @p time
     * + @p dt (locally owned entries) on the condition's nodes with mass.
     */
    virtual void
    correct_accelerations(NodalSystem<dim> &system,
                          const double      time,
                          const double      dt);

    /**
     * Correct the solved nodal velocities of the end of the step at
     * @p time (locally owned entries) on the condition's nodes with mass.
     */
    virtual void
    correct_velocities(NodalSystem<dim> &system, const double time) const;

    /**
     * Advance the condition's state over the step from @p time to @p time +
     * @p dt in which it exerted the force @p node_reactions[k] on the
     * material at the node where.functions[k] (a condition that holds_nodes();
     * empty for one that does not). Returns the positive part of the work it
     * did on this rank's nodes.
     */
    virtual double
    advance(const std::vector<Tensor<1, dim>> &node_reactions,
            const double                       time,
            const double                       dt);

    /**
     * Where the condition acts.
     */
    const ConditionNodes<dim> &
    nodes() const;

  protected:
    ConditionNodes<dim> where;

    friend class BoundaryConditions<dim>;
  };
} // namespace MpmOtm

#endif
