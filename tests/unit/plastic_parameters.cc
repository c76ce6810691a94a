// The entries of the elasto-plastic models: the cone coefficients of
// Drucker-Prager and the defaults against hand computations, the
// rejection by parse_parameters of inadmissible values with a message that
// names the entry (here in a named material, "Material sand"), and the
// strengths divided by a factor of a strength reduction
// (Material::reduce_strength()).

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/drucker_prager.h>
#include <mpm_otm/materials/mohr_coulomb.h>
#include <mpm_otm/materials/von_mises.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  using Entries = std::vector<std::pair<std::string, std::string>>;

  /**
   * The material "sand" of model @p model with the entries @p entries of the
   * model's subsection (E = 1000, nu = 0.3), declared as MaterialLibrary
   * declares it.
   */
  std::unique_ptr<Material<3>>
  make_sand(const std::string &model, const Entries &entries)
  {
    ParameterHandler prm;
    prm.enter_subsection("Material sand");
    Material<3>::declare_common_parameters(
      prm,
      PluginRegistry<Material<3>>::selection(),
      "");
    PluginRegistry<Material<3>>::declare_parameters(prm);
    prm.set("Model", model);
    prm.set("Young's modulus", 1000.);
    prm.set("Poisson's ratio", 0.3);
    prm.enter_subsection(model);
    for (const auto &entry : entries)
      prm.set(entry.first, entry.second);
    prm.leave_subsection();
    auto material = PluginRegistry<Material<3>>::create(model);
    material->set_subsection_path("Material sand");
    material->parse_parameters(prm);
    prm.leave_subsection();
    return material;
  }

  /**
   * parse_parameters must reject @p entries with a message naming
   * "Material sand/<model>/<entry>".
   */
  void
  check_rejected(const std::string &model,
                 const Entries     &entries,
                 const std::string &entry)
  {
    const std::string name     = "Material sand/" + model + "/" + entry;
    bool              rejected = false;
    try
      {
        make_sand(model, entries);
      }
    catch (const std::exception &e)
      {
        rejected = true;
        check(std::string(e.what()).find(name) != std::string::npos,
              "the message for " + name + " does not name it: " + e.what());
      }
    check(rejected, name + ": inadmissible value accepted");
    std::string values;
    for (const auto &e : entries)
      values += (values.empty() ? "" : ", ") + e.first + " = " + e.second;
    deallog << "rejected (" << values << "): " << name << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  // Drucker-Prager cones for phi = 30 degrees, c = 1 (sin = 1/2,
  // cos = sqrt(3)/2, tan = 1/sqrt(3)):
  // plane strain alpha = 3 tan / sqrt(9 + 12 tan^2) = sqrt(3/13),
  //   k = 3 / sqrt(13);
  // outer alpha = 6 sin / (sqrt(3) (3 - sin)) = 2 / (sqrt(3) 5/6 3) = 3 /
  //   (2.5 sqrt(3)), k = 6 cos / (sqrt(3) (3 - sin)) = 3 / 2.5 = 1.2;
  // inner the same with 3.5: alpha = 3 / (3.5 sqrt(3)), k = 6 / 7.
  // The apex k / alpha is c cot(phi) = sqrt(3) for all three.
  const std::vector<std::array<double, 2>> expected{
    {{std::sqrt(3. / 13.), 3. / std::sqrt(13.)}},
    {{3. / (2.5 * std::sqrt(3.)), 1.2}},
    {{3. / (3.5 * std::sqrt(3.)), 6. / 7.}}};
  const std::vector<std::string> cones{"plane strain", "outer", "inner"};
  for (unsigned int i = 0; i < 3; ++i)
    {
      const auto  material = make_sand("Drucker-Prager",
                                      {{"Friction angle", "30"},
                                        {"Dilatancy angle", "30"},
                                        {"Cohesion", "1"},
                                        {"Cone", cones[i]}});
      const auto &dp       = dynamic_cast<const DruckerPrager<3> &>(*material);
      check(std::abs(dp.alpha() - expected[i][0]) < 1e-15 &&
              std::abs(dp.k() - expected[i][1]) < 1e-15 &&
              std::abs(dp.alpha_psi() - dp.alpha()) < 1e-15,
            "Drucker-Prager, " + cones[i] + " cone: alpha, k");
      check(std::abs(dp.tension_cut_off() - std::sqrt(3.)) < 1e-14 &&
              std::abs(dp.friction_angle() - M_PI / 6.) < 1e-15 &&
              std::abs(dp.dilatancy_angle() - M_PI / 6.) < 1e-15,
            "Drucker-Prager: default cut-off at the apex, angles in radians");
      deallog << "Drucker-Prager, " << cones[i]
              << " cone: alpha = " << rounded(dp.alpha(), 9)
              << ", k = " << rounded(dp.k(), 9) << std::endl;
    }

  // Defaults: phi = 30, psi = 0, c = 0, cut-off at the apex (0 for c = 0).
  {
    const auto  material = make_sand("Mohr-Coulomb", {});
    const auto &mc       = dynamic_cast<const MohrCoulomb<3> &>(*material);
    check(std::abs(mc.friction_angle() - M_PI / 6.) < 1e-15 &&
            mc.dilatancy_angle() == 0. && mc.cohesion() == 0. &&
            mc.tension_cut_off() == 0.,
          "Mohr-Coulomb defaults");
    check(material->internal_variables() ==
            std::vector<std::string>{"plastic_strain", "separation"},
          "Mohr-Coulomb: internal variables");
    const auto material_2 =
      make_sand("Mohr-Coulomb",
                {{"Cohesion", "2"}, {"Tension cut-off", "1.5"}});
    check(std::abs(material_2->friction_angle() - M_PI / 6.) < 1e-15 &&
            dynamic_cast<const MohrCoulomb<3> &>(*material_2)
                .tension_cut_off() == 1.5,
          "Mohr-Coulomb: cut-off 1.5 below the apex 2 sqrt(3)");
    // phi = 0 (Tresca): no apex, any cut-off >= 0 is admissible, 'apex'
    // means none.
    const auto tresca =
      make_sand("Mohr-Coulomb", {{"Friction angle", "0"}, {"Cohesion", "1"}});
    check(!std::isfinite(
            dynamic_cast<const MohrCoulomb<3> &>(*tresca).tension_cut_off()),
          "Mohr-Coulomb, phi = 0: no cut-off by default");
    make_sand("Mohr-Coulomb",
              {{"Friction angle", "0"},
               {"Cohesion", "1"},
               {"Tension cut-off", "1e6"}});
    const auto vm = make_sand("von Mises", {});
    check(dynamic_cast<const VonMises<3> &>(*vm).yield_stress() == 40. &&
            dynamic_cast<const VonMises<3> &>(*vm).hardening_modulus() == 0. &&
            vm->friction_angle() == 0.,
          "von Mises defaults");
    deallog << "defaults and admissible values accepted" << std::endl;
  }

  for (const std::string model : {"Drucker-Prager", "Mohr-Coulomb"})
    {
      const Entries base{{"Friction angle", "30"}, {"Cohesion", "1"}};
      auto with = [&](const std::string &entry, const std::string &value) {
        Entries entries = base;
        entries.push_back({entry, value});
        return entries;
      };
      check_rejected(model, with("Dilatancy angle", "35"), "Dilatancy angle");
      check_rejected(model,
                     {{"Friction angle", "30"}, {"Cohesion", "-1"}},
                     "Cohesion");
      // The apex is c cot(30) = sqrt(3) = 1.7320508.
      check_rejected(model, with("Tension cut-off", "1.75"), "Tension cut-off");
      check_rejected(model, with("Tension cut-off", "-0.1"), "Tension cut-off");
      check_rejected(model, with("Tension cut-off", "none"), "Tension cut-off");
      check_rejected(model,
                     {{"Friction angle", "90"}, {"Cohesion", "1"}},
                     "Friction angle");
      // c = 0: the apex is at 0, so is the only admissible cut-off.
      check_rejected(model,
                     {{"Friction angle", "30"}, {"Tension cut-off", "0.1"}},
                     "Tension cut-off");
      // Strain softening: residual values at most the peak ones, strains
      // 0 <= eps_1 < eps_2, residual values only with strains.
      const auto softening = [&](const std::string &entry,
                                 const std::string &value) {
        Entries entries = with("Softening strains", "0, 0.1");
        entries.push_back({entry, value});
        return entries;
      };
      check_rejected(model,
                     softening("Residual cohesion", "1.5"),
                     "Residual cohesion");
      check_rejected(model,
                     softening("Residual friction angle", "35"),
                     "Residual friction angle");
      check_rejected(model,
                     softening("Residual cohesion", "few"),
                     "Residual cohesion");
      check_rejected(model,
                     {{"Friction angle", "30"},
                      {"Dilatancy angle", "20"},
                      {"Cohesion", "1"},
                      {"Softening strains", "0, 0.1"},
                      {"Residual friction angle", "10"}},
                     "Residual dilatancy angle");
      check_rejected(model,
                     with("Softening strains", "0.2, 0.1"),
                     "Softening strains");
      check_rejected(model,
                     with("Softening strains", "-0.1, 0.1"),
                     "Softening strains");
      check_rejected(model,
                     with("Softening strains", "0.1"),
                     "Softening strains");
      check_rejected(model,
                     with("Residual cohesion", "0.5"),
                     "Softening strains");
      // No strength at all, at the peak or at the residual.
      check_rejected(model,
                     {{"Friction angle", "0"}, {"Cohesion", "0"}},
                     "Cohesion");
      check_rejected(model,
                     {{"Friction angle", "0"},
                      {"Cohesion", "1"},
                      {"Softening strains", "0, 0.1"},
                      {"Residual cohesion", "0"}},
                     "Residual cohesion");
      const auto softening_material =
        make_sand(model, softening("Residual cohesion", "0.25"));
      check(softening_material->friction_angle() == M_PI / 6.,
            model + ": softening with the peak friction angle as residual");
    }
  check_rejected("von Mises", {{"Yield stress", "0"}}, "Yield stress");
  check_rejected("von Mises",
                 {{"Hardening modulus", "-1"}},
                 "Hardening modulus");

  // Strength reduction by F = 2: c / F and tan / F of the friction and
  // dilatancy angles, at the peak and the residual, for the frictional
  // models; the yield stress and the hardening modulus / F for von Mises.
  // Mohr-Coulomb c = 10, phi = 30 deg, psi = 10 deg softening to c = 4,
  // phi = 20 deg, psi = 0 between eps_p = 0 and 0.1: reduced, c = 5,
  // phi = atan(tan(30 deg) / 2) = 16.102 deg, and at the residual c = 2,
  // phi = atan(tan(20 deg) / 2) = 10.311 deg. A trial stress far outside
  // (principal -0, -50, -200) returns onto the reduced surface
  // (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin(phi) = 2 c cos(phi), at
  // the peak and (eps_p = 1) at the residual; the apex c cot(phi) and with
  // it the tension cut-off stay at 10 sqrt(3).
  {
    const double F             = 2.;
    const auto   reduced_angle = [F](const double degrees) {
      return std::atan(std::tan(degrees * M_PI / 180.) / F);
    };
    const Entries entries{{"Friction angle", "30"},
                          {"Dilatancy angle", "10"},
                          {"Cohesion", "10"},
                          {"Softening strains", "0, 0.1"},
                          {"Residual cohesion", "4"},
                          {"Residual friction angle", "20"},
                          {"Residual dilatancy angle", "0"}};
    auto          material = make_sand("Mohr-Coulomb", entries);
    material->reduce_strength(F);
    const auto &mc = dynamic_cast<const MohrCoulomb<3> &>(*material);
    check(std::abs(mc.friction_angle() - reduced_angle(30.)) < 1e-15 &&
            std::abs(mc.dilatancy_angle() - reduced_angle(10.)) < 1e-15 &&
            std::abs(mc.cohesion() - 5.) < 1e-15 &&
            std::abs(mc.tension_cut_off() - 10. * std::sqrt(3.)) < 1e-12,
          "Mohr-Coulomb reduced by 2: phi, psi, c, cut-off");
    double largest_error = 0;
    for (const auto &[plastic_strain, c, phi] :
         {std::tuple<double, double, double>{0., 5., reduced_angle(30.)},
          {1., 2., reduced_angle(20.)}})
      {
        SymmetricTensor<2, 3> stress;
        stress[1][1] = -50.;
        stress[2][2] = -200.;
        std::vector<double> variables{plastic_strain, 0.};
        mc.return_map(stress, make_array_view(variables));
        const auto   principal = eigenvalues(stress);
        const double yield     = (principal[0] - principal[2]) +
                             (principal[0] + principal[2]) * std::sin(phi) -
                             2. * c * std::cos(phi);
        largest_error = std::max(largest_error, std::abs(yield) / 200.);
      }
    check(largest_error < 1e-12,
          "Mohr-Coulomb reduced by 2: returned off the reduced surface by " +
            std::to_string(largest_error));
    deallog << "Mohr-Coulomb reduced by 2: phi = "
            << rounded(mc.friction_angle() * 180. / M_PI, 5)
            << " deg, psi = " << rounded(mc.dilatancy_angle() * 180. / M_PI, 5)
            << " deg, c = " << mc.cohesion()
            << "; returns onto the reduced peak and residual surfaces"
            << std::endl;

    // Drucker-Prager reduced by 2: the cone of the reduced parameters.
    auto dp_material = make_sand("Drucker-Prager", entries);
    dp_material->reduce_strength(F);
    const auto &dp = dynamic_cast<const DruckerPrager<3> &>(*dp_material);
    const auto  direct_material = make_sand(
      "Drucker-Prager",
      {{"Friction angle", std::to_string(reduced_angle(30.) * 180. / M_PI)},
        {"Dilatancy angle", std::to_string(reduced_angle(10.) * 180. / M_PI)},
        {"Cohesion", "5"}});
    const auto &direct =
      dynamic_cast<const DruckerPrager<3> &>(*direct_material);
    check(std::abs(dp.alpha() / direct.alpha() - 1.) < 1e-6 &&
            std::abs(dp.alpha_psi() / direct.alpha_psi() - 1.) < 1e-6 &&
            std::abs(dp.k() / direct.k() - 1.) < 1e-6,
          "Drucker-Prager reduced by 2: not the cone of c / 2, atan(tan / 2)");
    deallog << "Drucker-Prager reduced by 2: alpha = " << rounded(dp.alpha(), 6)
            << ", k = " << rounded(dp.k(), 6) << std::endl;

    auto vm_material =
      make_sand("von Mises",
                {{"Yield stress", "40"}, {"Hardening modulus", "10"}});
    vm_material->reduce_strength(F);
    const auto &vm = dynamic_cast<const VonMises<3> &>(*vm_material);
    check(vm.yield_stress() == 20. && vm.hardening_modulus() == 5.,
          "von Mises reduced by 2: yield stress, hardening modulus");
    deallog << "von Mises reduced by 2: yield stress " << vm.yield_stress()
            << ", hardening modulus " << vm.hardening_modulus() << std::endl;
  }
}
