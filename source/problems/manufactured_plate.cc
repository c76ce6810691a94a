#include <deal.II/base/numbers.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/materials/material.h>
#include <mpm_otm/problems/manufactured_plate.h>

#include <cmath>

namespace MpmOtm
{
  namespace
  {
    /**
     * Phase of component d: c pi t, plus pi for the second component.
     */
    double
    phase(const unsigned int d, const double c, const double time)
    {
      return c * numbers::PI * time + (d == 1 ? numbers::PI : 0.);
    }
  } // namespace



  template <int dim>
  void
  ManufacturedPlate<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Manufactured plate");
    prm.declare_entry("Amplitude",
                      "0.005",
                      Patterns::Double(),
                      "Displacement amplitude A (m).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  ManufacturedPlate<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Manufactured plate");
    amplitude = prm.get_double("Amplitude");
    prm.leave_subsection();
  }



  template <int dim>
  void
  ManufacturedPlate<dim>::initialize(const Material<dim>       &material,
                                     const BackgroundGrid<dim> &grid)
  {
    Problem<dim>::initialize(material, grid);
    rho    = material.density();
    c      = std::sqrt(material.youngs_modulus() / rho);
    lambda = material.lambda();
    mu     = material.mu();
  }



  template <int dim>
  Tensor<1, dim>
  ManufacturedPlate<dim>::initial_velocity(const Point<dim> &X) const
  {
    Tensor<1, dim> v;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] = amplitude * c * numbers::PI * std::sin(2. * numbers::PI * X[d]) *
             std::cos(phase(d, c, 0.));
    return v;
  }



  template <int dim>
  bool
  ManufacturedPlate<dim>::has_body_force() const
  {
    return true;
  }



  template <int dim>
  Tensor<1, dim>
  ManufacturedPlate<dim>::body_force(const Point<dim> &X,
                                     const double      time) const
  {
    // rho0 a = Div P + rho0 b with P = lambda ln(J) F^-T + mu (F - F^-T) and
    // F = diag(F_dd): dP_dd/dX_d = dF_dd/dX_d [lambda (1 - ln J) / F_dd^2 +
    // mu (1 + 1 / F_dd^2)].
    double F[dim];
    double J = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        F[d] = 1. + 2. * numbers::PI * amplitude *
                      std::cos(2. * numbers::PI * X[d]) *
                      std::sin(phase(d, c, time));
        J *= F[d];
      }
    Tensor<1, dim> b;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double s =
          std::sin(2. * numbers::PI * X[d]) * std::sin(phase(d, c, time));
        const double acceleration =
          -amplitude * std::pow(c * numbers::PI, 2) * s;
        const double dF_dX = -4. * numbers::PI * numbers::PI * amplitude * s;
        b[d]               = acceleration - dF_dX / rho *
                                (lambda * (1. - std::log(J)) / (F[d] * F[d]) +
                                 mu * (1. + 1. / (F[d] * F[d])));
      }
    return b;
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  ManufacturedPlate<dim>::fixed_components() const
  {
    std::vector<FixedComponents<dim>> result;
    // The manufactured displacement vanishes only in the normal direction
    // on each side (u1 = 0 at X1 = 0, 1; u2 = 0 at X2 = 0, 1), so only the
    // normal component is fixed.
    for (unsigned int side = 0; side < 2 * dim; ++side)
      result.push_back(FixedComponents<dim>::normal(side));
    return result;
  }



  template <int dim>
  bool
  ManufacturedPlate<dim>::has_exact_solution() const
  {
    return true;
  }



  template <int dim>
  Tensor<1, dim>
  ManufacturedPlate<dim>::exact_displacement(const Point<dim> &X,
                                             const double      time) const
  {
    Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = amplitude * std::sin(2. * numbers::PI * X[d]) *
             std::sin(phase(d, c, time));
    return u;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  ManufacturedPlate<dim>::exact_stress(const Point<dim> &X,
                                       const double      time) const
  {
    // Cauchy stress of journal Eq. 11 for F = diag(F_dd).
    double F[dim];
    double J = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        F[d] = 1. + 2. * numbers::PI * amplitude *
                      std::cos(2. * numbers::PI * X[d]) *
                      std::sin(phase(d, c, time));
        J *= F[d];
      }
    SymmetricTensor<2, dim> sigma;
    for (unsigned int d = 0; d < dim; ++d)
      sigma[d][d] = (lambda * std::log(J) + mu * (F[d] * F[d] - 1.)) / J;
    return sigma;
  }



  template class ManufacturedPlate<2>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<2>,
                        MpmOtm::ManufacturedPlate<2>,
                        "manufactured plate",
                        "neo-Hookean plate with manufactured solution (B3)")
