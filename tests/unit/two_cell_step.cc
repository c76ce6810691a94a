// MPM steps on a two-cell 1D problem against values computed by hand, and
// the consistent mass matrix reproducing a linear velocity field exactly.
//
// Cells [0, 1] and [1, 2], one point per cell at X = 0.5 and 1.5 with
// V = m = 1, v(X) = X, E = 1, lumped mass, USL, dt = 0.1:
//   nodal masses     (0.5, 1, 0.5)
//   nodal momenta    (0.25, 1, 0.75)  ->  nodal velocities (0.5, 1, 1.5)
//   forces 0 (no stress yet), so a = 0 and the points move by
//   dt (0.75, 1.25); grad v = 0.5 in both, F = 1.05, sigma = E (F - 1) =
//   0.05, V = 1.05.
// Second step: f = -sum_p V_p sigma_p dphi_i/dx = (0.0525, 0, -0.0525).

#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

const std::string parameters = R"(
set Dimension = 1
set Problem = custom
set Update scheme = USL
set Mass matrix = lumped
subsection Time
  set End time = 0.2
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
  set Particles per cell = 1
end
subsection Material
  set Young's modulus = 1
  set Density = 1
end
subsection Custom problem
  set Initial velocity = x
end
)";

void
expect(const std::string &what, const double computed, const double exact)
{
  check(std::abs(computed - exact) < 1e-13,
        what + " = " + std::to_string(computed) + ", by hand " +
          std::to_string(exact));
  deallog << what << " = " << computed << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using Layout = PropertyLayout<1>;
  {
    auto simulator      = make_simulator<1>("", parameters, "output-two-steps");
    const auto  &system = simulator->nodal_system();
    const double dt     = 0.1;
    unsigned int observed = 0;
    simulator->run([&](const unsigned int step, const Statistics<1> &) {
      observed += step;
      if (step == 1)
        {
          for (unsigned int i = 0; i < 3; ++i)
            {
              const double mass[3]     = {0.5, 1., 0.5};
              const double momentum[3] = {0.25, 1., 0.75};
              const double velocity[3] = {0.5, 1., 1.5};
              expect("step 1 mass " + std::to_string(i),
                     system.lumped_mass.local_element(i),
                     mass[i]);
              expect("step 1 momentum " + std::to_string(i),
                     system.momentum[0].local_element(i),
                     momentum[i]);
              expect("step 1 force " + std::to_string(i),
                     system.force[0].local_element(i),
                     0.);
              expect("step 1 velocity " + std::to_string(i),
                     system.velocity[0].local_element(i),
                     velocity[i]);
            }
          for (const auto &particle :
               simulator->material_points().particle_handler())
            {
              const auto   properties = particle.get_properties();
              const double X          = properties[Layout::initial_position];
              const double moved      = (X < 1 ? 0.75 : 1.25) * dt;
              expect("point " + std::to_string(X) + " position",
                     particle.get_location()[0],
                     X + moved);
              expect("point " + std::to_string(X) + " stress",
                     properties[Layout::stress],
                     0.05);
              expect("point " + std::to_string(X) + " volume",
                     Layout::volume(properties),
                     1.05);
            }
        }
      if (step == 2)
        {
          const double force[3] = {1.05 * 0.05, 0., -1.05 * 0.05};
          for (unsigned int i = 0; i < 3; ++i)
            expect("step 2 force " + std::to_string(i),
                   system.force[0].local_element(i),
                   force[i]);
        }
    });
    check(observed == 1 + 2, "steps 1 and 2 must both be checked");
  }
  {
    // Four points per cell make the consistent mass matrix regular; the L2
    // projection of the linear velocity v = x onto the linear functions is
    // exact, so M^-1 q gives the nodal values 0, 1, 2.
    auto simulator = make_simulator<1>("",
                                       parameters + R"(
set Mass matrix = consistent
subsection Time
  set End time = 1e-3
  set Time step = 1e-3
end
subsection Particles
  set Particles per cell = 4
end
)",
                                       "output-consistent");
    // No stress yet, so a = 0 and the USL velocities are M^-1 q.
    simulator->run();
    for (unsigned int i = 0; i < 3; ++i)
      expect("consistent projection of v = x, node " + std::to_string(i),
             simulator->nodal_system().velocity[0].local_element(i),
             1. * i);
  }
}
