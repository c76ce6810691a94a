#ifndef mpm_otm_materials_plastic_material_h
#define mpm_otm_materials_plastic_material_h

#include <mpm_otm/materials/hypo_elastic.h>

#include <limits>

namespace MpmOtm
{
  /**
   * The base of the elasto-plastic models (von Mises, Drucker-Prager,
   * Mohr-Coulomb): the elastic part is the hypo-elastic model with the
   * Jaumann rate (thesis Eq. 2.4), integrated per point and step with an
   * elastic predictor followed by the model's return mapping. Both work on
   * the three-dimensional stress: in 2D the point is in plane strain (its
   * sigma_zz is kept, the strain out of the plane is zero), in 1D in
   * uniaxial strain (lateral stresses sigma_yy = sigma_zz). Stresses are
   * positive in tension. Internal variable 0 is the equivalent plastic
   * strain, eps_p = integral of sqrt(2/3 d eps^p : d eps^p); a model may add
   * its own after it. Models with an apex (is_separated()) keep one more,
   * the last: "separation", the volumetric strain a point has taken while it
   * had lost contact (returned to the apex, where a cohesionless material
   * has no stress). A later compression first closes that separation
   * without stress, and only the rest of it is elastic: a granular point
   * that has spread out carries stress again only once it is back at the
   * density at which it lost contact (the disconnected state of Dunatunga
   * & Kamrin, J. Fluid Mech. 779, 2015, with the critical density of each
   * point its own). Without this, a point that spreads out at the apex
   * (its volume grows with no stress to resist it) and is then compressed
   * gets a stress as if it were solid at its large volume, whose force
   * V sigma grad phi makes the explicit step unstable. The rotation of the
   * stress in the predictor is integrated objectively (see
   * elastic_trial_stress()), so that, unlike HypoElastic, a rigid rotation
   * keeps the invariants of the stress.
   */
  template <int dim>
  class PlasticMaterial : public HypoElastic<dim>
  {
  public:
    std::vector<std::string>
    internal_variables() const override;

    void
    update_stress(const Tensor<2, dim> &F,
                  const Tensor<2, dim> &velocity_gradient,
                  const double          dt,
                  StressState<dim>     &state) const final;

    double
    equivalent_plastic_strain(
      const ArrayView<const double> &internal_variables) const override;

    /**
     * True.
     */
    bool
    is_plastic() const override;

    /**
     * Whether the point's separation (the last internal variable of a
     * model that can_separate()) is open.
     */
    bool
    is_disconnected(
      const ArrayView<const double> &internal_variables) const override;

    /**
     * can_separate().
     */
    bool
    can_lose_contact() const override;

    /**
     * The elastic predictor: @p stress advanced by the hypo-elastic rate of
     * thesis Eq. 2.4 over @p dt with the velocity gradient
     * @p velocity_gradient (both three-dimensional),
     * sigma_trial = R sigma R^T + lambda tr(de) I + 2 mu de - tr(de) sigma
     * with de = dt sym(L) and W = dt skew(L). The stretching part is that of
     * HypoElastic; the rotation part sigma + W sigma - sigma W of Eq. 2.4 is
     * integrated with the incremental rotation of Hughes and Winget (1980),
     * R = (I - W/2)^-1 (I + W/2), which agrees with it to first order in W
     * but is exactly orthogonal, so that a rigid rotation (de = 0) changes
     * the invariants p, J2, J3 of the stress only by round-off (the explicit
     * form sigma + W sigma - sigma W of HypoElastic makes them grow by a
     * factor 1 + O(W^2) per step). Over a step, R turns by the angle
     * 2 atan(w / 2) instead of w = |W_12| (for a spin about one axis).
     */
    SymmetricTensor<2, 3>
    elastic_trial_stress(const SymmetricTensor<2, 3> &stress,
                         const Tensor<2, 3>          &velocity_gradient,
                         const double                 dt) const;

    /**
     * Return the elastic trial stress @p stress to the yield surface if it
     * lies outside, and increment the equivalent plastic strain
     * @p internal_variables[0] (and the model's other internal variables);
     * leave both unchanged if @p stress is admissible.
     */
    virtual void
    return_map(SymmetricTensor<2, 3>   &stress,
               const ArrayView<double> &internal_variables) const = 0;

    /**
     * 1 if the strength softens (the internal variable "softening_strain"
     * follows the equivalent plastic strain), invalid otherwise.
     */
    unsigned int
    softening_variable() const override;

    /**
     * Whether the model's strength softens with the equivalent plastic
     * strain (false by default). If it does, its internal variables are
     * "plastic_strain", "softening_strain", the others: return_map() sees
     * the softening strain in place of the plastic strain, so that its
     * strength is that of the softening strain, and both grow by the
     * return's increment.
     */
    virtual bool
    softens() const;

