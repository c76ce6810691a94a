#ifndef mpm_otm_problems_vibrating_bar_h
#define mpm_otm_problems_vibrating_bar_h

#include <mpm_otm/problems/problem.h>

namespace MpmOtm
{
  template <int dim>
  class BackgroundGrid;
  /**
   * Bar with fixed ends set vibrating by v(X, 0) = v0 sin(pi X / L) in x
   * (BENCHMARKS.md B1, conference paper and journal Sect. 8.1; in 2D the bar
   * of thesis Sect. 4.1, B5). Both ends (boundaries 0 and 1) are fixed, the
   * other sides only in their normal direction. Exact small-deformation
   * solution u = (v0/w) sin(w t) sin(pi X/L), sigma_xx = v0 rho c sin(w t)
   * cos(pi X/L), w = pi c / L, with L the grid length in x and c the
   * longitudinal (uniaxial-strain) wave speed sqrt((lambda + 2 mu) / rho),
   * sqrt(E / rho) for nu = 0; the lateral stresses are lambda / (lambda +
   * 2 mu) sigma_xx.
   */
  template <int dim>
  class VibratingBar : public Problem<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    void
    initialize(const Material<dim>       &material,
               const BackgroundGrid<dim> &grid) override;

    Tensor<1, dim>
    initial_velocity(const Point<dim> &X) const override;

    std::vector<FixedComponents<dim>>
    fixed_components() const override;

    bool
    has_exact_solution() const override;

    Tensor<1, dim>
    exact_displacement(const Point<dim> &X, const double time) const override;

    SymmetricTensor<2, dim>
    exact_stress(const Point<dim> &X, const double time) const override;

  private:
    double v0        = 0;
    double length    = 0;
    double x0        = 0;
    double omega     = 0;
    double impedance = 0;
    double lateral   = 0;
  };
} // namespace MpmOtm

#endif
