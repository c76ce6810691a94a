#ifndef mpm_otm_tests_tests_h
#define mpm_otm_tests_tests_h

// Helpers shared by the test programs: the "output" file that the deal.II
// harness compares, a check that stops the test with a message, and runs of
// the benchmark parameter files in prm/ with appended changes.

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/simulator/simulator.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace MpmOtmTests
{
  using namespace dealii;

  /**
   * Attach deallog to the file "output" (rank 0 only in parallel tests).
   */
  inline void
  initlog(const MPI_Comm communicator = MPI_COMM_WORLD)
  {
    static std::ofstream logfile;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        logfile.open("output");
        deallog.attach(logfile, false);
      }
    deallog.depth_console(0);
  }

  /**
   * Stop the test (non-zero exit) with @p message unless @p condition.
   */
  inline void
  check(const bool condition, const std::string &message)
  {
    AssertThrow(condition, ExcMessage("Test check failed: " + message));
  }

  /**
   * The rows of stages.csv in the Output/Directory @p directory of a staged
   * run, without the header, each split at its commas: step (the stage's
   * last), stage, name, first_step, start_time, end_time, end.
   */
  inline std::vector<std::vector<std::string>>
  stage_rows(const std::string &directory)
  {
    std::ifstream                         file(directory + "/stages.csv");
    std::string                           line;
    std::vector<std::vector<std::string>> rows;
    std::getline(file, line);
    while (std::getline(file, line))
      rows.push_back(Utilities::split_string_list(line, ','));
    return rows;
  }

  /**
   * A communicator of world rank 0 alone (MPI_COMM_NULL on the others), for
   * runs on one rank inside a test on several.
   */
  inline MPI_Comm
  first_rank_only()
  {
    MPI_Comm  single;
    const int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    MPI_Comm_split(MPI_COMM_WORLD, rank == 0 ? 0 : MPI_UNDEFINED, 0, &single);
    return single;
  }

  /**
   * A number with @p digits significant digits, for output that must not
   * depend on round-off.
   */
  inline std::string
  rounded(const double value, const unsigned int digits = 3)
  {
    std::ostringstream text;
    text << std::setprecision(digits) << std::scientific << value;
    return text.str();
  }

  /**
   * Full path of a parameter file in prm/.
   */
  inline std::string
  prm_file(const std::string &name)
  {
    return std::string(MPM_OTM_SOURCE_DIR) + "/prm/" + name;
  }

  /**
   * Build a simulator from the parameter file contents @p text, as the
   * program does (quiet: its report goes nowhere); resume from the newest
   * checkpoint in the output directory if @p resume.
   */
  template <int dim>
  std::unique_ptr<MpmOtm::Simulator<dim>>
  simulator_from_text(const std::string &text,
                      const MPI_Comm     communicator = MPI_COMM_WORLD,
                      const bool         resume       = false)
  {
    static std::ostringstream quiet;
    ParameterHandler          prm;
    MpmOtm::Simulator<dim>::declare_parameters(prm,
                                               MpmOtm::SubsectionNames::read(
                                                 text));
    prm.parse_input_from_string(text);
    auto simulator =
      std::make_unique<MpmOtm::Simulator<dim>>(communicator, quiet);
    simulator->parse_parameters(prm);
    simulator->setup(prm, resume);
    return simulator;
  }

  /**
   * Build a simulator from prm/@p name with the lines @p changes appended
   * (as a user would append them) and field output switched off; output
   * goes to the test's directory @p directory.
   */
  template <int dim>
  std::unique_ptr<MpmOtm::Simulator<dim>>
  make_simulator(const std::string &name,
                 const std::string &changes,
                 const std::string &directory,
                 const MPI_Comm     communicator = MPI_COMM_WORLD,
                 const bool         resume       = false)
  {
    std::string text;
    if (!name.empty())
      {
        std::ifstream     file(prm_file(name));
        std::stringstream contents;
        contents << file.rdbuf();
        text = contents.str();
      }
    return simulator_from_text<dim>(text + "\n" + changes +
                                      "\nsubsection Output\n"
                                      "set Directory = " +
                                      directory +
                                      "\nset Format = none\n"
                                      "set Overwrite = true\n"
                                      "end\n",
                                    communicator,
                                    resume);
  }

  /**
   * A simulator on the unit box [0, 1]^dim with @p cells_per_direction
   * cells per direction (custom problem, at rest), whose grid the tests of
   * the shape-function families use.
   */
  template <int dim>
  std::unique_ptr<MpmOtm::Simulator<dim>>
  make_unit_box_simulator(const unsigned int cells_per_direction,
                          const std::string &directory)
  {
    std::string lower = "0", upper = "1",
                blocks = std::to_string(cells_per_direction);
    for (unsigned int d = 1; d < dim; ++d)
      {
        lower += ",0";
        upper += ",1";
        blocks += "," + std::to_string(cells_per_direction);
      }
    return make_simulator<dim>("",
                               "set Dimension = " + std::to_string(dim) +
                                 "\nset Problem = custom\n"
                                 "subsection Mesh\n set Lower corner = " +
                                 lower + "\n set Upper corner = " + upper +
                                 "\n set Subdivisions = " + blocks +
                                 "\nend\n"
                                 "subsection Time\n set Time step = 1e-6\n"
                                 "end\n",
                               directory);
  }

  /**
   * Value and gradient of the quadratic number @p i of 1, x, y, x^2, xy,
   * y^2 at @p x (the monomials the Powell-Sabin tests reproduce).
   */
  inline std::pair<double, dealii::Tensor<1, 2>>
  quadratic(const unsigned int i, const dealii::Point<2> &x)
  {
    const double values[6] =
      {1., x[0], x[1], x[0] * x[0], x[0] * x[1], x[1] * x[1]};
    const double gradients[6][2] = {{0., 0.},
                                    {1., 0.},
                                    {0., 1.},
                                    {2. * x[0], 0.},
                                    {x[1], x[0]},
                                    {0., 2. * x[1]}};
    return {values[i],
            dealii::Tensor<1, 2>({gradients[i][0], gradients[i][1]})};
  }
} // namespace MpmOtmTests

#endif
