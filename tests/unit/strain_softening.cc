// Strain softening of Mohr-Coulomb and Drucker-Prager: peak phi = 30, psi =
// 10 degrees, c = 20 softening to residual phi = 20, psi = 0, c = 5 between
// the equivalent plastic strains 0.01 and 0.05. At a point's plastic strain
// eps the strength is the linear interpolation, by hand here: the fraction
// f = (eps - 0.01) / 0.04 clamped to [0, 1] gives phi = 30 - 10 f, psi =
// 10 - 10 f, c = 20 - 15 f. For eps before, at the start of, inside and
// beyond the softening range, pseudo-random trial stresses (many outside the
// surface, in every return region including the apex) are returned by the
// softening model and by a model made with the hand-interpolated strength
// and no softening: the returned stresses agree to 1e-12 of the stress
// scale (return_mapping.h), so do the plastic strain increments (1e-10
// relatively), and the result lies on or inside the interpolated surface.

#include <mpm_otm/materials/drucker_prager.h>
#include <mpm_otm/materials/mohr_coulomb.h>

#include "return_mapping.h"

using namespace ReturnMappingTests;

namespace
{
  const Entries softening{{"Friction angle", "30"},
                          {"Dilatancy angle", "10"},
                          {"Cohesion", "20"},
                          {"Softening strains", "0.01, 0.05"},
                          {"Residual friction angle", "20"},
                          {"Residual dilatancy angle", "0"},
                          {"Residual cohesion", "5"}};

  /**
   * The strength entries interpolated by hand at the plastic strain @p eps.
   */
  Entries
  interpolated(const double eps)
  {
    const double f = std::min(1., std::max(0., (eps - 0.01) / 0.04));
    return {{"Friction angle", std::to_string(30. - 10. * f)},
            {"Dilatancy angle", std::to_string(10. - 10. * f)},
            {"Cohesion", std::to_string(20. - 15. * f)}};
  }

