#ifndef mpm_otm_problems_soil_column_h
#define mpm_otm_problems_soil_column_h

#include <mpm_otm/problems/problem.h>

namespace MpmOtm
{
  template <int dim>
  class BackgroundGrid;
  /**
   * Column under self-weight (BENCHMARKS.md B6, thesis Sects. 4.3-4.4): the
   * vertical direction is the last coordinate, the bottom (boundary
   * 2 (dim - 1)) is fixed, the sides only in their normal direction, the top
   * is free; gravity g acts from rest. Exact small-deformation solution
   * u(y, t) = (g / c^2) sum_n 16 H^2 / ((2n-1)^3 pi^3) (1 - cos(w_n t))
   * sin(k_n y), k_n = (2n - 1) pi / (2H), w_n = c k_n, c the longitudinal
   * wave speed sqrt((lambda + 2 mu) / rho) (sqrt(E / rho) for nu = 0); the
   * lateral stresses are lambda / (lambda + 2 mu) sigma_yy.
   */
  template <int dim>
  class SoilColumn : public Problem<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    void
    initialize(const Material<dim>       &material,
               const BackgroundGrid<dim> &grid) override;

    /**
     * The grid up to the column's height (Soil column/Column height).
     */
    BoundingBox<dim>
    material_region() const override;

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
    double       gravity = 0;
    unsigned int n_terms = 0;
    /// Column height from the parameter file; 0: the grid's height.
    double requested_height = 0;
    double height           = 0;
    double bottom           = 0;
    double c                = 0;
    double rho              = 0;
    double lateral          = 0;
  };
} // namespace MpmOtm

#endif
