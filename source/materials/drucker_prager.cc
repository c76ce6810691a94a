#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/drucker_prager.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace MpmOtm
{
  namespace
  {
    /**
     * The coefficient alpha (@p cohesion_term false) or k / c
     * (@p cohesion_term true) of the cone @p cone ("plane strain", "outer"
     * or "inner") matched to Mohr-Coulomb with the angle @p angle (radians);
     * alpha_psi is alpha of the dilatancy angle.
     */
    double
    cone_coefficient(const std::string &cone,
                     const double       angle,
                     const bool         cohesion_term)
    {
      if (cone == "plane strain")
        {
          const double t = std::tan(angle);
          return (cohesion_term ? 3. : 3. * t) / std::sqrt(9. + 12. * t * t);
        }
      const double s     = std::sin(angle);
      const double denom = std::sqrt(3.) * (cone == "outer" ? 3. - s : 3. + s);
      return (cohesion_term ? 6. * std::cos(angle) : 6. * s) / denom;
    }
  } // namespace



  template <int dim>
  void
  DruckerPrager<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Drucker-Prager");
    {
      PlasticMaterial<dim>::declare_frictional_parameters(
        prm,
        "sqrt(J2) + alpha_psi p, alpha_psi from psi as alpha from phi",
        "mean stress p_t = tr(sigma)/3");
      prm.declare_entry("Cone",
                        "plane strain",
                        Patterns::Selection("plane strain|outer|inner"),
                        "Matching of the cone to Mohr-Coulomb: plane strain "
                        "(alpha = 3 tan(phi) / sqrt(9 + 12 tan^2 phi), k = 3 "
                        "c / sqrt(9 + 12 tan^2 phi)), outer (through the "
                        "compressive meridians, alpha = 6 sin(phi) / "
                        "(sqrt(3) (3 - sin(phi))), k = 6 c cos(phi) / "
                        "(sqrt(3) (3 - sin(phi)))) or inner (the same with "
                        "3 + sin(phi)).");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  DruckerPrager<dim>::parse_parameters(ParameterHandler &prm)
  {
    Material<dim>::parse_parameters(prm);
    prm.enter_subsection("Drucker-Prager");
    cone_name = prm.get("Cone");
    strength  = this->parse_frictional_parameters(prm, "Drucker-Prager");
    const Cone   peak_cone = make_cone(strength);
    const double apex      = (strength.friction_angle > 0.) ?
                               peak_cone.k_cohesion / peak_cone.alpha_phi :
                               std::numeric_limits<double>::infinity();
    requested_cut_off =
      this->parse_tension_cut_off(prm,
                                  "Drucker-Prager/Tension cut-off",
                                  apex,
                                  "the apex c cot(phi)");
    prm.leave_subsection();
    peak     = make_cone(strength);
    residual = make_cone(strength.at(strength.softening_end));
  }



  template <int dim>
  void
  DruckerPrager<dim>::reduce_strength(const double factor)
  {
    strength = strength.reduced(factor);
    peak     = make_cone(strength);
    residual = make_cone(strength.at(strength.softening_end));
  }



  template <int dim>
  typename DruckerPrager<dim>::Cone
  DruckerPrager<dim>::make_cone(
    const typename PlasticMaterial<dim>::FrictionalParameters &strength) const
  {
    Cone cone;
    cone.alpha_phi =
      cone_coefficient(cone_name, strength.friction_angle, false);
    cone.alpha_dilatant =
      cone_coefficient(cone_name, strength.dilatancy_angle, false);
    cone.k_cohesion =
      strength.cohesion *
      cone_coefficient(cone_name, strength.friction_angle, true);
    const double apex = (strength.friction_angle > 0.) ?
                          cone.k_cohesion / cone.alpha_phi :
                          std::numeric_limits<double>::infinity();
    cone.p_cut_off    = std::min(requested_cut_off, apex);
    return cone;
  }



  template <int dim>
  typename DruckerPrager<dim>::Cone
  DruckerPrager<dim>::cone_at(const double plastic_strain) const
  {
    if (!(plastic_strain > strength.softening_start))
      return peak;
    if (plastic_strain >= strength.softening_end)
      return residual;
    return make_cone(strength.at(plastic_strain));
  }



  template <int dim>
  double
  DruckerPrager<dim>::yield_function(const SymmetricTensor<2, 3> &stress) const
  {
    const SymmetricTensor<2, 3> s = deviator(stress);
    return std::sqrt(0.5 * (s * s)) + peak.alpha_phi * trace(stress) / 3. -
           peak.k_cohesion;
  }



  template <int dim>
  typename DruckerPrager<dim>::Return
  DruckerPrager<dim>::return_stress(SymmetricTensor<2, 3> &stress,
                                    double                &plastic_strain) const
  {
    const Cone                  cone           = cone_at(plastic_strain);
    const double               &alpha_phi      = cone.alpha_phi;
    const double               &alpha_dilatant = cone.alpha_dilatant;
    const double               &k_cohesion     = cone.k_cohesion;
    const double               &p_cut_off      = cone.p_cut_off;
    const double                p_trial        = trace(stress) / 3.;
    const SymmetricTensor<2, 3> s_trial        = deviator(stress);
    const double tau_trial = std::sqrt(0.5 * (s_trial * s_trial));
    const double f_trial   = tau_trial + alpha_phi * p_trial - k_cohesion;
    if (!(f_trial > 0.) && !(p_trial > p_cut_off))
      return Return::elastic;

    const double G = this->mu_lame;
    const double K = this->lambda_lame + 2. / 3. * this->mu_lame;
    // Multipliers of the cone and of the cut-off; the new sqrt(J2) and p.
    double dgamma = 0., dgamma_t = 0., tau = tau_trial, p = p_trial;
    Return type = Return::corner;
    if (f_trial > 0.)
      {
        // Box 8.9 with constant cohesion.
        dgamma = f_trial / (G + K * alpha_phi * alpha_dilatant);
        tau    = tau_trial - G * dgamma;
        p      = p_trial - K * alpha_dilatant * dgamma;
        if (tau >= 0. && p <= p_cut_off)
          type = Return::cone;
      }
    if (type != Return::cone && p_trial > p_cut_off &&
        tau_trial + alpha_phi * p_cut_off - k_cohesion <= 0.)
      {
        dgamma   = 0.;
        dgamma_t = (p_trial - p_cut_off) / K;
        tau      = tau_trial;
        p        = p_cut_off;
        type     = Return::cut_off;
      }
    if (type == Return::corner)
      {
        // Only reached with a finite p_t (for phi = 0 without cut-off the
        // cone return is always valid). k - alpha p_t >= 0 as p_t is at most
        // the apex.
        tau      = std::max(k_cohesion - alpha_phi * p_cut_off, 0.);
        p        = p_cut_off;
        dgamma   = (tau_trial - tau) / G;
        dgamma_t = (p_trial - p_cut_off) / K - alpha_dilatant * dgamma;
      }

    stress = (tau_trial > 0. ? tau / tau_trial : 0.) * s_trial +
             p * unit_symmetric_tensor<3>();
    // |d eps^p|^2 = |deviatoric part|^2 + (volumetric part)^2 / 3 with
    // |d gamma s^tr / (2 sqrt(J2^tr))| = d gamma / sqrt(2).
    const double volumetric = alpha_dilatant * dgamma + dgamma_t;
    plastic_strain += std::sqrt(
      2. / 3. * (0.5 * dgamma * dgamma + volumetric * volumetric / 3.));
    return type;
  }



  template <int dim>
  void
  DruckerPrager<dim>::return_map(
    SymmetricTensor<2, 3>   &stress,
    const ArrayView<double> &internal_variables) const
  {
    return_stress(stress, internal_variables[0]);
  }



  template <int dim>
  bool
  DruckerPrager<dim>::can_separate() const
  {
    return std::isfinite(peak.p_cut_off) || std::isfinite(residual.p_cut_off);
  }



  template <int dim>
  bool
  DruckerPrager<dim>::is_separated(const SymmetricTensor<2, 3> &stress,
                                   const double plastic_strain) const
  {
    return this->is_hydrostatic_at(stress, cone_at(plastic_strain).p_cut_off);
  }



  template <int dim>
  bool
  DruckerPrager<dim>::softens() const
  {
    return strength.softens();
  }



  template <int dim>
  double
  DruckerPrager<dim>::friction_angle() const
  {
    return strength.friction_angle;
  }



  template <int dim>
  double
  DruckerPrager<dim>::dilatancy_angle() const
  {
    return strength.dilatancy_angle;
  }



  template <int dim>
  double
  DruckerPrager<dim>::alpha() const
  {
    return peak.alpha_phi;
  }



  template <int dim>
  double
  DruckerPrager<dim>::alpha_psi() const
  {
    return peak.alpha_dilatant;
  }



  template <int dim>
  double
  DruckerPrager<dim>::k() const
  {
    return peak.k_cohesion;
  }



  template <int dim>
  double
  DruckerPrager<dim>::tension_cut_off() const
  {
    return peak.p_cut_off;
  }



  template class DruckerPrager<1>;
  template class DruckerPrager<2>;
  template class DruckerPrager<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<1>,
  MpmOtm::DruckerPrager<1>,
  "Drucker-Prager",
  "Drucker-Prager cone matched to Mohr-Coulomb, non-associated, with a "
  "tension cut-off")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<2>,
  MpmOtm::DruckerPrager<2>,
  "Drucker-Prager",
  "Drucker-Prager cone matched to Mohr-Coulomb, non-associated, with a "
  "tension cut-off")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<3>,
  MpmOtm::DruckerPrager<3>,
  "Drucker-Prager",
  "Drucker-Prager cone matched to Mohr-Coulomb, non-associated, with a "
  "tension cut-off")