  /**
   * Sorted principal trial stresses in [-150, 40] (Pa; the apex lies at
   * c cot(phi) = 13.7 to 34.6).
   */
  std::array<double, 3>
  random_principal(Random &random)
  {
    std::array<double, 3> s;
    for (double &x : s)
      x = random.uniform(-150., 40.);
    std::sort(s.begin(), s.end(), std::greater<double>());
    return s;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const double scale = 150.;
  const auto   mc    = make_model<MohrCoulomb<3>>("Mohr-Coulomb", softening);
  const auto   dp = make_model<DruckerPrager<3>>("Drucker-Prager", softening);
  Random       random(35);
  for (const double eps : {0., 0.01, 0.02, 0.03, 0.05, 0.2})
    {
      const auto mc_reference =
        make_model<MohrCoulomb<3>>("Mohr-Coulomb", interpolated(eps));
      const auto dp_reference =
        make_model<DruckerPrager<3>>("Drucker-Prager", interpolated(eps));
      std::map<std::string, unsigned int> regions;
      unsigned int                        n_plastic = 0;
      for (unsigned int n = 0; n < 400; ++n)
        {
          // Mohr-Coulomb in principal space.
          std::array<double, 3> sigma     = random_principal(random);
          std::array<double, 3> reference = sigma;
          double                strain = eps, reference_strain = 0;
          const auto type = mc->return_principal_stresses(sigma, strain);
          const auto reference_type =
            mc_reference->return_principal_stresses(reference,
                                                    reference_strain);
          check(type == reference_type,
                "Mohr-Coulomb: a different return at eps = " +
                  std::to_string(eps));
          for (unsigned int i = 0; i < 3; ++i)
            check(std::abs(sigma[i] - reference[i]) < 1e-12 * scale,
                  "Mohr-Coulomb: returned stress differs at eps = " +
                    std::to_string(eps));
          check(std::abs((strain - eps) - reference_strain) <=
                  1e-10 * reference_strain,
                "Mohr-Coulomb: plastic strain increment differs");
          check(mc_reference->yield_function(sigma) < 1e-12 * scale,
                "Mohr-Coulomb: returned stress outside the surface");
          n_plastic += (type != MohrCoulomb<3>::Return::elastic);
          regions[std::to_string(static_cast<int>(type))]++;

          // Drucker-Prager on a rotated tensor.
          const std::array<double, 3> principal = random_principal(random);
          const Tensor<2, 3>          R         = random_rotation(random);
          Tensor<2, 3>                diagonal;
          for (unsigned int i = 0; i < 3; ++i)
            diagonal[i][i] = principal[i];
          SymmetricTensor<2, 3> stress =
            symmetrize(Tensor<2, 3>(R * diagonal * transpose(R)));
          SymmetricTensor<2, 3> reference_stress = stress;
          double                dp_strain = eps, dp_reference_strain = 0;
          const auto            dp_type = dp->return_stress(stress, dp_strain);
          const auto            dp_reference_type =
            dp_reference->return_stress(reference_stress, dp_reference_strain);
          check(dp_type == dp_reference_type,
                "Drucker-Prager: a different return at eps = " +
                  std::to_string(eps));
          check((stress - reference_stress).norm() < 1e-12 * scale,
                "Drucker-Prager: returned stress differs at eps = " +
                  std::to_string(eps));
          check(std::abs((dp_strain - eps) - dp_reference_strain) <=
                  1e-10 * dp_reference_strain,
                "Drucker-Prager: plastic strain increment differs");
          check(dp_reference->yield_function(stress) < 1e-12 * scale,
                "Drucker-Prager: returned stress outside the cone");
          n_plastic += (dp_type != DruckerPrager<3>::Return::elastic);
          regions["DP " + std::to_string(static_cast<int>(dp_type))]++;
        }
      check(n_plastic > 400, "too few plastic returns");
      deallog << "eps = " << eps
              << ": phi, psi, c = " << interpolated(eps)[0].second << ", "
              << interpolated(eps)[1].second << ", "
              << interpolated(eps)[2].second << "; 800 trials, " << n_plastic
              << " plastic in " << regions.size()
              << " kinds of return, as the interpolated model's" << std::endl;
    }

  // The strength really changes: a trial on the peak surface is admissible
  // at eps = 0 and returned at eps = 0.05.
  {
    const std::array<double, 3> on_peak{
      {0., 0., -2. * 20. * std::cos(M_PI / 6.) / (1. - std::sin(M_PI / 6.))}};
    std::array<double, 3> sigma  = on_peak;
    double                strain = 0.;
    check(mc->return_principal_stresses(sigma, strain) ==
              MohrCoulomb<3>::Return::elastic &&
            strain == 0.,
          "Mohr-Coulomb: the peak surface is not admissible at eps = 0");
    strain = 0.05;
    check(mc->return_principal_stresses(sigma, strain) !=
              MohrCoulomb<3>::Return::elastic &&
            strain > 0.05,
          "Mohr-Coulomb: the peak surface is admissible at the residual");
    deallog << "uniaxial compression at the peak strength 2 c cos(phi) / (1 - "
               "sin(phi)) = "
            << rounded(-on_peak[2], 6)
            << ": elastic at eps = 0, returned at eps = 0.05" << std::endl;
  }

  // In a time step (update_stress) the strength is that of the softening
  // strain, the internal variable a SofteningRegularisation replaces by a
  // nodal average; the plastic strain takes the same increment. The same
  // uniaxial stress on the peak surface, no deformation in the step: with
  // plastic strain 0.05 and softening strain 0 it stays (the peak
  // strength); with plastic strain 0 and softening strain 0.05 it returns
  // to the residual surface, and both strains grow by the same amount.
  {
    check(mc->internal_variables() ==
              std::vector<std::string>{"plastic_strain",
                                       "softening_strain",
                                       "separation"} &&
            mc->softening_variable() == 1,
          "Mohr-Coulomb with softening: internal variables");
    const auto step = [&](const double plastic, const double softening) {
      std::vector<double> variables{plastic, softening, 0.};
      StressState<3>      state;
      state.stress[2][2] =
        -2. * 20. * std::cos(M_PI / 6.) / (1. - std::sin(M_PI / 6.));
      state.internal_variables = make_array_view(variables);
      mc->update_stress(unit_symmetric_tensor<3>(), Tensor<2, 3>(), 1., state);
      return std::make_pair(state.stress, variables);
    };
    const auto [peak_stress, local] = step(0.05, 0.);
    check(std::abs(peak_stress[2][2] + 69.282032302755) < 1e-9 &&
            local[0] == 0.05 && local[1] == 0.,
          "the plastic strain alone softened the strength");
    const auto [residual_stress, averaged] = step(0., 0.05);
    const auto residual_model =
      make_model<MohrCoulomb<3>>("Mohr-Coulomb", interpolated(0.05));
    check(residual_model->yield_function(eigenvalues(residual_stress)) <
              1e-12 * scale &&
            residual_model->yield_function(eigenvalues(residual_stress)) >
              -1e-9 * scale &&
            averaged[0] > 0. &&
            std::abs(averaged[0] - (averaged[1] - 0.05)) < 1e-15,
          "the softening strain did not set the strength");
    deallog << "in a time step the softening strain sets the strength: "
               "plastic strain 0.05, softening strain 0 elastic; plastic "
               "strain 0, softening strain 0.05 returned to the residual "
               "surface, both grown by "
            << rounded(averaged[0], 3) << std::endl;
  }
}
