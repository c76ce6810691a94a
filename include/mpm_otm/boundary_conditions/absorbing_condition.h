#ifndef mpm_otm_boundary_conditions_absorbing_condition_h
#define mpm_otm_boundary_conditions_absorbing_condition_h

#include <deal.II/lac/la_parallel_vector.h>

#include <mpm_otm/boundary_conditions/condition.h>

namespace MpmOtm
{
  /**
   * Type = absorbing: a viscous boundary (Lysmer & Kuhlemeyer 1969) that
   * lets waves leave the model through a planar side: dashpots with the
   * tractions -rho c_p v_n along the outward normal n and -rho c_s v_t
   * along the side, which absorb a plane wave at normal incidence
   * completely. Each node of the side gets the force of its share A_i of
   * the side, the integral of its function over the side's faces
   * (ShapeFunctions::boundary_integrals(), which a family without them
   * refuses before the first step; on a moving grid recomputed in every
   * step). The dashpots act on the velocity at the end of the step
   * (backward Euler) with the lumped mass m_i, per direction
   * v_new = (q_i + dt f_i) / (m_i + dt A_i rho c), so that no time step
   * and no nearly empty node makes them overshoot; the force
   * -A_i rho c v_new is added to the node's force before the solve, which
   * must use the lumped mass too. The force is the condition's reaction;
   * the energy it takes out of the model is not counted as work (the
   * energy monitor's bound stays valid).
   */
  template <int dim>
  class AbsorbingCondition : public Condition<dim>
  {
  public:
    /**
     * Declare "Density", "P-wave speed" and "S-wave speed".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    bool
    needs_normal() const override;

    bool
    needs_lumped_mass() const override;

    /**
     * False: its reaction is its load.
     */
    bool
    holds_nodes() const override;

    void
    initialize(const ShapeFunctions<dim> &shape_functions) override;

    Tensor<1, dim>
    add_loads(NodalSystem<dim> &system,
              const double      time,
              const double      dt) override;

  private:
    /**
     * Set #shares to the integrals of the functions over the side.
     * Collective.
     */
    void
    find_shares();

    double density      = 0.;
    double p_wave_speed = 0.;
    double s_wave_speed = 0.;
    /// The family, for the nodes' shares of the side.
    const ShapeFunctions<dim> *functions = nullptr;
    /// A_i, the integral of each function over the side.
    LinearAlgebra::distributed::Vector<double> shares;
  };
} // namespace MpmOtm

#endif
