#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/von_mises.h>

#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  VonMises<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("von Mises");
    {
      prm.declare_entry("Yield stress",
                        "40",
                        Patterns::Double(),
                        "Initial uniaxial yield stress sigma_y (Pa), "
                        "positive.");
      prm.declare_entry("Hardening modulus",
                        "0",
                        Patterns::Double(),
                        "Linear isotropic hardening modulus H (Pa), >= 0: "
                        "the yield stress is sigma_y + H eps_p.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  VonMises<dim>::parse_parameters(ParameterHandler &prm)
  {
    Material<dim>::parse_parameters(prm);
    prm.enter_subsection("von Mises");
    {
      initial_yield_stress = prm.get_double("Yield stress");
      hardening            = prm.get_double("Hardening modulus");
    }
    prm.leave_subsection();
    AssertThrow(initial_yield_stress > 0 && std::isfinite(initial_yield_stress),
                ExcMessage(this->entry_name("von Mises/Yield stress") +
                           " must be positive (here " +
                           this->to_text(initial_yield_stress) + " Pa)."));
    AssertThrow(hardening >= 0 && std::isfinite(hardening),
                ExcMessage(this->entry_name("von Mises/Hardening modulus") +
                           " must be >= 0 (here " + this->to_text(hardening) +
                           " Pa)."));
  }



  template <int dim>
  void
  VonMises<dim>::reduce_strength(const double factor)
  {
    initial_yield_stress /= factor;
    hardening /= factor;
  }



  template <int dim>
  double
  VonMises<dim>::yield_function(const SymmetricTensor<2, 3> &stress,
                                const double plastic_strain) const
  {
    const SymmetricTensor<2, 3> s = deviator(stress);
    return std::sqrt(1.5 * (s * s)) -
           (initial_yield_stress + hardening * plastic_strain);
  }



  template <int dim>
  void
  VonMises<dim>::return_map(SymmetricTensor<2, 3>   &stress,
                            const ArrayView<double> &internal_variables) const
  {
    // de Souza Neto et al. (2008), Box 7.3 with the linear hardening of
    // Sect. 7.3: one closed-form step.
    const SymmetricTensor<2, 3> s_trial = deviator(stress);
    const double                q_trial = std::sqrt(1.5 * (s_trial * s_trial));
    const double                f_trial =
      q_trial - (initial_yield_stress + hardening * internal_variables[0]);
    if (!(f_trial > 0.))
      return;
    const double G      = this->mu_lame;
    const double dgamma = f_trial / (3. * G + hardening);
    // q = q_trial - 3 G dgamma > 0 since q_trial > sigma_y(eps_p) >= 0.
    stress -= (3. * G * dgamma / q_trial) * s_trial;
    internal_variables[0] += dgamma;
  }



  template <int dim>
  double
  VonMises<dim>::yield_stress() const
  {
    return initial_yield_stress;
  }



  template <int dim>
  double
  VonMises<dim>::hardening_modulus() const
  {
    return hardening;
  }



  template class VonMises<1>;
  template class VonMises<2>;
  template class VonMises<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<1>,
  MpmOtm::VonMises<1>,
  "von Mises",
  "J2 plasticity with linear isotropic hardening, radial return")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<2>,
  MpmOtm::VonMises<2>,
  "von Mises",
  "J2 plasticity with linear isotropic hardening, radial return")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<3>,
  MpmOtm::VonMises<3>,
  "von Mises",
  "J2 plasticity with linear isotropic hardening, radial return")
