#ifndef mpm_otm_algorithms_time_stepper_h
#define mpm_otm_algorithms_time_stepper_h

#include <deal.II/base/timer.h>

#include <mpm_otm/algorithms/grid_motion.h>
#include <mpm_otm/algorithms/nodal_update.h>
#include <mpm_otm/algorithms/particle_transfer.h>
#include <mpm_otm/algorithms/softening_regularisation.h>
#include <mpm_otm/algorithms/update_stress_last.h>
#include <mpm_otm/algorithms/volumetric_locking_remedy.h>
#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/boundary_conditions/boundary_conditions.h>
#include <mpm_otm/grid_system/local_damping.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/shape_functions/particle_shape_data.h>

namespace MpmOtm
{
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class ShapeFunctions;

  /**
   * One explicit time step, the same sequence for MPM, OTM and the unified
   * approach (journal Algs. 1-3 and their comparison in Sect. 5; thesis
   * Fig. 2.5). The strategies passed in are the only differences between
   * the methods: where the shape functions live (GridMotion), the form of
   * the nodal update (NodalUpdate) and the use of the mass matrix
   * (MassMatrix).
   *  1. evaluate the shape functions at the material points (once per step,
   *     on the current grid);
   *  2. assemble nodal masses, momenta and forces (Eqs. 19-21 / 48-50);
   *  3. damp the nodal forces (LocalDamping, if asked for), solve the nodal
   *     accelerations with the mass-matrix strategy (Eq. 22) if the nodal
   *     update uses them (OTM folds the force into its one solve, Eq. 51)
   *     and correct them for the boundary conditions (BoundaryConditions);
   *  4. advance the particle velocities, v_p += dt sum_i phi_i a_i (Eq. 27),
   *     if the nodal update asks for it (USL, MUSL, unified);
   *  5. nodal velocities v_i^{s+1} from the nodal-update strategy (USL,
   *     MUSL, OTM Eq. 51), constrained by the boundary conditions, the nodal
   *     displacement being dt v_i^{s+1};
   *  6. move the points, x_p += dt sum_i phi_i v_i^{s+1} (Eqs. 26 / 52),
   *     update F_p (Eqs. 28-29 / 55), V_p = det(F_p) V_p^0 (Eqs. 30 / 53)
   *     and the stress; for OTM v_p = (x_p^{s+1} - x_p^s) / dt (Eq. 57);
   *     with a VolumetricLockingRemedy, the velocity gradients of all points
   *     are computed first and changed by it before F_p and the stress;
   *  7. move the grid with the nodes (OTM, unified) and find the cells of
   *     the moved points (GridMotion).
   * A non-finite velocity or stress stops the run naming the point.
   */
  template <int dim>
  class TimeStepper
  {
  public:
    TimeStepper(MaterialPoints<dim>          &material_points,
                const ShapeFunctions<dim>    &shape_functions,
                NodalSystem<dim>             &system,
                MassMatrix<dim>              &mass_matrix,
                const NodalUpdate<dim>       &nodal_update,
                GridMotion<dim>              &grid_motion,
                const MaterialLibrary<dim>   &materials,
                const Problem<dim>           &problem,
                BoundaryConditions<dim>      &boundary_conditions,
                const LocalDamping<dim>      &damping,
                VolumetricLockingRemedy<dim> *locking_remedy,
                SofteningRegularisation<dim> *softening_regularisation,
                const ParticleTransfer<dim>  &particle_transfer,
                TimerOutput                  &timer);

    /**
     * Advance from @p time to @p time + @p dt.
     */
    void
    advance(const double time, const double dt);

    /**
     * This rank's share of the work done by gravity, body forces, tractions
     * and prescribed velocities since the start, for the EnergyMonitor: the
     * work of its prescribed velocities, and on the first rank the positive
     * part of each step's work of the loads on all points and nodes (so the
     * sum over the ranks does not depend on their number).
     */
    double
    supplied_work() const;

    /**
     * Save the state that this object carries from one time step to the
     * next into @p state, for a checkpoint.
     */
    void
    save(CheckpointState &state) const;

    /**
     * Restore the state saved by save() from @p state (of a run on any
     * number of ranks).
     */
    void
    load(const CheckpointState &state);

  private:
    /**
     * Update the deformation gradient F_p = (I + dt L_p) F_p and the
     * stress of the point with the property array @p properties from its
     * velocity gradient @p velocity_gradient L_p; false if the result is
     * not finite or det F_p <= 0.
     */
    bool
    update_deformation_and_stress(const ArrayView<double> &properties,
                                  const Tensor<2, dim>    &velocity_gradient,
                                  const double             dt) const;

    /**
     * The points' new velocities before MUSL projects them: v_p += dt
     * sum_i phi_i a_i (FLIP), or blended with sum_i phi_i v_i of the grid's
     * own nodal velocities in system.velocity (PIC, blend, APIC, which also
     * stores the affine velocity).
     */
    void
    advance_particle_velocities(const double dt);

    /**
     * The pass over the points that moves them with the nodal velocities
     * and updates F and the stress; it also advances the particle
     * velocities as @p particle_velocity says (in place for
     * ParticleVelocity::from_acceleration, so that USL reads each point's
     * functions once per step, by the rule of the ParticleTransfer; the
     * pass is compiled apart for FLIP, @p other_rule false, so that the
     * default pays nothing for the other rules).
     */
    template <bool other_rule>
    void
    update_particles(
      const double                                      dt,
      const typename NodalUpdate<dim>::ParticleVelocity particle_velocity);

    MaterialPoints<dim>        &material_points;
    const ShapeFunctions<dim>  &shape_functions;
    NodalSystem<dim>           &system;
    MassMatrix<dim>            &mass_matrix;
    const NodalUpdate<dim>     &nodal_update;
    GridMotion<dim>            &grid_motion;
    const MaterialLibrary<dim> &materials;
    const Problem<dim>         &problem;
    BoundaryConditions<dim>    &boundary_conditions;
    const LocalDamping<dim>    &damping;
    /// Null without a remedy.
    VolumetricLockingRemedy<dim> *locking_remedy;
    /// Null without a regularisation of softening.
    SofteningRegularisation<dim> *softening_regularisation;
    const ParticleTransfer<dim>  &particle_transfer;
    TimerOutput                  &timer;
    /// The grid's own nodal velocities M^-1 q + dt a, whose interpolation
    /// is PIC's particle velocity also under MUSL.
    UpdateStressLast<dim>  grid_velocities;
    ParticleShapeData<dim> data;
    /// With a volumetric locking remedy: the velocity gradient and the
    /// property array of each point in this step, in the order of the
    /// particle handler.
    std::vector<Tensor<2, dim>>    velocity_gradients;
    std::vector<ArrayView<double>> point_properties;

    /**
     * The constraints of the acceleration solves: the system's, with the
     * prescribed velocities of the boundary conditions.
     */
    typename NodalSystem<dim>::Constraints acceleration_constraints;

    /**
     * The constraints of the solves for the velocities at the end of the
     * step: the system's, with the prescribed velocities.
     */
    typename NodalSystem<dim>::Constraints velocity_constraints;

    /**
     * Length of the previous step (0 before the first).
     */
    double previous_dt = 0.;

    /**
     * See supplied_work().
     */
    double work_supplied = 0.;
  };
} // namespace MpmOtm

#endif
