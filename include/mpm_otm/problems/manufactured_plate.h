#ifndef mpm_otm_problems_manufactured_plate_h
#define mpm_otm_problems_manufactured_plate_h

#include <mpm_otm/problems/problem.h>

namespace MpmOtm
{
  template <int dim>
  class BackgroundGrid;
  /**
   * Neo-Hookean unit plate with the manufactured axis-aligned displacement
   * u1 = A sin(2 pi X1) sin(c pi t), u2 = A sin(2 pi X2) sin(c pi t + pi),
   * c = sqrt(E / rho0), and the body force that makes it exact
   * (BENCHMARKS.md B3, journal Sect. 8.3). Each side is fixed in its normal
   * direction: the manufactured displacement vanishes only there.
   * Two-dimensional only.
   */
  template <int dim>
  class ManufacturedPlate : public Problem<dim>
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

    bool
    has_body_force() const override;

    Tensor<1, dim>
    body_force(const Point<dim> &X, const double time) const override;

    std::vector<FixedComponents<dim>>
    fixed_components() const override;

    bool
    has_exact_solution() const override;

    Tensor<1, dim>
    exact_displacement(const Point<dim> &X, const double time) const override;

    SymmetricTensor<2, dim>
    exact_stress(const Point<dim> &X, const double time) const override;

  private:
    double amplitude = 0;
    double c         = 0;
    double rho       = 0;
    double lambda    = 0;
    double mu        = 0;
  };
} // namespace MpmOtm

#endif
