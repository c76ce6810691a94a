#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/mohr_coulomb.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace MpmOtm
{
  namespace
  {
    double
    dot(const std::array<double, 3> &a, const std::array<double, 3> &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }



    /**
     * The principal values of a stress for which z is a principal direction
     * (every point of a 2D, plane-strain model), in closed form from its
     * in-plane 2 x 2 block.
     */
    struct PlanePrincipalValues
    {
      /// sorted by decreasing value
      std::array<double, 3> values;
      /// which of (in-plane first, in-plane second, z) each value is
      std::array<unsigned int, 3> source;
      /// (s_xx - s_yy) / 2 and the radius of Mohr's circle
      double half_difference;
      double radius;
    };

    PlanePrincipalValues
    plane_principal_values(const SymmetricTensor<2, 3> &stress)
    {
      PlanePrincipalValues result;
      const double         centre = 0.5 * (stress[0][0] + stress[1][1]);
      result.half_difference      = 0.5 * (stress[0][0] - stress[1][1]);
      result.radius =
        std::sqrt(result.half_difference * result.half_difference +
                  stress[0][1] * stress[0][1]);
      result.values = {
        {centre + result.radius, centre - result.radius, stress[2][2]}};
      result.source = {{0, 1, 2}};
      if (result.values[2] > result.values[1])
        {
          std::swap(result.values[1], result.values[2]);
          std::swap(result.source[1], result.source[2]);
        }
      if (result.values[1] > result.values[0])
        {
          std::swap(result.values[0], result.values[1]);
          std::swap(result.source[0], result.source[1]);
        }
      return result;
    }
  } // namespace



  template <int dim>
  void
  MohrCoulomb<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mohr-Coulomb");
    PlasticMaterial<dim>::declare_frictional_parameters(
      prm,
      "(sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin(psi)",
      "principal stress sigma_t");
    prm.leave_subsection();
  }



  template <int dim>
  void
  MohrCoulomb<dim>::parse_parameters(ParameterHandler &prm)
  {
    Material<dim>::parse_parameters(prm);
    prm.enter_subsection("Mohr-Coulomb");
    strength = this->parse_frictional_parameters(prm, "Mohr-Coulomb");
    const double apex =
      (strength.friction_angle > 0.) ?
        strength.cohesion / std::tan(strength.friction_angle) :
        std::numeric_limits<double>::infinity();
    requested_cut_off =
      this->parse_tension_cut_off(prm,
                                  "Mohr-Coulomb/Tension cut-off",
                                  apex,
                                  "the apex c cot(phi)");
    prm.leave_subsection();
    peak     = make_surface(strength);
    residual = make_surface(strength.at(strength.softening_end));
  }



  template <int dim>
  void
  MohrCoulomb<dim>::reduce_strength(const double factor)
  {
    strength = strength.reduced(factor);
    peak     = make_surface(strength);
    residual = make_surface(strength.at(strength.softening_end));
  }



  template <int dim>
  typename MohrCoulomb<dim>::Surface
  MohrCoulomb<dim>::make_surface(
    const typename PlasticMaterial<dim>::FrictionalParameters &strength) const
  {
    Surface surface;
    surface.sin_phi      = std::sin(strength.friction_angle);
    surface.cos_phi      = std::cos(strength.friction_angle);
    surface.sin_psi      = std::sin(strength.dilatancy_angle);
    surface.c            = strength.cohesion;
    surface.apex_stress  = (strength.friction_angle > 0.) ?
                             surface.c * surface.cos_phi / surface.sin_phi :
                             std::numeric_limits<double>::infinity();
    surface.sigma_t      = std::min(requested_cut_off, surface.apex_stress);
    surface.with_cut_off = surface.sigma_t < surface.apex_stress;

    for (unsigned int i = 0; i < surface.planes.size(); ++i)
      surface.planes[i] = make_plane(surface, i);
    unsigned int n   = 0;
    const auto   add = [&](const std::array<unsigned int, 3> &active,
                         const unsigned int                 n_active,
                         const Return                       type) {
      surface.candidates[n++] = make_candidate(surface, active, n_active, type);
    };
    add({{0, 0, 0}}, 1, Return::plane);
    add({{0, 1, 0}}, 2, Return::right_edge);
    add({{0, 2, 0}}, 2, Return::left_edge);
    if (surface.with_cut_off)
      {
        add({{3, 0, 0}}, 1, Return::cut_off);
        add({{3, 4, 0}}, 2, Return::cut_off_edge);
        add({{0, 3, 0}}, 2, Return::plane_and_cut_off);
        add({{0, 1, 3}}, 3, Return::right_edge_and_cut_off);
        // The four planes through the corner of the left edge and the
        // cut-off, three at a time (their flow vectors span the same cone).
        for (const std::array<unsigned int, 3> corner :
             {std::array<unsigned int, 3>{{0, 2, 3}},
              std::array<unsigned int, 3>{{0, 3, 4}},
              std::array<unsigned int, 3>{{2, 3, 4}},
              std::array<unsigned int, 3>{{0, 2, 4}}})
          add(corner, 3, Return::left_edge_and_cut_off);
        add({{3, 4, 5}}, 3, Return::cut_off_apex);
      }
    surface.n_candidates = n;
    return surface;
  }



  template <int dim>
  const typename MohrCoulomb<dim>::Surface &
  MohrCoulomb<dim>::surface_at(const double plastic_strain,
                               Surface     &buffer) const
  {
    if (!(plastic_strain > strength.softening_start))
      return peak;
    if (plastic_strain >= strength.softening_end)
      return residual;
    buffer = make_surface(strength.at(plastic_strain));
    return buffer;
  }



  template <int dim>
  typename MohrCoulomb<dim>::Plane
  MohrCoulomb<dim>::make_plane(const Surface     &surface,
                               const unsigned int i) const
  {
    const double sp = surface.sin_phi, ss = surface.sin_psi,
                 r = 2. * surface.c * surface.cos_phi;
    switch (i)
      {
        case 0:
          return {{{1. + sp, 0., -(1. - sp)}}, {{1. + ss, 0., -(1. - ss)}}, r};
        case 1:
          return {{{1. + sp, -(1. - sp), 0.}}, {{1. + ss, -(1. - ss), 0.}}, r};
        case 2:
          return {{{0., 1. + sp, -(1. - sp)}}, {{0., 1. + ss, -(1. - ss)}}, r};
        default:
          {
            std::array<double, 3> e{{0., 0., 0.}};
            e[i - 3] = 1.;
            return {e, e, surface.sigma_t};
          }
      }
  }



  template <int dim>
  double
  MohrCoulomb<dim>::yield_function(
    const std::array<double, 3> &principal_stresses) const
  {
    return dot(peak.planes[0].a, principal_stresses) - peak.planes[0].r;
  }



  template <int dim>
  typename MohrCoulomb<dim>::Candidate
  MohrCoulomb<dim>::make_candidate(const Surface                     &surface,
                                   const std::array<unsigned int, 3> &active,
                                   const unsigned int                 n_active,
                                   const Return type) const
  {
    const auto  &planes = surface.planes;
    const double G      = this->mu_lame;
    const double lambda = this->lambda_lame;
    Candidate    candidate;
    candidate.planes   = active;
    candidate.n_planes = n_active;
    candidate.type     = type;
    candidate.inverse  = {};
    candidate.flow     = {};
    // flow_j = D n_j with D = lambda 1 1^T + 2 G I (principal space);
    // M_ij = a_i . flow_j, so that M d gamma = f(trial).
    double M[3][3];
    for (unsigned int j = 0; j < n_active; ++j)
      {
        const Plane &plane = planes[active[j]];
        const double trace = plane.n[0] + plane.n[1] + plane.n[2];
        for (unsigned int k = 0; k < 3; ++k)
          candidate.flow[j][k] = 2. * G * plane.n[k] + lambda * trace;
      }
    double largest = 0;
    for (unsigned int i = 0; i < n_active; ++i)
      for (unsigned int j = 0; j < n_active; ++j)
        {
          M[i][j]                 = dot(planes[active[i]].a, candidate.flow[j]);
          largest                 = std::max(largest, std::abs(M[i][j]));
          candidate.inverse[i][j] = (i == j) ? 1. : 0.;
        }
    // Gauss-Jordan elimination with partial pivoting; a pivot below 1e-12
    // of the largest entry marks planes without a common return.
    candidate.solvable = true;
    for (unsigned int k = 0; k < n_active; ++k)
      {
        unsigned int pivot = k;
        for (unsigned int i = k + 1; i < n_active; ++i)
          if (std::abs(M[i][k]) > std::abs(M[pivot][k]))
            pivot = i;
        if (!(std::abs(M[pivot][k]) > 1e-12 * largest))
          {
            candidate.solvable = false;
            return candidate;
          }
        std::swap(M[k], M[pivot]);
        std::swap(candidate.inverse[k], candidate.inverse[pivot]);
        const double scale = 1. / M[k][k];
        for (unsigned int j = 0; j < n_active; ++j)
          {
            M[k][j] *= scale;
            candidate.inverse[k][j] *= scale;
          }
        for (unsigned int i = 0; i < n_active; ++i)
          if (i != k)
            {
              const double factor = M[i][k];
              for (unsigned int j = 0; j < n_active; ++j)
                {
                  M[i][j] -= factor * M[k][j];
                  candidate.inverse[i][j] -= factor * candidate.inverse[k][j];
                }
            }
      }
    return candidate;
  }



  template <int dim>
  bool
  MohrCoulomb<dim>::try_return(
    const Surface               &surface,
    const Candidate             &candidate,
    const std::array<double, 3> &trial,
    const double                 tolerance,
    std::array<double, 3>       &result,
    std::array<double, 3>       &plastic_strain_increment) const
  {
    if (!candidate.solvable)
      return false;
    const auto        &planes   = surface.planes;
    const unsigned int n_active = candidate.n_planes;
    double             violation[3];
    for (unsigned int i = 0; i < n_active; ++i)
      {
        const Plane &plane = planes[candidate.planes[i]];
        violation[i]       = dot(plane.a, trial) - plane.r;
      }
    double dgamma[3];
    for (unsigned int i = 0; i < n_active; ++i)
      {
        dgamma[i] = 0.;
        for (unsigned int j = 0; j < n_active; ++j)
          dgamma[i] += candidate.inverse[i][j] * violation[j];
        if (dgamma[i] < -tolerance / this->mu_lame)
          return false;
      }

    result                   = trial;
    plastic_strain_increment = {{0., 0., 0.}};
    for (unsigned int j = 0; j < n_active; ++j)
      {
        const Plane &plane = planes[candidate.planes[j]];
        for (unsigned int k = 0; k < 3; ++k)
          {
            result[k] -= dgamma[j] * candidate.flow[j][k];
            plastic_strain_increment[k] += dgamma[j] * plane.n[k];
          }
      }
    // Admissible: every plane, and the order of the principal stresses.
    for (unsigned int i = 0; i < (surface.with_cut_off ? 6u : 3u); ++i)
      if (dot(planes[i].a, result) - planes[i].r > tolerance)
        return false;
    return result[0] >= result[1] - tolerance &&
           result[1] >= result[2] - tolerance;
  }



  template <int dim>
  typename MohrCoulomb<dim>::Return
  MohrCoulomb<dim>::return_principal_stresses(
    std::array<double, 3> &principal_stresses,
    double                &plastic_strain) const
  {
    Surface buffer;
    return return_to(surface_at(plastic_strain, buffer),
                     principal_stresses,
                     plastic_strain);
  }



  template <int dim>
  typename MohrCoulomb<dim>::Return
  MohrCoulomb<dim>::return_to(const Surface         &surface,
                              std::array<double, 3> &principal_stresses,
                              double                &plastic_strain) const
  {
    const double               &c            = surface.c;
    const double               &sin_phi      = surface.sin_phi;
    const double               &sin_psi      = surface.sin_psi;
    const double               &sigma_t      = surface.sigma_t;
    const bool                 &with_cut_off = surface.with_cut_off;
    const double               &apex_stress  = surface.apex_stress;
    const std::array<double, 3> trial        = principal_stresses;
    if (!(dot(surface.planes[0].a, trial) - surface.planes[0].r > 0.) &&
        !(with_cut_off && trial[0] > sigma_t))
      return Return::elastic;

    // Results are accepted with violations of 1e-12 of the stresses'
    // magnitude (round-off of the 3 x 3 solves is far below).
    double scale = std::max({std::abs(trial[0]), std::abs(trial[2]), c});
    if (with_cut_off)
      scale = std::max(scale, std::abs(sigma_t));
    const double tolerance =
      1e-12 * std::max(scale, std::numeric_limits<double>::min());

    // With psi = 0 and no cut-off, the returns to the planes and edges keep
    // the mean stress (their flow vectors have no trace), and no admissible
    // stress has a mean stress above the apex: a trial beyond it can only
    // return to the apex, and the candidates are skipped.
    const bool beyond_apex = !with_cut_off && sin_psi == 0. &&
                             trial[0] + trial[1] + trial[2] > 3. * apex_stress;
    std::array<double, 3> plastic_strain_increment;
    if (!beyond_apex)
      {
        // de Souza Neto's choice of the edge to try first: the right edge is
        // candidates[1], the left edge candidates[2].
        const bool right_first = (1. - sin_psi) * trial[0] - 2. * trial[1] +
                                   (1. + sin_psi) * trial[2] >=
                                 0.;
        for (unsigned int i = 0; i < surface.n_candidates; ++i)
          {
            const Candidate &candidate =
              surface.candidates[(right_first || i == 0 || i > 2) ? i : 3 - i];
            if (try_return(surface,
                           candidate,
                           trial,
                           tolerance,
                           principal_stresses,
                           plastic_strain_increment))
              {
                plastic_strain += std::sqrt(
                  2. / 3. *
                  dot(plastic_strain_increment, plastic_strain_increment));
                return candidate.type;
              }
          }
      }

    // No return to planes, edges or corners: the apex of the pyramid (de
    // Souza Neto), or that of the cut-off, with the elastic strain removed as
    // plastic strain, C^-1 (trial - apex).
    AssertThrow(with_cut_off || sin_phi > 0.,
                ExcMessage("Mohr-Coulomb return mapping: no return found for "
                           "the Tresca prism (phi = 0), which cannot happen."));
    const double vertex = with_cut_off ? sigma_t : apex_stress;
    const double G      = this->mu_lame;
    const double lambda = this->lambda_lame;
    const double volumetric =
      (trial[0] + trial[1] + trial[2] - 3. * vertex) / (3. * lambda + 2. * G);
    for (unsigned int k = 0; k < 3; ++k)
      {
        plastic_strain_increment[k] =
          (trial[k] - vertex - lambda * volumetric) / (2. * G);
        principal_stresses[k] = vertex;
      }
    plastic_strain += std::sqrt(
      2. / 3. * dot(plastic_strain_increment, plastic_strain_increment));
    return with_cut_off ? Return::cut_off_apex : Return::apex;
  }



  template <int dim>
  typename MohrCoulomb<dim>::Return
  MohrCoulomb<dim>::return_stress(SymmetricTensor<2, 3> &stress,
                                  double                &plastic_strain) const
  {
    Surface        buffer;
    const Surface &surface = surface_at(plastic_strain, buffer);
    // The principal stresses first (sorted by decreasing value): most
    // points are elastic or return to the apex, where the eigenvectors are
    // not needed.
    const auto hydrostatic = [&](const std::array<double, 3> &principal) {
      if (principal[0] != principal[1] || principal[1] != principal[2])
        return false;
      stress = principal[0] * unit_symmetric_tensor<3>();
      return true;
    };
    if (stress[0][2] != 0. || stress[1][2] != 0.)
      {
        const std::array<double, 3> trial     = eigenvalues(stress);
        std::array<double, 3>       principal = trial;
        const Return type = return_to(surface, principal, plastic_strain);
        if (type == Return::elastic || hydrostatic(principal))
          return type;
        // sigma = sum_i sigma_i v_i v_i^T with the trial's eigenvectors,
        // written as a correction of the trial stress.
        const auto eigen = eigenvectors(stress);
        for (unsigned int i = 0; i < 3; ++i)
          stress += (principal[i] - trial[i]) *
                    symmetrize(outer_product(eigen[i].second, eigen[i].second));
        return type;
      }

    // Plane strain: z is a principal direction, and the in-plane ones
    // follow in closed form.
    const PlanePrincipalValues trial     = plane_principal_values(stress);
    std::array<double, 3>      principal = trial.values;
    const Return type = return_to(surface, principal, plastic_strain);
    if (type == Return::elastic || hydrostatic(principal))
      return type;
    double change[3];
    for (unsigned int i = 0; i < 3; ++i)
      change[trial.source[i]] = principal[i] - trial.values[i];
    // The projector onto the first in-plane direction,
    // P = (S - sigma_second I) / (sigma_first - sigma_second) of the in-plane
    // block S (the x axis if the two are equal); the second's is I - P.
    const double p_xx = (trial.radius > 0.) ?
                          0.5 + 0.5 * trial.half_difference / trial.radius :
                          1.;
    const double p_xy =
      (trial.radius > 0.) ? 0.5 * stress[0][1] / trial.radius : 0.;
    stress[0][0] += change[0] * p_xx + change[1] * (1. - p_xx);
    stress[1][1] += change[0] * (1. - p_xx) + change[1] * p_xx;
    stress[0][1] += (change[0] - change[1]) * p_xy;
    stress[2][2] += change[2];
    return type;
  }



  template <int dim>
  void
  MohrCoulomb<dim>::return_map(
    SymmetricTensor<2, 3>   &stress,
    const ArrayView<double> &internal_variables) const
  {
    return_stress(stress, internal_variables[0]);
  }



  template <int dim>
  bool
  MohrCoulomb<dim>::can_separate() const
  {
    return std::isfinite(peak.sigma_t) || std::isfinite(residual.sigma_t);
  }



  template <int dim>
  bool
  MohrCoulomb<dim>::is_separated(const SymmetricTensor<2, 3> &stress,
                                 const double plastic_strain) const
  {
    // The vertex of the surface the return used: sigma_t is the apex
    // without a cut-off.
    double vertex = peak.sigma_t;
    if (plastic_strain >= strength.softening_end)
      vertex = residual.sigma_t;
    else if (plastic_strain > strength.softening_start)
      {
        const auto now = strength.at(plastic_strain);
        vertex         = std::min(requested_cut_off,
                          (now.friction_angle > 0.) ?
                                    now.cohesion / std::tan(now.friction_angle) :
                                    std::numeric_limits<double>::infinity());
      }
    return this->is_hydrostatic_at(stress, vertex);
  }



  template <int dim>
  bool
  MohrCoulomb<dim>::softens() const
  {
    return strength.softens();
  }



  template <int dim>
  double
  MohrCoulomb<dim>::friction_angle() const
  {
    return strength.friction_angle;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::dilatancy_angle() const
  {
    return strength.dilatancy_angle;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::cohesion() const
  {
    return strength.cohesion;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::tension_cut_off() const
  {
    return peak.sigma_t;
  }



  template class MohrCoulomb<1>;
  template class MohrCoulomb<2>;
  template class MohrCoulomb<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<1>,
  MpmOtm::MohrCoulomb<1>,
  "Mohr-Coulomb",
  "Mohr-Coulomb, non-associated, principal-stress return with a tension "
  "cut-off")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<2>,
  MpmOtm::MohrCoulomb<2>,
  "Mohr-Coulomb",
  "Mohr-Coulomb, non-associated, principal-stress return with a tension "
  "cut-off")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Material<3>,
  MpmOtm::MohrCoulomb<3>,
  "Mohr-Coulomb",
  "Mohr-Coulomb, non-associated, principal-stress return with a tension "
  "cut-off")
