#ifndef mpm_otm_grid_system_nodal_system_h
#define mpm_otm_grid_system_nodal_system_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/shape_functions/particle_shape_data.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialPoints;
  template <int dim>
  class ShapeFunctions;

  /**
   * The nodal (grid) side of a step: the vectors of nodal masses, momenta,
   * forces, accelerations and velocities, one per component, assembled from
   * the material points (journal Alg. 1, step 4, Eqs. 19-21; thesis
   * Eqs. 2.27-2.30) and the constraints of the solves (deal.II
   * AffineConstraints, one per component): the coefficients fixed by a
   * Dirichlet condition, those whose support holds no material point (no
   * NaN from empty cells) and, if asked for, those deactivated because
   * their diagonal mass M_ii = sum_p m_p phi_i(x_p)^2 is below a threshold
   * (thesis Sect. 5.2) are set to zero.
   * On request it also lists the functions at the edge of the material,
   * which partial lumping needs (thesis Sect. 5.4).
   * Vectors are distributed with ghost entries for every function that a
   * locally owned particle touches.
   */
  template <int dim>
  class NodalSystem
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;
    /// The constraints of each component's solves.
    using Constraints = std::array<AffineConstraints<double>, dim>;

    /**
     * Build the partition and the Dirichlet lists. Functions with
     * M_ii < @p deactivation_threshold are deactivated every step (0: none);
     * if @p find_material_boundary, every step lists the functions that do
     * not vanish on a cell with material points and on one without
     * (material_boundary_functions()).
     */
    void
    setup(const ShapeFunctions<dim>               &shape_functions,
          const std::vector<FixedComponents<dim>> &fixed_components,
          const double                             deactivation_threshold = 0.,
          const bool find_material_boundary = false);

    /**
     * Make the coefficients of the functions on the grid sides of
     * @p fixed_components the Dirichlet lists (replacing those of setup()),
     * from the next step's constraints on: a stage that switches conditions.
     */
    void
    set_fixed_components(
      const std::vector<FixedComponents<dim>> &fixed_components);

    /**
     * The partition of the function indices over the ranks.
     */
    const Utilities::MPI::Partitioner &
    partitioner() const;

    /**
     * The shape functions' ShapeFunctions::functions_per_node().
     */
    unsigned int
    functions_per_node() const;

    /**
     * Start the assembly of lumped masses sum_p m_p phi_i (journal Eq. 17),
     * momenta (Eq. 20) and forces f_i = sum_p [phi_i (m_p (b + g) + t_p) -
     * V_p sigma_p grad phi_i] (Eq. 21 and thesis Eq. 2.28) at @p time, g
     * the problem's gravity. The
     * tractions t_p of the boundary points are included if
     * @p tractions_on_points (a fixed grid, whose boundary is not the
     * material's); otherwise the caller adds them on the grid's boundary
     * faces. Entries of other ranks are summed by finish_assembly().
     */
    void
    assemble(const MaterialPoints<dim>    &material_points,
             const ParticleShapeData<dim> &shape_data,
             const Problem<dim>           &problem,
             const double                  time,
             const bool                    tractions_on_points);

    /**
     * Sum the contributions of all ranks, stop on a non-finite force or
     * momentum, and build constraints().
     */
    void
    finish_assembly();

    /**
     * Assemble only the momenta sum_p m_p phi_i v_p from the current particle
     * velocities (thesis Eq. 2.38).
     */
    void
    assemble_momentum(const MaterialPoints<dim>    &material_points,
                      const ParticleShapeData<dim> &shape_data);

    /**
     * The constraints of this step's solves, one per velocity component:
     * homogeneous lines (global indices, locally owned functions only) for
     * the functions fixed by a Dirichlet condition, without material or
     * deactivated. Built by finish_assembly(). Prescribed velocities add
     * inhomogeneous lines to a copy
     * (BoundaryConditions::make_acceleration_constraints()).
     */
    const Constraints &
    constraints() const;

    /**
     * The lines of @p constraints as pairs of a local index and its
     * inhomogeneity, sorted by index. Only lines x_i = b_i, without entries,
     * are supported.
     */
    std::vector<std::pair<unsigned int, double>>
    local_lines(const AffineConstraints<double> &constraints) const;

    /**
     * Locally owned functions (local indices, sorted) deactivated in this
     * step: material in their support, but M_ii below the threshold.
     */
    const std::vector<unsigned int> &
    deactivated_functions() const;

    /**
     * Locally owned functions (local indices, sorted) that do not vanish on
     * a locally owned cell with material points and on one without, found
     * in this step's assemble() (setup() must have asked for them).
     */
    const std::vector<unsigned int> &
    material_boundary_functions() const;

    /**
     * Work done in a step of length @p dt by the external forces on this
     * rank's points (gravity, body force, tractions on points) and on the
     * grid (tractions added to #force with add_external_power()), from the
     * power P at the start of the step and the kinetic energy
     * dt^2 |f_p|^2 / 2 m_p the point forces alone add: dt P + dt^2 sum_p
     * |f_p|^2 / 2 m_p, exact for a body in free fall.
     */
    double
    external_work(const double dt) const;

    /**
     * The kinetic energy of the grid's motion at the end of the step,
     * sum_i m_i |v_i|^2 / 2 with the lumped masses m_i and the velocities
     * v_i^{s+1} of all ranks: the motion the points are moved with. Unlike
     * the points' kinetic energy it holds nothing of particle velocities
     * that project to zero on the grid (the null space of the
     * particle-to-grid map). Collective.
     */
    double
    kinetic_energy() const;

    /**
     * Add @p power to the power of the external forces of this step (for
     * loads assembled directly on the grid).
     */
    void
    add_external_power(const double power);

    /**
     * Save the accelerations and velocities of the last step, from which
     * the next step's solves with a consistent mass matrix start, into
     * @p state for a checkpoint: each rank those of its functions.
     */
    void
    save(CheckpointState &state) const;

    /**
     * Restore what save() saved from @p state (of a run on any number of
     * ranks).
     */
    void
    load(const CheckpointState &state);

    /// Lumped nodal masses.
    VectorType lumped_mass;
    /// Nodal momenta q_k.
    std::array<VectorType, dim> momentum;
    /// Nodal forces f_k.
    std::array<VectorType, dim> force;
    /**
     * The share of #force that local damping added in this step (zero
     * without damping): a numerical force, which the boundary reactions
     * leave out.
     */
    std::array<VectorType, dim> damping_force;
    /// Nodal accelerations a_k.
    std::array<VectorType, dim> acceleration;
    /// Nodal velocities v_k^{s+1}.
    std::array<VectorType, dim> velocity;
    /// Masses of the particles in the order of the shape data.
    std::vector<double> particle_mass;

  private:
    /**
     * List the functions at the edge of the material from the cells'
     * occupation by @p material_points.
     */
    void
    find_material_boundary(const MaterialPoints<dim> &material_points);

    const ShapeFunctions<dim>                   *shape_functions = nullptr;
    std::shared_ptr<Utilities::MPI::Partitioner> index_partition;
    std::array<std::vector<unsigned int>, dim>   fixed;
    Constraints                                  zero_constraints;
    double                                       deactivation_threshold = 0.;
    /// Diagonal of the consistent mass matrix (only with a threshold).
    VectorType                diagonal_mass;
    std::vector<unsigned int> deactivated;
    /// Power f_p . v_p of the external forces at the start of the step and
    /// sum_p |f_p|^2 / m_p of the points on this rank.
    double external_power                 = 0.;
    double external_force_squared_by_mass = 0.;
    bool   track_material_boundary        = false;
    /// Cells with and without material next to each function.
    VectorType                           filled_cells, empty_cells;
    std::vector<unsigned int>            material_boundary;
    std::vector<types::global_dof_index> cell_functions;
  };
} // namespace MpmOtm

#endif
