#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/activity.h>
#include <mpm_otm/base/stop_signal.h>
#include <mpm_otm/simulator/simulator.h>
#include <mpm_otm/simulator/strength_reduction.h>

#ifdef __linux__
#  include <sys/prctl.h>
#endif

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

namespace
{
  /**
   * Read @p filename (empty: the defaults, i.e. the default benchmark) and
   * run the simulation in @p dim dimensions. A non-empty @p resume_directory
   * is the output directory of a run to continue from its newest
   * checkpoint; @p filename is then its parameters.prm.
   */
  template <int dim>
  void
  run(const std::string &filename,
      const bool         overwrite,
      const std::string &resume_directory)
  {
    std::string text;
    if (!filename.empty())
      {
        std::ifstream     file(filename);
        std::stringstream contents;
        contents << file.rdbuf();
        text = contents.str();
        // A file that sets nothing would silently run the default benchmark.
        std::istringstream lines(text);
        std::string        line;
        bool               sets_something = false;
        while (!sets_something && std::getline(lines, line))
          {
            const std::string word =
              dealii::Utilities::trim(line.substr(0, line.find('#')));
            sets_something =
              word.rfind("set ", 0) == 0 || word.rfind("subsection ", 0) == 0;
          }
        AssertThrow(sets_something,
                    dealii::ExcMessage(
                      "Parameter file <" + filename +
                      "> sets no parameter (it is empty or holds only "
                      "comments). Start from a file in prm/, e.g. "
                      "prm/G1-cantilever-static.prm."));
      }
    dealii::ParameterHandler prm;
    MpmOtm::Simulator<dim>::declare_parameters(prm,
                                               MpmOtm::SubsectionNames::read(
                                                 text));
    if (!filename.empty())
      try
        {
          prm.parse_input(filename);
        }
      catch (const dealii::ExceptionBase &error)
        {
          // A subsection "Body NAME" (Material, Boundary) whose NAME the
          // list entry does not hold: say which entry to extend.
          std::ostringstream message;
          error.print_info(message);
          const std::string information = message.str();
          for (const auto &[kind, list] :
               {std::pair<std::string, std::string>{"Body", "Bodies"},
                {"Material", "Materials"},
                {"Boundary", "Boundaries"},
                {"Surface load", "Surface loads"},
                {"Stage", "Stages"}})
            {
              const std::string marker =
                "no such subsection to be entered: " + kind + " ";
              const auto position = information.find(marker);
              if (position != std::string::npos)
                {
                  const std::string name = dealii::Utilities::trim(
                    information.substr(position + marker.size()));
                  AssertThrow(false,
                              dealii::ExcMessage(
                                "Parameter file <" + filename +
                                ">: subsection <" + kind + " " + name +
                                "> is not used: add " + name +
                                " to the entry " + list + "."));
                }
            }
          // An entry in a subsection "Stage NAME" that a stage cannot
          // change: say what a stage can.
          const std::regex undeclared(
            "Line <([0-9]+)> of file <([^>]*)>: No entry with name <([^>]*)>");
          std::smatch found;
          if (std::regex_search(information, found, undeclared))
            {
              std::ifstream file(found[2].str());
              std::string   line, subsection;
              for (int number = 1; number < std::stoi(found[1].str()) &&
                                   std::getline(file, line);
                   ++number)
                {
                  const std::string code =
                    dealii::Utilities::trim(line.substr(0, line.find('#')));
                  if (code.rfind("subsection ", 0) == 0)
                    subsection = dealii::Utilities::trim(code.substr(11));
                  else if (code == "end")
                    subsection.clear();
                }
              AssertThrow(subsection.rfind("Stage ", 0) != 0,
                          dealii::ExcMessage(
                            "Parameter file <" + found[2].str() + ">, line " +
                            found[1].str() + ": " + subsection + "/" +
                            found[3].str() +
                            ": a stage cannot set this entry. A stage sets "
                            "its End time, End at rest, Remove bodies, Add "
                            "bodies, Reset displacements, Local damping "
                            "coefficient and Surface loads; the grid, shape "
                            "functions, method, materials and conditions are "
                            "those of the whole run (manual, 'Stages')."));
            }
          throw;
        }
    if (overwrite)
      {
        prm.enter_subsection("Output");
        prm.set("Overwrite", true);
        prm.leave_subsection();
      }
    if (!resume_directory.empty())
      {
        // The directory may have moved since the run wrote its parameters.
        prm.enter_subsection("Output");
        prm.set("Directory", resume_directory);
        prm.leave_subsection();
      }
    if (MpmOtm::StrengthReduction<dim>::is_requested(prm))
      {
        AssertThrow(resume_directory.empty(),
                    dealii::ExcMessage(
                      "--resume: <" + resume_directory +
                      "> holds (a trial of) a strength reduction "
                      "(Analysis = strength reduction), which is not "
                      "resumed: run it again, with Strength reduction/Lower "
                      "factor and Upper factor narrowed to what its "
                      "strength-reduction.csv shows."));
        MpmOtm::StrengthReduction<dim> analysis(MPI_COMM_WORLD, std::cout);
        analysis.parse_parameters(prm);
        analysis.run(prm);
        return;
      }
    MpmOtm::Simulator<dim> simulator(MPI_COMM_WORLD, std::cout);
    simulator.parse_parameters(prm);
    simulator.setup(prm, !resume_directory.empty());
    simulator.run();
  }



