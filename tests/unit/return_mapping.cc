// The return mappings of the elasto-plastic models (von Mises, Drucker-Prager,
// Mohr-Coulomb) on three-dimensional trial stresses, against closed forms:
// - trial stresses built backwards from a chosen returned stress and chosen
//   plastic multipliers of a chosen return (trial = sigma + sum_j d gamma_j
//   D : n_j with the flow vectors n_j of the active surfaces), so that the
//   exact answer of the return is known: the returned stress, the region,
//   the principal directions and the plastic strain increment
//   sqrt(2/3) |sum_j d gamma_j n_j|; the Mohr-Coulomb ones are also checked
//   against de Souza Neto et al. (2008)'s closed-form plane and edge
//   returns;
// - many pseudo-random trial stresses outside the surface in several
//   regions: the returned stress lies on the surface, for associated flow it
//   is the closest admissible stress in the energy norm (checked through the
//   variational inequality against many admissible stresses), keeps the
//   trial's principal directions, and for Mohr-Coulomb without cut-off
//   equals the result of de Souza Neto's algorithm written out here;
// - trial stresses inside: returned unchanged, bit for bit, no plastic
//   strain; elastic unloading from a returned state stays elastic.
//
// Tolerances: every check compares quantities computed with O(10-100)
// floating-point operations on numbers of the size of the trial stress, so
// stresses are compared to 1e-12 of the stress scale (the size of the trial
// stress), and so are the yield functions (tighter than the 1e-10 the
// models must reach);
// multipliers and plastic strains, which are differences of stresses divided
// by the moduli, to 1e-10 relatively (the multipliers used are such that
// G d gamma is at least 1e-3 of the stress scale).

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/drucker_prager.h>
#include <mpm_otm/materials/mohr_coulomb.h>
#include <mpm_otm/materials/von_mises.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  using Entries = std::vector<std::pair<std::string, std::string>>;

  // E = 1000, nu = 0.3: G = 1000 / 2.6, K = 1000 / 1.2.
  constexpr double E      = 1000.;
  constexpr double nu     = 0.3;
  const double     G      = E / (2. * (1. + nu));
  const double     K      = E / (3. * (1. - 2. * nu));
  const double     lambda = K - 2. / 3. * G;

  /**
   * A three-dimensional material @p model with the entries @p entries of its
   * subsection, made as the material library makes it.
   */
  template <typename Model>
  std::unique_ptr<Model>
  make_model(const std::string &model, const Entries &entries)
  {
    ParameterHandler prm;
    Material<3>::declare_common_parameters(
      prm,
      PluginRegistry<Material<3>>::selection(),
      "");
    PluginRegistry<Material<3>>::declare_parameters(prm);
    prm.set("Model", model);
    prm.set("Young's modulus", E);
    prm.set("Poisson's ratio", nu);
    prm.enter_subsection(model);
    for (const auto &entry : entries)
      prm.set(entry.first, entry.second);
    prm.leave_subsection();
    auto   material = PluginRegistry<Material<3>>::create(model);
    Model *result   = dynamic_cast<Model *>(material.get());
    check(result != nullptr, model + ": wrong class");
    material.release();
    result->parse_parameters(prm);
    return std::unique_ptr<Model>(result);
  }

  /**
   * Deterministic pseudo-random numbers: the raw output of std::mt19937 is
   * fixed by the standard (the distributions are not).
   */
  class Random
  {
  public:
    explicit Random(const unsigned int seed)
      : generator(seed)
    {}

    double
    uniform(const double a, const double b)
    {
      return a + (b - a) * (generator() / 4294967296.);
    }

  private:
    std::mt19937 generator;
  };

  /**
   * A rotation from a random unit quaternion.
   */
  Tensor<2, 3>
  random_rotation(Random &random)
  {
    double q[4], norm = 0;
    do
      {
        norm = 0;
        for (double &x : q)
          {
            x = random.uniform(-1., 1.);
            norm += x * x;
          }
    } while (norm > 1. || norm < 1e-2);
    for (double &x : q)
      x /= std::sqrt(norm);
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    Tensor<2, 3> R;
    R[0][0] = 1 - 2 * (y * y + z * z);
    R[0][1] = 2 * (x * y - z * w);
    R[0][2] = 2 * (x * z + y * w);
    R[1][0] = 2 * (x * y + z * w);
    R[1][1] = 1 - 2 * (x * x + z * z);
    R[1][2] = 2 * (y * z - x * w);
    R[2][0] = 2 * (x * z - y * w);
    R[2][1] = 2 * (y * z + x * w);
    R[2][2] = 1 - 2 * (x * x + y * y);
    return R;
  }

  /**
   * sum_i principal[i] q_i q_i^T with q_i the columns of @p Q.
   */
  SymmetricTensor<2, 3>
  from_principal(const std::array<double, 3> &principal, const Tensor<2, 3> &Q)
  {
    SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          result[i][j] += principal[k] * Q[i][k] * Q[j][k];
    return result;
  }

  std::array<double, 3>
  sorted_eigenvalues(const SymmetricTensor<2, 3> &stress)
  {
    const auto pairs =
      eigenvectors(stress, SymmetricTensorEigenvectorMethod::jacobi);
    return {{pairs[0].first, pairs[1].first, pairs[2].first}};
  }

  double
  norm(const std::array<double, 3> &a)
  {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  }

  /**
   * D n in principal space: 2 G n + lambda tr(n) (1, 1, 1).
   */
  std::array<double, 3>
  elastic(const std::array<double, 3> &n)
  {
    const double tr = n[0] + n[1] + n[2];
    return {{2. * G * n[0] + lambda * tr,
             2. * G * n[1] + lambda * tr,
             2. * G * n[2] + lambda * tr}};
  }

  /**
   * C^-1 s in principal space (the elastic strain of the stress s).
   */
  std::array<double, 3>
  compliance(const std::array<double, 3> &s)
  {
    const double          tr = s[0] + s[1] + s[2];
    std::array<double, 3> e;
    for (unsigned int k = 0; k < 3; ++k)
      e[k] = (s[k] - lambda / (3. * K) * tr) / (2. * G);
    return e;
  }

  /**
   * a + sum_j c_j b_j.
   */
  std::array<double, 3>
  combine(std::array<double, 3>                                        a,
          const std::vector<std::pair<double, std::array<double, 3>>> &terms)
  {
    for (const auto &term : terms)
      for (unsigned int k = 0; k < 3; ++k)
        a[k] += term.first * term.second[k];
    return a;
  }

  double
  difference(const std::array<double, 3> &a, const std::array<double, 3> &b)
  {
    return std::max(
      {std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
  }

  double
  scale_of(const SymmetricTensor<2, 3> &stress)
  {
    return std::max(stress.norm(), 1.);
  }

  // ---------------------------------------------------------------------
  // von Mises
  // ---------------------------------------------------------------------

  void
  test_von_mises()
  {
    // sigma_y = 1, H = 100.
    const auto   model   = make_model<VonMises<3>>("von Mises",
                                               {{"Yield stress", "1"},
                                                    {"Hardening modulus", "100"}});
    const double sigma_y = 1., H = 100.;

    // Hand computation: uniaxial trial diag(3, 0, 0) at eps_p = 0:
    // q^tr = 3, d gamma = (3 - 1) / (3 G + H), s = (1 - 3 G d gamma / 3) s^tr,
    // p = 1: sigma_xx = 1 + 2 (1 - G d gamma), sigma_yy = 1 - (1 - G d gamma).
    {
      SymmetricTensor<2, 3> stress;
      stress[0][0]                  = 3.;
      std::vector<double> variables = {0.};
      model->return_map(stress, make_array_view(variables));
      const double dgamma = 2. / (3. * G + H);
      const double factor = 1. - G * dgamma;
      check(std::abs(stress[0][0] - (1. + 2. * factor)) < 1e-14 &&
              std::abs(stress[1][1] - (1. - factor)) < 1e-14 &&
              std::abs(stress[2][2] - (1. - factor)) < 1e-14 &&
              std::abs(stress[0][1]) < 1e-15,
            "von Mises: uniaxial trial against the hand computation");
      check(std::abs(variables[0] - dgamma) < 1e-17,
            "von Mises: uniaxial trial, plastic strain = d gamma");
      deallog << "von Mises, trial diag(3, 0, 0): sigma_xx = "
              << rounded(stress[0][0], 9)
              << ", eps_p = " << rounded(variables[0], 9) << std::endl;
    }

    Random       random(1);
    unsigned int n_outside = 0, n_inside = 0;
    for (unsigned int i = 0; i < 2000; ++i)
      {
        const double eps_0 = random.uniform(0., 0.05);
        const double yield = sigma_y + H * eps_0;
        // A deviator direction with sqrt(3/2 s:s) = 1, a mean stress, and
        // q^tr either in (1.001, 30) yield or in (0, 0.999) yield.
        std::array<double, 3> d{{random.uniform(-1, 1),
                                 random.uniform(-1, 1),
                                 random.uniform(-1, 1)}};
        const double          mean = (d[0] + d[1] + d[2]) / 3.;
        for (double &x : d)
          x -= mean;
        const SymmetricTensor<2, 3> direction =
          from_principal(d, random_rotation(random));
        const SymmetricTensor<2, 3> s_hat =
          direction / std::sqrt(1.5 * (direction * direction));
        const bool   outside = (i % 4 != 0);
        const double q_trial = outside ? random.uniform(1.001, 30.) * yield :
                                         random.uniform(0., 0.999) * yield;
        const double p       = random.uniform(-50., 50.);
        const SymmetricTensor<2, 3> trial =
          p * unit_symmetric_tensor<3>() + q_trial * s_hat;

        SymmetricTensor<2, 3> stress    = trial;
        std::vector<double>   variables = {eps_0};
        model->return_map(stress, make_array_view(variables));
        if (!outside)
          {
            check(stress == trial && variables[0] == eps_0,
                  "von Mises: a trial inside must be kept exactly");
            ++n_inside;
            continue;
          }
        ++n_outside;
        const double scale = scale_of(trial);
        // Box 7.3, linear hardening: d gamma = f^tr / (3 G + H), radial.
        const double                dgamma   = (q_trial - yield) / (3. * G + H);
        const SymmetricTensor<2, 3> expected = trial - 3. * G * dgamma * s_hat;
        check((stress - expected).norm() < 1e-12 * scale,
              "von Mises: radial return against the closed form");
        check(std::abs(model->yield_function(stress, variables[0])) <
                1e-12 * scale,
              "von Mises: returned stress not on the yield surface");
        // sqrt(2/3) |d eps^p| with d eps^p = dev(trial - sigma) / (2 G).
        const SymmetricTensor<2, 3> plastic =
          deviator(trial - stress) / (2. * G);
        check(std::abs(variables[0] - eps_0 - dgamma) < 1e-10 * dgamma &&
                std::abs(std::sqrt(2. / 3.) * plastic.norm() - dgamma) <
                  1e-10 * dgamma,
              "von Mises: plastic strain increment");

        // Elastic unloading from the returned state: a trial moved towards
        // the hydrostatic p I, strictly inside, is kept.
        const SymmetricTensor<2, 3> unloaded =
          stress +
          random.uniform(0.01, 1.) * (p * unit_symmetric_tensor<3>() - stress);
        SymmetricTensor<2, 3> again = unloaded;
        const double          eps_n = variables[0];
        model->return_map(again, make_array_view(variables));
        check(again == unloaded && variables[0] == eps_n,
              "von Mises: unloading must stay elastic");
      }
    deallog << "von Mises: " << n_outside << " trials outside returned, "
            << n_inside << " inside kept" << std::endl;
  }

  // ---------------------------------------------------------------------
  // Drucker-Prager
  // ---------------------------------------------------------------------

  /**
   * A random deviator direction s_hat with sqrt(J2(s_hat)) = 1.
   */
  SymmetricTensor<2, 3>
  random_unit_deviator(Random &random)
  {
    std::array<double, 3> d{
      {random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)}};
    const double mean = (d[0] + d[1] + d[2]) / 3.;
    for (double &x : d)
      x -= mean;
    const SymmetricTensor<2, 3> s = from_principal(d, random_rotation(random));
    return s / std::sqrt(0.5 * (s * s));
  }

  /**
   * max(f, p - p_t): zero on the boundary of the admissible set.
   */
  double
  drucker_prager_boundary(const DruckerPrager<3>      &model,
                          const SymmetricTensor<2, 3> &stress)
  {
    return std::max(model.yield_function(stress),
                    trace(stress) / 3. - model.tension_cut_off());
  }

  void
  test_drucker_prager()
  {
    using Return = DruckerPrager<3>::Return;
    // phi = 30, psi = 10 degrees, c = 1, plane-strain cone, cut-off p_t =
    // 0.8 below the apex c cot(30) = 1.732.
    const auto model =
      make_model<DruckerPrager<3>>("Drucker-Prager",
                                   {{"Friction angle", "30"},
                                    {"Dilatancy angle", "10"},
                                    {"Cohesion", "1"},
                                    {"Tension cut-off", "0.8"}});
    const double alpha = model->alpha(), alpha_psi = model->alpha_psi(),
                 k = model->k(), p_t = 0.8;
    // Hand values: alpha = 3 tan 30 / sqrt(9 + 12 tan^2 30) = sqrt(3/13),
    // k = 3 / sqrt(13); alpha_psi with tan 10 degrees.
    const double t10 = std::tan(10. * M_PI / 180.);
    check(std::abs(alpha - std::sqrt(3. / 13.)) < 1e-15 &&
            std::abs(k - 3. / std::sqrt(13.)) < 1e-15 &&
            std::abs(alpha_psi - 3. * t10 / std::sqrt(9. + 12. * t10 * t10)) <
              1e-15,
          "Drucker-Prager: plane-strain cone coefficients");

    // Trials built backwards from the returned stress and the multipliers
    // d gamma (cone) and d gamma_t (cut-off): D : dg/dsigma = G s_hat +
    // K alpha_psi I (s_hat = s / sqrt(J2)), D : I / 3 = K I.
    Random                     random(2);
    std::map<std::string, int> counts;
    const double               r_t = k - alpha * p_t; // corner radius
    for (unsigned int i = 0; i < 600; ++i)
      {
        const SymmetricTensor<2, 3> s_hat = random_unit_deviator(random);
        const SymmetricTensor<2, 3> I     = unit_symmetric_tensor<3>();
        double                      p = 0, tau = 0, dgamma = 0, dgamma_t = 0;
        Return                      expected;
        std::string                 name;
        switch (i % 3)
          {
            case 0:
              p        = random.uniform(-30., p_t - 1e-3);
              tau      = k - alpha * p;
              dgamma   = random.uniform(0.002, 0.05);
              expected = Return::cone;
              name     = "cone";
              break;
            case 1:
              p        = p_t;
              tau      = random.uniform(0., r_t * 0.999);
              dgamma_t = random.uniform(0.002, 0.05);
              expected = Return::cut_off;
              name     = "cut-off";
              break;
            default:
              p        = p_t;
              tau      = r_t;
              dgamma   = random.uniform(0.002, 0.05);
              dgamma_t = random.uniform(0.002, 0.05);
              expected = Return::corner;
              name     = "corner";
          }
        const SymmetricTensor<2, 3> sigma = p * I + tau * s_hat;
        const SymmetricTensor<2, 3> trial =
          sigma + dgamma * (G * s_hat + K * alpha_psi * I) + dgamma_t * K * I;
        SymmetricTensor<2, 3> stress = trial;
        double                eps    = 0.;
        const Return          type   = model->return_stress(stress, eps);
        const double          scale  = scale_of(trial);
        check(type == expected, "Drucker-Prager: " + name + " trial, region");
        check((stress - sigma).norm() < 1e-12 * scale,
              "Drucker-Prager: " + name + " trial, returned stress");
        check(std::abs(drucker_prager_boundary(*model, stress)) < 1e-12 * scale,
              "Drucker-Prager: " + name + " trial, not on the boundary");
        // d eps^p = d gamma (s_hat / 2 + alpha_psi I / 3) + d gamma_t I / 3:
        // |.|^2 = d gamma^2 / 2 + (alpha_psi d gamma + d gamma_t)^2 / 3.
        const double volumetric   = alpha_psi * dgamma + dgamma_t;
        const double expected_eps = std::sqrt(
          2. / 3. * (0.5 * dgamma * dgamma + volumetric * volumetric / 3.));
        check(std::abs(eps - expected_eps) < 1e-10 * expected_eps,
              "Drucker-Prager: " + name + " trial, plastic strain");
        ++counts[name];

        // Unloading from the returned state towards (p_t - 5) I, strictly
        // inside (the admissible set is convex): elastic.
        const SymmetricTensor<2, 3> unloaded =
          stress + random.uniform(0.01, 1.) * ((p_t - 5.) * I - stress);
        SymmetricTensor<2, 3> again = unloaded;
        double                eps_2 = 0.;
        check(model->return_stress(again, eps_2) == Return::elastic &&
                again == unloaded && eps_2 == 0.,
              "Drucker-Prager: unloading must stay elastic");
      }
    deallog << "Drucker-Prager, trials built from the return: cone "
            << counts["cone"] << ", cut-off " << counts["cut-off"]
            << ", corner " << counts["corner"] << std::endl;

    // Random trials in a box of (p, sqrt(J2)) that covers all regions: on
    // the boundary after the return; inside kept exactly.
    std::map<Return, int> regions;
    for (unsigned int i = 0; i < 3000; ++i)
      {
        const SymmetricTensor<2, 3> trial =
          random.uniform(-20., 20.) * unit_symmetric_tensor<3>() +
          random.uniform(0., 20.) * random_unit_deviator(random);
        SymmetricTensor<2, 3> stress = trial;
        double                eps    = 0.;
        const Return          type   = model->return_stress(stress, eps);
        ++regions[type];
        if (drucker_prager_boundary(*model, trial) <= 0.)
          check(type == Return::elastic && stress == trial && eps == 0.,
                "Drucker-Prager: a trial inside must be kept exactly");
        else
          check(std::abs(drucker_prager_boundary(*model, stress)) <
                    1e-12 * scale_of(trial) &&
                  eps > 0.,
                "Drucker-Prager: random trial not returned to the boundary");
      }
    check(regions.size() == 4, "Drucker-Prager: random trials miss a region");
    deallog << "Drucker-Prager, random trials: elastic "
            << regions[Return::elastic] << ", cone " << regions[Return::cone]
            << ", cut-off " << regions[Return::cut_off] << ", corner "
            << regions[Return::corner] << std::endl;

    // A hydrostatic trial far beyond the cut-off: p_t I (a trial with a
    // deviator keeps it up to the corner radius k - alpha p_t, see the
    // cut-off trials above).
    {
      SymmetricTensor<2, 3> stress = 100. * unit_symmetric_tensor<3>();
      double                eps    = 0.;
      check(model->return_stress(stress, eps) == Return::cut_off &&
              (stress - p_t * unit_symmetric_tensor<3>()).norm() < 1e-12 * 100.,
            "Drucker-Prager: far beyond the cut-off, hydrostatic p_t");
      // d eps^p = (100 - p_t) / (3 K) I: sqrt(2/3) |.| = sqrt(2) (100 - p_t)
      // / (3 K).
      check(std::abs(eps - std::sqrt(2.) * (100. - p_t) / (3. * K)) <
              1e-12 * eps,
            "Drucker-Prager: cut-off return, plastic strain");
    }

    // The apex return (default cut-off, the apex c cot(phi)), for psi = 10
    // and for psi = 0 (whose cone return could never reach the apex): a
    // trial far beyond the apex returns to the hydrostatic c cot(phi) I
    // with zero deviator, and the plastic strain is the elastic strain
    // removed, dev(trial) / (2 G) + (p^tr - apex) / (3 K) I.
    for (const std::string psi : {"10", "0"})
      {
        const auto apex_model =
          make_model<DruckerPrager<3>>("Drucker-Prager",
                                       {{"Friction angle", "30"},
                                        {"Dilatancy angle", psi},
                                        {"Cohesion", "1"}});
        const double apex = 1. / std::tan(M_PI / 6.);
        check(std::abs(apex_model->tension_cut_off() - apex) < 1e-14,
              "Drucker-Prager: default cut-off at the apex");
        const SymmetricTensor<2, 3> trial =
          50. * unit_symmetric_tensor<3>() + 2. * random_unit_deviator(random);
        SymmetricTensor<2, 3> stress = trial;
        double                eps    = 0.;
        check(apex_model->return_stress(stress, eps) == Return::corner,
              "Drucker-Prager: apex return expected");
        check((stress - apex * unit_symmetric_tensor<3>()).norm() <
                  1e-12 * 50. &&
                deviator(stress).norm() < 1e-12 * 50.,
              "Drucker-Prager: apex return must give c cot(phi) I");
        const SymmetricTensor<2, 3> plastic =
          deviator(trial) / (2. * G) +
          (trace(trial) / 3. - apex) / (3. * K) * unit_symmetric_tensor<3>();
        check(std::abs(eps - std::sqrt(2. / 3.) * plastic.norm()) < 1e-10 * eps,
              "Drucker-Prager: apex return, plastic strain");
        deallog << "Drucker-Prager apex return, psi = " << psi
                << ": p = " << rounded(trace(stress) / 3., 9) << ", deviator 0"
                << std::endl;
      }

    // phi = 0, c = 1: a von Mises cylinder sqrt(J2) = k = c (plane strain),
    // 2 c / sqrt(3) (outer); the return keeps p, no apex, no NaN.
    for (const std::string cone : {"plane strain", "outer"})
      {
        const auto cylinder = make_model<DruckerPrager<3>>(
          "Drucker-Prager",
          {{"Friction angle", "0"}, {"Cohesion", "1"}, {"Cone", cone}});
        const double radius = (cone == "outer") ? 2. / std::sqrt(3.) : 1.;
        check(std::abs(cylinder->k() - radius) < 1e-15 &&
                cylinder->alpha() == 0. &&
                !std::isfinite(cylinder->tension_cut_off()),
              "Drucker-Prager, phi = 0: cylinder of radius k = c");
        for (unsigned int i = 0; i < 200; ++i)
          {
            const SymmetricTensor<2, 3> s_hat = random_unit_deviator(random);
            const double                p     = random.uniform(-1e3, 1e3);
            const SymmetricTensor<2, 3> trial =
              p * unit_symmetric_tensor<3>() +
              random.uniform(1.01, 100.) * radius * s_hat;
            SymmetricTensor<2, 3> stress = trial;
            double                eps    = 0.;
            check(cylinder->return_stress(stress, eps) == Return::cone,
                  "Drucker-Prager, phi = 0: cone return expected");
            const SymmetricTensor<2, 3> expected =
              p * unit_symmetric_tensor<3>() + radius * s_hat;
            check((stress - expected).norm() < 1e-12 * scale_of(trial),
                  "Drucker-Prager, phi = 0: radial return to sqrt(J2) = k");
          }
      }
    deallog << "Drucker-Prager, phi = 0: radial returns to sqrt(J2) = k"
            << std::endl;
  }

  // ---------------------------------------------------------------------
  // Mohr-Coulomb
  // ---------------------------------------------------------------------

  struct MohrCoulombCase
  {
    std::string                                           name;
    MohrCoulomb<3>::Return                                expected;
    std::array<double, 3>                                 sigma;
    std::vector<std::pair<double, std::array<double, 3>>> flows;
  };

  std::string
  name_of(const MohrCoulomb<3>::Return type)
  {
    using Return = MohrCoulomb<3>::Return;
    switch (type)
      {
        case Return::elastic:
          return "elastic";
        case Return::plane:
          return "plane";
        case Return::right_edge:
          return "right edge";
        case Return::left_edge:
          return "left edge";
        case Return::apex:
          return "apex";
        case Return::cut_off:
          return "cut-off";
        case Return::cut_off_edge:
          return "cut-off edge";
        case Return::plane_and_cut_off:
          return "plane and cut-off";
        case Return::right_edge_and_cut_off:
          return "right edge and cut-off";
        case Return::left_edge_and_cut_off:
          return "left edge and cut-off";
        default:
          return "cut-off apex";
      }
  }

  /**
   * max(f, sigma_1 - sigma_t) of the sorted principal stresses @p s (the
   * largest Mohr-Coulomb plane is the one of sigma_1 and sigma_3).
   */
  double
  mohr_coulomb_boundary(const MohrCoulomb<3>        &model,
                        const std::array<double, 3> &s)
  {
    return std::max(model.yield_function(s), s[0] - model.tension_cut_off());
  }

  /**
   * Run @p test: trial = sigma + sum_j d gamma_j D n_j, rotated by a random
   * rotation; check region, returned stress (in the trial's principal
   * directions) and plastic strain sqrt(2/3) |sum_j d gamma_j n_j|.
   */
  void
  check_mohr_coulomb_case(const MohrCoulomb<3>  &model,
                          const MohrCoulombCase &test,
                          Random                &random)
  {
    std::array<double, 3> trial = test.sigma, plastic = {{0., 0., 0.}};
    for (const auto &flow : test.flows)
      {
        trial   = combine(trial, {{flow.first, elastic(flow.second)}});
        plastic = combine(plastic, {{flow.first, flow.second}});
      }
    check(trial[0] >= trial[1] && trial[1] >= trial[2],
          "Mohr-Coulomb: " + test.name + ": trial not sorted (test setup)");
    const Tensor<2, 3>           Q      = random_rotation(random);
    SymmetricTensor<2, 3>        stress = from_principal(trial, Q);
    const double                 scale  = scale_of(stress);
    double                       eps    = 0.;
    const MohrCoulomb<3>::Return type   = model.return_stress(stress, eps);
    check(type == test.expected, "Mohr-Coulomb: " + test.name + ": region");
    check((stress - from_principal(test.sigma, Q)).norm() < 1e-12 * scale,
          "Mohr-Coulomb: " + test.name +
            ": returned stress (principal values or directions) wrong");
    check(std::abs(mohr_coulomb_boundary(model, sorted_eigenvalues(stress))) <
            1e-12 * scale,
          "Mohr-Coulomb: " + test.name + ": not on the boundary");
    const double expected_eps = std::sqrt(2. / 3.) * norm(plastic);
    check(std::abs(eps - expected_eps) < 1e-10 * expected_eps,
          "Mohr-Coulomb: " + test.name + ": plastic strain increment");

    // Unloading from the returned state towards -5 I, strictly inside (the
    // admissible set is convex), stays elastic.
    const SymmetricTensor<2, 3> unloaded =
      stress +
      random.uniform(0.01, 1.) * (-5. * unit_symmetric_tensor<3>() - stress);
    SymmetricTensor<2, 3> again = unloaded;
    double                eps_2 = 0.;
    check(model.return_stress(again, eps_2) ==
              MohrCoulomb<3>::Return::elastic &&
            again == unloaded && eps_2 == 0.,
          "Mohr-Coulomb: " + test.name + ": unloading must stay elastic");
  }

  void
  test_mohr_coulomb_regions()
  {
    using Return = MohrCoulomb<3>::Return;
    // phi = 30, psi = 10 degrees, c = 1; apex c cot(30) = sqrt(3).
    const double                sp = 0.5, cp = std::sqrt(3.) / 2., c = 1.;
    const double                ss   = std::sin(10. * M_PI / 180.);
    const double                apex = c * cp / sp;
    const std::array<double, 3> n13{{1. + ss, 0., -(1. - ss)}},
      n12{{1. + ss, -(1. - ss), 0.}}, n23{{0., 1. + ss, -(1. - ss)}},
      e1{{1., 0., 0.}}, e2{{0., 1., 0.}}, e3{{0., 0., 1.}};
    // sigma_3 on the main plane for a given sigma_1, and vice versa.
    const auto sigma_3_of = [&](const double s1) {
      return (s1 * (1. + sp) - 2. * c * cp) / (1. - sp);
    };
    const auto sigma_1_of = [&](const double s3) {
      return (2. * c * cp + s3 * (1. - sp)) / (1. + sp);
    };
    Random random(3);

    {
      const auto model = make_model<MohrCoulomb<3>>("Mohr-Coulomb",
                                                    {{"Friction angle", "30"},
                                                     {"Dilatancy angle", "10"},
                                                     {"Cohesion", "1"}});
      check(std::abs(model->friction_angle() - M_PI / 6.) < 1e-15 &&
              std::abs(model->tension_cut_off() - apex) < 1e-14,
            "Mohr-Coulomb: friction angle, default cut-off at the apex");
      // de Souza Neto's constants (Sect. 8.2.2): a (main plane), b of the
      // right and the left edge.
      const double a = 4. * G * (1. + sp * ss / 3.) + 4. * K * sp * ss;
      const double b_right =
        2. * G * (1. + sp + ss - sp * ss / 3.) + 4. * K * sp * ss;
      const double b_left =
        2. * G * (1. - sp - ss - sp * ss / 3.) + 4. * K * sp * ss;
      const auto phi_of = [&](const double x, const double y) {
        return (x - y) + (x + y) * sp - 2. * c * cp;
      };
      std::map<std::string, int> counts;
      for (unsigned int i = 0; i < 400; ++i)
        {
          MohrCoulombCase test;
          const double    ga = random.uniform(0.002, 0.05);
          const double    gb = random.uniform(0.002, 0.05);
          switch (i % 4)
            {
              case 0:
                {
                  const double s1 = random.uniform(apex - 30., apex - 0.1);
                  const double s3 = sigma_3_of(s1);
                  test            = {"plane",
                                     Return::plane,
                                     {{s1, s3 + random.uniform(0.1, 0.9) * (s1 - s3), s3}},
                                     {{ga, n13}}};
                  break;
                }
              case 1:
                {
                  // Right edge: sigma_2 = sigma_3; d gamma_a >= d gamma_b
                  // keeps the trial sorted (t_2 - t_3 = 2 G (1 - sin psi)
                  // (d gamma_a - d gamma_b)).
                  const double s3 = random.uniform(apex - 30., apex - 0.1);
                  test            = {"right edge",
                                     Return::right_edge,
                                     {{sigma_1_of(s3), s3, s3}},
                                     {{std::max(ga, gb), n13}, {std::min(ga, gb), n12}}};
                  break;
                }
              case 2:
                {
                  // Left edge: sigma_1 = sigma_2; d gamma_a >= d gamma_b
                  // (t_1 - t_2 = 2 G (1 + sin psi) (d gamma_a - d gamma_b)).
                  const double s1 = random.uniform(apex - 30., apex - 0.1);
                  test            = {"left edge",
                                     Return::left_edge,
                                     {{s1, s1, sigma_3_of(s1)}},
                                     {{std::max(ga, gb), n13}, {std::min(ga, gb), n23}}};
                  break;
                }
              default:
                {
                  // Apex: a trial far on the tensile side with a small
                  // deviator; the plastic strain is the elastic strain
                  // removed, C^-1 (trial - apex).
                  const double          p = apex + random.uniform(5., 50.);
                  std::array<double, 3> trial{{p + random.uniform(0.5, 1.),
                                               p,
                                               p - random.uniform(0.5, 1.)}};
                  const std::array<double, 3> removed =
                    compliance(combine(trial, {{-1., {{apex, apex, apex}}}}));
                  test = {"apex",
                          Return::apex,
                          {{apex, apex, apex}},
                          {{1., removed}}};
                  // The flows are plastic strains here: trial = apex +
                  // D removed.
                }
            }
          check_mohr_coulomb_case(*model, test, random);
          ++counts[test.name];

          // The closed forms of de Souza Neto for the plane and the edges.
          std::array<double, 3> t = test.sigma;
          for (const auto &flow : test.flows)
            t = combine(t, {{flow.first, elastic(flow.second)}});
          std::array<double, 3> book;
          if (test.expected == Return::plane)
            {
              const double dgamma = phi_of(t[0], t[2]) / a;
              check(std::abs(dgamma - ga) < 1e-10 * ga,
                    "Mohr-Coulomb: plane, d gamma = f / a");
              book = {
                {t[0] - (2. * G * (1. + ss / 3.) + 2. * K * ss) * dgamma,
                 t[1] + (4. * G / 3. - 2. * K) * ss * dgamma,
                 t[2] + (2. * G * (1. - ss / 3.) - 2. * K * ss) * dgamma}};
            }
          else if (test.expected == Return::right_edge ||
                   test.expected == Return::left_edge)
            {
              const bool   right = (test.expected == Return::right_edge);
              const double b     = right ? b_right : b_left;
              const double fa    = phi_of(t[0], t[2]);
              const double fb = right ? phi_of(t[0], t[1]) : phi_of(t[1], t[2]);
              const double dga = (a * fa - b * fb) / (a * a - b * b);
              const double dgb = (a * fb - b * fa) / (a * a - b * b);
              check(std::abs(dga - test.flows[0].first) < 1e-10 * dga &&
                      std::abs(dgb - test.flows[1].first) < 1e-10 * dgb,
                    "Mohr-Coulomb: edge multipliers from [[a, b], [b, a]]");
              book = combine(t,
                             {{-dga, elastic(n13)},
                              {-dgb, elastic(right ? n12 : n23)}});
              // On both planes: two equal principal stresses.
              check(std::abs(right ? book[1] - book[2] : book[0] - book[1]) <
                      1e-12 * norm(t),
                    "Mohr-Coulomb: edge return with unequal stresses");
            }
          else
            book = {{apex, apex, apex}};
          check(difference(book, test.sigma) < 1e-12 * norm(t),
                "Mohr-Coulomb: " + test.name +
                  ": built trial differs from de Souza Neto's return");
        }
      deallog << "Mohr-Coulomb, trials built from the return: plane "
              << counts["plane"] << ", right edge " << counts["right edge"]
              << ", left edge " << counts["left edge"] << ", apex "
              << counts["apex"] << std::endl;

      // One hand computation: trial (1, 0, -2), psi = 10: the main plane.
      std::array<double, 3> s{{1., 0., -2.}};
      double                eps = 0.;
      check(model->return_principal_stresses(s, eps) == Return::plane,
            "Mohr-Coulomb: trial (1, 0, -2) goes to the main plane");
      const double dgamma = phi_of(1., -2.) / a;
      check(std::abs(s[0] - (1. - (2. * G * (1. + ss / 3.) + 2. * K * ss) *
                                    dgamma)) < 1e-13,
            "Mohr-Coulomb: trial (1, 0, -2), sigma_1");
      deallog << "Mohr-Coulomb, trial (1, 0, -2): " << rounded(s[0], 9) << ' '
              << rounded(s[1], 9) << ' ' << rounded(s[2], 9) << std::endl;
    }

    // With a tension cut-off sigma_t = 0.5 below the apex: the Rankine
    // plane, its edge, its lines and corners with the Mohr-Coulomb planes.
    {
      const double sigma_t = 0.5;
      const auto   model =
        make_model<MohrCoulomb<3>>("Mohr-Coulomb",
                                   {{"Friction angle", "30"},
                                    {"Dilatancy angle", "10"},
                                    {"Cohesion", "1"},
                                    {"Tension cut-off", "0.5"}});
      const double               s3_star = sigma_3_of(sigma_t);
      std::map<std::string, int> counts;
      for (unsigned int i = 0; i < 600; ++i)
        {
          MohrCoulombCase test;
          double          g[4];
          for (double &x : g)
            x = random.uniform(0.002, 0.05);
          std::sort(g, g + 4);
          const double u = random.uniform(0.1, 0.9);
          const double s3 =
            s3_star + random.uniform(0.1, 0.9) * (sigma_t - s3_star);
          switch (i % 6)
            {
              case 0:
                test = {"cut-off",
                        Return::cut_off,
                        {{sigma_t, s3 + u * (sigma_t - s3), s3}},
                        {{g[0], e1}}};
                break;
              case 1:
                test = {"cut-off edge",
                        Return::cut_off_edge,
                        {{sigma_t, sigma_t, s3}},
                        {{g[1], e1}, {g[0], e2}}};
                break;
              case 2:
                test = {"plane and cut-off",
                        Return::plane_and_cut_off,
                        {{sigma_t, s3_star + u * (sigma_t - s3_star), s3_star}},
                        {{g[0], n13}, {g[1], e1}}};
                break;
              case 3:
                test = {"right edge and cut-off",
                        Return::right_edge_and_cut_off,
                        {{sigma_t, s3_star, s3_star}},
                        {{g[1], n13}, {g[0], n12}, {g[2], e1}}};
                break;
              case 4:
                test = {"left edge and cut-off",
                        Return::left_edge_and_cut_off,
                        {{sigma_t, sigma_t, s3_star}},
                        {{g[1], n13}, {g[0], n23}, {g[3], e1}, {g[2], e2}}};
                break;
              default:
                test = {"cut-off apex",
                        Return::cut_off_apex,
                        {{sigma_t, sigma_t, sigma_t}},
                        {{g[2], e1}, {g[1], e2}, {g[0], e3}}};
            }
          check_mohr_coulomb_case(*model, test, random);
          ++counts[test.name];
        }
      std::string text;
      for (const auto &count : counts)
        text += (text.empty() ? " " : ", ") + count.first + ' ' +
                std::to_string(count.second);
      deallog << "Mohr-Coulomb with cut-off, trials built from the return:"
              << text << std::endl;
    }
  }

  /**
   * de Souza Neto et al. (2008)'s return for Mohr-Coulomb without cut-off
   * (Sect. 8.2.2, perfect plasticity), written out independently of the
   * model: main plane if the result keeps the order of the principal
   * stresses (up to round-off); else the edge on the trial's side (right if (1
   * - sin psi) t_1
   * - 2 t_2 + (1 + sin psi) t_3 >= 0) if its result keeps the order; else
   * the apex. @p t: sorted trial principal stresses.
   */
  std::array<double, 3>
  de_souza_neto_return(const std::array<double, 3> &t,
                       const double                 phi,
                       const double                 psi,
                       const double                 c)
  {
    const double sp = std::sin(phi), cp = std::cos(phi), ss = std::sin(psi);
    const double a    = 4. * G * (1. + sp * ss / 3.) + 4. * K * sp * ss;
    const double aux1 = 2. * G * (1. + ss / 3.) + 2. * K * ss;
    const double aux2 = (4. * G / 3. - 2. * K) * ss;
    const double aux3 = 2. * G * (1. - ss / 3.) - 2. * K * ss;
    const auto   f    = [&](const double x, const double y) {
      return (x - y) + (x + y) * sp - 2. * c * cp;
    };
    // In order up to round-off (the edge returns give two equal values).
    const auto sorted = [](const std::array<double, 3> &s) {
      const double delta = 1e-10 * norm(s);
      return s[0] + delta >= s[1] && s[1] + delta >= s[2];
    };
    const double          dgamma = f(t[0], t[2]) / a;
    std::array<double, 3> s{
      {t[0] - aux1 * dgamma, t[1] + aux2 * dgamma, t[2] + aux3 * dgamma}};
    if (sorted(s))
      return s;
    const bool   right = (1. - ss) * t[0] - 2. * t[1] + (1. + ss) * t[2] >= 0.;
    const double b =
      right ? 2. * G * (1. + sp + ss - sp * ss / 3.) + 4. * K * sp * ss :
              2. * G * (1. - sp - ss - sp * ss / 3.) + 4. * K * sp * ss;
    const double fa = f(t[0], t[2]);
    const double fb = right ? f(t[0], t[1]) : f(t[1], t[2]);
    const double ga = (a * fa - b * fb) / (a * a - b * b);
    const double gb = (a * fb - b * fa) / (a * a - b * b);
    if (right)
      s = {{t[0] - aux1 * (ga + gb),
            t[1] + aux2 * ga + aux3 * gb,
            t[2] + aux3 * ga + aux2 * gb}};
    else
      s = {{t[0] - aux1 * ga + aux2 * gb,
            t[1] + aux2 * ga - aux1 * gb,
            t[2] + aux3 * (ga + gb)}};
    if (sorted(s))
      return s;
    const double apex = c * cp / sp;
    return {{apex, apex, apex}};
  }

  /**
   * A rotation by a random angle about the z axis: a trial built with it is
   * a plane-strain stress (z a principal direction), which the model
   * returns with its closed-form in-plane directions.
   */
  Tensor<2, 3>
  random_rotation_about_z(Random &random)
  {
    const double angle = random.uniform(-numbers::PI, numbers::PI);
    Tensor<2, 3> R;
    R[0][0] = R[1][1] = std::cos(angle);
    R[0][1]           = -std::sin(angle);
    R[1][0]           = std::sin(angle);
    R[2][2]           = 1.;
    return R;
  }

  /**
   * Random trials for Mohr-Coulomb with dilatancy @p psi and cut-off
   * @p cut_off, rotated at random in 3D or, if @p plane_strain, about z
   * only (z then holds the largest, middle or smallest principal stress
   * at random): the result is on the boundary and keeps the trial's
   * principal directions; for psi = phi it is the closest admissible stress
   * in the energy norm, i.e. (trial - sigma) : C^-1 : (tau - sigma) <= 0 for
   * every admissible tau (checked for admissible tau with the same
   * eigenvectors, in any order, which suffices for an isotropic set).
   */
  void
  test_mohr_coulomb_random(const std::string &psi,
                           const std::string &cut_off,
                           const bool         plane_strain = false)
  {
    using Return = MohrCoulomb<3>::Return;
    Entries entries{{"Friction angle", "30"},
                    {"Dilatancy angle", psi},
                    {"Cohesion", "1"}};
    if (!cut_off.empty())
      entries.push_back({"Tension cut-off", cut_off});
    const auto model      = make_model<MohrCoulomb<3>>("Mohr-Coulomb", entries);
    const bool associated = (psi == "30");

    // Admissible stresses for the variational inequality.
    Random                             random(4);
    std::vector<std::array<double, 3>> admissible;
    while (admissible.size() < 300)
      {
        std::array<double, 3> tau{{random.uniform(-40., 5.),
                                   random.uniform(-40., 5.),
                                   random.uniform(-40., 5.)}};
        std::array<double, 3> sorted = tau;
        std::sort(sorted.begin(), sorted.end(), std::greater<double>());
        if (mohr_coulomb_boundary(*model, sorted) <= 0.)
          admissible.push_back(tau);
      }

    std::map<Return, int> regions;
    for (unsigned int i = 0; i < 4000; ++i)
      {
        // Principal trial stresses in a box around the apex, some far out
        // on the tensile side.
        const double          spread = (i % 2) ? 10. : 40.;
        std::array<double, 3> t{{random.uniform(-spread, 10.),
                                 random.uniform(-spread, 10.),
                                 random.uniform(-spread, 10.)}};
        const Tensor<2, 3> Q = plane_strain ? random_rotation_about_z(random) :
                                              random_rotation(random);
        const SymmetricTensor<2, 3> trial  = from_principal(t, Q);
        SymmetricTensor<2, 3>       stress = trial;
        double                      eps    = 0.;
        const Return                type   = model->return_stress(stress, eps);
        ++regions[type];
        const double scale = scale_of(trial);
        std::sort(t.begin(), t.end(), std::greater<double>());
        if (mohr_coulomb_boundary(*model, t) <= 0.)
          {
            check(type == Return::elastic && stress == trial && eps == 0.,
                  "Mohr-Coulomb: a trial inside must be kept exactly");
            continue;
          }
        check(std::abs(
                mohr_coulomb_boundary(*model, sorted_eigenvalues(stress))) <
                1e-12 * scale,
              "Mohr-Coulomb: random trial not returned to the boundary");
        // Principal directions kept: the result is diagonal in the trial's
        // eigenvectors, Q^T sigma Q.
        const Tensor<2, 3>    rotated = transpose(Q) * Tensor<2, 3>(stress) * Q;
        std::array<double, 3> s;
        for (unsigned int a = 0; a < 3; ++a)
          {
            s[a] = rotated[a][a];
            for (unsigned int b = 0; b < 3; ++b)
              if (a != b)
                check(std::abs(rotated[a][b]) < 1e-12 * scale,
                      "Mohr-Coulomb: principal directions not kept");
          }
        // The principal trial stresses in the same order as s, and the
        // elastic strain the return removed, C^-1 (trial - sigma).
        const Tensor<2, 3> trial_rotated =
          transpose(Q) * Tensor<2, 3>(trial) * Q;
        std::array<double, 3> trial_principal;
        for (unsigned int a = 0; a < 3; ++a)
          trial_principal[a] = trial_rotated[a][a];
        const std::array<double, 3> removed =
          compliance(combine(trial_principal, {{-1., s}}));
        if (cut_off.empty())
          {
            // The same principal stresses as de Souza Neto's algorithm.
            std::array<double, 3> sorted_s = s;
            std::sort(sorted_s.begin(), sorted_s.end(), std::greater<double>());
            check(difference(sorted_s,
                             de_souza_neto_return(t,
                                                  M_PI / 6.,
                                                  std::stod(psi) * M_PI / 180.,
                                                  1.)) < 1e-12 * scale,
                  "Mohr-Coulomb: differs from de Souza Neto's return");
          }
        if (type == Return::cut_off_apex)
          // A valid return to sigma_t I: the flow vectors there are e_1,
          // e_2, e_3, so the removed strain has no negative principal value.
          check(*std::min_element(removed.begin(), removed.end()) >
                  -1e-12 * norm(removed),
                "Mohr-Coulomb: return to the cut-off apex not valid");
        if (associated)
          {
            for (const auto &tau : admissible)
              {
                const std::array<double, 3> d = combine(tau, {{-1., s}});
                check(removed[0] * d[0] + removed[1] * d[1] +
                          removed[2] * d[2] <=
                        1e-12 * norm(removed) * (norm(d) + scale),
                      "Mohr-Coulomb, psi = phi: not the closest point");
              }
          }
      }
    deallog << "Mohr-Coulomb" << (plane_strain ? " (plane strain)" : "")
            << ", psi = " << psi << ", cut-off "
            << (cut_off.empty() ? "apex" : cut_off)
            << ", random trials per region:";
    std::string text;
    for (const auto &region : regions)
      text += (text.empty() ? " " : ", ") + name_of(region.first) + ' ' +
              std::to_string(region.second);
    deallog << text << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  test_von_mises();
  test_drucker_prager();
  test_mohr_coulomb_regions();
  test_mohr_coulomb_random("0", "");
  test_mohr_coulomb_random("10", "");
  test_mohr_coulomb_random("30", "");
  test_mohr_coulomb_random("10", "0.5");
  test_mohr_coulomb_random("30", "0.5");
  test_mohr_coulomb_random("0", "0");
  test_mohr_coulomb_random("10", "", true);
  test_mohr_coulomb_random("30", "0.5", true);
}
