#ifndef mpm_otm_problems_traction_bar_h
#define mpm_otm_problems_traction_bar_h

#include <mpm_otm/problems/problem.h>

namespace MpmOtm
{
  template <int dim>
  class BackgroundGrid;
  /**
   * Bar fixed at X = 0 and loaded from rest by a traction on its free end
   * X = l (BENCHMARKS.md B2, journal Sect. 8.2, Eq. 103, after Steffen,
   * Kirby & Berzins 2008). The material fills [0, l] in x, starting at the
   * grid's lower corner 0, so that an MPM grid may extend beyond the free
   * end; in 2D and 3D it fills the whole grid in the other directions, whose
   * sides are fixed in their normal direction (uniaxial strain, as in
   * VibratingBar). Boundary 0 (X = 0) is fixed in every component; the
   * traction sigma(l, t) e_x acts on the material's right face (boundary id
   * 1, carried by the outermost material points).
   *
   * Exact small-strain solution: with w = pi / l and c the longitudinal wave
   * speed sqrt((lambda + 2 mu) / rho) (sqrt(E / rho) for nu = 0; the
   * benchmark has c = 1), Eq. 103 with t replaced by c t reads
   * sigma_xx(X, t) = f(c t + X) + f(c t - X), f(s) = sin(w s) for
   * l <= s < 3l and 0 otherwise: a sine pulse of one wave length 2l enters
   * at the free end, is reflected at the fixed end with the same sign and
   * leaves through the free end, where sigma(l, t) = -sin(w c t) for
   * c t < 4l and 0 afterwards (the traction is switched off at c t = 4l, so
   * the solution holds for all t >= 0). The displacement is
   * u_x(X, t) = (1/M) int_0^X sigma_xx(s, t) ds = (g(c t + X) - g(c t - X))
   * / M with g(s) = -(1 + cos(w s)) / w for l <= s < 3l, 0 otherwise (the
   * antiderivative of f) and M = rho c^2 = lambda + 2 mu (E for nu = 0); the
   * lateral stresses are lambda / (lambda + 2 mu) sigma_xx. The run itself
   * is finite strain (neo-Hookean, strain about 1 / M), so agreement is
   * close but not exact. The parameter Amplitude A multiplies stress,
   * traction and displacement (A = -1 pulls the free end outward first).
   */
  template <int dim>
  class TractionBar : public Problem<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * Checks that the grid starts at x = 0 and reaches x = l.
     */
    void
    initialize(const Material<dim>       &material,
               const BackgroundGrid<dim> &grid) override;

    /**
     * [0, l] in x, the grid's extent in the other directions.
     */
    BoundingBox<dim>
    material_region() const override;

    Tensor<1, dim>
    initial_velocity(const Point<dim> &X) const override;

    std::vector<FixedComponents<dim>>
    fixed_components() const override;

    /**
     * Boundary id 1, the material's face X = l.
     */
    std::vector<types::boundary_id>
    traction_boundaries() const override;

    /**
     * sigma_xx(l, t) e_x on boundary 1.
     */
    Tensor<1, dim>
    traction(const types::boundary_id boundary_id,
             const double             time) const override;

    bool
    has_exact_solution() const override;

    Tensor<1, dim>
    exact_displacement(const Point<dim> &X, const double time) const override;

    SymmetricTensor<2, dim>
    exact_stress(const Point<dim> &X, const double time) const override;

  private:
    /**
     * The pulse f(s) = sin(w s) on [l, 3l), 0 elsewhere.
     */
    double
    pulse(const double s) const;

    /**
     * Its antiderivative g(s) = int_{-inf}^s f, zero outside [l, 3l).
     */
    double
    pulse_integral(const double s) const;

    /**
     * sigma_xx(X, t) of Eq. 103 with t replaced by c t.
     */
    double
    axial_stress(const double X, const double time) const;

    double length = 1;
    /// Factor A on the stress of Eq. 103.
    double amplitude = 1;
    double omega     = 0;
    double c         = 0;
    double modulus   = 0;
    double lateral   = 0;
  };
} // namespace MpmOtm

#endif
