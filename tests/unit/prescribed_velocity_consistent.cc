// A prescribed velocity enters the consistent mass solve as an
// inhomogeneous constraint, against a hand computation.
//
// Two linear cells [0, 1] and [1, 2] of material at rest (no stress, no
// gravity, so f = 0 and q = 0), the left end moved at v = 1 from t = 0.
// The first step's accelerations solve M a = 0 with a_0 = (1 - 0) / dt:
//   a_0 = 1 / dt,  [M_11 M_12; M_21 M_22] (a_1, a_2) = -(M_10, M_20) a_0,
// with M_ij = sum_p m_p phi_i(x_p) phi_j(x_p) summed here from the points'
// positions and the hat functions. The free nodes accelerate through the
// mass coupling: a_1 < 0, a_2 > 0. With the condition applied after the
// solve (the nodal treatment) they would stay at rest. With a lumped mass
// matrix the free nodes do not couple to the prescribed one: a_1 = a_2 = 0.
// The reaction of the condition is what the constrained row leaves over,
// (M a - f)_0 = sum_j M_0j a_j (lumped: (sum_j M_0j) a_0).

#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

const std::string parameters = R"(
set Dimension = 1
set Problem = custom
set Update scheme = USL
set Boundaries = left
subsection Time
  set End time = 0.1
  set Time step = 0.1
end
subsection Output
  set Interval = 1
end
subsection Mesh
  set Lower corner = 0
  set Upper corner = 2
  set Subdivisions = 2
end
subsection Particles
  set Particles per cell = 4
end
subsection Material
  set Young's modulus = 1
  set Density = 1
end
subsection Boundary left
  set Type = velocity
  set Boundary ids = 0
  set Velocity = 1
end
)";

void
expect(const std::string &what, const double computed, const double exact)
{
  check(std::abs(computed - exact) < 1e-12 * std::max(1., std::abs(exact)),
        what + " = " + std::to_string(computed) + ", by hand " +
          std::to_string(exact));
  deallog << what << " = " << computed << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using Layout    = PropertyLayout<1>;
  const double dt = 0.1;
  for (const std::string mass_matrix : {"consistent", "lumped"})
    {
      auto simulator =
        make_simulator<1>("",
                          parameters + "set Mass matrix = " + mass_matrix,
                          "output-" + mass_matrix);
      // The mass matrix from the points' positions at the start of the step.
      double M[3][3] = {};
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const double x = particle.get_location()[0];
          const double m = particle.get_properties()[Layout::mass];
          double       phi[3];
          phi[0] = std::max(1. - x, 0.);
          phi[1] = 1. - std::abs(x - 1.);
          phi[2] = std::max(x - 1., 0.);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              M[i][j] += m * phi[i] * phi[j];
        }
      double reaction = 0.;
      simulator->run([&](const unsigned int step, const Statistics<1> &stats) {
        if (step == 1)
          reaction = stats.boundary_reactions.at(0).first[0];
      });

      double a[3] = {1. / dt, 0., 0.};
      if (mass_matrix == "consistent")
        {
          const double det = M[1][1] * M[2][2] - M[1][2] * M[2][1];
          const double b1  = -M[1][0] * a[0];
          const double b2  = -M[2][0] * a[0];
          a[1]             = (M[2][2] * b1 - M[1][2] * b2) / det;
          a[2]             = (M[1][1] * b2 - M[2][1] * b1) / det;
          check(a[1] < -0.1 / dt && a[2] > 0.1 / dt,
                "the hand solution couples the free nodes");
        }
      const auto &system = simulator->nodal_system();
      for (unsigned int i = 0; i < 3; ++i)
        expect(mass_matrix + " acceleration " + std::to_string(i),
               system.acceleration[0].local_element(i),
               a[i]);
      const double row_sum = M[0][0] + M[0][1] + M[0][2];
      expect(mass_matrix + " reaction",
             reaction,
             mass_matrix == "consistent" ?
               M[0][0] * a[0] + M[0][1] * a[1] + M[0][2] * a[2] :
               row_sum * a[0]);
      expect(mass_matrix + " prescribed velocity at the end of the step",
             system.velocity[0].local_element(0),
             1.);
    }
}
