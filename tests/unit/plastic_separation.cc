// The lost-contact state of the frictional models (PlasticMaterial,
// "separation"): a cohesionless Drucker-Prager or Mohr-Coulomb point
// (phi = 30 deg, c = 0, E = 100, nu = 0.25: K = 200/3) that expands at the
// apex keeps zero stress and stores the expansion, and a later compression
// first closes it without stress. By hand, with steps of dt = 1 and a
// purely volumetric velocity gradient L = (e / 3) I:
//  1. e = +0.01 from zero stress: the trial stress K e I is beyond the apex,
//     so the stress returns to 0 and the separation becomes 0.01;
//  2. e = -0.004: it closes 0.004 of the separation, stress 0, 0.006 left;
//  3. e = -0.01: it closes the remaining 0.006, and the rest, -0.004, is
//     elastic: sigma = K (-0.004) I = -0.26667 I (the stress before is 0,
//     so the term -tr(d eps) sigma of Eq. 2.4 vanishes);
//  4. e = +0.002 from that compressed state is elastic (no new
//     separation): sigma = (-0.26667 + K 0.002) I (1 - 0.002).
// Plane strain (2D) with the same increments but L = diag(e, 0): then the
// trial of step 1 has a deviator, which the apex return removes too; steps
// 1-3 as above in the volume: after step 3 the mean stress is K (-0.004)
// (the deviator of d eps may yield; with psi = 0 the return keeps the mean
// stress).

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/material.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

template <int dim>
std::unique_ptr<Material<dim>>
make_material(const std::string &model)
{
  ParameterHandler prm;
  Material<dim>::declare_common_parameters(
    prm,
    PluginRegistry<Material<dim>>::selection(),
    "");
  PluginRegistry<Material<dim>>::declare_parameters(prm);
  prm.set("Model", model);
  prm.set("Young's modulus", "100");
  prm.set("Poisson's ratio", "0.25");
  prm.enter_subsection(model);
  prm.set("Friction angle", "30");
  prm.set("Cohesion", "0");
  prm.leave_subsection();
  auto material = PluginRegistry<Material<dim>>::create(model);
  material->parse_parameters(prm);
  return material;
}

template <int dim>
void
check_model(const std::string &model_name)
{
  const auto model = make_material<dim>(model_name);
  const auto names = model->internal_variables();
  check(names.back() == "separation",
        model_name + ": no internal variable 'separation'");
  std::vector<double> variables(names.size(), 0.);
  StressState<dim>    state;
  state.internal_variables = make_array_view(variables);

  const double K    = 200. / 3.;
  const auto   step = [&](const double e) {
    Tensor<2, dim> L;
    if (dim == 3)
      L = (e / 3.) * Tensor<2, dim>(unit_symmetric_tensor<dim>());
    else
      L[0][0] = e;
    model->update_stress(unit_symmetric_tensor<dim>(), L, 1., state);
  };
  const auto stress_norm = [&]() {
    return state.stress.norm() + std::abs(state.out_of_plane_stress);
  };
  const std::string label = model_name + " " + std::to_string(dim) + "D";

  step(0.01);
  check(stress_norm() < 1e-12 && std::abs(variables.back() - 0.01) < 1e-14,
        label + ", step 1: stress not 0 or separation not 0.01");
  step(-0.004);
  check(stress_norm() < 1e-12 && std::abs(variables.back() - 0.006) < 1e-14,
        label + ", step 2: stress not 0 or separation not 0.006");
  step(-0.01);
  check(std::abs(variables.back()) < 1e-14,
        label + ", step 3: separation not closed");
  // The elastic volume change -0.004: mean stress K (-0.004), in 2D too,
  // where the deviatoric part may yield (with psi = 0 the return keeps the
  // mean stress); in 3D the whole stress is K (-0.004) I.
  const double mean =
    (trace(state.stress) + (dim < 3 ? state.out_of_plane_stress : 0.)) / 3.;
  check(std::abs(mean - K * (-0.004)) < 1e-12,
        label + ", step 3: mean stress is not K (-0.004)");
  if (dim == 3)
    check((state.stress - K * (-0.004) * unit_symmetric_tensor<dim>()).norm() <
            1e-12,
          label + ", step 3: stress is not K (-0.004) I");
  deallog << label << ": after closing the separation the mean stress is "
          << rounded(mean, 5) << " (by hand " << rounded(K * (-0.004), 5) << ")"
          << std::endl;
  const SymmetricTensor<2, 3> expected =
    K * (-0.004) * unit_symmetric_tensor<3>();
  if (dim == 3)
    {
      const SymmetricTensor<2, 3> before = expected;
      step(0.002);
      const SymmetricTensor<2, 3> by_hand =
        (before + K * 0.002 * unit_symmetric_tensor<3>()) - 0.002 * before;
      double deviation = 0;
      for (unsigned int i = 0; i < 3; ++i)
        deviation =
          std::max(deviation, std::abs(state.stress[i][i] - by_hand[i][i]));
      check(deviation < 1e-12 && variables.back() == 0.,
            label + ", step 4: unloading is not elastic");
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const std::string model : {"Drucker-Prager", "Mohr-Coulomb"})
    {
      check_model<3>(model);
      check_model<2>(model);
    }
}
