#ifndef mpm_otm_boundary_conditions_boundary_conditions_h
#define mpm_otm_boundary_conditions_boundary_conditions_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/boundary_conditions/condition.h>
#include <mpm_otm/problems/problem.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class MassMatrix;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class NodalSystem;
  template <int dim>
  struct ParticleShapeData;
  template <int dim>
  class ShapeFunctions;

  /**
   * The manager of the conditions a user names in the entry "Boundaries",
   * each read from subsection "Boundary <name>": where it acts (the
   * functions of some boundary ids of the grid, or those of the grid
   * vertices inside a box), read and found on the grid here, and what it
   * does, a Condition plugin chosen by the entry "Type". The conditions act
   * on the nodal (coefficient) velocities, v_new = v + dt a at the end of
   * the step with v = q / m, of MPM's fixed grid or of the unified
   * approach's moving grid (check_method()). The time step calls five phases,
   * each of which runs every condition in the order of "Boundaries":
   *
   * - add_loads(): the conditions' forces on the nodes (an absorbing side's
   *   dashpots), in particle-to-grid;
   * - make_acceleration_constraints(): the components the conditions fix
   *   enter the solve for the accelerations as inhomogeneous affine
   *   constraints a_i = (v_target - v_i) / dt;
   * - correct_accelerations(): the corrections of the solved accelerations
   *   (friction, slip on an inclined side) and the reactions;
   * - make_velocity_constraints(): the solves for the velocities of the end
   *   of the step (USL's M v = q, MUSL's re-projection) get v_i = v_target,
   *   so that with a consistent mass matrix the free coefficients feel the
   *   prescribed ones in every solve;
   * - correct_velocities(): the corrections of the solved velocities.
   *
   * The reaction of a condition that holds its nodes is the sum of
   * (M a - f)_i over them, with the mass matrix M of the solves: the force
   * the boundary exerts on the material, which the free nodes' equations
   * M a = f leave over at the constrained ones; that of a condition that
   * only adds loads (Condition::holds_nodes()) is its loads. f there is without
   * the local damping's force (NodalSystem::damping_force), a numerical force
   * that the boundary does not exert: with it, a coefficient alpha changed the
   * reaction of a loading platen by up to alpha times itself. Conditions that
   * fix whole components on sides normal to a coordinate direction also
   * constrain them to zero in the velocity solves (fixed_components()), as the
   * problems' own FixedComponents do.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    /**
     * Declare a subsection "Boundary <name>" per name in @p names.
     */
    static void
    declare_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &names);

    /**
     * Read the conditions listed in the entry "Boundaries".
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Stop if the conditions cannot act with the method @p method_name
     * (named in the messages): every condition needs the nodal
     * accelerations of the step (@p computes_accelerations; OTM's position
     * update has none), a condition on a box of nodes a @p fixed_grid, and
     * some (Condition::needs_lumped_mass()) a @p lumped_mass matrix.
     * On a moving grid (the unified approach) the conditions on Boundary ids
     * act on the nodes of their sides, which move with the material.
     */
    void
    check_method(const std::string &method_name,
                 const bool         fixed_grid,
                 const bool         computes_accelerations,
                 const bool         lumped_mass);

    /**
     * Whether no condition is given.
     */
    bool
    empty() const;

    /**
     * Find the functions of every condition and the outward normal of its
     * boundary (which must be planar for slip and friction) on @p grid.
     */
    void
    setup(const ShapeFunctions<dim> &shape_functions,
          const BackgroundGrid<dim> &grid);

    /**
     * The acting conditions that fix whole components on sides normal to a
     * coordinate direction, for the mass-matrix solves.
     */
    std::vector<FixedComponents<dim>>
    fixed_components() const;

    /**
     * Let the conditions act for which @p acts (one value per condition, in
     * the order of "Boundaries") is true, from the next step on (a stage;
     * every condition acts until then). A condition that does not act
     * leaves its nodes free, adds no load, has no reaction and does not
     * move; its fixed_components() are left out, so the NodalSystem's
     * Dirichlet lists must be set again.
     */
    void
    set_acting(const std::vector<bool> &acts);

    /**
     * The names of the conditions that act.
     */
    std::vector<std::string>
    acting_names() const;

    /**
     * Stop if a condition cannot hold until @p end_time (Condition::
     * check_run()). Call after setup(), before anything is written.
     */
    void
    check_run(const double end_time) const;

    /**
     * Add the conditions' loads to the assembled nodal forces of the step
     * from @p time to @p time + @p dt (Condition::add_loads()). Collective.
     */
    void
    add_loads(NodalSystem<dim> &system, const double time, const double dt);

    /**
     * Set @p constraints to the system's NodalSystem::constraints() and add
     * the conditions that fix components, for the accelerations of the step
     * from @p time to @p time + @p dt: a_i = (v_prescribed - q_i / m_i) /
     * dt on the nodes with mass.
     */
    void
    make_acceleration_constraints(
      const NodalSystem<dim>                 &system,
      const double                            time,
      const double                            dt,
      typename NodalSystem<dim>::Constraints &constraints);

    /**
     * Correct the accelerations of the step from @p time to @p time + @p dt
     * (locally owned entries of system.acceleration, solved subject to
     * make_acceleration_constraints()) by every condition, after each has
     * measured what it needs from @p material_points, and compute the
     * reactions with @p mass_matrix, assembled from @p shape_data.
     * Collective.
     */
    void
    correct_accelerations(NodalSystem<dim>             &system,
                          const MassMatrix<dim>        &mass_matrix,
                          const MaterialPoints<dim>    &material_points,
                          const ParticleShapeData<dim> &shape_data,
                          const double                  time,
                          const double                  dt);

    /**
     * Set @p constraints to the system's NodalSystem::constraints() and add
     * the conditions that fix components, v_i = v_prescribed(@p time), for
     * the velocities of the end of the step that reaches @p time, on the
     * nodes with mass. Call after make_acceleration_constraints() of the
     * step, which moves the boxes.
     */
    void
    make_velocity_constraints(
      const NodalSystem<dim>                 &system,
      const double                            time,
      typename NodalSystem<dim>::Constraints &constraints) const;

    /**
     * Correct the nodal velocities of the end of the step (locally owned
     * entries of system.velocity, solved subject to
     * make_velocity_constraints()) at @p time by every condition.
     */
    void
    correct_velocities(NodalSystem<dim> &system, const double time) const;

    /**
     * The work done by the prescribed velocities on this rank's nodes since
     * the last call (the positive part of each step's work: the impulse of
     * the reaction times the prescribed velocity). Resets it.
     */
    double
    take_work_of_prescribed_velocities();

    /**
     * The names of the conditions.
     */
    std::vector<std::string>
    names() const;

    /**
     * The reaction of each condition, averaged over the steps since the
     * last call of this function with @p start_new_window, and the mean
     * displacement of its nodes since the start (the integral of their mean
     * velocity). With @p start_new_window the averages start anew; an
     * output that a signal adds keeps them, so that a run stopped and
     * resumed writes the same averages at its next regular output as a run
     * that was never stopped.
     */
    std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>>
    reactions_and_displacements(const bool start_new_window);

    /**
     * Save the displacements of the prescribed velocities and the reactions
     * summed since the last output into @p state, for a checkpoint.
     */
    void
    save(CheckpointState &state) const;

    /**
     * Restore what save() saved from @p state (of a run on any number of
     * ranks).
     */
    void
    load(const CheckpointState &state);

  private:
    /**
     * Stop if nodes of the grid lie on a side of @p condition's box that is
     * inside the grid: whether the box holds them is then decided by
     * round-off (a B-spline platen of half a cell around a row of vertices
     * has the Greville points exactly on its sides). Collective.
     */
    void
    refuse_nodes_on_box_sides(const ConditionNodes<dim> &where) const;

    /**
     * Find the outward normal of the sides of @p where (which must be
     * planar if the condition needs it), the offset of their plane and the
     * depth of the cells along them. Collective.
     */
    void
    find_normal(ConditionNodes<dim> &where,
                const bool           needs_normal,
                const std::string   &type) const;

    /**
     * Set @p constraints to the system's NodalSystem::constraints() and add
     * a line per component that a condition fixes on each of its nodes with
     * mass, with the inhomogeneity @p value(i, c, target) for the local
     * index i, the component c and the condition's target velocity at the
     * node at @p time.
     */
    void
    add_prescribed_lines(
      const NodalSystem<dim>                                          &system,
      const double                                                     time,
      const std::function<double(unsigned int, unsigned int, double)> &value,
      typename NodalSystem<dim>::Constraints &constraints) const;

    /**
     * List the locally owned functions of the vertices in the box of
     * @p where, moved by its displacement.
     */
    void
    find_box_functions(ConditionNodes<dim> &where) const;

    std::vector<std::unique_ptr<Condition<dim>>> conditions;
    /// Whether each condition acts (set_acting()).
    std::vector<bool> acting;
    /// The name of each condition's Type.
    std::vector<std::string> types;
    /// Per condition, this rank's reactions summed since the last output.
    std::vector<Tensor<1, dim>> reaction_sums;
    /// Per condition, the loads it added on this rank in the current step.
    std::vector<Tensor<1, dim>> loads;
    /// Per condition, the number of steps summed.
    std::vector<unsigned int> n_steps;
    /// Scratch: a condition's target velocities or reactions at its nodes.
    mutable std::vector<Tensor<1, dim>> node_values;
    /// M a, per component, for the reactions.
    std::array<LinearAlgebra::distributed::Vector<double>, dim> inertia;
    double                     work_of_prescribed_velocities = 0.;
    MPI_Comm                   communicator                  = MPI_COMM_WORLD;
    const ShapeFunctions<dim> *functions                     = nullptr;
    const BackgroundGrid<dim> *background_grid               = nullptr;
  };
} // namespace MpmOtm

#endif
