#ifndef mpm_otm_materials_mohr_coulomb_h
#define mpm_otm_materials_mohr_coulomb_h

#include <mpm_otm/materials/plastic_material.h>

#include <array>
#include <vector>

namespace MpmOtm
{
  /**
   * Mohr-Coulomb plasticity (perfectly plastic, non-associated) with a
   * tension cut-off on the largest principal stress, for frictional-cohesive
   * soils. With principal stresses sigma_1 >= sigma_2 >= sigma_3, positive
   * in tension, the admissible stresses satisfy
   *   f = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin(phi) - 2 c cos(phi)
   *     <= 0                                (the Mohr-Coulomb pyramid) and
   *   sigma_1 - sigma_t <= 0                (the Rankine tension cut-off),
   * with the plastic potential
   * g = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin(psi) on the
   * Mohr-Coulomb planes (dilatancy angle psi <= phi) and associated flow on
   * the cut-off planes sigma_i = sigma_t. The apex of the pyramid is the
   * hydrostatic stress c cot(phi); phi = 0 gives Tresca's prism.
   *
   * The return mapping works on the principal stresses of the elastic trial
   * stress, with the elastic law in principal space (Delta sigma_i =
   * -sum_j (lambda + 2 G delta_ij) Delta eps^p_j), and rebuilds the stress
   * with the trial's eigenvectors (de Souza Neto, Peric and Owen,
   * Computational Methods for Plasticity, 2008, Sect. 8.2, Boxes 8.4-8.7):
   * - main plane: one multiplier, d gamma = f^tr / a with
   *   a = 4 G (1 + sin(phi) sin(psi) / 3) + 4 K sin(phi) sin(psi); valid if
   *   the result keeps the order sigma_1 >= sigma_2 >= sigma_3;
   * - right edge (sigma_2 = sigma_3, the planes (1, 3) and (1, 2)) and left
   *   edge (sigma_1 = sigma_2, the planes (1, 3) and (2, 3)): two
   *   multipliers from the 2 x 2 system [[a, b], [b, a]]; the edge tried
   *   first is the one on the side of the trial given by the sign of
   *   (1 - sin psi) sigma_1^tr - 2 sigma_2^tr + (1 + sin psi) sigma_3^tr
   *   (>= 0: right), then the other;
   * - apex: the hydrostatic stress c cot(phi), the plastic strain
   *   being the elastic strain removed, as in de Souza Neto, when neither
   *   the plane nor the edges give a valid state (needs phi > 0).
   *   With psi = 0 and no cut-off, a trial whose mean stress is above the
   *   apex goes there directly: the plane and edge returns keep the mean
   *   stress, and no admissible stress has a larger one.
   * A return is accepted when its multipliers are >= 0 and its result
   * satisfies every plane (the six Mohr-Coulomb planes reduce to the three
   * above and the order of the principal stresses, the cut-off to
   * sigma_1 <= sigma_t), i.e. when it is a solution of the discrete
   * Kuhn-Tucker conditions; for psi = phi this solution is unique (the
   * closest point in the energy norm).
   *
   * The tension cut-off sigma_t (if set below the apex) adds the Rankine
   * planes sigma_i = sigma_t with associated flow (Delta eps^p_i =
   * d gamma_t >= 0). After the Mohr-Coulomb returns above (accepted only if
   * their result has sigma_1 <= sigma_t), the returns tried are, with the
   * same acceptance rule: to the cut-off plane sigma_1 = sigma_t; to its
   * edge sigma_1 = sigma_2 = sigma_t; to the line where the main plane meets
   * the cut-off (sigma_1 = sigma_t, sigma_3 = (sigma_t (1 + sin phi) -
   * 2 c cos phi) / (1 - sin phi)); to the corner where the right edge meets
   * the cut-off (sigma_2 = sigma_3 on that line); to the corner where the
   * left edge meets it (sigma_1 = sigma_2 = sigma_t), with any three of the
   * four planes through it; and to the cut-off apex sigma_1 = sigma_2 =
   * sigma_3 = sigma_t. Every one solves a linear system of at most 3 x 3
   * with the multipliers of its planes. Together they cover every face,
   * edge and corner of the admissible set, so that (for psi = phi, and in
   * every case the tests try for psi < phi) one of them is accepted; should
   * none be (a non-associated trial far in tension), the stress goes to the
   * cut-off apex.
   *
   * The equivalent plastic strain (internal variable 0) grows by
   * sqrt(2/3) |Delta eps^p| with Delta eps^p = sum of d gamma_j times the
   * flow vectors of the active planes (the elastic strain removed at the
   * apex).
   *
   * Entries (subsection "Mohr-Coulomb"): Friction angle (degrees, in
   * [0, 90)), Dilatancy angle (degrees, in [0, Friction angle]), Cohesion
   * (Pa, >= 0), Tension cut-off (Pa in [0, c cot(phi)], or "apex", the
   * default: no cut-off besides the apex for phi > 0, none for phi = 0).
   */
  template <int dim>
  class MohrCoulomb : public PlasticMaterial<dim>
  {
  public:
    /**
     * Which return return_principal_stresses() took.
     */
    enum class Return
    {
      /// The trial stress was admissible and is kept.
      elastic,
      /// To the main plane (sigma_1, sigma_3).
      plane,
      /// To the edge sigma_2 = sigma_3.
      right_edge,
      /// To the edge sigma_1 = sigma_2.
      left_edge,
      /// To the apex c cot(phi).
      apex,
      /// To the cut-off plane sigma_1 = sigma_t.
      cut_off,
      /// To the edge sigma_1 = sigma_2 = sigma_t of the cut-off.
      cut_off_edge,
      /// To the line where the main plane meets the cut-off.
      plane_and_cut_off,
      /// To the corner where the right edge meets the cut-off.
      right_edge_and_cut_off,
      /// To the corner where the left edge meets the cut-off.
      left_edge_and_cut_off,
      /// To sigma_1 = sigma_2 = sigma_3 = sigma_t.
      cut_off_apex
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
     * The return mapping of return_map(): return @p stress, add the
     * equivalent plastic strain increment to @p plastic_strain and say which
     * return was taken.
     */
    Return
    return_stress(SymmetricTensor<2, 3> &stress, double &plastic_strain) const;

