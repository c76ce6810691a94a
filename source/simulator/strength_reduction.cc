#include <mpm_otm/base/exception_message.h>
#include <mpm_otm/base/stop_signal.h>
#include <mpm_otm/io/output_directory.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/simulator/simulator.h>
#include <mpm_otm/simulator/strength_reduction.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * @p value with @p digits significant digits.
     */
    std::string
    text(const double value, const int digits = 6)
    {
      std::ostringstream out;
      out << std::setprecision(digits) << value;
      return out.str();
    }

    /**
     * The directory, in the analysis' Output/Directory, of the state at the
     * start of the last stage that the first trial writes and the others
     * start from.
     */
    const std::string state_directory_name = "state-before-last-stage";
  } // namespace



  template <int dim>
  StrengthReduction<dim>::StrengthReduction(const MPI_Comm communicator,
                                            std::ostream  &log)
    : communicator(communicator)
    , log(log)
    , pcout(log, Utilities::MPI::this_mpi_process(communicator) == 0)
    , root(Utilities::MPI::this_mpi_process(communicator) == 0)
  {}



  template <int dim>
  void
  StrengthReduction<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Analysis",
      "simulation",
      Patterns::Selection("simulation|strength reduction"),
      "simulation: one run of the parameter file. strength reduction: the "
      "factor of safety, by runs of the parameter file with the strengths "
      "of the materials divided by trial factors (subsection Strength "
      "reduction; manual, \"Strength reduction\").");
    prm.enter_subsection("Strength reduction");
    prm.declare_entry("Lower factor",
                      "0.5",
                      Patterns::Double(0),
                      "A factor the body stands with: the first trial "
                      "checks it (if the body fails, the factor of safety "
                      "is below it and the analysis ends).");
    prm.declare_entry("Upper factor",
                      "3",
                      Patterns::Double(0),
                      "A factor the body fails with: the second trial "
                      "checks it (if the body stands, the factor of safety "
                      "is above it and the analysis ends).");
    prm.declare_entry("Tolerance",
                      "0.01",
                      Patterns::Double(0),
                      "Bisection ends when the factors the body stands and "
                      "fails with differ by less than this; the factor of "
                      "safety is their middle.");
    prm.declare_entry("Displacement limit",
                      "0",
                      Patterns::Double(0),
                      "A trial fails when a material point has moved "
                      "further than this (m) from its initial position, or "
                      "when it has not come to rest (Quasi-static end) by "
                      "Time/End time. Required: e.g. a tenth of a slope's "
                      "height.");
    prm.leave_subsection();
  }



  template <int dim>
  bool
  StrengthReduction<dim>::is_requested(const ParameterHandler &prm)
  {
    return prm.get("Analysis") == "strength reduction";
  }



  template <int dim>
  void
  StrengthReduction<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Strength reduction");
    lower_factor       = prm.get_double("Lower factor");
    upper_factor       = prm.get_double("Upper factor");
    tolerance          = prm.get_double("Tolerance");
    displacement_limit = prm.get_double("Displacement limit");
    prm.leave_subsection();
    AssertThrow(lower_factor > 0 && upper_factor > lower_factor &&
                  std::isfinite(upper_factor),
                ExcMessage("Strength reduction/Lower factor and Upper "
                           "factor must be positive, the upper above the "
                           "lower (here " +
                           text(lower_factor) + " and " + text(upper_factor) +
                           ")."));
    AssertThrow(tolerance > 0 && tolerance < upper_factor - lower_factor,
                ExcMessage("Strength reduction/Tolerance must be positive "
                           "and below Upper factor - Lower factor = " +
                           text(upper_factor - lower_factor) + " (here " +
                           text(tolerance) + ")."));
    AssertThrow(displacement_limit > 0 && std::isfinite(displacement_limit),
                ExcMessage(
                  "Strength reduction/Displacement limit must be set to a "
                  "positive length (m): a trial fails when a material point "
                  "has moved further than it, e.g. a tenth of a slope's "
                  "height (here " +
                  text(displacement_limit) + ")."));
  }



  template <int dim>
  double
  StrengthReduction<dim>::run(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    const std::string directory = prm.get("Directory");
    const bool        overwrite = prm.get_bool("Overwrite");
    prm.leave_subsection();

    // Everything a trial would refuse, and what the analysis needs, is
    // checked before anything is written.
    {
      Simulator<dim> check(communicator, log);
      check.parse_parameters(prm);
      bool plastic = false;
      for (unsigned int id = 0; id < check.material_library().n_materials();
           ++id)
        plastic = plastic || check.material_library()[id].is_plastic();
      AssertThrow(plastic,
                  ExcMessage(
                    "Analysis = strength reduction needs a material with a "
                    "strength (Model = Mohr-Coulomb, Drucker-Prager or von "
                    "Mises); every material of this file is elastic."));
      AssertThrow(check.ends_at_rest(),
                  ExcMessage(
                    "Analysis = strength reduction needs Quasi-static "
                    "end/Kinetic energy ratio > 0: a trial stands when it "
                    "comes to rest, so the runs must be able to end at "
                    "rest."));
    }
    clear_directory(directory, overwrite);

    pcout << "Strength reduction: factors " << lower_factor << " to "
          << upper_factor << ", tolerance " << tolerance
          << ", displacement limit " << displacement_limit << " m."
          << std::endl;
    double       stands_at = lower_factor;
    double       fails_at  = upper_factor;
    unsigned int number    = 0;
    std::string  mechanism;
    const auto   trial_and_report = [&](const double factor) {
      // The first trial's set-up completes the checks of the input (files
      // it reads, bodies on the grid) before the analysis writes anything.
      ++number;
      const Trial trial =
        run_trial(prm, directory, number, factor, [&, number]() {
          if (number == 1)
            {
              // The trial has read its own directory; the analysis' file
              // names the analysis' directory.
              prm.enter_subsection("Output");
              prm.set("Directory", directory);
              prm.leave_subsection();
              start_files(prm, directory);
            }
        });
      if (trial.fails)
        {
          fails_at  = std::min(fails_at, factor);
          mechanism = trial.directory;
        }
      else
        stands_at = std::max(stands_at, factor);
      pcout << "Strength reduction, trial " << number << ": F = " << factor
            << (trial.fails ? " fails" : " stands") << " ("
            << (trial.at_rest ? "at rest at t = " : "still moving at t = ")
            << text(trial.end_time, 4) << " s, largest displacement "
            << text(trial.largest_displacement, 3) << " m); ";
      return trial.fails;
    };

    double      factor_of_safety = 0;
    std::string result;
    if (trial_and_report(lower_factor))
      {
        factor_of_safety = lower_factor;
        result           = "the factor of safety is below the Lower factor " +
                 text(lower_factor);
        pcout << result << '.' << std::endl;
      }
    else
      {
        pcout << "next: the Upper factor." << std::endl;
        if (!trial_and_report(upper_factor))
          {
            factor_of_safety = upper_factor;
            result = "the factor of safety is above the Upper factor " +
                     text(upper_factor);
            pcout << result << '.' << std::endl;
          }
        else
          {
            pcout << "the factor of safety lies in [" << stands_at << ", "
                  << fails_at << "]." << std::endl;
            while (fails_at - stands_at > tolerance)
              {
                trial_and_report(0.5 * (stands_at + fails_at));
                pcout << "the factor of safety lies in [" << stands_at << ", "
                      << fails_at << "]." << std::endl;
              }
            factor_of_safety = 0.5 * (stands_at + fails_at);
            result           = "factor of safety " + text(factor_of_safety) +
                     " (stands at " + text(stands_at) + ", fails at " +
                     text(fails_at) + ")";
          }
      }
    std::string summary = result + "\ntrials: " + std::to_string(number) +
                          " (strength-reduction.csv)\n";
    if (!mechanism.empty())
      summary += "failure mechanism: the plastic strain of <" + mechanism +
                 ">, the last trial that failed\n";
    write_result(directory, summary);
    pcout << "Strength reduction: " << result;
    if (!mechanism.empty())
      pcout << "; the failure mechanism is the plastic strain in <" << mechanism
            << ">";
    pcout << '.' << std::endl;
    return factor_of_safety;
  }



  template <int dim>
  typename StrengthReduction<dim>::Trial
  StrengthReduction<dim>::run_trial(ParameterHandler            &prm,
                                    const std::string           &directory,
                                    const unsigned int           number,
                                    const double                 factor,
                                    const std::function<void()> &after_setup)
  {
    std::ostringstream name;
    name << directory << "/trial-" << std::setw(2) << std::setfill('0')
         << number;
    Trial trial;
    trial.factor    = factor;
    trial.directory = name.str();
    prm.enter_subsection("Output");
    prm.set("Directory", trial.directory);
    prm.leave_subsection();
    pcout << "Strength reduction, trial " << number << ": F = " << factor
          << ", output in <" << trial.directory << ">." << std::endl;
    try
      {
        Simulator<dim> simulator(communicator, log);
        simulator.parse_parameters(prm);
        simulator.share_state_before_last_stage(directory + "/" +
                                                  state_directory_name,
                                                number == 1);
        simulator.setup(prm);
        if (after_setup)
          after_setup();
        simulator.reduce_strength(factor);
        simulator.run();
        trial.at_rest              = simulator.at_rest();
        trial.end_time             = simulator.time();
        trial.largest_displacement = simulator.largest_displacement();
      }
    catch (const StoppedBySignal &stop)
      {
        throw StoppedBySignal(
          std::string(stop.what()) + " (This was trial " +
            std::to_string(number) +
            " of a strength reduction, which is not resumed: run it again, "
            "with the Lower and Upper factor narrowed to what "
            "strength-reduction.csv in <" +
            directory + "> shows.)",
          stop.exit_status() == 128 + 2 ? "SIGINT" : "SIGTERM");
      }
    catch (const ExceptionBase &error)
      {
        AssertThrow(false,
                    ExcMessage(
                      "Strength reduction, trial " + std::to_string(number) +
                      " (F = " + text(factor) + "): " + message_of(error)));
      }
    prm.enter_subsection("Output");
    prm.set("Directory", directory);
    prm.leave_subsection();
    trial.fails =
      !trial.at_rest || trial.largest_displacement > displacement_limit;
    record(directory, number, trial);
    return trial;
  }



  template <int dim>
  void
  StrengthReduction<dim>::clear_directory(const std::string &directory,
                                          const bool         overwrite) const
  {
    namespace fs = std::filesystem;
    std::string problem;
    if (root)
      {
        problem = OutputDirectory::clear_previous_run(directory, overwrite);
        std::error_code error;
        // The trials of an earlier analysis, which a shorter one would
        // leave beside its own, and the state they started from.
        if (problem.empty() && fs::is_directory(directory, error))
          for (const auto &entry : fs::directory_iterator(directory, error))
            if (problem.empty() &&
                (entry.path().filename().string().rfind("trial-", 0) == 0 ||
                 entry.path().filename() == state_directory_name))
              {
                fs::remove_all(entry.path(), error);
                if (error)
                  problem = "Output/Overwrite: cannot remove <" +
                            entry.path().string() + ">: " + error.message() +
                            ".";
              }
      }
    problem = Utilities::MPI::broadcast(communicator, problem, 0);
    AssertThrow(problem.empty(), ExcMessage(problem));
  }



  template <int dim>
  void
  StrengthReduction<dim>::start_files(const ParameterHandler &prm,
                                      const std::string      &directory) const
  {
    std::string problem;
    if (root)
      {
        problem = OutputDirectory::write_file_atomically(
          directory + "/parameters.prm",
          [&](std::ostream &out) {
            prm.print_parameters(out, ParameterHandler::PRM);
          });
        if (problem.empty())
          problem = OutputDirectory::write_file_atomically(
            directory + "/strength-reduction.csv",
            [](std::ostream &out) {
              out << "trial,factor,outcome,at_rest,end_time,"
                     "largest_displacement,directory\n";
            });
      }
    problem = Utilities::MPI::broadcast(communicator, problem, 0);
    AssertThrow(problem.empty(), ExcMessage(problem));
  }



  template <int dim>
  void
  StrengthReduction<dim>::record(const std::string &directory,
                                 const unsigned int number,
                                 const Trial       &trial) const
  {
    std::string problem;
    if (root)
      {
        std::ostringstream row;
        row << std::setprecision(10) << number << ',' << trial.factor << ','
            << (trial.fails ? "fails" : "stands") << ',' << trial.at_rest << ','
            << trial.end_time << ',' << trial.largest_displacement << ','
            << trial.directory << '\n';
        problem =
          OutputDirectory::append_to_file(directory + "/strength-reduction.csv",
                                          row.str());
      }
    problem = Utilities::MPI::broadcast(communicator, problem, 0);
    AssertThrow(problem.empty(), ExcMessage(problem));
  }



  template <int dim>
  void
  StrengthReduction<dim>::write_result(const std::string &directory,
                                       const std::string &text) const
  {
    std::string problem;
    if (root)
      problem =
        OutputDirectory::write_file_atomically(directory +
                                                 "/factor-of-safety.txt",
                                               [&](std::ostream &out) {
                                                 out << text;
                                               });
    problem = Utilities::MPI::broadcast(communicator, problem, 0);
    AssertThrow(problem.empty(), ExcMessage(problem));
  }



  template class StrengthReduction<1>;
  template class StrengthReduction<2>;
  template class StrengthReduction<3>;
} // namespace MpmOtm
