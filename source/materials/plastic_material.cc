#include <deal.II/base/utilities.h>

#include <mpm_otm/materials/plastic_material.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * The three-dimensional stress of a point in plane strain (2D) or
     * uniaxial strain (1D).
     */
    template <int dim>
    SymmetricTensor<2, 3>
    to_three_dimensions(const StressState<dim> &state)
    {
      SymmetricTensor<2, 3> stress;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          stress[i][j] = state.stress[i][j];
      for (unsigned int d = dim; d < 3; ++d)
        stress[d][d] = state.out_of_plane_stress;
      return stress;
    }

    /**
     * The velocity gradient padded with zeros (no motion out of the plane or
     * the line).
     */
    template <int dim>
    Tensor<2, 3>
    to_three_dimensions(const Tensor<2, dim> &velocity_gradient)
    {
      Tensor<2, 3> result;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          result[i][j] = velocity_gradient[i][j];
      return result;
    }
  } // namespace



  template <int dim>
  std::vector<std::string>
  PlasticMaterial<dim>::internal_variables() const
  {
    std::vector<std::string> names{"plastic_strain"};
    if (softens())
      names.push_back("softening_strain");
    const auto others = additional_internal_variables();
    names.insert(names.end(), others.begin(), others.end());
    if (can_separate())
      names.push_back("separation");
    return names;
  }



  template <int dim>
  std::vector<std::string>
  PlasticMaterial<dim>::additional_internal_variables() const
  {
    return {};
  }



  template <int dim>
  bool
  PlasticMaterial<dim>::can_separate() const
  {
    return false;
  }



  template <int dim>
  unsigned int
  PlasticMaterial<dim>::softening_variable() const
  {
    return softens() ? 1 : numbers::invalid_unsigned_int;
  }



  template <int dim>
  bool
  PlasticMaterial<dim>::softens() const
  {
    return false;
  }



  template <int dim>
  bool
  PlasticMaterial<dim>::is_separated(const SymmetricTensor<2, 3> &,
                                     const double) const
  {
    return false;
  }



  template <int dim>
  bool
  PlasticMaterial<dim>::is_hydrostatic_at(const SymmetricTensor<2, 3> &stress,
                                          const double vertex) const
  {
    const double tolerance = 1e-12 * this->young;
    for (unsigned int i = 0; i < 3; ++i)
      if (!(std::abs(stress[i][i] - vertex) <= tolerance))
        return false;
    return std::abs(stress[0][1]) <= tolerance &&
           std::abs(stress[0][2]) <= tolerance &&
           std::abs(stress[1][2]) <= tolerance;
  }



  template <int dim>
  SymmetricTensor<2, 3>
  PlasticMaterial<dim>::elastic_trial_stress(
    const SymmetricTensor<2, 3> &stress,
    const Tensor<2, 3>          &velocity_gradient,
    const double                 dt) const
  {
    // The rotation part of Eq. 2.4, sigma + W sigma - sigma W, integrated
    // with the Hughes-Winget rotation R = (I - W/2)^-1 (I + W/2): R is
    // orthogonal for every skew W and equals I + W + O(W^2), so that the
    // update is Eq. 2.4 to first order and a rigid rotation keeps the
    // invariants of the stress to round-off.
    // In closed form (the Cayley transform of the skew W):
    // R = I + (W + W^2 / 2) / (1 + |w|^2 / 4), |w|^2 = -tr(W^2) / 2.
    // The velocity gradient of a 2D (1D) model vanishes out of the plane
    // (line), so W and R - I live in the leading dim x dim block.
    // (Plain arrays: this is the hot path of every plastic model, and
    // SymmetricTensor's element access and temporaries are slower.)
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = std::max(i + 1, static_cast<unsigned int>(dim));
           j < 3;
           ++j)
        Assert(velocity_gradient[i][j] == velocity_gradient[j][i],
               ExcMessage("The spin of a plane-strain (uniaxial-strain) "
                          "point must lie in its plane (line)."));
    double old_stress[3][3];
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        old_stress[i][j] = stress[i][j];
    double rotation[dim][dim];
    if constexpr (dim == 2)
      {
        // W = [[0, w], [-w, 0]], W^2 = -w^2 I: R = [[a, b], [-b, a]] with
        // a = (1 - w^2 / 4) / (1 + w^2 / 4), b = w / (1 + w^2 / 4).
        const double w =
          0.5 * dt * (velocity_gradient[0][1] - velocity_gradient[1][0]);
        const double factor = 1. / (1. + 0.25 * w * w);
        rotation[0][0] = rotation[1][1] = (1. - 0.25 * w * w) * factor;
        rotation[0][1]                  = w * factor;
        rotation[1][0]                  = -w * factor;
      }
    else
      {
        double spin[dim][dim];
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            spin[i][j] =
              0.5 * dt * (velocity_gradient[i][j] - velocity_gradient[j][i]);
        double spin_squared[dim][dim];
        double trace_spin_squared = 0;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              spin_squared[i][j] = 0;
              for (unsigned int k = 0; k < dim; ++k)
                spin_squared[i][j] += spin[i][k] * spin[k][j];
            }
        for (unsigned int i = 0; i < dim; ++i)
          trace_spin_squared += spin_squared[i][i];
        const double factor = 1. / (1. - trace_spin_squared / 8.);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            rotation[i][j] = ((i == j) ? 1. : 0.) +
                             factor * (spin[i][j] + 0.5 * spin_squared[i][j]);
      }

    const double volumetric_increment =
      dt * (velocity_gradient[0][0] + velocity_gradient[1][1] +
            velocity_gradient[2][2]);
    const double          two_mu = 2. * this->mu_lame;
    SymmetricTensor<2, 3> trial;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        {
          // R sigma R^T of the old stress sigma; R = I outside the leading
          // block.
          double rotated = 0;
          if (j < dim)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = 0; l < dim; ++l)
                rotated += rotation[i][k] * old_stress[k][l] * rotation[j][l];
          else if (i < dim)
            for (unsigned int k = 0; k < dim; ++k)
              rotated += rotation[i][k] * old_stress[k][j];
          else
            rotated = old_stress[i][j];
          const double strain_increment =
            0.5 * dt * (velocity_gradient[i][j] + velocity_gradient[j][i]);
          trial[i][j] =
            rotated + two_mu * strain_increment -
            volumetric_increment * old_stress[i][j] +
            ((i == j) ? this->lambda_lame * volumetric_increment : 0.);
        }
    return trial;
  }



  template <int dim>
  void
  PlasticMaterial<dim>::update_stress(const Tensor<2, dim> &,
                                      const Tensor<2, dim> &velocity_gradient,
                                      const double          dt,
                                      StressState<dim>     &state) const
  {
    Tensor<2, 3>             gradient = to_three_dimensions(velocity_gradient);
    const ArrayView<double> &internal = state.internal_variables;
    double *const            separation =
      can_separate() ? &internal[internal.size() - 1] : nullptr;
    // A compression first closes the separation, without stress.
    const double volumetric = dt * trace(gradient);
    if (separation != nullptr && *separation > 0. && volumetric < 0.)
      {
        const double closed = std::min(*separation, -volumetric);
        *separation -= closed;
        gradient +=
          Tensor<2, 3>((closed / (3. * dt)) * unit_symmetric_tensor<3>());
      }
    SymmetricTensor<2, 3> stress =
      elastic_trial_stress(to_three_dimensions(state), gradient, dt);
    const double trial_trace = trace(stress);
    // With softening, the return sees the softening strain (the strength's
    // variable) in the plastic strain's place; the plastic strain takes the
    // same increment.
    const bool   softening      = softens();
    const double plastic_strain = internal[0];
    const double strength_strain =
      softening ? internal[softening_variable()] : plastic_strain;
    internal[0] = strength_strain;
    return_map(stress, internal);
    if (softening)
      {
        const double updated           = internal[0];
        internal[softening_variable()] = updated;
        if (strength_strain != plastic_strain)
          internal[0] = plastic_strain + (updated - strength_strain);
      }
    // Returned to the apex: the volumetric plastic strain of the return is
    // the separation taken in this step.
    if (separation != nullptr && is_separated(stress, strength_strain))
      *separation += (trial_trace - trace(stress)) /
                     (3. * this->lambda_lame + 2. * this->mu_lame);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        state.stress[i][j] = stress[i][j];
    state.out_of_plane_stress = (dim < 3) ? stress[2][2] : 0.;
  }



  template <int dim>
  double
  PlasticMaterial<dim>::equivalent_plastic_strain(
    const ArrayView<const double> &internal_variables) const
  {
    return internal_variables[0];
  }



  template <int dim>
  bool
  PlasticMaterial<dim>::is_plastic() const
  {
    return true;
  }



  template <int dim>
  bool
  PlasticMaterial<dim>::can_lose_contact() const
  {
    return can_separate();
  }



  template <int dim>
  bool
  PlasticMaterial<dim>::is_disconnected(
    const ArrayView<const double> &internal_variables) const
  {
    return can_separate() &&
           internal_variables[internal_variables.size() - 1] > 0.;
  }



  template <int dim>
  std::string
  PlasticMaterial<dim>::to_text(const double value)
  {
    std::ostringstream text;
    text << std::setprecision(6) << value;
    return text.str();
  }



  template <int dim>
  void
  PlasticMaterial<dim>::declare_frictional_parameters(
    ParameterHandler  &prm,
    const std::string &plastic_potential,
    const std::string &cut_off)
  {
    prm.declare_entry("Friction angle",
                      "30",
                      Patterns::Double(0., 90.),
                      "Friction angle phi (degrees), in [0, 90).");
    prm.declare_entry("Dilatancy angle",
                      "0",
                      Patterns::Double(0., 90.),
                      "Dilatancy angle psi (degrees), in [0, phi]: the "
                      "plastic potential is " +
                        plastic_potential + ".");
    prm.declare_entry("Cohesion",
                      "0",
                      Patterns::Double(),
                      "Cohesion c (Pa), >= 0.");
    prm.declare_entry("Tension cut-off",
                      "apex",
                      Patterns::Anything(),
                      "Largest admissible " + cut_off +
                        " (Pa, stresses positive in tension), in [0, c "
                        "cot(phi)]; the word 'apex' (default) puts it at "
                        "the apex c cot(phi) of the yield surface, i.e. no "
                        "cut-off besides the apex (none at all for phi = "
                        "0). With softening, 'apex' follows the softened "
                        "apex, and a number is lowered to it where it lies "
                        "above.");
    prm.declare_entry(
      "Softening strains",
      "",
      Patterns::Anything(),
      "Strain softening: 'eps_1, eps_2', two values of the equivalent plastic "
      "strain (the internal variable plastic_strain), 0 <= eps_1 < eps_2. The "
      "friction angle, dilatancy angle and cohesion keep their (peak) values "
      "up to eps_1, take their residual values from eps_2 on and are linear "
      "in between (evaluated with the point's strain at the start of each "
      "step). Empty (default): no softening. The results then depend on the "
      "cell size (manual, 'Materials').");
    prm.declare_entry("Residual friction angle",
                      "",
                      Patterns::Anything(),
                      "With Softening strains: the residual friction angle "
                      "(degrees, at most the friction angle). Empty: the "
                      "friction angle.");
    prm.declare_entry("Residual dilatancy angle",
                      "",
                      Patterns::Anything(),
                      "With Softening strains: the residual dilatancy angle "
                      "(degrees, at most the dilatancy angle and the "
                      "residual friction angle). Empty: the dilatancy "
                      "angle.");
    prm.declare_entry("Residual cohesion",
                      "",
                      Patterns::Anything(),
                      "With Softening strains: the residual cohesion (Pa, "
                      "at most the cohesion). Empty: the cohesion.");
  }



  template <int dim>
  bool
  PlasticMaterial<dim>::FrictionalParameters::softens() const
  {
    return std::isfinite(softening_start);
  }



  template <int dim>
  typename PlasticMaterial<dim>::FrictionalParameters
  PlasticMaterial<dim>::FrictionalParameters::at(
    const double plastic_strain) const
  {
    FrictionalParameters result;
    const double         fraction =
      !softens() || plastic_strain <= softening_start ?
                0. :
              plastic_strain >= softening_end ?
                1. :
                (plastic_strain - softening_start) / (softening_end - softening_start);
    result.friction_angle =
      friction_angle + fraction * (residual_friction_angle - friction_angle);
    result.dilatancy_angle =
      dilatancy_angle + fraction * (residual_dilatancy_angle - dilatancy_angle);
    result.cohesion = cohesion + fraction * (residual_cohesion - cohesion);
    result.residual_friction_angle  = result.friction_angle;
    result.residual_dilatancy_angle = result.dilatancy_angle;
    result.residual_cohesion        = result.cohesion;
    return result;
  }



  template <int dim>
  typename PlasticMaterial<dim>::FrictionalParameters
  PlasticMaterial<dim>::FrictionalParameters::reduced(const double factor) const
  {
    const auto angle = [factor](const double phi) {
      return std::atan(std::tan(phi) / factor);
    };
    FrictionalParameters result     = *this;
    result.friction_angle           = angle(friction_angle);
    result.dilatancy_angle          = angle(dilatancy_angle);
    result.cohesion                 = cohesion / factor;
    result.residual_friction_angle  = angle(residual_friction_angle);
    result.residual_dilatancy_angle = angle(residual_dilatancy_angle);
    result.residual_cohesion        = residual_cohesion / factor;
    return result;
  }



  template <int dim>
  typename PlasticMaterial<dim>::FrictionalParameters
  PlasticMaterial<dim>::parse_frictional_parameters(
    ParameterHandler  &prm,
    const std::string &model) const
  {
    const double phi_degrees = prm.get_double("Friction angle");
    const double psi_degrees = prm.get_double("Dilatancy angle");
    const double c           = prm.get_double("Cohesion");
    AssertThrow(phi_degrees >= 0. && phi_degrees < 90.,
                ExcMessage(this->entry_name(model + "/Friction angle") +
                           " must lie in [0, 90) degrees (here " +
                           to_text(phi_degrees) + ")."));
    AssertThrow(psi_degrees >= 0. && psi_degrees <= phi_degrees,
                ExcMessage(
                  this->entry_name(model + "/Dilatancy angle") +
                  " must lie in [0, Friction angle = " + to_text(phi_degrees) +
                  "] degrees (here " + to_text(psi_degrees) + ")."));
    AssertThrow(c >= 0. && std::isfinite(c),
                ExcMessage(this->entry_name(model + "/Cohesion") +
                           " must be >= 0 (here " + to_text(c) + " Pa)."));
    AssertThrow(phi_degrees > 0. || c > 0.,
                ExcMessage(this->entry_name(model + "/Cohesion") +
                           " = 0 with Friction angle = 0 leaves the material "
                           "no strength at all: give a cohesion or a friction "
                           "angle above 0."));
    FrictionalParameters parameters;
    parameters.friction_angle  = phi_degrees * M_PI / 180.;
    parameters.dilatancy_angle = psi_degrees * M_PI / 180.;
    parameters.cohesion        = c;

    // Strain softening: the residual values, each the peak one if empty.
    const auto number = [&](const std::string &entry,
                            const double       peak,
                            const std::string &unit) {
      const std::string text = Utilities::trim(prm.get(entry));
      if (text.empty())
        return peak;
      double value = 0;
      try
        {
          value = Utilities::string_to_double(text);
        }
      catch (...)
        {
          AssertThrow(false,
                      ExcMessage(this->entry_name(model + "/" + entry) +
                                 " must be a number (" + unit +
                                 ") or empty; here it is <" + text + ">."));
        }
      AssertThrow(std::isfinite(value) && value >= 0. && value <= peak,
                  ExcMessage(this->entry_name(model + "/" + entry) +
                             " must lie in [0, " + to_text(peak) + "] " + unit +
                             ", at most the peak value (here " +
                             to_text(value) + ")."));
      return value;
    };
    const double phi_residual =
      number("Residual friction angle", phi_degrees, "degrees");
    const double psi_residual =
      number("Residual dilatancy angle", psi_degrees, "degrees");
    const double c_residual = number("Residual cohesion", c, "Pa");
    AssertThrow(phi_residual > 0. || c_residual > 0.,
                ExcMessage(this->entry_name(model + "/Residual cohesion") +
                           " = 0 with a residual friction angle of 0 leaves "
                           "the softened material no strength at all: give a "
                           "residual cohesion or friction angle above 0."));
    AssertThrow(psi_residual <= phi_residual,
                ExcMessage(
                  this->entry_name(model + "/Residual dilatancy angle") +
                  " must not exceed the residual friction angle " +
                  to_text(phi_residual) + " degrees (here " +
                  to_text(psi_residual) + ")."));
    parameters.residual_friction_angle  = phi_residual * M_PI / 180.;
    parameters.residual_dilatancy_angle = psi_residual * M_PI / 180.;
    parameters.residual_cohesion        = c_residual;
    const std::string strains = Utilities::trim(prm.get("Softening strains"));
    const bool        residual_differs = phi_residual != phi_degrees ||
                                  psi_residual != psi_degrees ||
                                  c_residual != c;
    if (strains.empty())
      {
        AssertThrow(!residual_differs,
                    ExcMessage(
                      "Residual values of " + this->entry_name(model) +
                      " are given, but no " +
                      this->entry_name(model + "/Softening strains") +
                      ": give 'eps_1, eps_2', the equivalent plastic strains "
                      "between which the strengths soften."));
      }
    else
      {
        const std::string message =
          this->entry_name(model + "/Softening strains") +
          " must be two equivalent plastic strains 'eps_1, eps_2' with "
          "0 <= eps_1 < eps_2; here it is <" +
          strains + ">.";
        std::vector<double> values;
        try
          {
            values = Utilities::string_to_double(
              Utilities::split_string_list(strains, ','));
          }
        catch (...)
          {
            AssertThrow(false, ExcMessage(message));
          }
        AssertThrow(values.size() == 2 && std::isfinite(values[0]) &&
                      std::isfinite(values[1]) && values[0] >= 0. &&
                      values[0] < values[1],
                    ExcMessage(message));
        parameters.softening_start = values[0];
        parameters.softening_end   = values[1];
      }
    return parameters;
  }



  template <int dim>
  double
  PlasticMaterial<dim>::parse_tension_cut_off(
    ParameterHandler  &prm,
    const std::string &entry,
    const double       apex,
    const std::string &apex_text) const
  {
    const std::string text = Utilities::trim(prm.get("Tension cut-off"));
    if (text == "apex")
      return std::numeric_limits<double>::infinity();
    const std::string allowed =
      " must be the word 'apex' or a number of Pa >= 0" +
      (std::isfinite(apex) ?
         " and <= " + to_text(apex) + " (" + apex_text + ")" :
         std::string()) +
      "; here it is <" + text + ">.";
    double value = 0;
    try
      {
        value = Utilities::string_to_double(text);
      }
    catch (...)
      {
        AssertThrow(false, ExcMessage(this->entry_name(entry) + allowed));
      }
    // A value above the apex by round-off only (a relative 1e-12, e.g. the
    // apex computed elsewhere from c and phi) counts as the apex.
    AssertThrow(value >= 0 && std::isfinite(value) &&
                  !(value > apex * (1. + 1e-12)),
                ExcMessage(this->entry_name(entry) + allowed));
    return std::min(value, apex);
  }



  template class PlasticMaterial<1>;
  template class PlasticMaterial<2>;
  template class PlasticMaterial<3>;
} // namespace MpmOtm
