#ifndef mpm_otm_boundary_conditions_friction_condition_h
#define mpm_otm_boundary_conditions_friction_condition_h

#include <deal.II/lac/la_parallel_vector.h>

#include <mpm_otm/boundary_conditions/condition.h>

namespace MpmOtm
{
  /**
   * Type = friction: a Coulomb wall on a planar boundary with outward
   * normal n (Bardenhagen et al. 2001). After the solve, each node's
   * velocity v* = v + dt a that moves into the wall (v* . n > 0) loses its
   * normal part and its tangential speed is reduced by at most mu times the
   * removed normal velocity; the acceleration becomes (v_new - v) / dt, so
   * that the particles follow. The material may separate from the wall.
   *
   * The wall acts on a node only where the material touches it: the gap
   * between the wall and the points in the node's support (each point's
   * distance from the wall less half its size, the smallest over the
   * points) must close within the step, gap <= dt v* . n. Without this test
   * a node holds the material as soon as any point lies in its support, and
   * the one-sided condition, which keeps every motion away from the wall,
   * lets a vibrating or sliding body climb off the wall step by step. The
   * nodes found in contact keep no normal velocity in the velocities the
   * update scheme computes at the end of the step (MUSL's re-projection),
   * whichever its sign.
   */
  template <int dim>
  class FrictionCondition : public Condition<dim>
  {
  public:
    /**
     * Declare "Friction coefficient".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    bool
    needs_normal() const override;

    /**
     * Measure the gap between the wall and the points in the support of
     * each node.
     */
    void
    prepare(const MaterialPoints<dim>    &material_points,
            const ParticleShapeData<dim> &data,
            const NodalSystem<dim>       &system) override;

    void
    correct_accelerations(NodalSystem<dim> &system,
                          const double      time,
                          const double      dt) override;

    void
    correct_velocities(NodalSystem<dim> &system,
                       const double      time) const override;

  private:
    double friction_coefficient = 0.;
    /// The smallest gap between the wall and the points in the support of
    /// each function (entries of the nodal vectors).
    LinearAlgebra::distributed::Vector<double> gap;
    /// Whether each of the condition's functions pressed against the wall
    /// in the current step.
    std::vector<bool> in_contact;
  };
} // namespace MpmOtm

#endif
