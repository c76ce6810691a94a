// The return mapping of Mohr-Coulomb on three-dimensional trial stresses,
// against closed forms (von Mises and Drucker-Prager: return_mapping.cc;
// tolerances: return_mapping.h):
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

#include <mpm_otm/materials/mohr_coulomb.h>

#include "return_mapping.h"

using namespace ReturnMappingTests;

namespace
{
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
