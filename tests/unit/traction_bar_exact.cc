// The exact solution of the traction bar (B2, journal Eq. 103) against hand
// computations: the traction at the free end is -sin(pi c t / l) while the
// pulse enters and leaves (0 <= c t < 4l) and 0 afterwards; the stress is
// zero ahead of the wave front; the stress doubles at the fixed end during
// the reflection; u(0, t) = 0; du/dX = sigma / M (M = rho c^2 = E for
// nu = 0) by a central difference, before and after the reflection; the
// largest end displacement -2 l / (pi M) at c t = l. Once with the
// benchmark's c = 1 and once with c = 2, l = 2; and the grid checks.

#include <deal.II/base/numbers.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/materials/material.h>
#include <mpm_otm/problems/problem.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

/**
 * A traction bar with its material, built from parameter text as the
 * simulator does, on the grid [lower, upper].
 */
struct Bar
{
  Bar(const std::string &parameters, const double lower, const double upper)
  {
    ParameterHandler prm;
    Simulator<1>::declare_parameters(prm);
    prm.parse_input_from_string(
      "set Problem = traction bar\n" + parameters +
      "subsection Mesh\n set Lower corner = " + Utilities::to_string(lower) +
      "\n set Upper corner = " + Utilities::to_string(upper) +
      "\n set Subdivisions = 4\nend\n");
    problem = PluginRegistry<Problem<1>>::create(prm.get("Problem"));
    problem->parse_parameters(prm);
    prm.enter_subsection("Material");
    material = PluginRegistry<Material<1>>::create(prm.get("Model"));
    material->parse_parameters(prm);
    prm.leave_subsection();
    BackgroundGrid<1> grid;
    grid.parse_parameters(prm);
    grid.create(MPI_COMM_SELF);
    problem->initialize(*material, grid);
  }

  double
  stress(const double X, const double t) const
  {
    return problem->exact_stress(Point<1>(X), t)[0][0];
  }

  double
  displacement(const double X, const double t) const
  {
    return problem->exact_displacement(Point<1>(X), t)[0];
  }

  std::unique_ptr<Problem<1>>  problem;
  std::unique_ptr<Material<1>> material;
};

std::string
parameters(const double length, const double E, const double rho)
{
  return "subsection Traction bar\n set Bar length = " +
         std::to_string(length) +
         "\nend\n"
         "subsection Material\n set Model = neo-Hookean\n"
         " set Poisson's ratio = 0\n set Young's modulus = " +
         std::to_string(E) + "\n set Density = " + std::to_string(rho) +
         "\nend\n";
}

void
expect(const std::string &what,
       const double       computed,
       const double       expected,
       const double       tolerance = 1e-13)
{
  check(std::abs(computed - expected) <= tolerance,
        what + ": " + std::to_string(computed) + ", by hand " +
          std::to_string(expected));
}

