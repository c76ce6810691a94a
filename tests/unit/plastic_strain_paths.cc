// Single-point strain paths with closed-form answers through the full
// update_stress of the elasto-plastic models (elastic predictor of
// PlasticMaterial, thesis Eq. 2.4 with the Hughes-Winget rotation, followed by
// the return mapping):
// 1. von Mises, uniaxial stress (3D, mixed control: axial strain increments,
//    the lateral strain increments iterated so that the lateral stresses
//    vanish), loading past yield and unloading;
// 2. Drucker-Prager, plane-strain simple shear (2D) from an isotropic
//    compressive stress to its limit shear stress;
// 3. Mohr-Coulomb, 1D uniaxial-strain compression onto the active line;
// 4. a rigid rotation of a stressed point (3D and 2D) keeps p, J2, J3.

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/drucker_prager.h>
#include <mpm_otm/materials/plastic_material.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  using Entries = std::vector<std::pair<std::string, std::string>>;

  template <int dim>
  std::unique_ptr<Material<dim>>
  make_material(const std::string &model,
                const double       E,
                const double       nu,
                const Entries     &entries)
  {
    ParameterHandler prm;
    Material<dim>::declare_common_parameters(
      prm,
      PluginRegistry<Material<dim>>::selection(),
      "");
    PluginRegistry<Material<dim>>::declare_parameters(prm);
    prm.set("Model", model);
    prm.set("Young's modulus", E);
    prm.set("Poisson's ratio", nu);
    if (!entries.empty())
      {
        prm.enter_subsection(model);
        for (const auto &entry : entries)
          prm.set(entry.first, entry.second);
        prm.leave_subsection();
      }
    auto material = PluginRegistry<Material<dim>>::create(model);
    material->parse_parameters(prm);
    return material;
  }

  /**
   * A material point: its stress state and the storage of its internal
   * variables.
   */
  template <int dim>
  struct Point
  {
    explicit Point(const Material<dim> &model)
      : variables(model.internal_variables().size(), 0.)
    {
      state.internal_variables = make_array_view(variables);
    }

    Point(const Point &other)
      : state(other.state)
      , variables(other.variables)
    {
      state.internal_variables = make_array_view(variables);
    }

    Point &
    operator=(const Point &other)
    {
      state                    = other.state;
      variables                = other.variables;
      state.internal_variables = make_array_view(variables);
      return *this;
    }

    /**
     * One step of length 1 with the velocity gradient @p L.
     */
    void
    step(const Material<dim> &model, const Tensor<2, dim> &L)
    {
      model.update_stress(unit_symmetric_tensor<dim>(), L, 1., state);
    }

    StressState<dim>    state;
    std::vector<double> variables;
  };

  /**
   * The three-dimensional stress of a point (sigma_zz = out-of-plane stress
   * in 2D).
   */
  template <int dim>
  SymmetricTensor<2, 3>
  stress_3d(const StressState<dim> &state)
  {
    SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        result[i][j] = state.stress[i][j];
    for (unsigned int d = dim; d < 3; ++d)
      result[d][d] = state.out_of_plane_stress;
    return result;
  }

  // ---------------------------------------------------------------------
  // 1. von Mises, uniaxial stress
  // ---------------------------------------------------------------------

  /**
   * The uniaxial response of the hypo-elastic predictor and the radial
   * return, per step of axial strain a (lateral strain b, lateral stress 0)
   * from the axial stress sigma_n. With de = diag(a, b, b), t = a + 2 b:
   * the trial is sigma_n (1 - t) + lambda t + 2 mu a axially and
   * lambda t + 2 mu b laterally; the radial return keeps p and scales the
   * deviator, so the result diag(sigma, 0, 0) satisfies
   *   sigma = sigma_n (1 - t) + 3 K t                       (p kept),
   *   sigma = sigma_n (1 - t) + 2 mu (a - b)   elastically,
   *   sigma = (H q^tr + 3 G sigma_y(eps_p)) / (3 G + H)    plastically,
   *   q^tr = sigma_n (1 - t) + 2 mu (a - b).
   * Eliminating t and b: sigma - sigma_n = E_n a elastically and
   * sigma - sigma_n = E_n H / (E_n + H) a plastically (with sigma_n on the
   * yield surface), where E_n = E (1 - sigma_n / (3 K)) = E - (1 - 2 nu)
   * sigma_n: the hypo-elastic term -tr(de) sigma of Eq. 2.4 lowers the
   * uniaxial modulus by (1 - 2 nu) sigma_n, a relative O(sigma / E). So the
   * slope after yield is E H / (E + H) up to a relative (1 - 2 nu) sigma / E
   * (times H / (E + H)), and exactly E_n H / (E_n + H) per step.
   */
  void
  test_uniaxial_von_mises()
  {
    const double E = 1000., nu = 0.3, sigma_y = 1., H = 100.;
    const auto   model =
      make_material<3>("von Mises",
                       E,
                       nu,
                       {{"Yield stress", "1"}, {"Hardening modulus", "100"}});
    Point<3>     point(*model);
    const double a         = 1e-5; // axial strain per step
    double       b_guess   = -nu * a;
    unsigned int n_elastic = 0, n_plastic = 0;
    double       largest_deviation = 0;

    // One step with the lateral strain iterated (secant method; the lateral
    // stress is piecewise linear in b, so it converges in a few
    // iterations) until the lateral stress is below 1e-13 sigma_y.
    const auto uniaxial_step = [&](const double axial) {
      const auto lateral = [&](const double b, Point<3> &result) {
        result = point;
        Tensor<2, 3> L;
        L[0][0] = axial;
        L[1][1] = L[2][2] = b;
        result.step(*model, L);
        return result.state.stress[1][1];
      };
      Point<3>     trial(point);
      double       b0 = b_guess, b1 = b_guess * 1.01 + 1e-3 * axial;
      double       g0 = lateral(b0, trial), g1 = lateral(b1, trial);
      unsigned int iteration = 0;
      while (std::abs(g1) > 1e-13 * sigma_y)
        {
          check(++iteration < 50, "uniaxial: lateral iteration diverges");
          const double b2 = b1 - g1 * (b1 - b0) / (g1 - g0);
          b0              = b1;
          g0              = g1;
          b1              = b2;
          g1              = lateral(b1, trial);
        }
      check(std::abs(trial.state.stress[2][2]) < 1e-13 * sigma_y &&
              std::abs(trial.state.stress[0][1]) == 0. &&
              std::abs(trial.state.stress[1][2]) == 0.,
            "uniaxial: stress not uniaxial");
      b_guess = b1;
      point   = trial;
    };

    // Loading to an axial strain of 1 % (1000 steps).
    for (unsigned int n = 0; n < 1000; ++n)
      {
        const double sigma_n = point.state.stress[0][0];
        const double eps_n   = point.variables[0];
        uniaxial_step(a);
        const double sigma = point.state.stress[0][0];
        const double eps   = point.variables[0];
        const double E_n   = E - (1. - 2. * nu) * sigma_n;
        if (eps == 0.)
          {
            // Elastic: slope E_n, below the yield stress.
            check(std::abs(sigma - sigma_n - E_n * a) < 1e-9 * E_n * a &&
                    sigma < sigma_y,
                  "uniaxial: elastic step");
            ++n_elastic;
            continue;
          }
        // Plastic: on the yield surface sigma = sigma_y + H eps_p.
        check(std::abs(sigma - (sigma_y + H * eps)) < 1e-12 * sigma_y,
              "uniaxial: stress off the hardening line");
        if (eps_n == 0.)
          // The step in which yield starts: from below sigma_y.
          check(sigma_n < sigma_y, "uniaxial: yield step");
        else
          {
            const double slope = (sigma - sigma_n) / a;
            check(std::abs(slope - E_n * H / (E_n + H)) <
                    1e-9 * E_n * H / (E_n + H),
                  "uniaxial: slope after yield differs from E_n H / (E_n + "
                  "H)");
            const double deviation = std::abs(slope / (E * H / (E + H)) - 1.);
            check(deviation <= (1. - 2. * nu) * sigma / E,
                  "uniaxial: slope after yield differs from E H / (E + H) "
                  "by more than (1 - 2 nu) sigma / E");
            largest_deviation = std::max(largest_deviation, deviation);
            ++n_plastic;
          }
      }
    const double sigma_max = point.state.stress[0][0];
    const double eps_max   = point.variables[0];
    deallog << "von Mises uniaxial: " << n_elastic << " elastic steps, "
            << n_plastic << " plastic steps after yield; at 1 % strain sigma = "
            << rounded(sigma_max, 6) << ", eps_p = " << rounded(eps_max, 6)
            << std::endl;
    deallog << "von Mises uniaxial: slope after yield / (E H / (E + H)) - 1 "
               "<= "
            << rounded(largest_deviation, 2) << std::endl;
    // The first yield: the elastic steps follow sigma_{n+1} = sigma_n +
    // (E - (1 - 2 nu) sigma_n) a, i.e. sigma_n = E / (1 - 2 nu) (1 - (1 -
    // (1 - 2 nu) a)^n): yield in step n with sigma_{n-1} < sigma_y <=
    // sigma_n of this closed form.
    const double c       = 1. - 2. * nu;
    unsigned int n_yield = 0;
    while (E / c * (1. - std::pow(1. - c * a, n_yield + 1)) < sigma_y)
      ++n_yield;
    check(n_elastic == n_yield, "uniaxial: yield in the wrong step");

    // Unloading by 200 steps of -a: elastic, slope E_n, eps_p constant.
    for (unsigned int n = 0; n < 200; ++n)
      {
        const double sigma_n = point.state.stress[0][0];
        uniaxial_step(-a);
        const double E_n = E - (1. - 2. * nu) * sigma_n;
        check(point.variables[0] == eps_max &&
                std::abs(point.state.stress[0][0] - sigma_n + E_n * a) <
                  1e-9 * E_n * a,
              "uniaxial: unloading must be elastic");
      }
    deallog << "von Mises uniaxial: unloaded elastically to sigma = "
            << rounded(point.state.stress[0][0], 6) << std::endl;
  }

  // ---------------------------------------------------------------------
  // 2. Drucker-Prager, plane-strain simple shear
  // ---------------------------------------------------------------------

  /**
   * Simple shear L = [[0, g], [0, 0]] (g = d gamma per step) in plane strain
   * from sigma = p0 I, for the plane-strain cone with psi = 0.
   *
   * The limit: tr(L) = 0 and psi = 0 keep the volume elastic and plastic,
   * and the rotation term is traceless, so p = p0 in every step (the trial
   * has p0, the cone return with alpha_psi = 0 keeps it). At the limit the
   * stress is stationary: with the deviator z = (sigma_xx - sigma_yy) / 2 +
   * i sigma_xy (a complex number) and s_zz, one step maps the state to the
   * trial z^tr = e^{-2 i theta} z + i G g (the Hughes-Winget rotation by
   * theta = 2 atan(g / 4) turns z by -2 theta, 2 G de adds G g to sigma_xy),
   * s_zz^tr = s_zz, and the return scales the deviator to
   * sqrt(J2) = Y = k - alpha p0. A fixed point has s_zz = 0 (it is scaled by
   * a factor < 1 each step), |z| = Y (J2 = |z|^2 for s_zz = 0) and
   * z (1 / beta - e^{-2 i theta}) = i G g. Its modulus gives
   * 1 / beta = cos 2 theta + sqrt((G g / Y)^2 - sin^2 2 theta), its argument
   *   sigma_xy = Y sqrt(1 - (Y sin(2 theta) / (G g))^2),
   *   (sigma_xx - sigma_yy) / 2 = Y^2 sin(2 theta) / (G g),
   * which for g -> 0 tends to the continuous limit of the Jaumann rate,
   * sigma_xy = Y sqrt(1 - (Y / G)^2), (sigma_xx - sigma_yy) / 2 = Y^2 / G:
   * the limit shear stress is Y = k - alpha p0 = 3 (c - tan(phi) p0) /
   * sqrt(9 + 12 tan^2 phi) up to the small spin correction (Y / G)^2 / 2.
   * (For psi = 0 this is below Mohr-Coulomb's c cos(phi) - p0 sin(phi); the
   * plane-strain match is exact for associated flow.)
   */
  void
  test_simple_shear_drucker_prager()
  {
    const double E = 1000., nu = 0.25, c = 1., p0 = -10.;
    const double G       = E / (2. * (1. + nu));
    const auto   model   = make_material<2>("Drucker-Prager",
                                        E,
                                        nu,
                                        {{"Friction angle", "30"},
                                             {"Dilatancy angle", "0"},
                                             {"Cohesion", "1"},
                                             {"Cone", "plane strain"}});
    const double tan_phi = std::tan(M_PI / 6.);
    const double Y =
      3. * (c - tan_phi * p0) / std::sqrt(9. + 12. * tan_phi * tan_phi);
    const auto &dp = dynamic_cast<const DruckerPrager<2> &>(*model);
    check(std::abs(Y - (dp.k() - dp.alpha() * p0)) < 1e-14 * Y,
          "simple shear: Y = k - alpha p0");

    Point<2> point(*model);
    point.state.stress              = p0 * unit_symmetric_tensor<2>();
    point.state.out_of_plane_stress = p0;
    const double g                  = 5e-4;
    Tensor<2, 2> L;
    L[0][1] = g;
    // Elastic until G gamma = Y, then the approach to the limit, which
    // converges geometrically over a shear strain of a few Y / G (= 0.014):
    // after gamma = 2 it is reached to round-off.
    const unsigned int n_steps         = 4000;
    double             largest_p_error = 0;
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        point.step(*model, L);
        const double p  = trace(stress_3d(point.state)) / 3.;
        largest_p_error = std::max(largest_p_error, std::abs(p - p0));
      }
    check(largest_p_error < 1e-12 * std::abs(p0),
          "simple shear: the mean stress must stay p0");

    const double theta     = 2. * std::atan(g / 4.);
    const double ratio     = Y * std::sin(2. * theta) / (G * g);
    const double tau_limit = Y * std::sqrt(1. - ratio * ratio);
    const double a_limit   = Y * ratio;
    const double tau       = point.state.stress[0][1];
    const double a =
      0.5 * (point.state.stress[0][0] - point.state.stress[1][1]);
    const double s_zz = point.state.out_of_plane_stress - p0;
    check(std::abs(tau - tau_limit) < 1e-12 * Y &&
            std::abs(a - a_limit) < 1e-12 * Y && std::abs(s_zz) < 1e-12 * Y,
          "simple shear: limit state differs from the closed form");
    // The continuous limit (g -> 0) differs by O(g^2) relatively.
    const double tau_continuous = Y * std::sqrt(1. - Y * Y / (G * G));
    check(std::abs(tau - tau_continuous) < g * g * Y,
          "simple shear: differs from the Jaumann-rate limit");
    check(std::abs(tau / Y - 1.) < 0.5 * Y * Y / (G * G) * 1.01,
          "simple shear: limit shear stress differs from k - alpha p0");
    deallog << "Drucker-Prager simple shear: Y = k - alpha p0 = "
            << rounded(Y, 9) << ", limit sigma_xy / Y = " << rounded(tau / Y, 9)
            << ", (sigma_xx - sigma_yy) / (2 Y^2 / G) = "
            << rounded(a / (Y * Y / G), 6) << std::endl;
    // At the limit the plastic strain rate is the deformation rate
    // sym(L) (elastic strain stationary up to the O(Y / G) rotation term),
    // so eps_p grows by sqrt(2/3) |sym(L)| = g / sqrt(3) per step: eps_p =
    // (gamma - gamma_y) / sqrt(3) with the yield strain gamma_y = Y / G, up to
    // the elastic-plastic transition, which lasts a shear strain of a few
    // Y / G and changes eps_p by less than Y / G.
    const double gamma = n_steps * g;
    check(std::abs(point.variables[0] - (gamma - Y / G) / std::sqrt(3.)) <
            Y / G,
          "simple shear: equivalent plastic strain");
    deallog << "Drucker-Prager simple shear: equivalent plastic strain at "
               "gamma = 2: "
            << rounded(point.variables[0], 6) << std::endl;
  }

  // ---------------------------------------------------------------------
  // 3. Mohr-Coulomb, 1D uniaxial strain (oedometric compression)
  // ---------------------------------------------------------------------

  /**
   * 1D uniaxial-strain compression of Mohr-Coulomb (phi = 30, psi = 0,
   * c = 1, nu = 0.2): elastically the point follows the hypo-elastic model
   * (no spin, so the Hughes-Winget rotation is the identity), with the
   * lateral stress near nu / (1 - nu) = 1/4 of the axial one, below the
   * active ratio (1 - sin phi) / (1 + sin phi) = 1/3; once it reaches the
   * pyramid, the two equal lateral stresses are sigma_1 = sigma_2 and the
   * axial one sigma_3, the return is to the left edge, and the lateral
   * stress follows f = 0: sigma_lateral = (2 c cos(phi) + sigma_axial
   * (1 - sin phi)) / (1 + sin phi) (the active earth pressure of a cohesive
   * soil).
   */
  void
  test_oedometer_mohr_coulomb()
  {
    const Entries entries{{"Friction angle", "30"},
                          {"Dilatancy angle", "0"},
                          {"Cohesion", "1"}};
    const auto    model = make_material<1>("Mohr-Coulomb", 1000., 0.2, entries);
    const auto    elastic = make_material<1>("hypo-elastic", 1000., 0.2, {});
    Point<1>      point(*model), reference(*elastic);
    Tensor<2, 1>  L;
    L[0][0]                = -1e-4;
    unsigned int n_elastic = 0, n_plastic = 0;
    for (unsigned int n = 0; n < 500; ++n)
      {
        point.step(*model, L);
        reference.step(*elastic, L);
        const double axial   = point.state.stress[0][0];
        const double lateral = point.state.out_of_plane_stress;
        if (point.variables[0] == 0.)
          {
            check(std::abs(axial - reference.state.stress[0][0]) <
                      1e-13 * std::abs(axial) &&
                    std::abs(lateral - reference.state.out_of_plane_stress) <
                      1e-13 * std::abs(axial),
                  "oedometer: elastic steps differ from hypo-elastic");
            ++n_elastic;
          }
        else
          {
            const double active = (2. * std::sqrt(3.) / 2. + axial * 0.5) / 1.5;
            check(std::abs(lateral - active) < 1e-12 * std::abs(axial),
                  "oedometer: lateral stress off the Mohr-Coulomb line");
            ++n_plastic;
          }
      }
    check(n_elastic > 0 && n_plastic > 0,
          "oedometer: both regimes must be reached");
    deallog << "Mohr-Coulomb oedometer (1D): " << n_elastic
            << " elastic steps, then lateral / axial stress = "
            << rounded(point.state.out_of_plane_stress /
                         point.state.stress[0][0],
                       6)
            << " at 5 % compression, on the active line" << std::endl;
  }

  // ---------------------------------------------------------------------
  // 4. Objectivity of the predictor
  // ---------------------------------------------------------------------

  struct Invariants
  {
    double p, J2, J3;
  };

  Invariants
  invariants(const SymmetricTensor<2, 3> &stress)
  {
    const SymmetricTensor<2, 3> s = deviator(stress);
    return {trace(stress) / 3., 0.5 * (s * s), determinant(s)};
  }

  /**
   * Rotation by @p angle about the unit vector @p axis (Rodrigues).
   */
  Tensor<2, 3>
  rotation(const Tensor<1, 3> &axis, const double angle)
  {
    Tensor<2, 3> K;
    K[0][1] = -axis[2];
    K[0][2] = axis[1];
    K[1][0] = axis[2];
    K[1][2] = -axis[0];
    K[2][0] = -axis[1];
    K[2][1] = axis[0];
    return Tensor<2, 3>(unit_symmetric_tensor<3>()) + std::sin(angle) * K +
           (1. - std::cos(angle)) * K * K;
  }

  /**
   * Rotate a stressed point rigidly by 90 degrees about @p axis in
   * @p n_steps steps (L = omega [axis]_x, omega dt = pi / (2 n_steps)) and
   * return the largest change of p, J2, J3 relative to |sigma|, J2,
   * J2^(3/2); check the final stress
   * against Q sigma_0 Q^T, Q the rotation by the angle of the Hughes-Winget
   * steps, n_steps 2 atan(omega dt / 2), if @p exact.
   */
  template <int dim>
  double
  rotate(const Material<dim>         &model,
         const SymmetricTensor<2, 3> &sigma_0,
         const Tensor<1, 3>          &axis,
         const unsigned int           n_steps,
         const bool                   exact)
  {
    Point<dim> point(model);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        point.state.stress[i][j] = sigma_0[i][j];
    point.state.out_of_plane_stress = (dim < 3) ? sigma_0[2][2] : 0.;
    const double       omega_dt     = M_PI / 2. / n_steps;
    Tensor<2, dim>     L;
    const Tensor<2, 3> spin = rotation(axis, 1.) - rotation(axis, -1.);
    // [axis]_x = (R(1) - R(-1)) / (2 sin 1).
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        L[i][j] = omega_dt * spin[i][j] / (2. * std::sin(1.));
    const Invariants before = invariants(sigma_0);
    for (unsigned int n = 0; n < n_steps; ++n)
      point.step(model, L);
    const SymmetricTensor<2, 3> sigma = stress_3d(point.state);
    const Invariants            after = invariants(sigma);
    const double                scale = sigma_0.norm();
    if (exact)
      {
        const Tensor<2, 3> Q =
          rotation(axis, n_steps * 2. * std::atan(omega_dt / 2.));
        const Tensor<2, 3> expected = Q * Tensor<2, 3>(sigma_0) * transpose(Q);
        check((Tensor<2, 3>(sigma) - expected).norm() < 1e-12 * scale,
              "rotation: stress differs from Q sigma_0 Q^T");
        check(point.variables.empty() || point.variables[0] == 0.,
              "rotation: plastic strain in a rigid rotation");
      }
    // Changes relative to the natural scales |sigma|, J2, J2^(3/2) (round-off
    // in J3 is of the order of J2^(3/2) even where J3 itself is smaller).
    return std::max(
      {std::abs(after.p - before.p) / scale,
       std::abs(after.J2 - before.J2) / before.J2,
       std::abs(after.J3 - before.J3) / std::pow(before.J2, 1.5)});
  }

  void
  test_rotation()
  {
    // A stress inside all three yield surfaces (von Mises sigma_y = 10,
    // Drucker-Prager and Mohr-Coulomb phi = 30, c = 1), eigenvalues
    // distinct, J3 != 0.
    SymmetricTensor<2, 3> sigma_3d;
    sigma_3d[0][0]                 = -5.;
    sigma_3d[1][1]                 = -4.;
    sigma_3d[2][2]                 = -8.;
    sigma_3d[0][1]                 = 0.7;
    sigma_3d[0][2]                 = 0.3;
    sigma_3d[1][2]                 = -0.5;
    SymmetricTensor<2, 3> sigma_2d = sigma_3d;
    sigma_2d[0][2] = sigma_2d[1][2] = 0.;
    Tensor<1, 3> axis_3d, axis_2d;
    axis_3d[0] = 1. / 3.;
    axis_3d[1] = 2. / 3.;
    axis_3d[2] = 2. / 3.;
    axis_2d[2] = 1.;

    const Entries frictional{{"Friction angle", "30"}, {"Cohesion", "1"}};
    const std::vector<std::pair<std::string, Entries>> models{
      {"von Mises", {{"Yield stress", "10"}}},
      {"Drucker-Prager", frictional},
      {"Mohr-Coulomb", frictional}};
    // 1000 steps, each adding a rounding error of a few 1e-16 relatively:
    // the invariants are kept to 1e-12.
    const unsigned int n_steps = 1000;
    for (const auto &m : models)
      {
        const double change_3d =
          rotate<3>(*make_material<3>(m.first, 1000., 0.3, m.second),
                    sigma_3d,
                    axis_3d,
                    n_steps,
                    true);
        const double change_2d =
          rotate<2>(*make_material<2>(m.first, 1000., 0.3, m.second),
                    sigma_2d,
                    axis_2d,
                    n_steps,
                    true);
        check(change_3d < 1e-12 && change_2d < 1e-12,
              m.first + ": rigid rotation changes the invariants");
        deallog << m.first
                << ": rigid rotation by 90 degrees keeps p, J2, J3 to 1e-12"
                << std::endl;
      }
    // For comparison, the explicit rotation sigma + W sigma - sigma W of
    // HypoElastic: J2 grows by a factor (1 + O(omega dt)^2) per step,
    // about 1 + (pi / 2)^2 / n_steps = 1 + 2.5e-3 in all.
    const double change_hypo =
      rotate<3>(*make_material<3>("hypo-elastic", 1000., 0.3, {}),
                sigma_3d,
                axis_3d,
                n_steps,
                false);
    check(change_hypo > 1e-3, "hypo-elastic: rotation should change J2");
    deallog << "hypo-elastic (explicit rotation): largest relative change of "
               "p, J2, J3 = "
            << rounded(change_hypo, 2) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  test_uniaxial_von_mises();
  test_simple_shear_drucker_prager();
  test_oedometer_mohr_coulomb();
  test_rotation();
}
