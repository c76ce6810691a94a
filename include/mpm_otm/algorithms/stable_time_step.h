#ifndef mpm_otm_algorithms_stable_time_step_h
#define mpm_otm_algorithms_stable_time_step_h

#include <mpm_otm/algorithms/nodal_update.h>
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
  class Problem;
  template <int dim>
  class ShapeFunctions;

  /**
   * The largest time step for which the explicit update of the actual
   * discretisation is stable: dt_stable = 2 / omega_max, omega_max^2 the
   * largest eigenvalue of M^-1 K, with M the mass matrix the run uses
   * (lumped, consistent or partially lumped, with its constraints)
   * and K = sum_p V_p B_p^T C_p B_p the stiffness of the material points
   * with each point's elastic moduli (lambda, mu: the initial tangent of
   * every model, an upper bound for plastic ones), both at the initial
   * configuration. The eigenvalue comes from at most 60 Lanczos steps with
   * matrix-free products (one pass over the points and one mass-matrix
   * solve each); the largest Ritz value is a lower bound that rises to
   * omega_max^2 (so dt_stable can only come out too large, by the
   * relative change of the last steps when they do not converge).
   * Functions whose mass is round-off (below 1e-6 of the largest point
   * mass) are left out. It starts from a vector that depends on the
   * points' initial positions only (not on the global function numbers,
   * which depend on the partition), so every number of ranks finds the same
   * value to round-off, also when the iteration has not converged. Unlike the
   * bound h / c of thesis Eq. 2.48, which holds for linear functions with
   * lumped mass in 1D, it accounts for the family, its degree, the mass matrix
   * and the dimension.
   *
   * With a mass matrix M other than the consistent one M_C (lumped,
   * partially lumped), the nodal update matters, because the velocities
   * projected from the points' momenta see the previous accelerations
   * through S = M^-1 M_C rather than in full:
   *  - MUSL computes the strains from the projected velocities: an
   *    explicit scheme for M^-1 K S, whose frequencies are at most those of
   *    M^-1 K, so 2 / omega_max above is safe;
   *  - USL computes them from v + dt a, while the points carry
   *    v_p + dt sum_i phi_i a_i (FLIP): stable up to 2 / omega_max with
   *    omega_max^2 the largest eigenvalue of M^-1 K M^-1 (2 M - M_C), about
   *    0.75 of the step above for every family;
   *  - OTM's update moves the points with the nodal velocities, which the
   *    next step projects again (v_p = sum_i phi_i v_i): stable up to
   *    2 / omega_max with omega_max^2 the largest eigenvalue of
   *    K q = lambda (M + M_C) / 2 q, about 0.8 of the step above.
   * (Both follow from the two-step recurrences of the schemes for one
   * mode, q'' - 2 q' + q = -dt^2 A (q' - (I - S) q) for USL, and are the
   * limits of a numerical check on the full matrices.) Lanczos then works
   * with M^-1 replaced by M^-1 (2 M - M_C) M^-1 = 2 M^-1 - M^-1 M_C M^-1
   * (two solves and a product with M_C) or by ((M + M_C) / 2)^-1 (a CG
   * solve preconditioned with the lumped mass).
   */
  template <int dim>
  class StableTimeStep
  {
  public:
    /**
     * The result of an estimate.
     */
    struct Estimate
    {
      /// omega_max, the largest angular frequency (1/s).
      double largest_frequency = 0;
      /// 2 / omega_max (s).
      double time_step = 0;
      /// Lanczos steps done.
      unsigned int iterations = 0;
      /// Whether the largest Ritz value changed by less than 1e-8
      /// (relative) in the last step; otherwise the change in it.
      bool   converged   = false;
      double last_change = 0;
    };

    /**
     * Estimate the stable time step of @p material_points with
     * @p shape_functions and @p mass_matrix, for a nodal update whose
     * points' velocities follow @p particle_velocity. Assembles @p system
     * (its vectors are overwritten by the first step). Collective.
     */
    Estimate
    estimate(
      const MaterialPoints<dim>                        &material_points,
      const ShapeFunctions<dim>                        &shape_functions,
      NodalSystem<dim>                                 &system,
      MassMatrix<dim>                                  &mass_matrix,
      const MaterialLibrary<dim>                       &materials,
      const Problem<dim>                               &problem,
      const typename NodalUpdate<dim>::ParticleVelocity particle_velocity);

  private:
    using VectorType = typename NodalSystem<dim>::VectorType;

    /**
     * stiffness_product = K @p x (locally owned entries, summed over the
     * ranks); @p x needs its ghost entries.
     */
    void
    apply_stiffness(const MaterialPoints<dim>         &material_points,
                    const MaterialLibrary<dim>        &materials,
                    const std::array<VectorType, dim> &x,
                    std::array<VectorType, dim>       &stiffness_product) const;

    /**
     * @p product = M_C @p x on the locally owned entries, with M_C the
     * consistent mass matrix of the points; @p x needs its ghost entries.
     */
    void
    apply_consistent_mass(const NodalSystem<dim> &system,
                          const VectorType       &x,
                          VectorType             &product) const;

    ParticleShapeData<dim> data;
  };
} // namespace MpmOtm

#endif
