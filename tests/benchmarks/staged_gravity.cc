// Gravity that stages change (Stage NAME/Gravity), against closed forms, on
// the elastic column of prm/surface-load-column.prm ([0, 1] x [0, 4], E =
// 10 MPa, nu = 0.3, rho = 2000, local damping 0.1) with its surface load
// switched off (Surface loads = none) and its base on rollers as its sides
// (so that each reaction is that of one direction: a node that two
// conditions share counts in the reactions of both, and at the corners the
// slip of one side takes x, that of the base y):
// 1. weightless: no gravity until t = 0.2 s; no point moves.
// 2. gravity: Gravity = 0, -10 at once, until at rest. Exact: the column
//    settles by u_y(Y) = -rho g (H Y - Y^2 / 2) / M, M = E (1 - nu) / ((1 +
//    nu) (1 - 2 nu)), 11.9 mm at the top; every point within 1 % of the
//    top's settlement.
// 3. seismic: Gravity = 3, -10 (a pseudo-static horizontal coefficient of
//    0.3), until at rest: the walls carry the horizontal body force, the
//    sum of their reactions in x is -m g_x = -24 kN/m (within 0.5 %), the
//    base's in y still -m g_y (within 0.5 %), and the settlement is that of
//    stage 2 (within 1 %).

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
  using Layout      = PropertyLayout<2>;
  const double  rho = 2000., E = 10e6, nu = 0.3, H = 4., g_x = 3., g_y = -10.;
  const double  M    = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  const double  mass = rho * H * 1.;
  const double  top  = -rho * g_y * H * H / (2. * M);
  std::ifstream file(prm_file("surface-load-column.prm"));
  std::stringstream contents;
  contents << file.rdbuf();
  auto simulator = simulator_from_text<2>(contents.str() + R"(
set Stages = weightless, gravity, seismic
subsection Time
  set End time = 1e-3
end
subsection Boundary base
  set Type = slip
end
subsection Stage weightless
  set End time      = 0.2
  set Surface loads = none
end
subsection Stage gravity
  set End time    = 4
  set End at rest = true
  set Gravity     = 0, -10
end
subsection Stage seismic
  set End time    = 8
  set End at rest = true
  set Gravity     = 3, -10
end
subsection Quasi-static end
  set Kinetic energy ratio = 1e-7
end
subsection Monitoring
  set Points =
end
subsection Output
  set Directory          = output-staged-gravity
  set Format             = none
  set Overwrite          = true
  set Write particle CSV = false
end
)");
  // Per output step: the walls' reaction in x and the base's in y, the largest
  // displacement and the largest error of the settlement against the exact one.
  struct AtStep
  {
    Tensor<1, 2> reactions;
    double       largest = 0, error = 0;
  };
  std::map<unsigned int, AtStep> at_step;
  simulator->run([&](const unsigned int step, const Statistics<2> &stats) {
    AtStep here;
    // Boundaries left, right, base.
    here.reactions[0] = stats.boundary_reactions[0].first[0] +
                        stats.boundary_reactions[1].first[0];
    here.reactions[1] = stats.boundary_reactions[2].first[1];
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const Point<2>     X(Layout::get_vector(particle.get_properties(),
                                            Layout::initial_position));
        const Tensor<1, 2> u = particle.get_location() - X;
        const double exact   = rho * g_y * (H * X[1] - X[1] * X[1] / 2.) / M;
        here.largest         = std::max(here.largest, u.norm());
        here.error = std::max(here.error, std::abs(u[1] - exact) / top);
      }
    at_step[step] = here;
  });
  std::vector<AtStep> ends;
  std::string         how_ended;
  for (const auto &row : stage_rows("output-staged-gravity"))
    {
      ends.push_back(at_step.at(std::stoul(row[0])));
      how_ended += (how_ended.empty() ? "" : ", ") + row[2] + ": " + row[6];
    }
  check(ends.size() == 3, "the column has not three stages");
  deallog << "stages " << how_ended << "; weightless: largest displacement "
          << ends[0].largest << " m; gravity: settlement error "
          << rounded(100. * ends[1].error, 2)
          << " % of rho g H^2 / (2 M) = " << rounded(top)
          << " m, reactions / (m g) "
          << rounded(ends[1].reactions[1] / (-mass * g_y), 4)
          << "; seismic: reactions / (m g) "
          << rounded(ends[2].reactions[0] / (-mass * g_x), 4) << ", "
          << rounded(ends[2].reactions[1] / (-mass * g_y), 4)
          << ", settlement error " << rounded(100. * ends[2].error, 2) << " %"
          << std::endl;
  check(ends[0].largest == 0., "the column moved without gravity");
  check(ends[1].error < 0.01, "the settlement under gravity is not exact");
  check(std::abs(ends[1].reactions[1] / (-mass * g_y) - 1.) < 0.005,
        "the reactions do not carry the column's weight");
  check(std::abs(ends[2].reactions[0] / (-mass * g_x) - 1.) < 0.005 &&
          std::abs(ends[2].reactions[1] / (-mass * g_y) - 1.) < 0.005,
        "the reactions do not carry the seismic body force");
  check(ends[2].error < 0.01,
        "the settlement changed under the horizontal body force");
}
