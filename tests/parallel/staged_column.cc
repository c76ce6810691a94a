// Stages (Stages, subsections "Stage NAME") against closed forms, and a run
// resumed inside a stage.
//
// prm/staged-column.prm on 0.5 m cells (the prm's are 0.25 m; doc/
// benchmarks.md, "Stages", has its numbers): a hypo-elastic column
// [0, 1] x [0, 6], sides on
// rollers, base fixed, gravity 10 m/s^2, M = E (1 - nu) / ((1 + nu)
// (1 - 2 nu)) = 13.46 MPa, in three stages:
// - initial: the base (Y < 4) and the layer cut (4 < Y < 6) in their
//   geostatic state, which is at rest;
// - excavation: cut removed, displacements reset: the base unloads by
//   q1 = rho g 2 m = 40 kPa and heaves by u_y(Y) = q1 Y / M (11.9 mm at its
//   top), its stress sigma_yy = -rho g (4 - Y);
// - backfill: fill (E = 5 MPa, rho = 1500 kg/m^3) takes cut's place with
//   the geostatic stress of its own weight, displacements reset: the base
//   settles by u_y(Y) = -q2 Y / M, q2 = 30 kPa, sigma_yy = -rho g (4 - Y) -
//   q2, and the fill moves down with the base's top, by -q2 4 m / M.
// Each loaded stage ends at rest (Quasi-static end, at 1e-8).
// Asserted at the end of each stage (from stages.csv): the number of points
// (96, 64, 96), every base point's displacement within 1 % of q H / M of
// the closed form, the base's sigma_yy within 1 % of q; the fill's
// displacement within 1.5 % of q2 4 m / M (the base's top cell errs most,
// by the usual MPM error of a settlement against the cell size, and the
// fill moves with it). stages.csv: the three stages in order, each
// starting the step after the one before ended, the first by its End time,
// the others at rest.
//
// The geostatic stress integrates the weight of the bodies above a point;
// on these cells its steps land on the boundary between base and cut,
// which both bodies contain (it once stopped there as an overlap).
//
// Then the run is resumed from its checkpoint of step 200, inside the
// excavation stage (the newer ones removed): it crosses into the backfill
// stage, adds the fill and must end with every point, stages.csv and
// monitoring.csv equal to the uninterrupted run's (bit by bit on the same
// number of ranks). Its monitoring points follow the points they followed
// (one in the cut, gone since the excavation: nan), not the nearest ones at
// the resume (none within reach of the cut's: the resume used to stop).
//
// Last, a strength reduction of a staged run divides the strengths at the
// start of its last stage only: a von Mises column 4 m high (yield stress
// 60 kPa, rho = 2000 kg/m^3, geostatic with K0 = 0.5, so that the von
// Mises stress (1 - K0) rho g (4 m - Y) is at most 38.75 kPa at the lowest
// points) in two stages, with its strength divided by 2 (30 kPa): no point
// may yield in the first stage, points below Y = 1 m (where the stress
// exceeds 30 kPa) must yield in the second. The same column by
// Analysis = strength reduction: its second trial (F = 2) starts from the
// state the first wrote before the last stage, runs that stage only and
// ends with the statistics of the run above to the last digit.

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/simulator/strength_reduction.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  const double E = 10e6, nu = 0.3, rho = 2000., g = 10.;
  const double M  = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  const double q1 = rho * g * 2., q2 = 1500. * g * 2.;

  /// The errors at one output step.
  struct StepErrors
  {
    types::particle_index n_points                = 0;
    double                excavation_displacement = 0, excavation_stress = 0;
    double backfill_displacement = 0, backfill_stress = 0, fill = 0;
  };

  StepErrors
  errors(const Simulator<2> &simulator)
  {
    using Layout = PropertyLayout<2>;
    StepErrors result;
    double     worst[5] = {0, 0, 0, 0, 0};
    for (const auto &particle : simulator.material_points().particle_handler())
      {
        const auto     properties = particle.get_properties();
        const Point<2> X(
          Layout::get_vector(properties, Layout::initial_position));
        const double u = particle.get_location()[1] - X[1];
        const double s = Layout::get_stress(properties)[1][1];
        if (X[1] < 4.)
          {
            const double weight = -rho * g * (4. - X[1]);
            worst[0] =
              std::max(worst[0], std::abs(u - q1 * X[1] / M) / (q1 * 4. / M));
            worst[1] = std::max(worst[1], std::abs(s - weight) / q1);
            worst[2] =
              std::max(worst[2], std::abs(u + q2 * X[1] / M) / (q2 * 4. / M));
            worst[3] = std::max(worst[3], std::abs(s - weight + q2) / q2);
          }
        else
          worst[4] =
            std::max(worst[4], std::abs(u + q2 * 4. / M) / (q2 * 4. / M));
      }
    Utilities::MPI::max(ArrayView<const double>(worst, 5),
                        MPI_COMM_WORLD,
                        ArrayView<double>(worst, 5));
    result.n_points = simulator.material_points().n_global_points();
    result.excavation_displacement = worst[0];
    result.excavation_stress       = worst[1];
    result.backfill_displacement   = worst[2];
    result.backfill_stress         = worst[3];
    result.fill                    = worst[4];
    return result;
  }

  std::vector<std::vector<std::string>>
  read_stages(const std::string &directory)
  {
    std::ifstream                         in(directory + "/stages.csv");
    std::string                           line;
    std::vector<std::vector<std::string>> rows;
    std::getline(in, line);
    check(line == "step,stage,name,first_step,start_time,end_time,end",
          "stages.csv has the header <" + line + ">");
    while (std::getline(in, line))
      rows.push_back(Utilities::split_string_list(line, ','));
    return rows;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const std::string directory = "output-staged-column";
  const std::string changes =
    "subsection Mesh\n set Subdivisions = 2, 13\nend\n"
    "subsection Checkpoint\n set Interval = 100\n"
    " set Number kept = 10\nend\n"
    "subsection Monitoring\n"
    " set Points = top: 0.5, 4; middle: 0.5, 2; cut: 0.5, 5\nend\n";
  std::map<unsigned int, StepErrors>        at_step;
  std::map<types::particle_index, Point<2>> uninterrupted;
  {
    auto simulator = make_simulator<2>("staged-column.prm", changes, directory);
    simulator->run([&](const unsigned int step, const Statistics<2> &) {
      at_step[step] = errors(*simulator);
    });
    for (const auto &particle : simulator->material_points().particle_handler())
      uninterrupted[particle.get_id()] = particle.get_location();
  }
  const auto read_file = [](const std::string &name) {
    std::ifstream     in(name);
    std::stringstream contents;
    contents << in.rdbuf();
    return contents.str();
  };
  const std::string monitoring = read_file(directory + "/monitoring.csv");
  const auto        stages     = read_stages(directory);
  check(stages.size() == 3, "stages.csv has not three stages");
  const char *names[3]  = {"initial", "excavation", "backfill"};
  const char *ending[3] = {"end time", "at rest", "at rest"};
  for (unsigned int k = 0; k < 3; ++k)
    {
      check(stages[k].size() == 7 && stages[k][1] == std::to_string(k) &&
              stages[k][2] == names[k] && stages[k][6] == ending[k],
            "row " + std::to_string(k) + " of stages.csv is not stage " +
              names[k] + " ending by " + ending[k]);
      check(std::stoul(stages[k][3]) ==
              (k == 0 ? 1 : std::stoul(stages[k - 1][0]) + 1),
            std::string("stage ") + names[k] +
              " does not start after the stage before");
    }
  check(std::stod(stages[0][5]) == 0.1, "stage initial ends at its End time");
  deallog << "stages.csv: initial, excavation, backfill; each starts after "
             "the one before; initial ends at its End time, the others at "
             "rest"
          << std::endl;

  const auto &initial    = at_step.at(std::stoul(stages[0][0]));
  const auto &excavation = at_step.at(std::stoul(stages[1][0]));
  const auto &backfill   = at_step.at(std::stoul(stages[2][0]));
  // One decimal: local damping, which acts against the sign of each nodal
  // velocity, lets the motion near rest differ between rank counts (and so
  // the step at which a stage comes to rest), by 1e-4 of the values here.
  deallog << std::fixed << std::setprecision(1)
          << "points: " << initial.n_points << ", " << excavation.n_points
          << ", " << backfill.n_points << std::endl
          << "excavation: heave error "
          << 100. * excavation.excavation_displacement
          << " % of q1 H / M, sigma_yy error "
          << 100. * excavation.excavation_stress << " % of q1" << std::endl
          << "backfill: settlement error "
          << 100. * backfill.backfill_displacement
          << " % of q2 H / M, sigma_yy error "
          << 100. * backfill.backfill_stress << " % of q2, fill displacement "
          << 100. * backfill.fill << " % of q2 H / M" << std::endl;
  check(initial.n_points == 96 && excavation.n_points == 64 &&
          backfill.n_points == 96,
        "the stages do not remove and add the bodies' points");
  check(excavation.excavation_displacement < 0.01 &&
          excavation.excavation_stress < 0.01,
        "the excavation's heave or stress is not the closed form");
  check(backfill.backfill_displacement < 0.01 &&
          backfill.backfill_stress < 0.01,
        "the backfill's settlement or stress is not the closed form");
  check(backfill.fill < 0.015, "the fill does not move with the base's top");

  // Resume from the checkpoint of step 200, in the excavation stage.
  check(std::stoul(stages[1][3]) < 200 && std::stoul(stages[1][0]) > 200,
        "step 200 is not in the excavation stage");
  MPI_Barrier(MPI_COMM_WORLD);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      {
        const std::string name = entry.path().filename().string();
        if (name.rfind("checkpoint-", 0) == 0 &&
            std::stoul(name.substr(11)) > 200)
          std::filesystem::remove_all(entry.path());
      }
  MPI_Barrier(MPI_COMM_WORLD);
  {
    auto simulator = make_simulator<2>("staged-column.prm",
                                       changes,
                                       directory,
                                       MPI_COMM_WORLD,
                                       true);
    simulator->run();
    unsigned int n_different = 0, n_points = 0;
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const auto found = uninterrupted.find(particle.get_id());
        n_different += (found == uninterrupted.end() ||
                        found->second != particle.get_location()) ?
                         1 :
                         0;
        ++n_points;
      }
    n_different = Utilities::MPI::sum(n_different, MPI_COMM_WORLD);
    n_points    = Utilities::MPI::sum(n_points, MPI_COMM_WORLD);
    const unsigned int n_uninterrupted =
      Utilities::MPI::sum(static_cast<unsigned int>(uninterrupted.size()),
                          MPI_COMM_WORLD);
    check(n_points == n_uninterrupted && n_different == 0,
          "the resumed run ends with " + std::to_string(n_different) +
            " points elsewhere than the uninterrupted run's");
  }
  check(read_stages(directory) == stages,
        "the resumed run's stages.csv differs from the uninterrupted run's");
  check(monitoring.find("nan") != std::string::npos &&
          read_file(directory + "/monitoring.csv") == monitoring,
        "the resumed run's monitoring.csv differs from the uninterrupted "
        "run's, or the monitored point of the cut is not gone (nan)");
  deallog << "resumed at step 200 in stage excavation: every point, "
             "stages.csv and monitoring.csv (the cut's point nan once "
             "removed) as in the uninterrupted run"
          << std::endl;

  {
    const std::string text      = R"(
set Dimension = 2
set Problem   = custom
set Bodies    = column
set Boundaries = left, right, bottom
set Stages    = initial, reduced
subsection Time
  set Time step = auto
end
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 4.5
  set Subdivisions = 4, 18
end
subsection Material
  set Model           = von Mises
  set Young's modulus = 10e6
  set Poisson's ratio = 0.3
  set Density         = 2000
  subsection von Mises
    set Yield stress = 60e3
  end
end
subsection Body column
  set Lower corner         = 0, 0
  set Upper corner         = 1, 4
  set Initial stress       = geostatic
  set Lateral stress ratio = 0.5
end
subsection Stage initial
  set End time = 0.05
end
subsection Stage reduced
  set End time    = 0.4
  set End at rest = true
end
subsection Quasi-static end
  set Kinetic energy ratio = 1e-6
end
subsection Boundary left
  set Type = slip
  set Boundary ids = 0
end
subsection Boundary right
  set Type = slip
  set Boundary ids = 1
end
subsection Boundary bottom
  set Type = fixed
  set Boundary ids = 2
end
subsection Gravity
  set Vector = 0, -10
end
subsection Damping
  set Local damping coefficient = 0.2
end
subsection Output
  set Format        = none
  set Overwrite     = true
  set Time interval = 0.05
end
)";
    auto              simulator = simulator_from_text<2>(
      text +
      "subsection Output\nset Directory = output-staged-reduction\nend\n");
    simulator->reduce_strength(2.);
    // The largest plastic strain of the points below 0.9 m and above 1.1 m
    // at each output step.
    std::map<unsigned int, std::pair<double, double>> plastic;
    simulator->run([&](const unsigned int step, const Statistics<2> &) {
      using Layout           = PropertyLayout<2>;
      const auto &library    = simulator->material_library();
      double      largest[2] = {0, 0};
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          const auto         properties = particle.get_properties();
          const unsigned int id         = Layout::get_material_id(properties);
          const double       strain =
            library[id].equivalent_plastic_strain(ArrayView<const double>(
              &properties[library.first_internal_variable(id)],
              library.n_internal_variables(id)));
          const double Y =
            Layout::get_vector(properties, Layout::initial_position)[1];
          if (Y < 0.9)
            largest[0] = std::max(largest[0], strain);
          else if (Y > 1.1)
            largest[1] = std::max(largest[1], strain);
        }
      Utilities::MPI::max(ArrayView<const double>(largest, 2),
                          MPI_COMM_WORLD,
                          ArrayView<double>(largest, 2));
      plastic[step] = {largest[0], largest[1]};
    });
    const auto reduction = read_stages("output-staged-reduction");
    check(reduction.size() == 2, "the reduction run has not two stages");
    const auto first  = plastic.at(std::stoul(reduction[0][0]));
    const auto second = plastic.at(std::stoul(reduction[1][0]));
    check(first.first == 0. && first.second == 0.,
          "a point yielded in the first stage, before the strength was "
          "reduced");
    check(second.first > 0.,
          "no point below 0.9 m yielded with the reduced strength");
    deallog << "strength reduction in stages: no plastic strain at the end "
               "of stage initial; below 0.9 m "
            << (second.first > 0. ? "plastic" : "elastic")
            << " at the end of stage reduced" << std::endl;

    // The same column by Analysis = strength reduction at the factors 1 and
    // 2 (a bracket of width 1 against a tolerance of 0.9: the analysis ends
    // after them or one more). The second trial starts from the state the first
    // wrote before stage reduced: it runs that stage only and must end as
    // the run above, which ran both stages with the strength divided by 2.
    ParameterHandler   prm;
    const std::string  analysis_text = text + R"(
