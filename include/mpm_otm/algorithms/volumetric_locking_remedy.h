#ifndef mpm_otm_algorithms_volumetric_locking_remedy_h
#define mpm_otm_algorithms_volumetric_locking_remedy_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <mpm_otm/shape_functions/particle_shape_data.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class NodalSystem;
  template <int dim>
  class ShapeFunctions;

  /**
   * A treatment of volumetric locking: it changes the velocity gradients of
   * the material points, after they are interpolated from the nodal
   * velocities and before the deformation gradients and the stresses are
   * updated with them (journal Alg. 1, steps 11-12), so that their
   * dilatation comes from a space of lower order than the shape functions'.
   * With linear functions and several points per cell, the velocity
   * gradients cannot be isochoric at every point unless the motion is
   * nearly rigid, so an isochoric (plastic or nearly incompressible) flow
   * is over-stiff; the remedy leaves each point's deviatoric motion alone
   * and replaces its volume change. It works on the point's kinematics
   * (and may adjust the updated stresses), so every material model uses it
   * unchanged. Implementations
   * register with PluginRegistry; the entry "Volumetric locking remedy"
   * chooses one.
   */
  template <int dim>
  class VolumetricLockingRemedy
  {
  public:
    virtual ~VolumetricLockingRemedy() = default;

    /**
     * Read the remedy's own entries from @p prm.
     */
    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /**
     * Get ready for @p shape_functions, the nodal vectors of @p system and
     * the models of @p materials, or stop with a message naming the entry
     * if the remedy cannot work with them.
     */
    virtual void
    initialize(const ShapeFunctions<dim>  &shape_functions,
               const NodalSystem<dim>     &system,
               const MaterialLibrary<dim> &materials) = 0;

    /**
     * One line for the start of a run: what the remedy does.
     */
    virtual std::string
    description() const = 0;

    /**
     * Change @p velocity_gradients, the velocity gradients L_p of the
     * points of @p material_points in the order of the particle handler,
     * for the time step @p dt, whose shape functions are @p shape_data. A
     * collective call: every rank makes it in every step, also a rank
     * without points.
     */
    virtual void
    correct(MaterialPoints<dim>          &material_points,
            const ParticleShapeData<dim> &shape_data,
            const double                  dt,
            std::vector<Tensor<2, dim>>  &velocity_gradients) = 0;

    /**
     * Change the stresses of @p material_points after the models have
     * updated them with the velocity gradients of correct() (same points,
     * same order). Nothing by default.
     */
    virtual void
    after_stress_update(MaterialPoints<dim> &material_points);
  };
} // namespace MpmOtm

#endif
