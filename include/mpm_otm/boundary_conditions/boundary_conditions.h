#ifndef mpm_otm_boundary_conditions_boundary_conditions_h
#define mpm_otm_boundary_conditions_boundary_conditions_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/base/parsed_expression.h>
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
   * The boundary conditions a user names in the entry "Boundaries", each
   * read from subsection "Boundary <name>": where (the functions of some
   * boundary ids of the grid, or those of the grid vertices inside a box)
   * and what - fixed, slip (the normal velocity zero), Coulomb friction, or
   * a prescribed velocity (functions of time) on some components. A box of
   * prescribed velocity moves with the displacement it prescribes (a
   * settling footing, a moving platen): every step it acts on the vertices
   * inside the moved box. They act on the nodal (coefficient) velocities
   * of a fixed grid, v_new = v + dt a at the end of the step with
   * v = q / m (Bardenhagen, Brackbill & Sulsky 2000; Bardenhagen et al.
   * 2001). The conditions that fix components - fixed, slip on a side
   * normal to a coordinate direction, prescribed velocity - enter the
   * solve for the accelerations as inhomogeneous affine constraints
   * a_i = (v_prescribed - v_i) / dt (make_acceleration_constraints()), and
   * the solves for the velocities of the end of the step (USL's
   * M v = q, MUSL's re-projection, OTM's solve) as v_i = v_prescribed
   * (make_velocity_constraints()), so that with a consistent mass matrix
   * the free coefficients feel the prescribed ones in every solve. Friction
   * and slip on an inclined side are not affine in one component: after
   * the solve, each node's velocity v* = v + dt a is corrected - for
   * friction the velocity into the wall (along the boundary's outward
   * normal n, v*.n > 0) is removed and the tangential velocity reduced by
   * at most mu times the removed normal velocity - and the acceleration set
   * to (v_new - v) / dt, so that the particles follow.
   * A frictional wall acts on a node only where the material touches it:
   * the gap between the wall and the points in the node's support (each
   * point's distance from the wall less half its size, the smallest over
   * the points) must close within the step, gap <= dt v*.n. Without this
   * test a node holds the material as soon as any point lies in its
   * support, and the one-sided condition, which keeps every motion away
   * from the wall, lets a vibrating or sliding body climb off the wall
   * step by step. The nodes found in contact then keep no normal velocity
   * in the velocities the update scheme computes at the end of the step
   * (MUSL's re-projection), whichever its sign.
   * The reaction of a condition is the sum of (M a - f)_i over its nodes,
   * with the mass matrix M of the solves: the force the boundary exerts on
   * the material, which the free nodes' equations M a = f leave over at
   * the constrained ones. f there is without the local damping's force
   * (NodalSystem::damping_force), a numerical force that the boundary does
   * not exert: with it, a coefficient alpha changed the reaction of a
   * loading platen by up to alpha times itself. Fixed and slip conditions on
   * sides normal to a coordinate direction also constrain the fixed components
   * to zero in the velocity solves (fixed_components()), as the problems' own
   * FixedComponents do.
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
     * The conditions that fix whole components on sides normal to a
     * coordinate direction, for the mass-matrix solves.
     */
    std::vector<FixedComponents<dim>>
    fixed_components() const;

    /**
     * Refuse a velocity condition on grid sides (Boundary ids) whose
     * prescribed motion takes it more than half a cell into the grid before
     * @p end_time: MPM's grid stays where it is, so the material leaves the
     * side's nodes, which then hold less and less of it, and the condition's
     * reaction stops being the load on the material (a platen on the grid's
     * top side lost the specimen of the biaxial test after 0.04 m of travel
     * on 0.05 m cells). A condition on a box follows its displacement.
     * Call after setup(), before anything is written.
     */
    void
    check_travel_into_grid(const double end_time) const;

    /**
     * Measure, for every frictional condition, the gap between its wall and
     * the material in the support of each of its nodes, from the points'
     * locations and volumes and the shape function data @p data of the
     * step. Collective; does nothing without frictional conditions.
     */
    void
    measure_gaps(const MaterialPoints<dim>    &material_points,
                 const ParticleShapeData<dim> &data,
                 const NodalSystem<dim>       &system);

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
     * make_acceleration_constraints()) for friction and slip on inclined
     * sides, and compute the reactions with @p mass_matrix, assembled from
     * @p shape_data. Collective.
     */
    void
    constrain_accelerations(NodalSystem<dim>             &system,
                            const MassMatrix<dim>        &mass_matrix,
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
     * make_velocity_constraints()) at @p time for the conditions that are
     * not affine in one component: slip on an inclined side, and friction
     * on the nodes found in contact in constrain_accelerations(), which
     * keep no normal velocity.
     */
    void
    constrain_velocities(NodalSystem<dim> &system, const double time) const;

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
    enum class Type
    {
      fixed,
      slip,
      friction,
      velocity
    };

    /**
     * One condition.
     */
    struct Condition
    {
      std::string                            name;
      Type                                   type = Type::fixed;
      std::vector<types::boundary_id>        boundary_ids;
      BoundingBox<dim>                       box;
      bool                                   on_box               = false;
      double                                 friction_coefficient = 0;
      std::array<bool, dim>                  components{};
      std::unique_ptr<ParsedExpression<dim>> velocity;
      Tensor<1, dim>                         normal;
      /// normal * x for the points x of a planar boundary.
      double wall_offset = 0;
      /// The least depth, along the normal, of the cells at its sides.
      double cell_depth = 0;
      /// For friction: the smallest gap between the wall and the points in
      /// the support of each function (entries of the nodal vectors).
      LinearAlgebra::distributed::Vector<double> gap;
      /// Local indices of the locally owned functions it acts on.
      std::vector<unsigned int> functions;
      /// For friction: whether each of them pressed against the wall in
      /// the current step.
      std::vector<bool> in_contact;
      Tensor<1, dim>    reaction_sum;
      Tensor<1, dim>    displacement;
      unsigned int      n_steps = 0;
    };

    /**
     * The components that @p condition fixes by an affine constraint (none
     * for friction and for slip on an inclined side).
     */
    std::array<bool, dim>
    constrained_components(const Condition &condition) const;

    /**
     * Stop if nodes of the grid lie on a side of @p condition's box that is
     * inside the grid: whether the box holds them is then decided by
     * round-off (a B-spline platen of half a cell around a row of vertices
     * has the Greville points exactly on its sides). Collective.
     */
    void
    refuse_nodes_on_box_sides(const Condition &condition) const;

    /**
     * Set @p constraints to the system's NodalSystem::constraints() and add
     * a line per component that a condition fixes on each of its nodes with
     * mass, with the inhomogeneity @p value(i, c, target) for the local
     * index i, the component c and the condition's velocity target at
     * @p time.
     */
    void
    add_prescribed_lines(
      const NodalSystem<dim>                                          &system,
      const double                                                     time,
      const std::function<double(unsigned int, unsigned int, double)> &value,
      typename NodalSystem<dim>::Constraints &constraints) const;

    /**
     * The corrected velocity of a node with velocity @p v under
     * @p condition at @p time.
     */
    Tensor<1, dim>
    corrected_velocity(const Condition      &condition,
                       const Tensor<1, dim> &v,
                       const double          time) const;

    /**
     * List the locally owned functions of the vertices in the box of
     * @p condition, moved by its displacement.
     */
    void
    find_box_functions(Condition &condition) const;

    std::vector<Condition> conditions;
    /// M a, per component, for the reactions.
    std::array<LinearAlgebra::distributed::Vector<double>, dim> inertia;
    double                     work_of_prescribed_velocities = 0.;
    MPI_Comm                   communicator                  = MPI_COMM_WORLD;
    const ShapeFunctions<dim> *functions                     = nullptr;
    const BackgroundGrid<dim> *background_grid               = nullptr;
  };
} // namespace MpmOtm

#endif
