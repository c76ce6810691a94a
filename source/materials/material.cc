#include <mpm_otm/materials/material.h>

#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  Material<dim>::declare_common_parameters(
    ParameterHandler  &prm,
    const std::string &model_names,
    const std::string &model_documentation)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Model",
                        "linear elastic",
                        Patterns::Selection(model_names),
                        "Constitutive model:" + model_documentation);
      prm.declare_entry("Young's modulus",
                        "4e3",
                        Patterns::Double(0.,
                                         Patterns::Double::max_double_value),
                        "Young's modulus E (Pa), positive.");
      prm.declare_entry("Poisson's ratio",
                        "0",
                        Patterns::Double(-1., 0.5),
                        "Poisson's ratio nu, in (-1, 0.5).");
      prm.declare_entry("Density",
                        "1",
                        Patterns::Double(0.,
                                         Patterns::Double::max_double_value),
                        "Initial mass density rho (kg/m^dim), positive.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Material<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    young   = prm.get_double("Young's modulus");
    poisson = prm.get_double("Poisson's ratio");
    rho     = prm.get_double("Density");
    prm.leave_subsection();
    AssertThrow(young > 0,
                ExcMessage("Material/Young's modulus must be positive."));
    AssertThrow(rho > 0, ExcMessage("Material/Density must be positive."));
    AssertThrow(poisson > -1. && poisson < 0.5,
                ExcMessage("Material/Poisson's ratio must lie in (-1, 0.5)."));
    lambda_lame = young * poisson / ((1. + poisson) * (1. - 2. * poisson));
    mu_lame     = young / (2. * (1. + poisson));
  }



  template <int dim>
  double
  Material<dim>::density() const
  {
    return rho;
  }



  template <int dim>
  double
  Material<dim>::youngs_modulus() const
  {
    return young;
  }



  template <int dim>
  double
  Material<dim>::lambda() const
  {
    return lambda_lame;
  }



  template <int dim>
  double
  Material<dim>::mu() const
  {
    return mu_lame;
  }



  template <int dim>
  double
  Material<dim>::wave_speed() const
  {
    return std::sqrt((lambda_lame + 2. * mu_lame) / rho);
  }



  template class Material<1>;
  template class Material<2>;
  template class Material<3>;
} // namespace MpmOtm
