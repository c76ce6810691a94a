#ifndef mpm_otm_materials_linear_elastic_h
#define mpm_otm_materials_linear_elastic_h

#include <mpm_otm/materials/material.h>

namespace MpmOtm
{
  /**
   * The finite-strain "linear elastic" model of journal Eq. 10, sigma =
   * lambda/J tr(eps) F + 2 mu/J F eps with eps = (F + F^T)/2 - I (symmetric
   * part stored).
   */
  template <int dim>
  class LinearElastic : public Material<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    update_stress(const Tensor<2, dim> &F,
                  const Tensor<2, dim> &velocity_gradient,
                  const double          dt,
                  StressState<dim>     &state) const override;

    double
    strain_energy(const Tensor<2, dim>          &F,
                  const SymmetricTensor<2, dim> &stress,
                  const double                   initial_volume,
                  const double                   volume) const override;

    /**
     * False: the stress is a function of F alone.
     */
    bool
    keeps_initial_stress() const override;
  };
} // namespace MpmOtm

#endif