set Analysis = strength reduction
subsection Strength reduction
  set Lower factor       = 1
  set Upper factor       = 2
  set Tolerance          = 0.9
  set Displacement limit = 0.1
end
subsection Output
  set Directory = output-staged-strength-reduction
end
)";
    std::ostringstream quiet;
    Simulator<2>::declare_parameters(prm, SubsectionNames::read(analysis_text));
    prm.parse_input_from_string(analysis_text);
    StrengthReduction<2> analysis(MPI_COMM_WORLD, quiet);
    analysis.parse_parameters(prm);
    analysis.run(prm);
    const std::string trial = "output-staged-strength-reduction/trial-02";
    const auto        trial_stages = read_stages(trial);
    check(trial_stages.size() == 1 && trial_stages[0][2] == "reduced" &&
            trial_stages[0][3] == reduction[1][3],
          "the second trial has not started at stage reduced, in step " +
            reduction[1][3]);
    const auto last_row = [](const std::string &directory) {
      std::ifstream in(directory + "/statistics.csv");
      std::string   line, last;
      while (std::getline(in, line))
        if (!line.empty() && line[0] != '#')
          last = line;
      return last;
    };
    const std::string run_end   = last_row("output-staged-reduction");
    const std::string trial_end = last_row(trial);
    check(trial_stages[0] == reduction[1] && !run_end.empty() &&
            trial_end == run_end,
          "the second trial ends otherwise than the run: <" + trial_end +
            "> against <" + run_end + ">");
    deallog << "strength reduction from the state before stage reduced: the "
               "trial at F = 2 starts at step "
            << trial_stages[0][3] << " and ends as the run, every digit of "
            << "its last statistics" << std::endl;
  }
}
