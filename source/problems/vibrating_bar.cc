#include <deal.II/base/numbers.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/materials/material.h>
#include <mpm_otm/problems/vibrating_bar.h>

#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  VibratingBar<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Vibrating bar");
    prm.declare_entry("Initial velocity amplitude",
                      "0.6",
                      Patterns::Double(),
                      "v0 in v(X, 0) = v0 sin(pi X / L) (m/s).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  VibratingBar<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Vibrating bar");
    v0 = prm.get_double("Initial velocity amplitude");
    prm.leave_subsection();
  }



  template <int dim>
  void
  VibratingBar<dim>::initialize(const Material<dim>       &material,
                                const BackgroundGrid<dim> &grid)
  {
    Problem<dim>::initialize(material, grid);
    const BoundingBox<dim> &box = grid.box();
    x0                          = box.get_boundary_points().first[0];
    length                      = box.side_length(0);
    const double c              = material.wave_speed();
    omega                       = numbers::PI * c / length;
    impedance                   = material.density() * c;
    lateral = material.lambda() / (material.lambda() + 2. * material.mu());
  }



  template <int dim>
  Tensor<1, dim>
  VibratingBar<dim>::initial_velocity(const Point<dim> &X) const
  {
    Tensor<1, dim> v;
    v[0] = v0 * std::sin(numbers::PI * (X[0] - x0) / length);
    return v;
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  VibratingBar<dim>::fixed_components() const
  {
    std::vector<FixedComponents<dim>> result;
    // Both ends clamped, the other sides rollers.
    for (unsigned int side = 0; side < 2 * dim; ++side)
      result.push_back(side < 2 ? FixedComponents<dim>::all(side) :
                                  FixedComponents<dim>::normal(side));
    return result;
  }



  template <int dim>
  bool
  VibratingBar<dim>::has_exact_solution() const
  {
    return true;
  }



  template <int dim>
  Tensor<1, dim>
  VibratingBar<dim>::exact_displacement(const Point<dim> &X,
                                        const double      time) const
  {
    Tensor<1, dim> u;
    u[0] = v0 / omega * std::sin(omega * time) *
           std::sin(numbers::PI * (X[0] - x0) / length);
    return u;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  VibratingBar<dim>::exact_stress(const Point<dim> &X, const double time) const
  {
    SymmetricTensor<2, dim> sigma;
    sigma[0][0] = v0 * impedance * std::sin(omega * time) *
                  std::cos(numbers::PI * (X[0] - x0) / length);
    for (unsigned int d = 1; d < dim; ++d)
      sigma[d][d] = lateral * sigma[0][0];
    return sigma;
  }



  template class VibratingBar<1>;
  template class VibratingBar<2>;
  template class VibratingBar<3>;
} // namespace MpmOtm

#define MPM_OTM_VIBRATING_BAR_DESCRIPTION \
  "bar with fixed ends and initial velocity v0 sin(pi X/L) (B1, B5)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<1>,
                        MpmOtm::VibratingBar<1>,
                        "vibrating bar",
                        MPM_OTM_VIBRATING_BAR_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<2>,
                        MpmOtm::VibratingBar<2>,
                        "vibrating bar",
                        MPM_OTM_VIBRATING_BAR_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<3>,
                        MpmOtm::VibratingBar<3>,
                        "vibrating bar",
                        MPM_OTM_VIBRATING_BAR_DESCRIPTION)
