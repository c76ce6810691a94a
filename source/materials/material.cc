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
  }



  template <int dim>
  void
  Material<dim>::parse_parameters(ParameterHandler &prm)
  {
    young   = prm.get_double("Young's modulus");
    poisson = prm.get_double("Poisson's ratio");
    rho     = prm.get_double("Density");
    AssertThrow(young > 0,
                ExcMessage(entry_name("Young's modulus") +
                           " must be positive."));
    AssertThrow(rho > 0,
                ExcMessage(entry_name("Density") + " must be positive."));
    AssertThrow(poisson > -1. && poisson < 0.5,
                ExcMessage(entry_name("Poisson's ratio") +
                           " must lie in (-1, 0.5)."));
    lambda_lame = young * poisson / ((1. + poisson) * (1. - 2. * poisson));
    mu_lame     = young / (2. * (1. + poisson));
  }



  template <int dim>
  void
  Material<dim>::set_subsection_path(const std::string &path)
  {
    subsection_path = path;
  }



  template <int dim>
  std::string
  Material<dim>::entry_name(const std::string &entry) const
  {
    return subsection_path + "/" + entry;
  }



  template <int dim>
  std::vector<std::string>
  Material<dim>::internal_variables() const
  {
    return {};
  }



  template <int dim>
  double
  Material<dim>::equivalent_plastic_strain(
    const ArrayView<const double> &) const
  {
    return 0.;
  }



  template <int dim>
  unsigned int
  Material<dim>::softening_variable() const
  {
    return numbers::invalid_unsigned_int;
  }



  template <int dim>
  bool
  Material<dim>::is_plastic() const
  {
    return false;
  }



  template <int dim>
  void
  Material<dim>::reduce_strength(const double)
  {}



  template <int dim>
  bool
  Material<dim>::keeps_initial_stress() const
  {
    return true;
  }



  template <int dim>
  bool
  Material<dim>::is_disconnected(const ArrayView<const double> &) const
  {
    return false;
  }



  template <int dim>
  bool
  Material<dim>::can_lose_contact() const
  {
    return false;
  }



  template <int dim>
  double
  Material<dim>::friction_angle() const
  {
    return 0.;
  }



  template <int dim>
  double
  Material<dim>::elastic_out_of_plane_stress(
    const SymmetricTensor<2, dim> &stress) const
  {
    if (dim == 2)
      return poisson * trace(stress);
    if (dim == 1)
      return poisson / (1. - poisson) * stress[0][0];
    return 0.;
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
  Material<dim>::poissons_ratio() const
  {
    return poisson;
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
