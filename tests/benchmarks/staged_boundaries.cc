// Boundary conditions that a stage switches off (Stage NAME/Boundaries),
// against closed forms: an elastic column [0, 1] x [0, 4] (E = 10 MPa,
// nu = 0.3, rho = 2000, 0.25 m cells, 2 x 2 points per cell, lumped mass)
// in a grid that reaches 0.5 m below it, its sides on rollers (slip,
// Boundaries left and right), its base held by the condition base (Type =
// fixed on the row of vertices at y = 0), gravity 10 m/s^2 down.
// 1. settle (to t = 3.5 s, local damping 0.1): the column settles by
//    u_y(Y) = -rho g (H Y - Y^2 / 2) / M, M = E (1 - nu) / ((1 + nu) (1 - 2
//    nu)), every point within 1 % of the top's settlement, and the base's
//    reaction in y is the weight m g (within 0.5 %).
// 2. drop (Boundaries = left, right; no damping; to t = 3.6 s): the base
//    no longer holds the column, which falls: nothing acts on it in y but
//    gravity, so its momentum in y changes by exactly -m g (3.6 - 3.5) (to
//    round-off, 1e-9 of it), the base's reaction is zero (every component)
//    and its lowest point has fallen by more than 0.8 g t^2 / 2.

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>

#include <map>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using Layout     = PropertyLayout<2>;
  const double rho = 2000., E = 10e6, nu = 0.3, H = 4., g = 10.;
  const double M         = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  const double mass      = rho * H * 1.;
  const double top       = rho * g * H * H / (2. * M);
  auto         simulator = simulator_from_text<2>(R"(
set Dimension       = 2
set Problem         = custom
set Method          = MPM
set Shape functions = linear
set Mass matrix     = lumped
set Bodies          = column
set Boundaries      = left, right, base
set Stages          = settle, drop
subsection Time
  set Time step = auto
end
subsection Mesh
  set Lower corner = 0, -0.5
  set Upper corner = 1, 4.5
  set Subdivisions = 4, 20
end
subsection Material
  set Model           = linear elastic
  set Young's modulus = 10e6
  set Poisson's ratio = 0.3
  set Density         = 2000
end
subsection Body column
  set Shape        = box
  set Lower corner = 0, 0
  set Upper corner = 1, 4
end
subsection Gravity
  set Vector = 0, -10
end
subsection Boundary left
  set Type         = slip
  set Boundary ids = 0
end
subsection Boundary right
  set Type         = slip
  set Boundary ids = 1
end
subsection Boundary base
  set Type             = fixed
  set Box lower corner = -0.1, -0.05
  set Box upper corner = 1.1, 0.05
end
subsection Damping
  set Local damping coefficient = 0.1
end
subsection Stage settle
  set End time = 3.5
end
subsection Stage drop
  set End time                  = 3.6
  set Boundaries                = left, right
  set Local damping coefficient = 0
end
subsection Output
  set Directory          = output-staged-boundaries
  set Format             = none
  set Overwrite          = true
  set Time interval      = 0.05
  set Write particle CSV = false
end
)");
  // Per output step: the base's reaction, the momentum in y, the largest
  // error of the settlement against the exact one and the lowest point.
  struct AtStep
  {
    Tensor<1, 2> base_reaction;
    double       momentum = 0, error = 0, lowest = 0;
  };
  std::map<unsigned int, AtStep> at_step;
  simulator->run([&](const unsigned int step, const Statistics<2> &stats) {
    AtStep here;
    here.base_reaction = stats.boundary_reactions[2].first;
    here.momentum      = stats.momentum[1];
    here.lowest        = std::numeric_limits<double>::max();
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const Point<2>     X(Layout::get_vector(particle.get_properties(),
                                            Layout::initial_position));
        const Tensor<1, 2> u     = particle.get_location() - X;
        const double       exact = -rho * g * (H * X[1] - X[1] * X[1] / 2.) / M;
        here.error  = std::max(here.error, std::abs(u[1] - exact) / top);
        here.lowest = std::min(here.lowest, particle.get_location()[1]);
      }
    at_step[step] = here;
  });
  std::vector<AtStep> ends;
  std::vector<double> end_times;
  for (const auto &row : stage_rows("output-staged-boundaries"))
    {
      ends.push_back(at_step.at(std::stoul(row[0])));
      end_times.push_back(std::stod(row[5]));
    }
  check(ends.size() == 2, "the column has not two stages");
  const double fall    = -mass * g * (end_times[1] - end_times[0]);
  const double change  = ends[1].momentum - ends[0].momentum;
  const double lowest0 = ends[0].lowest;
  deallog << "settle: settlement error " << rounded(100. * ends[0].error, 2)
          << " % of rho g H^2 / (2 M) = " << rounded(top)
          << " m, base reaction / (m g) "
          << rounded(ends[0].base_reaction[1] / (mass * g), 4) << "; drop for "
          << end_times[1] - end_times[0] << " s: momentum change / (-m g t) "
          << rounded(change / fall, 9) << ", base reaction "
          << ends[1].base_reaction << ", lowest point from "
          << rounded(lowest0, 4) << " to " << rounded(ends[1].lowest, 4) << " m"
          << std::endl;
  check(ends[0].error < 0.01, "the settlement under gravity is not exact");
  check(std::abs(ends[0].base_reaction[1] / (mass * g) - 1.) < 0.005,
        "the base does not carry the column's weight");
  check(std::abs(change / fall - 1.) < 1e-9,
        "something other than gravity acted on the falling column");
  check(ends[1].base_reaction.norm() == 0.,
        "the base switched off has a reaction");
  const double t = end_times[1] - end_times[0];
  check(ends[1].lowest < lowest0 - 0.8 * g * t * t / 2.,
        "the column did not fall");
}
