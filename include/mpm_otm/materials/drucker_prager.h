#ifndef mpm_otm_materials_drucker_prager_h
#define mpm_otm_materials_drucker_prager_h

#include <mpm_otm/materials/plastic_material.h>

namespace MpmOtm
{
  /**
   * Drucker-Prager plasticity (perfectly plastic, non-associated) with a
   * tension cut-off on the mean stress, for frictional-cohesive soils when a
   * smooth cone is wanted instead of Mohr-Coulomb's pyramid. With stresses
   * positive in tension, p = tr(sigma) / 3, s = dev(sigma) and
   * J2 = s : s / 2 the admissible stresses satisfy
   *   f = sqrt(J2) + alpha p - k <= 0   (the cone) and
   *   p - p_t <= 0                      (the tension cut-off),
   * with the plastic potential g = sqrt(J2) + alpha_psi p on the cone and an
   * associated (purely volumetric) flow on the cut-off. alpha, k and
   * alpha_psi follow from the friction angle phi, the cohesion c and the
   * dilatancy angle psi by matching Mohr-Coulomb (de Souza Neto, Peric and
   * Owen, Computational Methods for Plasticity, 2008, Ch. 6 and Sect. 8.3):
   * - plane strain: alpha = 3 tan(phi) / sqrt(9 + 12 tan^2 phi),
   *   k = 3 c / sqrt(9 + 12 tan^2 phi) (the cone gives Mohr-Coulomb's
   *   plane-strain collapse for associated flow);
   * - outer (the cone through the outer edges, triaxial compression):
   *   alpha = 6 sin(phi) / (sqrt(3) (3 - sin phi)),
   *   k = 6 c cos(phi) / (sqrt(3) (3 - sin phi));
   * - inner (through the inner edges, triaxial extension): the same with
   *   3 + sin phi;
   * alpha_psi is alpha's formula with psi in place of phi. The apex of the
   * cone is p = k / alpha = c cot(phi) for all three; phi = 0 gives a
   * von Mises cylinder sqrt(J2) = k without an apex.
   *
   * Return mapping (perfect plasticity, closed form; K bulk, G shear
   * modulus; sigma^tr the elastic trial stress):
   * - cone (de Souza Neto Box 8.9): d gamma = f^tr / (G + K alpha alpha_psi),
   *   sqrt(J2) = sqrt(J2^tr) - G d gamma, p = p^tr - K alpha_psi d gamma,
   *   s = s^tr sqrt(J2) / sqrt(J2^tr); valid if sqrt(J2) >= 0 and p <= p_t;
   * - cut-off: p = p_t, s = s^tr; valid if the result lies in the cone;
   * - corner (where the cone meets the cut-off plane, a circle of radius
   *   sqrt(J2) = k - alpha p_t): p = p_t, sqrt(J2) = k - alpha p_t, with the
   *   multipliers d gamma = (sqrt(J2^tr) - sqrt(J2)) / G of the cone and
   *   (p^tr - p_t) / K - alpha_psi d gamma of the cut-off, both >= 0 in the
   *   region where neither single return is valid. For the default cut-off,
   *   p_t at the apex, the corner is the apex and this is the apex return of
   *   Box 8.10 (hydrostatic stress c cot(phi), the whole trial deviator
   *   removed, the volumetric plastic strain (p^tr - p_t) / K); it also
   *   covers psi = 0, for which a pure cone return could never reach the
   *   apex.
   * The plastic strain increment is d gamma (s^tr / (2 sqrt(J2^tr)) +
   * alpha_psi I / 3) + d gamma_t I / 3 and the equivalent plastic strain
   * (internal variable 0) grows by sqrt(2/3) times its norm.
   *
   * Strain softening (Softening strains, Residual friction angle, ...;
   * PlasticMaterial::FrictionalParameters): alpha, k, alpha_psi and the
   * cut-off are those of phi, psi and c at the point's equivalent plastic
   * strain at the start of the step (explicit softening; a numeric cut-off
   * is lowered to a softened apex below it).
   *
   * Entries (subsection "Drucker-Prager"): Friction angle (degrees, in
   * [0, 90)), Dilatancy angle (degrees, in [0, Friction angle]), Cohesion
   * (Pa, >= 0), Tension cut-off (Pa in [0, c cot(phi)], or "apex", the
   * default: the apex itself for phi > 0, no cut-off for phi = 0), Cone
   * (plane strain | outer | inner).
   */
  template <int dim>
  class DruckerPrager : public PlasticMaterial<dim>
  {
  public:
    /**
     * Which return return_map() took.
     */
    enum class Return
    {
      /// The trial stress was admissible and is kept.
      elastic,
      /// To the cone.
      cone,
      /// To the cut-off plane p = p_t.
      cut_off,
      /// To the circle where the cone meets the cut-off plane (the apex for
      /// p_t = c cot(phi)).
      corner
    };

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * Cohesion and tan(phi), tan(psi), peak and residual, divided by @p factor
     * (FrictionalParameters::reduced()); the tension cut-off stays (the apex c
     * cot(phi) does not move).
     */
    void
    reduce_strength(const double factor) override;

