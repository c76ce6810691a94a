// A prescribed velocity enters the consistent mass solves (accelerations
// and velocities) as an inhomogeneous constraint, against a hand
// computation, for USL and MUSL.
//
// Two linear cells [0, 1] and [1, 2] of stress-free material (no gravity,
// so f = 0) with the initial velocity v0(x) = 2 - 2 x, the left end moved
// at v = 3 from t = 0. With M_ij = sum_p m_p phi_i(x_p) phi_j(x_p) and
// q_i = sum_p m_p phi_i(x_p) v0(x_p), summed here from the points'
// positions and the hat functions, and the lumped masses m_i = sum_j M_ij,
// the first step's accelerations solve M a = 0 with
//   a_0 = (3 - q_0 / m_0) / dt,  M_ff a_f = -M_f0 a_0
// for the free nodes f = 1, 2. They accelerate through the mass coupling
// (a_1 < 0, a_2 > 0); with the condition applied after the solve (the
// nodal treatment) they would not. With a lumped mass matrix the free
// nodes do not couple to the prescribed one: a_1 = a_2 = 0. The reaction
// of the condition is what the constrained row leaves over,
// (M a - f)_0 = sum_j M_0j a_j (lumped: m_0 a_0).
//
// The velocities at the end of the step are solved with the prescribed
// value as a constraint too. With a consistent mass matrix USL (M v^s = q
// with v^s_0 = 3 - dt a_0, then v = v^s + dt a) and MUSL (M v = q + dt M a
// with v_0 = 3, where (M a)_f = f_f = 0) both give the constrained
// projection
//   M_ff v_f = q_f - 3 M_f0.
// Solving M v^s = q unconstrained and setting v_0 = 3 afterwards would give
// v_f = v0(x_f) + dt a_f instead (M reproduces the linear field), which
// differs by M_ff^-1 M_f0 (v0(0) - q_0 / m_0). With a lumped mass matrix
// USL gives v_f = q_f / m_f and MUSL (q_f + dt M_f0 a_0) / m_f.

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
subsection Custom problem
  set Initial velocity = 2 - 2*x
end
subsection Material
  set Young's modulus = 1
  set Density = 1
end
subsection Boundary left
  set Type = velocity
  set Boundary ids = 0
  set Velocity = 3
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

// The solution x_f of M_ff x_f = b_f for the free nodes 1 and 2.
std::array<double, 2>
solve_free(const double (&M)[3][3], const double b1, const double b2)
{
  const double det = M[1][1] * M[2][2] - M[1][2] * M[2][1];
  return {(M[2][2] * b1 - M[1][2] * b2) / det,
          (M[1][1] * b2 - M[2][1] * b1) / det};
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using Layout    = PropertyLayout<1>;
  const double dt = 0.1;
  for (const std::string scheme : {"USL", "MUSL"})
    for (const std::string mass_matrix : {"consistent", "lumped"})
      {
        const std::string name = scheme + " " + mass_matrix;
        auto              simulator =
          make_simulator<1>("",
                            parameters + "set Mass matrix = " + mass_matrix +
                              "\nset Update scheme = " + scheme,
                            "output-" + scheme + "-" + mass_matrix);
        // The mass matrix and momenta from the points at the start of the
        // step.
        double M[3][3] = {}, q[3] = {};
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
              {
                q[i] += m * phi[i] * (2. - 2. * x);
                for (unsigned int j = 0; j < 3; ++j)
                  M[i][j] += m * phi[i] * phi[j];
              }
          }
        double reaction = 0.;
        simulator->run(
          [&](const unsigned int step, const Statistics<1> &stats) {
            if (step == 1)
              reaction = stats.boundary_reactions.at(0).first[0];
          });

        double m[3];
        for (unsigned int i = 0; i < 3; ++i)
          m[i] = M[i][0] + M[i][1] + M[i][2];
        double a[3] = {(3. - q[0] / m[0]) / dt, 0., 0.};
        double v[3] = {3., q[1] / m[1], q[2] / m[2]};
        if (mass_matrix == "consistent")
          {
            const auto a_free = solve_free(M, -M[1][0] * a[0], -M[2][0] * a[0]);
            a[1]              = a_free[0];
            a[2]              = a_free[1];
            check(a[1] < -0.1 / dt && a[2] > 0.1 / dt,
                  "the hand solution couples the free nodes");
            const auto v_free =
              solve_free(M, q[1] - 3. * M[1][0], q[2] - 3. * M[2][0]);
            v[1] = v_free[0];
            v[2] = v_free[1];
            // What the velocity solve without the constraint would give.
            for (unsigned int i = 1; i < 3; ++i)
              check(std::abs(v[i] - (2. - 2. * i + dt * a[i])) > 0.05,
                    "the constrained velocity differs from the velocity "
                    "corrected after the solve");
          }
        else if (scheme == "MUSL")
          for (unsigned int i = 1; i < 3; ++i)
            v[i] = (q[i] + dt * M[i][0] * a[0]) / m[i];

        const auto &system = simulator->nodal_system();
        for (unsigned int i = 0; i < 3; ++i)
          expect(name + " acceleration " + std::to_string(i),
                 system.acceleration[0].local_element(i),
                 a[i]);
        expect(name + " reaction",
               reaction,
               mass_matrix == "consistent" ?
                 M[0][0] * a[0] + M[0][1] * a[1] + M[0][2] * a[2] :
                 m[0] * a[0]);
        for (unsigned int i = 0; i < 3; ++i)
          expect(name + " velocity at the end of the step " + std::to_string(i),
                 system.velocity[0].local_element(i),
                 v[i]);
      }
}
