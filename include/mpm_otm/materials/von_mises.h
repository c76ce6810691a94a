#ifndef mpm_otm_materials_von_mises_h
#define mpm_otm_materials_von_mises_h

#include <mpm_otm/materials/plastic_material.h>

namespace MpmOtm
{
  /**
   * J2 (von Mises) plasticity with linear isotropic hardening, for metals
   * and for undrained (total-stress) soils: the yield function is
   * f(sigma, eps_p) = q - (sigma_y + H eps_p) with q = sqrt(3 J2),
   * J2 = s : s / 2, s = dev(sigma), with associated flow
   * d eps^p = d gamma sqrt(3/2) s / |s|, so that the equivalent plastic
   * strain (internal variable 0) grows by d gamma = sqrt(2/3) |d eps^p|.
   *
   * The return mapping is the radial return of de Souza Neto, Peric and Owen,
   * Computational Methods for Plasticity (2008), Sect. 7.3 (Boxes 7.3-7.4),
   * which for linear hardening needs no iteration: with the trial stress
   * sigma^tr and f^tr = q^tr - sigma_y(eps_p) > 0,
   * d gamma = f^tr / (3 G + H), s = (1 - 3 G d gamma / q^tr) s^tr, p = p^tr.
   * A trial stress with f^tr <= 0 is returned unchanged. In uniaxial stress
   * the tangent after yield is E H / (E + H); with the hypo-elastic
   * predictor of PlasticMaterial (its term -tr(de) sigma) it is exactly
   * E' H / (E' + H) with E' = E - (1 - 2 nu) sigma, the same up to a
   * relative O(sigma / E).
   *
   * Entries (subsection "von Mises" of the material's subsection): Yield
   * stress sigma_y (Pa, positive), Hardening modulus H (Pa, >= 0).
   */
  template <int dim>
  class VonMises : public PlasticMaterial<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * The yield stress and the hardening modulus divided by @p factor (the
     * undrained strength c_u / F of a Tresca-like clay).
     */
    void
    reduce_strength(const double factor) override;

    void
    return_map(SymmetricTensor<2, 3>   &stress,
               const ArrayView<double> &internal_variables) const override;

    /**
     * The yield function f = sqrt(3 J2) - (sigma_y + H eps_p) of @p stress
     * at the equivalent plastic strain @p plastic_strain (Pa).
     */
    double
    yield_function(const SymmetricTensor<2, 3> &stress,
                   const double                 plastic_strain) const;

    /**
     * Initial uniaxial yield stress sigma_y (Pa).
     */
    double
    yield_stress() const;

    /**
     * Linear isotropic hardening modulus H (Pa).
     */
    double
    hardening_modulus() const;

  private:
    double initial_yield_stress = 0;
    double hardening            = 0;
  };
} // namespace MpmOtm

#endif
