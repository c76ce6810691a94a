#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/hypo_elastic.h>

namespace MpmOtm
{
  template <int dim>
  void
  HypoElastic<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  HypoElastic<dim>::update_stress(const Tensor<2, dim> &,
                                  const Tensor<2, dim> &velocity_gradient,
                                  const double          dt,
                                  StressState<dim>     &state) const
  {
    // Thesis Eqs. 2.40-2.43: strain and spin increments from the velocity
    // gradient, D from K and G (Eqs. 2.6-2.7, so that K - 2G/3 = lambda).
    const SymmetricTensor<2, dim> strain_increment =
      dt * symmetrize(velocity_gradient);
    const Tensor<2, dim> spin_increment =
      0.5 * dt * (velocity_gradient - transpose(velocity_gradient));
    const double             volumetric_increment = trace(strain_increment);
    SymmetricTensor<2, dim> &stress               = state.stress;
    const Tensor<2, dim>     old_stress(stress);
    const Tensor<2, dim>     rotation =
      spin_increment * old_stress - old_stress * spin_increment;
    stress +=
      this->lambda_lame * volumetric_increment * unit_symmetric_tensor<dim>() +
      2. * this->mu_lame * strain_increment -
      volumetric_increment * SymmetricTensor<2, dim>(stress) +
      symmetrize(rotation);
    // The out-of-plane component (no strain or spin out of the plane).
    if (dim < 3)
      state.out_of_plane_stress +=
        (this->lambda_lame - state.out_of_plane_stress) * volumetric_increment;
  }



  template <int dim>
  double
  HypoElastic<dim>::strain_energy(const Tensor<2, dim> &,
                                  const SymmetricTensor<2, dim> &stress,
                                  const double,
                                  const double volume) const
  {
    // Complementary energy 1/2 sigma : D^-1 : sigma of the current stress;
    // D^-1 sigma = (sigma - lambda / (dim lambda + 2 mu) tr(sigma) I) / 2 mu.
    const double                  lambda = this->lambda_lame;
    const double                  mu     = this->mu_lame;
    const SymmetricTensor<2, dim> elastic_strain =
      (stress - lambda / (dim * lambda + 2. * mu) * trace(stress) *
                  unit_symmetric_tensor<dim>()) /
      (2. * mu);
    return 0.5 * volume * (stress * elastic_strain);
  }



  template class HypoElastic<1>;
  template class HypoElastic<2>;
  template class HypoElastic<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<1>,
                        MpmOtm::HypoElastic<1>,
                        "hypo-elastic",
                        "hypo-elastic with Jaumann rate, thesis Eq. 2.4")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<2>,
                        MpmOtm::HypoElastic<2>,
                        "hypo-elastic",
                        "hypo-elastic with Jaumann rate, thesis Eq. 2.4")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<3>,
                        MpmOtm::HypoElastic<3>,
                        "hypo-elastic",
                        "hypo-elastic with Jaumann rate, thesis Eq. 2.4")
