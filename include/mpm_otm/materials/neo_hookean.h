#ifndef mpm_otm_materials_neo_hookean_h
#define mpm_otm_materials_neo_hookean_h

#include <mpm_otm/materials/material.h>

namespace MpmOtm
{
  /**
   * The compressible neo-Hookean model of journal Eq. 11, sigma = lambda
   * ln(J)/J I + mu/J (F F^T - I).
   */
  template <int dim>
  class NeoHookean : public Material<dim>
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
