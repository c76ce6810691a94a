// Bodies of Problem = custom seeded on box grids of quadrilaterals and of
// triangles: a disk (Shape = ball, and the same disk as a level set) and an
// L-shaped polygon of two materials' densities, each with the mass
// density x area that the seeding pattern allows.
//  - The L-shape's corners lie on block boundaries, so whole blocks are
//    filled and its mass is rho x area to round-off (of a sum of up to 1e4
//    point masses: 1e-11 relative).
//  - The disk's mass must be rho s^2 times the number of the pattern's
//    points (spacing s) in it, counted here by hand. A point of the
//    pattern stands for a square of side s around it; only the squares that the
//    disk's circle crosses can be counted wrongly, and a curve of length P
//    crosses at most 4 (P / s + 1) of them, so |m - rho pi R^2| <= rho 4 (P / s
//    + 1) s^2. The error need not fall monotonically with s (the pattern's
//    squares and the circle meet differently on every grid), but it must fall
//    to below half when s falls by 4.
//  - The disk as a level set gets exactly the points of the ball.
//  - Every point carries its body's material id, and a geostatic stress of
//    the L-shape (g = -10, K0 = 0.5) is -rho g (top - y) at each point (the
//    top at x is 1 for x < 1 and 2 above the L's tall part).
//  - The disk (Drucker-Prager, phi = 40 deg, geostatic without a Lateral
//    stress ratio) has the vertical stress -rho g (1 + sqrt(0.36 - (x -
//    3)^2) - y) of the material above it on the circle and the default K0 of
//    a frictional material, 1 - sin(phi) = 0.357, times it horizontally and
//    out of the plane.

#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

struct Seeded
{
  double       mass_per_material[3] = {0, 0, 0};
  unsigned int n_points             = 0;
  double       largest_stress_error = 0;
};

Seeded
seed(const std::string &cell_type,
     const unsigned int subdivisions,
     const std::string &disk_shape)
{
  const std::string disk =
    disk_shape == "ball" ?
      "  set Shape = ball\n  set Centre = 3, 1\n  set Radius = 0.6\n" :
      "  set Shape = level set\n  set Level set = (x-3)^2 + (y-1)^2 - 0.36\n";
  auto        simulator = make_simulator<2>("",
                                     R"(
set Dimension = 2
set Problem = custom
set Materials = heavy
set Bodies = L, disk
subsection Mesh
  set Cell type = )" + cell_type + R"(
  set Lower corner = 0, 0
  set Upper corner = 4, 2
  set Subdivisions = )" + std::to_string(2 * subdivisions) +
                                       ", " + std::to_string(subdivisions) +
                                       R"(
end
subsection Particles
  set Particles per cell = 2
end
subsection Material
  set Model = Drucker-Prager
  set Density = 2
  subsection Drucker-Prager
    set Friction angle = 40
  end
end
subsection Material heavy
  set Model = hypo-elastic
  set Density = 5
end
subsection Gravity
  set Vector = 0, -10
end
subsection Body L
  set Shape = polygon
  set Vertices = 0, 0; 2, 0; 2, 1; 1, 1; 1, 2; 0, 2
  set Material = heavy
  set Initial stress = geostatic
  set Lateral stress ratio = 0.5
end
subsection Body disk
)" + disk + R"(
  set Initial stress = geostatic
end
subsection Time
  set Time step = 1e-6
end
)",
                                     "output-" + cell_type);
  Seeded      result;
  const auto &points = simulator->material_points();
  for (const auto &particle : points.particle_handler())
    {
      using Layout                  = PropertyLayout<2>;
      const auto         properties = particle.get_properties();
      const unsigned int id         = Layout::get_material_id(properties);
      result.mass_per_material[id] += properties[Layout::mass];
      ++result.n_points;
      const Point<2> X = particle.get_location();
      check((id == 1) == (X[0] < 2. && X[1] < 2.),
            "material id of the point at " + Utilities::to_string(X[0]));
      // The weight of the material above, times the body's K0.
      const double top = id == 1 ?
                           (X[0] < 1. ? 2. : 1.) :
                           1. + std::sqrt(0.36 - std::pow(X[0] - 3., 2));
      const double sv  = -(id == 1 ? 5. : 2.) * 10. * (top - X[1]);
      const double K0 = id == 1 ? 0.5 : 1. - std::sin(40. * numbers::PI / 180.);
      const auto   sigma = Layout::get_stress(properties);
      result.largest_stress_error =
        std::max({result.largest_stress_error,
                  std::abs(sigma[1][1] - sv),
                  std::abs(sigma[0][0] - K0 * sv),
                  std::abs(sigma[0][1]),
                  std::abs(properties[Layout::out_of_plane_stress] - K0 * sv)});
    }
  return result;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double disk_area = numbers::PI * 0.36;
  for (const std::string cell_type : {"hypercube", "simplex"})
    {
      double previous_error = 0;
      for (const unsigned int n : {10u, 20u, 40u})
        {
          const Seeded ball     = seed(cell_type, n, "ball");
          const Seeded levelset = seed(cell_type, n, "level set");
          // Block size 2 / n, 2 x 2 points per block.
          const double s = 1. / n;
          // Round-off of the sum of up to 1e4 point masses.
          check(std::abs(ball.mass_per_material[1] - 5. * 3.) < 1e-11 * 15.,
                cell_type + ": the L-shape's mass is not rho A = 15");
          check(std::max(ball.largest_stress_error,
                         levelset.largest_stress_error) < 1e-9,
                cell_type + ": geostatic stress of a body differs by " +
                  std::to_string(ball.largest_stress_error));
          // The pattern's points: (i + 1/2, j + 1/2) s; those in the disk
          // times rho s^2 are its mass.
          unsigned int inside = 0;
          for (unsigned int i = 0; i < 4 * n; ++i)
            for (unsigned int j = 0; j < 2 * n; ++j)
              inside += (std::pow((i + 0.5) * s - 3., 2) +
                           std::pow((j + 0.5) * s - 1., 2) <=
                         0.36);
          check(std::abs(ball.mass_per_material[0] - 2. * s * s * inside) <
                  1e-11 * 2. * disk_area,
                cell_type + ": the disk's mass is not that of the pattern's "
                            "points in it");
          const double error =
            std::abs(ball.mass_per_material[0] - 2. * disk_area);
          const double bound =
            2. * 4. * (2. * numbers::PI * 0.6 / s + 1.) * s * s;
          check(error <= bound,
                cell_type + ": disk mass error above the pattern's bound");

          check(levelset.n_points == ball.n_points &&
                  levelset.mass_per_material[0] == ball.mass_per_material[0],
                cell_type + ": the level-set disk differs from the ball");
          if (n == 10)
            previous_error = error;
          else if (n == 40)
            check(error < 0.5 * previous_error,
                  cell_type + ": the disk mass error does not fall when "
                              "the point spacing falls by 4");
          deallog << cell_type << ", point spacing " << s
                  << ": disk mass relative error "
                  << rounded(error / (2. * disk_area), 2) << " (bound "
                  << rounded(bound / (2. * disk_area), 2) << "), L-shape mass "
                  << ball.mass_per_material[1] << std::endl;
        }
    }
}