void
check_bar(const double length, const double E, const double rho)
{
  const Bar    bar(parameters(length, E, rho), 0., 1.25 * length);
  const double c = std::sqrt(E / rho);
  const double w = numbers::PI / length;
  const double M = E; // nu = 0
  deallog << "l = " << length << ", E = " << E << ", rho = " << rho
          << ", c = " << c << std::endl;

  // The problem's set-up: traction on boundary 1 (X = l), fixed at X = 0.
  check(bar.problem->traction_boundaries() ==
          std::vector<types::boundary_id>{1},
        "traction boundary must be 1");
  const auto fixed = bar.problem->fixed_components();
  check(fixed.size() == 1 && fixed[0].boundary_id == 0 && fixed[0].fixed[0],
        "the bar must be fixed (only) at boundary 0");
  const auto region = bar.problem->material_region().get_boundary_points();
  expect("material region, left", region.first[0], 0.);
  expect("material region, right", region.second[0], length);
  expect("initial velocity",
         bar.problem->initial_velocity(Point<1>(0.5 * length))[0],
         0.);

  // Traction and stress at the free end: -sin(w c t) while the pulse enters
  // (c t < 2l) and leaves (2l <= c t < 4l), zero afterwards.
  for (unsigned int i = 0; i <= 20; ++i)
    {
      const double t        = 0.25 * i * length / c;
      const double expected = (c * t < 4. * length - 1e-12) ?
                                -std::sin(numbers::PI * c * t / length) :
                                0.;
      expect("sigma(l, t = " + std::to_string(t) + ")",
             bar.stress(length, t),
             expected);
      expect("traction(1, t = " + std::to_string(t) + ")",
             bar.problem->traction(1, t)[0],
             expected);
    }

  // Ahead of the front (c t < l - X) the bar is at rest and unstrained.
  for (const double X : {0., 0.2, 0.5, 0.9})
    for (const double ct : {0., 0.05, 0.3, 0.0999})
      if (ct < 1. - X)
        {
          expect("sigma ahead of the front",
                 bar.stress(X * length, ct * length / c),
                 0.);
          expect("u ahead of the front",
                 bar.displacement(X * length, ct * length / c),
                 0.);
        }

  // Reflection at the fixed end doubles the stress: sigma(0, t) =
  // 2 sin(w c t) for l <= c t < 3l.
  for (const double ct : {1.25, 1.5, 2.2, 2.75})
    expect("sigma(0, c t = " + std::to_string(ct) + " l)",
           bar.stress(0., ct * length / c),
           2. * std::sin(numbers::PI * ct));

  // The fixed end does not move.
  for (const double ct : {0., 0.5, 1., 1.3, 2., 2.7, 3.5, 4.2})
    expect("u(0, t)", bar.displacement(0., ct * length / c), 0.);

  // du/dX = sigma / M by central differences, before (c t < l) and after
  // (c t > l) the reflection, away from the kinks of sigma at c t +- X = l,
  // 3l (the difference is exact to O(h^2) there).
  const double h = 1e-5 * length;
  for (const double X : {0.1, 0.35, 0.6, 0.85})
    for (const double ct : {0.3, 0.7, 1.2, 1.55, 2.5, 3.3})
      {
        const double x = X * length, t = ct * length / c;
        const double derivative =
          (bar.displacement(x + h, t) - bar.displacement(x - h, t)) / (2. * h);
        const double error = std::abs(derivative - bar.stress(x, t) / M);
        check(error < 1e-9 / length,
              "du/dX differs from sigma/M at X = " + std::to_string(x) +
                ", t = " + std::to_string(t) + " by " + std::to_string(error));
      }
  deallog << "du/dX = sigma/M at 24 points, before and after the reflection"
          << std::endl;

  // Largest displacement of the free end: u(l, l/c) = -2 l / (pi M), the
  // integral of one half sine wave of the incoming pulse.
  expect("u(l, l/c)",
         bar.displacement(length, length / c),
         -2. / (w * M),
         1e-15);
  deallog << "u(l, l/c) = " << rounded(bar.displacement(length, length / c), 6)
          << ", u(l, 0.4 l/c) = "
          << rounded(bar.displacement(length, 0.4 * length / c), 6)
          << std::endl;
  // After the pulse has left (c t >= 4l) the bar is at rest in its initial
  // configuration.
  for (const double X : {0., 0.3, 0.7, 1.})
    {
      expect("sigma after the pulse",
             bar.stress(X * length, 4.5 * length / c),
             0.);
      expect("u after the pulse",
             bar.displacement(X * length, 4.5 * length / c),
             0.);
    }
}

/**
 * Whether building the bar on [lower, upper] stops with a message
 * containing @p text.
 */
void
check_grid_error(const double       lower,
                 const double       upper,
                 const std::string &text)
{
  try
    {
      Bar bar(parameters(1., 100., 100.), lower, upper);
    }
  catch (const ExceptionBase &error)
    {
      const std::string message = error.what();
      check(message.find(text) != std::string::npos,
            "unexpected message: " + message);
      deallog << "grid [" << lower << ", " << upper << "]: stops with <" << text
              << ">" << std::endl;
      return;
    }
  check(false,
        "the grid [" + std::to_string(lower) + ", " + std::to_string(upper) +
          "] was accepted");
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  check_bar(1., 100., 100.);
  check_bar(2., 400., 100.);
  check_grid_error(-0.5, 1.25, "set Mesh/Lower corner to 0");
  check_grid_error(0., 0.9, "set Mesh/Upper corner to at least 1");
  {
    // The benchmark's grid for the 68 material nodes ends past l.
    Bar bar(parameters(1., 100., 100.), 0., 84. / 67.);
    deallog << "grid [0, 84/67] accepted" << std::endl;
  }
}