    /**
     * Names of the model's internal variables after the equivalent plastic
     * strain (and the softening strain; none by default).
     */
    virtual std::vector<std::string>
    additional_internal_variables() const;

    /**
     * Whether @p stress, returned by return_map() with the strength of the
     * equivalent plastic strain @p plastic_strain (the point's at the start
     * of the step), is the stress of a point that has lost contact: the
     * hydrostatic stress of the apex of a frictional model (0 for a
     * cohesionless one), where it can only expand. False by default (von
     * Mises has no apex).
     */
    virtual bool
    is_separated(const SymmetricTensor<2, 3> &stress,
                 const double                 plastic_strain) const;

    /**
     * Whether the model has an apex where points can lose contact (and so
     * keeps the internal variable "separation"). False by default.
     */
    virtual bool
    can_separate() const;

  protected:
    /**
     * Friction angle phi and dilatancy angle psi (radians) and cohesion c
     * (Pa) of a frictional model (Drucker-Prager, Mohr-Coulomb), at their
     * peak and, with strain softening, their residual values: the peak
     * holds up to the equivalent plastic strain eps_1, the residual from
     * eps_2 on, and each of the three is linear in eps_p between them.
     */
    struct FrictionalParameters
    {
      double friction_angle           = 0;
      double dilatancy_angle          = 0;
      double cohesion                 = 0;
      double residual_friction_angle  = 0;
      double residual_dilatancy_angle = 0;
      double residual_cohesion        = 0;
      /// eps_1 and eps_2; infinite without softening.
      double softening_start = std::numeric_limits<double>::infinity();
      double softening_end   = std::numeric_limits<double>::infinity();

      /**
       * Whether the strengths soften.
       */
      bool
      softens() const;

      /**
       * The friction angle, dilatancy angle and cohesion at the equivalent
       * plastic strain @p plastic_strain (the returned object's peak
       * values; it does not soften).
       */
      FrictionalParameters
      at(const double plastic_strain) const;

      /**
       * The parameters with the strength divided by @p factor: the
       * cohesions c / F, and the friction and dilatancy angles, peak and
       * residual, atan(tan(angle) / F) (so the dilatancy stays at or below
       * the friction, and the apex c cot(phi) where it was).
       */
      FrictionalParameters
      reduced(const double factor) const;
    };

    /**
     * Declare, in the current subsection of @p prm (the model's), the
     * entries every frictional model has: Friction angle, Dilatancy angle
     * (documented with @p plastic_potential, the model's plastic potential),
     * Cohesion and Tension cut-off (documented with @p cut_off, the stress
     * it limits), and those of strain softening: Softening strains,
     * Residual friction angle, Residual dilatancy angle, Residual cohesion.
     */
    static void
    declare_frictional_parameters(ParameterHandler  &prm,
                                  const std::string &plastic_potential,
                                  const std::string &cut_off);

    /**
     * Read and check the entries of declare_frictional_parameters() but the
     * tension cut-off from the current subsection of @p prm, that of the
     * model @p model (named in messages): the peak values, and the
     * residual ones (each the peak value if left empty) with the strains of
     * "Softening strains" (none if empty). A residual above its peak, a
     * residual dilatancy above the residual friction, residual values
     * without softening strains, and strains that are negative or not
     * increasing are refused with a message that names the entry.
     */
    FrictionalParameters
    parse_frictional_parameters(ParameterHandler  &prm,
                                const std::string &model) const;

    /**
     * Whether every component of @p stress is within 1e-12 E of that of the
     * hydrostatic stress @p vertex I (never for an infinite @p vertex): the
     * test of is_separated() for a model whose apex is @p vertex. It
     * compares one component at a time, so that most stresses are rejected
     * after the first (it runs for every point in every step).
     */
    bool
    is_hydrostatic_at(const SymmetricTensor<2, 3> &stress,
                      const double                 vertex) const;

    /**
     * @p value as text with up to 6 significant digits, for messages.
     */
    static std::string
    to_text(const double value);

    /**
     * Read the entry "Tension cut-off" of the current subsection of @p prm,
     * which is either the word "apex" (no cut-off besides the apex
     * @p apex of the yield surface; @p apex is infinite if the surface has
     * none) or a number of Pa in [0, @p apex], and return its value
     * (infinite for "apex": the cut-off follows the apex, also a softened
     * one). @p entry names the entry in messages, e.g.
     * "Drucker-Prager/Tension cut-off"; @p apex_text says what the apex is.
     */
    double
    parse_tension_cut_off(ParameterHandler  &prm,
                          const std::string &entry,
                          const double       apex,
                          const std::string &apex_text) const;
  };
} // namespace MpmOtm

#endif
