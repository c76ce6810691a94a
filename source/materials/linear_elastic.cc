#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/linear_elastic.h>

namespace MpmOtm
{
  template <int dim>
  void
  LinearElastic<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  LinearElastic<dim>::update_stress(const Tensor<2, dim> &F,
                                    const Tensor<2, dim> &,
                                    const double,
                                    StressState<dim> &state) const
  {
    const SymmetricTensor<2, dim> strain =
      symmetrize(F) - unit_symmetric_tensor<dim>();
    const double J = determinant(F);
    // Journal Eq. 10; F eps is not symmetric in general, its symmetric part
    // is the stress that enters the momentum balance.
    const Tensor<2, dim> sigma =
      (this->lambda_lame / J) * trace(strain) * F +
      (2. * this->mu_lame / J) * F * Tensor<2, dim>(strain);
    state.stress = symmetrize(sigma);
    // Plane strain (2D) and uniaxial strain (1D): F and eps have no
    // out-of-plane part, so sigma_zz = lambda / J tr(eps).
    state.out_of_plane_stress =
      (dim < 3) ? (this->lambda_lame / J) * trace(strain) : 0.;
  }



  template <int dim>
  double
  LinearElastic<dim>::strain_energy(const Tensor<2, dim> &F,
                                    const SymmetricTensor<2, dim> &,
                                    const double initial_volume,
                                    const double) const
  {
    const SymmetricTensor<2, dim> strain =
      symmetrize(F) - unit_symmetric_tensor<dim>();
    return initial_volume *
           (0.5 * this->lambda_lame * trace(strain) * trace(strain) +
            this->mu_lame * strain * strain);
  }



  template <int dim>
  bool
  LinearElastic<dim>::keeps_initial_stress() const
  {
    return false;
  }



  template class LinearElastic<1>;
  template class LinearElastic<2>;
  template class LinearElastic<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<1>,
                        MpmOtm::LinearElastic<1>,
                        "linear elastic",
                        "finite-strain linear elastic, journal Eq. 10")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<2>,
                        MpmOtm::LinearElastic<2>,
                        "linear elastic",
                        "finite-strain linear elastic, journal Eq. 10")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<3>,
                        MpmOtm::LinearElastic<3>,
                        "linear elastic",
                        "finite-strain linear elastic, journal Eq. 10")
