#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/neo_hookean.h>

#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  NeoHookean<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  NeoHookean<dim>::update_stress(const Tensor<2, dim> &F,
                                 const Tensor<2, dim> &,
                                 const double,
                                 StressState<dim> &state) const
  {
    const double                  J = determinant(F);
    const SymmetricTensor<2, dim> left_cauchy_green =
      symmetrize(F * transpose(F));
    state.stress =
      (this->lambda_lame * std::log(J) / J) * unit_symmetric_tensor<dim>() +
      (this->mu_lame / J) * (left_cauchy_green - unit_symmetric_tensor<dim>());
    // No stretch out of the plane: b_zz = 1.
    state.out_of_plane_stress =
      (dim < 3) ? this->lambda_lame * std::log(J) / J : 0.;
  }



  template <int dim>
  double
  NeoHookean<dim>::strain_energy(const Tensor<2, dim> &F,
                                 const SymmetricTensor<2, dim> &,
                                 const double initial_volume,
                                 const double) const
  {
    const double J       = determinant(F);
    const double log_J   = std::log(J);
    const double trace_C = trace(symmetrize(transpose(F) * F));
    return initial_volume *
           (0.5 * this->mu_lame * (trace_C - dim) - this->mu_lame * log_J +
            0.5 * this->lambda_lame * log_J * log_J);
  }



  template <int dim>
  bool
  NeoHookean<dim>::keeps_initial_stress() const
  {
    return false;
  }



  template class NeoHookean<1>;
  template class NeoHookean<2>;
  template class NeoHookean<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<1>,
                        MpmOtm::NeoHookean<1>,
                        "neo-Hookean",
                        "compressible neo-Hookean, journal Eq. 11")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<2>,
                        MpmOtm::NeoHookean<2>,
                        "neo-Hookean",
                        "compressible neo-Hookean, journal Eq. 11")
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Material<3>,
                        MpmOtm::NeoHookean<3>,
                        "neo-Hookean",
                        "compressible neo-Hookean, journal Eq. 11")
