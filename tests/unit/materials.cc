// Each constitutive model against stresses computed by hand, and zero stress
// at F = I.

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/material.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

template <int dim>
std::unique_ptr<Material<dim>>
make_material(const std::string &model, const double E, const double nu)
{
  ParameterHandler prm;
  Material<dim>::declare_common_parameters(
    prm,
    PluginRegistry<Material<dim>>::selection(),
    "");
  prm.set("Model", model);
  prm.set("Young's modulus", E);
  prm.set("Poisson's ratio", nu);
  auto material = PluginRegistry<Material<dim>>::create(model);
  material->parse_parameters(prm);
  return material;
}

/**
 * Update @p sigma (a state without internal variables) and return the
 * out-of-plane stress.
 */
template <int dim>
double
update(const Material<dim>     &model,
       const Tensor<2, dim>     F,
       const Tensor<2, dim>    &velocity_gradient,
       SymmetricTensor<2, dim> &sigma,
       const double             out_of_plane_stress = 0.)
{
  StressState<dim> state;
  state.stress              = sigma;
  state.out_of_plane_stress = out_of_plane_stress;
  model.update_stress(F, velocity_gradient, 1., state);
  sigma = state.stress;
  return state.out_of_plane_stress;
}

void
check_stress(const std::string           &label,
             const SymmetricTensor<2, 2> &computed,
             const SymmetricTensor<2, 2> &expected)
{
  const double error = (computed - expected).norm();
  check(error < 1e-12 * (1. + expected.norm()),
        label + ": stress differs from the hand computation by " +
          std::to_string(error));
  deallog << label << ": " << computed[0][0] << ' ' << computed[1][1] << ' '
          << computed[0][1] << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  deallog << std::setprecision(8);

  // E = 100, nu = 0.25: lambda = 40, mu = 40.
  Tensor<2, 2> stretch = unit_symmetric_tensor<2>();
  stretch[0][0]        = 1.1;
  Tensor<2, 2> shear   = unit_symmetric_tensor<2>();
  shear[0][1]          = 0.2;
  const Tensor<2, 2> no_rate;

  {
    const auto            model = make_material<2>("linear elastic", 100, 0.25);
    SymmetricTensor<2, 2> sigma;
    SymmetricTensor<2, 2> expected;
    // sigma = lambda/J tr(eps) F + 2 mu/J F eps, eps = diag(0.1, 0), J = 1.1
    const double zz = update(*model, stretch, no_rate, sigma);
    // Plane strain: sigma_zz = lambda / J tr(eps).
    check(std::abs(zz - 4. / 1.1) < 1e-12, "linear elastic, sigma_zz");
    deallog << "linear elastic, stretch, sigma_zz: " << zz << std::endl;
    expected[0][0] = 4. + 8.;
    expected[1][1] = 40. * 0.1 / 1.1;
    check_stress("linear elastic, stretch", sigma, expected);
    // eps = [[0, 0.1], [0.1, 0]]: sigma = 2 mu F eps = [[1.6, 8], [8, 0]]
    update(*model, shear, no_rate, sigma);
    expected       = SymmetricTensor<2, 2>();
    expected[0][0] = 1.6;
    expected[0][1] = 8.;
    check_stress("linear elastic, shear", sigma, expected);
    update<2>(*model, unit_symmetric_tensor<2>(), no_rate, sigma);
    check_stress("linear elastic, F = I", sigma, SymmetricTensor<2, 2>());
  }
  {
    const auto            model = make_material<2>("neo-Hookean", 100, 0.25);
    SymmetricTensor<2, 2> sigma;
    SymmetricTensor<2, 2> expected;
    // sigma = lambda ln(J)/J I + mu/J (F F^T - I)
    const double zz            = update(*model, stretch, no_rate, sigma);
    const double pressure_part = 40. * std::log(1.1) / 1.1;
    // Plane strain: b_zz = 1, sigma_zz = lambda ln(J) / J.
    check(std::abs(zz - pressure_part) < 1e-12, "neo-Hookean, sigma_zz");
    deallog << "neo-Hookean, stretch, sigma_zz: " << zz << std::endl;
    expected[0][0] = pressure_part + 40. / 1.1 * 0.21;
    expected[1][1] = pressure_part;
    check_stress("neo-Hookean, stretch", sigma, expected);
    update<2>(*model, unit_symmetric_tensor<2>(), no_rate, sigma);
    check_stress("neo-Hookean, F = I", sigma, SymmetricTensor<2, 2>());
  }
  {
    const auto            model = make_material<2>("hypo-elastic", 100, 0.25);
    SymmetricTensor<2, 2> sigma;
    SymmetricTensor<2, 2> expected;
    // Stretching: d sigma = lambda tr(d eps) I + 2 mu d eps, d eps =
    // diag(0.01, 0).
    Tensor<2, 2> rate;
    rate[0][0] = 0.01;
    const double zz =
      update<2>(*model, unit_symmetric_tensor<2>(), rate, sigma);
    // Plane strain: d sigma_zz = lambda tr(d eps).
    check(std::abs(zz - 0.4) < 1e-12, "hypo-elastic, sigma_zz");
    deallog << "hypo-elastic, stretching, sigma_zz: " << zz << std::endl;
    expected[0][0] = 1.2;
    expected[1][1] = 0.4;
    check_stress("hypo-elastic, stretching", sigma, expected);
    // Pure spin of sigma = diag(1, 0): d sigma = W sigma - sigma W with
    // W = [[0, 0.01], [-0.01, 0]].
    Tensor<2, 2> spin;
    spin[0][1]  = 0.01;
    spin[1][0]  = -0.01;
    sigma       = SymmetricTensor<2, 2>();
    sigma[0][0] = 1.;
    update<2>(*model, unit_symmetric_tensor<2>(), spin, sigma);
    expected       = SymmetricTensor<2, 2>();
    expected[0][0] = 1.;
    expected[0][1] = -0.01;
    check_stress("hypo-elastic, spin", sigma, expected);
    sigma = SymmetricTensor<2, 2>();
    update<2>(*model, unit_symmetric_tensor<2>(), no_rate, sigma);
    check_stress("hypo-elastic, no deformation",
                 sigma,
                 SymmetricTensor<2, 2>());
  }
  {
    // 1D, nu = 0: every model gives E (F - 1) to first order; linear elastic
    // exactly.
    const auto   model = make_material<1>("linear elastic", 100, 0.);
    Tensor<2, 1> F;
    F[0][0] = 1.1;
    SymmetricTensor<2, 1> sigma;
    update<1>(*model, F, Tensor<2, 1>(), sigma);
    check(std::abs(sigma[0][0] - 10.) < 1e-12, "1D linear elastic");
    deallog << "1D linear elastic, F = 1.1: " << sigma[0][0] << std::endl;
  }
}
