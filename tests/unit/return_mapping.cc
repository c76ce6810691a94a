// The return mappings of von Mises and Drucker-Prager on three-dimensional
// trial stresses, against closed forms (Mohr-Coulomb:
// mohr_coulomb_return_mapping.cc; tolerances: return_mapping.h):
// - trial stresses built backwards from a chosen returned stress and chosen
//   plastic multipliers of a chosen return (trial = sigma + sum_j d gamma_j
//   D : n_j with the flow vectors n_j of the active surfaces), so that the
//   exact answer of the return is known: the returned stress, the region,
//   the principal directions and the plastic strain increment
//   sqrt(2/3) |sum_j d gamma_j n_j|;
// - many pseudo-random trial stresses outside the surface in several
//   regions: the returned stress lies on the surface, for associated flow it
//   is the closest admissible stress in the energy norm (checked through the
//   variational inequality against many admissible stresses), keeps the
//   trial's principal directions;
// - trial stresses inside: returned unchanged, bit for bit, no plastic
//   strain; elastic unloading from a returned state stays elastic.

#include "return_mapping.h"

#include <mpm_otm/materials/drucker_prager.h>
#include <mpm_otm/materials/von_mises.h>

using namespace ReturnMappingTests;

namespace
{
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
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  test_von_mises();
  test_drucker_prager();
}
