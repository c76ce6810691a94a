// Loads on a body's surface (Surface loads) against closed forms.
//
// 1. prm/surface-load-column.prm: an elastic column [0, 1] x [0, 4], sides
//    on rollers, base fixed, a pressure q = 10 kPa on its top, damped to
//    rest. Exact: sigma_yy = -q and sigma_xx = nu / (1 - nu) sigma_yy at
//    every point, u_y(Y) = -q Y / M. Asserted: the load's force in the
//    statistics is (0, -q x 1 m) to round-off (the points' shares sum to
//    the segment's length); both stresses within 0.2 % of their exact values
//    at every point below the top cell (the two points of a cell weigh
//    lambda_2 h of the compressed column, so the discrete stress is
//    -q / lambda_2, 0.07 % above q) and within 2 % in it (the settlement,
//    3 mm, moves the surface into the top cell, whose points still count it
//    as full: the usual MPM error, which the surface offset keeps to the
//    settlement over the cell size); every point's settlement within 1 % of
//    q H / M of -q Y / M; the mean displacement of the loaded points (the
//    statistics' top_displacement_y) within 1 % of the exact one at their
//    height.
// 2. A neo-Hookean block [0, 1]^2, left side and base on rollers, the rest
//    free, compressed by 20 % of E on its top: by a pressure, which acts on
//    the current area, and by a dead traction of the same value per initial
//    area; Method = Unified, whose grid moves with the material, so that
//    the block deforms homogeneously (on MPM's fixed grid points crossing
//    cells at this strain make the stress noisy). The block widens by the
//    lateral stretch lambda_1 (the mean of x_p / X_p): the pressure's total
//    force is -p lambda_1 w_0 (within 0.5 % of p w_0) and the Cauchy stress
//    sigma_yy = -p, the traction's force -t w_0 (to round-off) and sigma_yy
//    = -t / lambda_1 (both within 1 % of p at every point), the horizontal
//    force below 0.5 % of p w_0; lambda_1 - 1 is above 3 %, so that a
//    pressure that did not follow the surface would fail.
// 3. The column of 1. in stages that switch the load off, on and off again
//    (Stage NAME/Surface loads; see below).

#include <deal.II/base/mpi.h>

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>

#include <map>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  const std::string block = R"(
set Dimension     = 2
set Problem       = custom
set Method        = Unified
set Boundaries    = left, base
set Surface loads = top
subsection Time
  set End time  = 3
  set Time step = auto
end
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 4, 4
end
subsection Material
  set Model           = neo-Hookean
  set Young's modulus = 1e6
  set Poisson's ratio = 0.3
  set Density         = 1000
end
subsection Boundary left
  set Type         = slip
  set Boundary ids = 0
end
subsection Boundary base
  set Type         = slip
  set Boundary ids = 2
end
subsection Damping
  set Local damping coefficient = 0.1
