#ifndef mpm_otm_materials_hypo_elastic_h
#define mpm_otm_materials_hypo_elastic_h

#include <mpm_otm/materials/material.h>

namespace MpmOtm
{
  /**
   * The hypo-elastic model with the Jaumann stress rate of thesis Eqs. 2.4-2.7,
   * integrated incrementally as in thesis Eqs. 2.40-2.43.
   */
  template <int dim>
  class HypoElastic : public Material<dim>
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
  };
} // namespace MpmOtm

#endif