    /**
     * Whether Softening strains are given.
     */
    bool
    softens() const override;

    void
    return_map(SymmetricTensor<2, 3>   &stress,
               const ArrayView<double> &internal_variables) const override;

    /**
     * The return mapping of return_map(): return @p stress with the cone of
     * the equivalent plastic strain @p plastic_strain, add the increment to
     * @p plastic_strain and say which return was taken.
     */
    Return
    return_stress(SymmetricTensor<2, 3> &stress, double &plastic_strain) const;

    double
    friction_angle() const override;

    bool
    can_separate() const override;

    /**
     * True for the hydrostatic stress of the apex (of the cut-off, if
     * set), every component to 1e-12 E.
     */
    bool
    is_separated(const SymmetricTensor<2, 3> &stress,
                 const double                 plastic_strain) const override;

    /**
     * The (peak) dilatancy angle psi (radians).
     */
    double
    dilatancy_angle() const;

    /**
     * The (peak) cone's friction coefficient alpha.
     */
    double
    alpha() const;

    /**
     * The plastic potential's coefficient alpha_psi.
     */
    double
    alpha_psi() const;

    /**
     * The cone's cohesion term k (Pa): f = sqrt(J2) + alpha p - k.
     */
    double
    k() const;

    /**
     * The largest admissible mean stress p_t (Pa), infinite if there is
     * none (phi = 0 and the default cut-off).
     */
    double
    tension_cut_off() const;

    /**
     * The (peak) cone's yield function sqrt(J2) + alpha p - k of @p stress
     * (Pa).
     */
    double
    yield_function(const SymmetricTensor<2, 3> &stress) const;

  private:
    /**
     * The cone of one strength: alpha, alpha_psi, k and the cut-off p_t.
     */
    struct Cone
    {
      double alpha_phi      = 0;
      double alpha_dilatant = 0;
      double k_cohesion     = 0;
      double p_cut_off      = 0;
    };

    /**
     * The cone of the friction angle, dilatancy angle and cohesion of
     * @p strength (its peak values) with the requested cut-off.
     */
    Cone
    make_cone(const typename PlasticMaterial<dim>::FrictionalParameters
                &strength) const;

    /**
     * The cone at the equivalent plastic strain @p plastic_strain.
     */
    Cone
    cone_at(const double plastic_strain) const;

    /// Peak and residual strengths and the softening strains.
    typename PlasticMaterial<dim>::FrictionalParameters strength;
    /// "plane strain", "outer" or "inner".
    std::string cone_name;
    /// The requested cut-off: a number, or infinite for "apex".
    double requested_cut_off = 0;
    /// The cones of the peak and the residual strength.
    Cone peak;
    Cone residual;
  };
} // namespace MpmOtm

#endif
