#ifndef mpm_otm_algorithms_time_stepper_h
#define mpm_otm_algorithms_time_stepper_h

#include <deal.II/base/timer.h>

#include <mpm_otm/algorithms/nodal_update.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/shape_functions/particle_shape_data.h>

namespace MpmOtm
{
  template <int dim>
  class Material;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class ShapeFunctions;

  /**
   * One explicit time step, the same sequence for every method (journal
   * Alg. 1 / thesis Fig. 2.5); the strategies passed in are the only
   * differences between methods:
   *  1. evaluate the shape functions at the material points (once per step);
   *  2. assemble nodal masses, momenta and forces (Eqs. 19-21);
   *  3. solve the nodal accelerations with the mass-matrix strategy (Eq. 22);
   *  4. advance the particle velocities, v_p += dt sum_i phi_i a_i (Eq. 27);
   *  5. nodal velocities v_i^{s+1} from the nodal-update strategy (USL,
   *     MUSL);
   *  6. move the points, x_p += dt sum_i phi_i v_i^{s+1} (Eq. 26), update
   *     F_p (Eqs. 28-29), V_p (Eq. 30) and the stress (step 12);
   *  7. find the cells of the moved points.
   * A non-finite velocity or stress stops the run naming the point.
   */
  template <int dim>
  class TimeStepper
  {
  public:
    TimeStepper(MaterialPoints<dim>       &material_points,
                const ShapeFunctions<dim> &shape_functions,
                NodalSystem<dim>          &system,
                const MassMatrix<dim>     &mass_matrix,
                const NodalUpdate<dim>    &nodal_update,
                const Material<dim>       &material,
                const Problem<dim>        &problem,
                TimerOutput               &timer);

    /**
     * Advance from @p time to @p time + @p dt.
     */
    void
    advance(const double time, const double dt);

  private:
    void
    advance_particle_velocities(const double dt);

    void
    update_particles(const double dt);

    MaterialPoints<dim>       &material_points;
    const ShapeFunctions<dim> &shape_functions;
    NodalSystem<dim>          &system;
    const MassMatrix<dim>     &mass_matrix;
    const NodalUpdate<dim>    &nodal_update;
    const Material<dim>       &material;
    const Problem<dim>        &problem;
    TimerOutput               &timer;
    ParticleShapeData<dim>     data;
  };
} // namespace MpmOtm

#endif
