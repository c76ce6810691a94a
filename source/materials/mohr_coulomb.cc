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
     * The principal values of @p stress, sorted by decreasing value: in
     * closed form from the in-plane 2 x 2 block when z is a principal
     * direction (every point of a 2D, plane-strain model), else deal.II's
     * eigenvalues().
     */
    std::array<double, 3>
    principal_values(const SymmetricTensor<2, 3> &stress)
    {
      if (stress[0][2] != 0. || stress[1][2] != 0.)
        return eigenvalues(stress);
      const double centre    = 0.5 * (stress[0][0] + stress[1][1]);
      const double half_diff = 0.5 * (stress[0][0] - stress[1][1]);
      const double radius =
        std::sqrt(half_diff * half_diff + stress[0][1] * stress[0][1]);
      std::array<double, 3> values{
        {centre + radius, centre - radius, stress[2][2]}};
      if (values[2] > values[1])
        std::swap(values[1], values[2]);
      if (values[1] > values[0])
        std::swap(values[0], values[1]);
      return values;
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
    const auto parameters =
      this->parse_frictional_parameters(prm, "Mohr-Coulomb");
    phi          = parameters.friction_angle;
    psi          = parameters.dilatancy_angle;
    c            = parameters.cohesion;
    sin_phi      = std::sin(phi);
    cos_phi      = std::cos(phi);
    sin_psi      = std::sin(psi);
    apex_stress  = (phi > 0.) ? c * cos_phi / sin_phi :
                                std::numeric_limits<double>::infinity();
    sigma_t      = this->parse_tension_cut_off(prm,
                                          "Mohr-Coulomb/Tension cut-off",
                                          apex_stress,
                                          "the apex c cot(phi)");
    with_cut_off = sigma_t < apex_stress;
    prm.leave_subsection();
  }



  template <int dim>
  typename MohrCoulomb<dim>::Plane
  MohrCoulomb<dim>::plane(const unsigned int i) const
  {
    const double sp = sin_phi, ss = sin_psi, r = 2. * c * cos_phi;
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
            return {e, e, sigma_t};
          }
      }
  }



  template <int dim>
  double
  MohrCoulomb<dim>::yield_function(
    const std::array<double, 3> &principal_stresses) const
  {
    const Plane main = plane(0);
    return dot(main.a, principal_stresses) - main.r;
  }



  template <int dim>
  bool
  MohrCoulomb<dim>::try_return(
    const unsigned int          *active,
    const unsigned int           n_active,
    const std::array<double, 3> &trial,
    const double                 tolerance,
    std::array<double, 3>       &result,
    std::array<double, 3>       &plastic_strain_increment) const
  {
    const double G      = this->mu_lame;
    const double lambda = this->lambda_lame;
    // M_ij = a_i . D n_j with D = lambda 1 1^T + 2 G I (principal space);
    // M d gamma = f(trial).
    Plane                 planes[3];
    std::array<double, 3> flow[3];
    double                M[3][3], rhs[3];
    for (unsigned int i = 0; i < n_active; ++i)
      {
        planes[i]       = plane(active[i]);
        const double tr = planes[i].n[0] + planes[i].n[1] + planes[i].n[2];
        for (unsigned int k = 0; k < 3; ++k)
          flow[i][k] = 2. * G * planes[i].n[k] + lambda * tr;
        rhs[i] = dot(planes[i].a, trial) - planes[i].r;
      }
    double largest = 0;
    for (unsigned int i = 0; i < n_active; ++i)
      for (unsigned int j = 0; j < n_active; ++j)
        {
          M[i][j] = dot(planes[i].a, flow[j]);
          largest = std::max(largest, std::abs(M[i][j]));
        }
    // Gaussian elimination with partial pivoting.
    unsigned int row[3] = {0, 1, 2};
    for (unsigned int k = 0; k < n_active; ++k)
      {
        unsigned int pivot = k;
        for (unsigned int i = k + 1; i < n_active; ++i)
          if (std::abs(M[row[i]][k]) > std::abs(M[row[pivot]][k]))
            pivot = i;
        std::swap(row[k], row[pivot]);
        if (!(std::abs(M[row[k]][k]) > 1e-12 * largest))
          return false;
        for (unsigned int i = k + 1; i < n_active; ++i)
          {
            const double factor = M[row[i]][k] / M[row[k]][k];
            for (unsigned int j = k; j < n_active; ++j)
              M[row[i]][j] -= factor * M[row[k]][j];
            rhs[row[i]] -= factor * rhs[row[k]];
          }
      }
    double dgamma[3];
    for (unsigned int k = n_active; k-- > 0;)
      {
        double sum = rhs[row[k]];
        for (unsigned int j = k + 1; j < n_active; ++j)
          sum -= M[row[k]][j] * dgamma[j];
        dgamma[k] = sum / M[row[k]][k];
        if (dgamma[k] < -tolerance / G)
          return false;
      }

    result                   = trial;
    plastic_strain_increment = {{0., 0., 0.}};
    for (unsigned int j = 0; j < n_active; ++j)
      for (unsigned int k = 0; k < 3; ++k)
        {
          result[k] -= dgamma[j] * flow[j][k];
          plastic_strain_increment[k] += dgamma[j] * planes[j].n[k];
        }
    // Admissible: every plane, and the order of the principal stresses.
    for (unsigned int i = 0; i < (with_cut_off ? 6u : 3u); ++i)
      {
        const Plane other = plane(i);
        if (dot(other.a, result) - other.r > tolerance)
          return false;
      }
    return result[0] >= result[1] - tolerance &&
           result[1] >= result[2] - tolerance;
  }



  template <int dim>
  typename MohrCoulomb<dim>::Return
  MohrCoulomb<dim>::return_principal_stresses(
    std::array<double, 3> &principal_stresses,
    double                &plastic_strain) const
  {
    const std::array<double, 3> trial = principal_stresses;
    if (!(yield_function(trial) > 0.) && !(with_cut_off && trial[0] > sigma_t))
      return Return::elastic;

    // Results are accepted with violations of 1e-12 of the stresses'
    // magnitude (round-off of the 3 x 3 solves is far below).
    double scale = std::max({std::abs(trial[0]), std::abs(trial[2]), c});
    if (with_cut_off)
      scale = std::max(scale, std::abs(sigma_t));
    const double tolerance =
      1e-12 * std::max(scale, std::numeric_limits<double>::min());

    struct Candidate
    {
      unsigned int planes[3];
      unsigned int n_planes;
      Return       type;
    };
    // de Souza Neto's choice of the edge to try first.
    const bool right_first =
      (1. - sin_psi) * trial[0] - 2. * trial[1] + (1. + sin_psi) * trial[2] >=
      0.;
    const Candidate right{{0, 1, 0}, 2, Return::right_edge};
    const Candidate left{{0, 2, 0}, 2, Return::left_edge};
    const Candidate candidates[] = {
      {{0, 0, 0}, 1, Return::plane},
      right_first ? right : left,
      right_first ? left : right,
      // With the cut-off only:
      {{3, 0, 0}, 1, Return::cut_off},
      {{3, 4, 0}, 2, Return::cut_off_edge},
      {{0, 3, 0}, 2, Return::plane_and_cut_off},
      {{0, 1, 3}, 3, Return::right_edge_and_cut_off},
      // The four planes through the corner of the left edge and the cut-off,
      // three at a time (their flow vectors span the same cone).
      {{0, 2, 3}, 3, Return::left_edge_and_cut_off},
      {{0, 3, 4}, 3, Return::left_edge_and_cut_off},
      {{2, 3, 4}, 3, Return::left_edge_and_cut_off},
      {{0, 2, 4}, 3, Return::left_edge_and_cut_off},
      {{3, 4, 5}, 3, Return::cut_off_apex}};
    const unsigned int n_candidates = with_cut_off ? 12 : 3;

    std::array<double, 3> plastic_strain_increment;
    for (unsigned int i = 0; i < n_candidates; ++i)
      if (try_return(candidates[i].planes,
                     candidates[i].n_planes,
                     trial,
                     tolerance,
                     principal_stresses,
                     plastic_strain_increment))
        {
          plastic_strain += std::sqrt(
            2. / 3. * dot(plastic_strain_increment, plastic_strain_increment));
          return candidates[i].type;
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
    // The principal stresses first (closed form, sorted by decreasing
    // value): most points are elastic or return to the apex, where the
    // eigenvectors are not needed.
    const std::array<double, 3> trial     = principal_values(stress);
    std::array<double, 3>       principal = trial;
    const Return type = return_principal_stresses(principal, plastic_strain);
    if (type == Return::elastic)
      return type;
    if (principal[0] == principal[1] && principal[1] == principal[2])
      {
        stress = principal[0] * unit_symmetric_tensor<3>();
        return type;
      }
    // sigma = sum_i sigma_i v_i v_i^T with the trial's eigenvectors, written
    // as a correction of the trial stress.
    std::array<Tensor<1, 3>, 3> directions;
    if (stress[0][2] == 0. && stress[1][2] == 0.)
      {
        // Plane strain: z is a principal direction, the in-plane ones
        // follow from the 2 x 2 block in closed form.
        const double angle =
          0.5 * std::atan2(2. * stress[0][1], stress[0][0] - stress[1][1]);
        Tensor<1, 3> first, second, z;
        first[0]  = std::cos(angle);
        first[1]  = std::sin(angle);
        second[0] = -first[1];
        second[1] = first[0];
        z[2]      = 1.;
        // Match each direction to its principal stress.
        const double s_first  = first * (stress * first);
        const double s_second = second * (stress * second);
        const std::array<std::pair<double, Tensor<1, 3>>, 3> pairs{
          {{s_first, first}, {s_second, second}, {stress[2][2], z}}};
        std::array<unsigned int, 3> order{{0, 1, 2}};
        std::sort(order.begin(),
                  order.end(),
                  [&](const unsigned int a, const unsigned int b) {
                    return pairs[a].first > pairs[b].first;
                  });
        for (unsigned int i = 0; i < 3; ++i)
          directions[i] = pairs[order[i]].second;
      }
    else
      {
        const auto eigen = eigenvectors(stress);
        for (unsigned int i = 0; i < 3; ++i)
          directions[i] = eigen[i].second;
      }
    for (unsigned int i = 0; i < 3; ++i)
      stress += (principal[i] - trial[i]) *
                symmetrize(outer_product(directions[i], directions[i]));
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
    return std::isfinite((with_cut_off ? sigma_t : apex_stress));
  }



  template <int dim>
  bool
  MohrCoulomb<dim>::is_separated(const SymmetricTensor<2, 3> &stress) const
  {
    const double vertex    = (with_cut_off ? sigma_t : apex_stress);
    const double tolerance = 1e-12 * this->young;
    return std::isfinite(vertex) &&
           std::abs(trace(stress) / 3. - vertex) <= tolerance &&
           deviator(stress).norm() <= tolerance;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::friction_angle() const
  {
    return phi;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::dilatancy_angle() const
  {
    return psi;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::cohesion() const
  {
    return c;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::tension_cut_off() const
  {
    return sigma_t;
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