  /**
   * Report @p message and return the exit status. Serial runs just print it.
   * In parallel, the errors of the application are raised on every rank at
   * once (rank 0 prints them), but an error of one rank alone would leave
   * the others waiting in a collective operation for ever. So rank 0 prints
   * and aborts all ranks; any other rank first gives rank 0 the time to do
   * so for the same error, and if it is still running, the error was its
   * own: it prints it with its rank and aborts all ranks.
   */
  int
  stop_with_error(const std::string &message)
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (rank != 0)
      std::this_thread::sleep_for(std::chrono::seconds(3));
    std::cerr << "\nmpm-otm stopped with an error";
    if (rank != 0)
      std::cerr << " on MPI rank " << rank;
    std::cerr << ":\n" << message << std::endl;
    if (n_ranks > 1)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
} // namespace



int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
#ifdef __linux__
  // The ranks of an MPI run die with the launcher (mpirun, or the daemon
  // that started them): killed with SIGKILL, it cannot stop them, and they
  // would go on writing output. A serial run is left alone (nohup).
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
  const bool root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  bool        failed = false;
  std::string error_message;
  try
    {
      const std::string usage =
        "Usage: mpm-otm [--overwrite] [parameter file]\n"
        "       mpm-otm --resume OUTPUT-DIRECTORY\n"
        "       mpm-otm --print-parameters 1|2|3\n"
        "       mpm-otm --help\n"
        "Without a file the default benchmark (B1b, 1D vibrating bar, MPM) "
        "runs. --overwrite lets the run replace another run's output in its "
        "Output/Directory. --resume continues the run whose output is in "
        "OUTPUT-DIRECTORY from its newest checkpoint, with the parameters "
        "of its parameters.prm, on any number of MPI ranks.\n";
      std::vector<std::string> arguments(argv + 1, argv + argc);
      const auto               overwrite_option =
        std::find(arguments.begin(), arguments.end(), "--overwrite");
      const bool overwrite = overwrite_option != arguments.end();
      if (overwrite)
        arguments.erase(overwrite_option);
      AssertThrow(std::find(arguments.begin(),
                            arguments.end(),
                            "--overwrite") == arguments.end(),
                  dealii::ExcMessage("--overwrite is given twice; once is "
                                     "enough.\n" +
                                     usage));
      std::string resume_directory;
      const auto  resume_option =
        std::find(arguments.begin(), arguments.end(), "--resume");
      if (resume_option != arguments.end())
        {
          AssertThrow(arguments.size() == 2 &&
                        resume_option == arguments.begin() && !overwrite,
                      dealii::ExcMessage(
                        "--resume needs the output directory of the run to "
                        "continue, and nothing else.\n" +
                        usage));
          resume_directory = arguments[1];
          AssertThrow(std::filesystem::is_regular_file(resume_directory +
                                                       "/parameters.prm"),
                      dealii::ExcMessage(
                        "--resume: <" + resume_directory +
                        "> holds no parameters.prm; give the Output/"
                        "Directory of the run to continue.\n" +
                        usage));
          arguments = {resume_directory + "/parameters.prm"};
        }
      const std::string argument = arguments.empty() ? "" : arguments[0];
      if (argument == "--help" || argument == "-h")
        {
          AssertThrow(arguments.size() == 1,
                      dealii::ExcMessage("--help takes no further "
                                         "argument.\n" +
                                         usage));
          if (root)
            std::cout << usage;
          return 0;
        }
      if (argument == "--print-parameters")
        {
          const std::string dimension =
            (arguments.size() == 2) ? arguments[1] : "";
          AssertThrow(dimension == "1" || dimension == "2" || dimension == "3",
                      dealii::ExcMessage(
                        "--print-parameters needs the dimension, 1, 2 or 3, "
                        "and nothing else.\n" +
                        usage));
          // One subsection of each named kind, called "example", stands for
          // those the entries Materials, Bodies and Boundaries name.
          MpmOtm::SubsectionNames examples;
          examples.materials     = {"example"};
          examples.bodies        = {"example"};
          examples.boundaries    = {"example"};
          examples.surface_loads = {"example"};
          examples.stages        = {"example"};
          dealii::ParameterHandler prm;
          if (dimension == "1")
            MpmOtm::Simulator<1>::declare_parameters(prm, examples);
          else if (dimension == "3")
            MpmOtm::Simulator<3>::declare_parameters(prm, examples);
          else
            MpmOtm::Simulator<2>::declare_parameters(prm, examples);
          prm.set("Dimension", dimension);
          if (root)
            prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
          return 0;
        }
      for (const auto &other : arguments)
        AssertThrow(other.empty() || other[0] != '-',
                    dealii::ExcMessage("Unknown option <" + other + ">.\n" +
                                       usage));
      AssertThrow(arguments.size() <= 1,
                  dealii::ExcMessage(
                    "Give one parameter file, not " +
                    std::to_string(arguments.size()) + " (<" + arguments[0] +
                    ">, <" + arguments[1] + ">" +
                    (arguments.size() > 2 ? ", ..." : "") + ").\n" + usage));

      switch (MpmOtm::read_dimension(argument))
        {
          case 1:
            run<1>(argument, overwrite, resume_directory);
            break;
          case 2:
            run<2>(argument, overwrite, resume_directory);
            break;
          default:
            run<3>(argument, overwrite, resume_directory);
            break;
        }
    }
  catch (const MpmOtm::StoppedBySignal &stop)
    {
      // Every rank stops at the same step: no rank is left waiting.
      if (root)
        std::cerr << "\nmpm-otm stopped:\n    " << stop.what() << std::endl;
      return stop.exit_status();
    }
  catch (const std::bad_alloc &)
    {
      failed        = true;
      error_message = MpmOtm::Activity::out_of_memory();
    }
  catch (const dealii::ExceptionBase &error)
    {
      std::ostringstream text;
      error.print_info(text);
      failed        = true;
      error_message = text.str();
    }
  catch (const std::exception &error)
    {
      failed        = true;
      error_message = error.what();
    }
  return failed ? stop_with_error(error_message) : 0;
}