end
subsection Surface load top
  set From = 0, 1
  set To   = 1, 1
)";
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using Layout = PropertyLayout<2>;

  {
    const double q = 10e3, E = 10e6, nu = 0.3, H = 4., h = 0.25;
    const double M          = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
    auto         simulator  = make_simulator<2>("surface-load-column.prm",
                                       "subsection Output\n"
                                                " set Write particle CSV = false\n"
                                                "end\n",
                                       "output-surface-load-column");
    const auto   statistics = simulator->run();
    check(statistics.boundary_names.back() == "top",
          "the load's columns follow the boundaries'");
    const auto [force, displacement] = statistics.boundary_reactions.back();
    // The largest errors of sigma_yy and sigma_xx below the top cell and in
    // it.
    double stress[2] = {0, 0}, lateral[2] = {0, 0}, settlement = 0;
    double loaded_height = 0;
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const auto     properties = particle.get_properties();
        const auto     sigma      = Layout::get_stress(properties);
        const Point<2> X(
          Layout::get_vector(properties, Layout::initial_position));
        const unsigned int top = (X[1] > H - h) ? 1 : 0;
        stress[top]  = std::max(stress[top], std::abs(sigma[1][1] + q) / q);
        lateral[top] = std::max(lateral[top],
                                std::abs(sigma[0][0] + nu / (1. - nu) * q) /
                                  (nu / (1. - nu) * q));
        settlement =
          std::max(settlement,
                   std::abs(particle.get_location()[1] - X[1] + q * X[1] / M) /
                     (q * H / M));
        loaded_height = std::max(loaded_height, X[1]);
      }
    const double mean_error =
      std::abs(displacement[1] + q * loaded_height / M) / (q * H / M);
    deallog << "column: load force_y " << std::fixed << std::setprecision(5)
            << force[1] / q << " q m; sigma_yy error " << std::setprecision(2)
            << 100. * stress[0] << " % of q below the top cell, "
            << 100. * stress[1] << " % in it; sigma_xx error "
            << 100. * lateral[0] << " % below, " << 100. * lateral[1]
            << " % in it; settlement error " << 100. * settlement
            << " % of q H / M; loaded points' mean displacement error "
            << 100. * mean_error << " %" << std::defaultfloat << std::endl;
    check(std::abs(force[0]) < 1e-10 * q && std::abs(force[1] + q) < 1e-10 * q,
          "the load's force is not -q times the top's length");
    check(stress[0] < 2e-3 && lateral[0] < 2e-3,
          "the stress is not the exact one below the top cell");
    check(stress[1] < 2e-2 && lateral[1] < 2e-2,
          "the stress is not the exact one in the top cell");
    check(settlement < 1e-2, "the settlement is not q Y / M");
    check(mean_error < 1e-2,
          "the loaded points' mean displacement is not q Y / M");
  }

  const double p = 2e5;
  for (const std::string load : {"Pressure = 2e5", "Traction = 0; -2e5"})
    {
      auto simulator = simulator_from_text<2>(
        block + " set " + load +
        "\nend\nsubsection Output\n set Directory = output-block\n"
        " set Format = none\n set Overwrite = true\nend\n");
      const auto statistics            = simulator->run();
      const auto [force, displacement] = statistics.boundary_reactions.back();
      // The lateral stretch: the mean of x_p / X_p.
      double       stretch = 0;
      unsigned int n       = 0;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const Point<2> X(Layout::get_vector(particle.get_properties(),
                                              Layout::initial_position));
          stretch += particle.get_location()[0] / X[0];
          ++n;
        }
      stretch /= n;
      const bool   pressure = (load[0] == 'P');
      const double expected = pressure ? -p * stretch : -p;
      // The Cauchy stress: -p for the pressure, -t / lambda_1 for the
      // traction.
      const double sigma_yy = pressure ? -p : -p / stretch;
      double       error    = 0;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        error = std::max(error,
                         std::abs(
                           Layout::get_stress(particle.get_properties())[1][1] -
                           sigma_yy) /
                           p);
      deallog << load << ": lateral stretch " << std::fixed
              << std::setprecision(4) << stretch << ", force_y / (-p w_0) "
              << force[1] / -p << " (exact " << expected / -p
              << "), |force_x| / (p w_0) " << std::abs(force[0]) / p
              << "; sigma_yy error " << std::setprecision(2) << 100. * error
              << " % of p" << std::defaultfloat << std::endl;
      check(stretch > 1.03, "the block does not widen enough to tell");
      check(std::abs(force[0]) < 5e-3 * p, "the load has a horizontal force");
      check(std::abs(force[1] - expected) < (pressure ? 5e-3 : 1e-10) * p,
            "the load's force does not follow the surface as it should");
      check(error < 1e-2, "sigma_yy is not the exact one");
    }

  // 3. The column of 1. in three stages that switch the load (Stage
  //    NAME/Surface loads): none acts to 0.2 s, then the pressure q until the
  //    column is at rest, then none again until it is at rest. Asserted at
  //    the end of each stage: the load's force in the statistics (0, -q x
  //    1 m, 0, to round-off) and the largest error of the points'
  //    settlements against 0, -q Y / M and 0 (no point has moved at all in
  //    the first stage; the others within 1 % of q H / M: the elastic
  //    column springs back).
  {
    const double      q = 10e3, E = 10e6, nu = 0.3, H = 4.;
    const double      M = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
    std::ifstream     file(prm_file("surface-load-column.prm"));
    std::stringstream contents;
    contents << file.rdbuf();
    auto simulator = simulator_from_text<2>(contents.str() + R"(
set Stages = unloaded, loaded, unloading
subsection Time
  set End time = 1e-3
end
subsection Stage unloaded
  set End time      = 0.2
  set Surface loads = none
end
subsection Stage loaded
  set End time      = 2
  set End at rest   = true
  set Surface loads = top
end
subsection Stage unloading
  set End time      = 4
  set End at rest   = true
  set Surface loads = none
end
subsection Quasi-static end
  set Kinetic energy ratio = 1e-8
end
subsection Output
  set Directory          = output-surface-load-stages
  set Format             = none
  set Overwrite          = true
  set Write particle CSV = false
end
)");
    // Per output step: the load's force and the largest settlement error
    // against no load and against q.
    struct AtStep
    {
      Tensor<1, 2> force;
      double       unloaded = 0, loaded = 0;
    };
    std::map<unsigned int, AtStep> at_step;
    simulator->run([&](const unsigned int step, const Statistics<2> &stats) {
      AtStep here;
      here.force = stats.boundary_reactions.back().first;
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const Point<2> X(Layout::get_vector(particle.get_properties(),
                                              Layout::initial_position));
          const double   u = particle.get_location()[1] - X[1];
          here.unloaded    = std::max(here.unloaded, std::abs(u));
          here.loaded =
            std::max(here.loaded, std::abs(u + q * X[1] / M) / (q * H / M));
        }
      here.unloaded = Utilities::MPI::max(here.unloaded, MPI_COMM_WORLD);
      here.loaded   = Utilities::MPI::max(here.loaded, MPI_COMM_WORLD);
      at_step[step] = here;
    });
    std::vector<AtStep> ends;
    std::string         how_ended;
    for (const auto &row : stage_rows("output-surface-load-stages"))
      {
        ends.push_back(at_step.at(std::stoul(row[0])));
        how_ended += (how_ended.empty() ? "" : ", ") + row[2] + ": " + row[6];
      }
    check(ends.size() == 3, "the staged column has not three stages");
    deallog << "stages " << how_ended << "; force_y / q "
            << ends[0].force[1] / q << ", " << ends[1].force[1] / q << ", "
            << ends[2].force[1] / q << "; settlement " << ends[0].unloaded
            << " m, error " << std::fixed << std::setprecision(2)
            << 100. * ends[1].loaded << " % and "
            << 100. * ends[2].unloaded / (q * H / M) << " % of q H / M"
            << std::defaultfloat << std::endl;
    check(ends[0].force.norm() == 0. && ends[2].force.norm() == 0.,
          "a load that does not act has a force");
    check(std::abs(ends[1].force[1] + q) < 1e-10 * q &&
            std::abs(ends[1].force[0]) < 1e-10 * q,
          "the load acting in stage loaded has not the force -q");
    check(ends[0].unloaded == 0., "the column moved with no load acting");
    check(ends[1].loaded < 1e-2,
          "the loaded column's settlement is not q Y / M");
    check(ends[2].unloaded < 1e-2 * q * H / M,
          "the column has not sprung back with the load off");
  }
}