    /**
     * The return in principal space: @p principal_stresses (sorted,
     * sigma_1 >= sigma_2 >= sigma_3) are the trial's on entry and the
     * returned ones on exit, with the strength of the equivalent plastic
     * strain @p plastic_strain, to which the increment is added.
     */
    Return
    return_principal_stresses(std::array<double, 3> &principal_stresses,
                              double                &plastic_strain) const;

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
     * The dilatancy angle psi (radians).
     */
    double
    dilatancy_angle() const;

    /**
     * The cohesion c (Pa).
     */
    double
    cohesion() const;

    /**
     * The largest admissible principal stress sigma_t (Pa): the apex
     * c cot(phi) without a cut-off, infinite for phi = 0 without one.
     */
    double
    tension_cut_off() const;

    /**
     * The Mohr-Coulomb yield function of the sorted principal stresses
     * @p principal_stresses (Pa).
     */
    double
    yield_function(const std::array<double, 3> &principal_stresses) const;

  private:
    /**
     * One plane of the admissible set in the sextant sigma_1 >= sigma_2 >=
     * sigma_3: yield function a . sigma - r, flow vector n.
     */
    struct Plane
    {
      std::array<double, 3> a;
      std::array<double, 3> n;
      double                r;
    };

    /**
     * A return tried in return_principal_stresses(): its active planes and,
     * computed once from the material constants in parse_parameters(), the
     * inverse of its matrix M_ij = a_i . D n_j (D the elastic law in
     * principal space) and the stress change per multiplier, D n_j.
     */
    struct Candidate
    {
      std::array<unsigned int, 3>          planes;
      unsigned int                         n_planes;
      Return                               type;
      bool                                 solvable;
      std::array<std::array<double, 3>, 3> inverse;
      std::array<std::array<double, 3>, 3> flow;
    };

    /**
     * The admissible set of one strength (friction angle, dilatancy angle,
     * cohesion and cut-off): its planes and its returns, computed once
     * (for the peak and the residual strength in parse_parameters(), for
     * the strengths in between per point and step of a softening point).
     */
    struct Surface
    {
      double sin_phi      = 0;
      double cos_phi      = 1;
      double sin_psi      = 0;
      double c            = 0;
      double sigma_t      = 0;
      bool   with_cut_off = false;
      double apex_stress  = 0;
      /// The six planes of make_plane().
      std::array<Plane, 6> planes;
      /// The returns in the order they are tried: the main plane, the right
      /// edge, the left edge, then (with the cut-off only) the returns that
      /// involve the cut-off; the first n_candidates are used.
      std::array<Candidate, 12> candidates;
      unsigned int              n_candidates = 0;
    };

    /**
     * The surface of the friction angle, dilatancy angle and cohesion of
     * @p strength (its peak values) with the requested cut-off.
     */
    Surface
    make_surface(const typename PlasticMaterial<dim>::FrictionalParameters
                   &strength) const;

    /**
     * The surface at the equivalent plastic strain @p plastic_strain: the
     * peak or the residual one, or one made in @p buffer.
     */
    const Surface &
    surface_at(const double plastic_strain, Surface &buffer) const;

    /**
     * The plane @p i of the admissible set of @p surface: 0, 1, 2 the
     * Mohr-Coulomb planes of the pairs (1, 3), (1, 2), (2, 3); 3, 4, 5 the
     * cut-off planes sigma_1, sigma_2, sigma_3 = sigma_t.
     */
    Plane
    make_plane(const Surface &surface, const unsigned int i) const;

    /**
     * The candidate returning to @p n_planes of the planes @p planes of
     * @p surface.
     */
    Candidate
    make_candidate(const Surface                     &surface,
                   const std::array<unsigned int, 3> &planes,
                   const unsigned int                 n_planes,
                   const Return                       type) const;

    /**
     * Try the return of @p candidate of @p surface from the trial @p trial;
     * on success (multipliers >= 0, result admissible) set @p result and
     * the plastic strain increment @p plastic_strain_increment (principal)
     * and return true.
     */
    bool
    try_return(const Surface               &surface,
               const Candidate             &candidate,
               const std::array<double, 3> &trial,
               const double                 tolerance,
               std::array<double, 3>       &result,
               std::array<double, 3>       &plastic_strain_increment) const;

    /**
     * The return in principal space with @p surface (see
     * return_principal_stresses()).
     */
    Return
    return_to(const Surface         &surface,
              std::array<double, 3> &principal_stresses,
              double                &plastic_strain) const;

    /// Peak and residual strengths and the softening strains.
    typename PlasticMaterial<dim>::FrictionalParameters strength;
    /// The requested cut-off: a number, or infinite for "apex".
    double requested_cut_off = 0;
    /// The surfaces of the peak and the residual strength.
    Surface peak;
    Surface residual;
  };
} // namespace MpmOtm

#endif
