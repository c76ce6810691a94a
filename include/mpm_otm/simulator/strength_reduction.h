#ifndef mpm_otm_simulator_strength_reduction_h
#define mpm_otm_simulator_strength_reduction_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <ostream>
#include <string>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The strength reduction method (`set Analysis = strength reduction`,
   * subsection "Strength reduction"): the factor of safety F of a body at
   * rest under its own weight is the largest factor by which its strengths
   * can be divided (Material::reduce_strength(): c / F and tan(phi) / F,
   * tan(psi) / F, or c_u / F) with the body still standing. Each trial is a
   * run of the parameter file, in the same process, whose last stage (the
   * run, without Stages) has the strengths divided by the trial's factor;
   * it goes on until it comes to rest (subsection "Quasi-static end") or
   * reaches its End time. The first trial seeds the points in their initial
   * state (e.g. geostatic, with the unreduced strengths), runs the earlier
   * stages and writes the state at the start of the last stage into
   * Output/Directory/state-before-last-stage; every later trial starts from
   * that state. A trial *fails* when a point has moved further
   * than the Displacement limit or the run has not come to rest by its End
   * time; it *stands* otherwise. The first two trials check that the Lower
   * factor stands and the Upper factor fails; bisection then halves the
   * bracket until it is narrower than the Tolerance. Each trial writes its
   * whole output to Output/Directory/trial-NN; strength-reduction.csv lists
   * the trials (a row as each ends), factor-of-safety.txt the result and
   * the trial whose plastic strain shows the failure mechanism (the last
   * that failed). Every rank runs every trial; the outcome of a trial is
   * decided on values all ranks share, so 1 and N ranks bisect alike.
   */
  template <int dim>
  class StrengthReduction
  {
  public:
    /**
     * @p log receives the progress lines (rank 0).
     */
    StrengthReduction(const MPI_Comm communicator, std::ostream &log);

    /**
     * Declare the entry Analysis and the subsection "Strength reduction".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Whether @p prm asks for a strength reduction (Analysis).
     */
    static bool
    is_requested(const ParameterHandler &prm);

    /**
     * Read and check the subsection "Strength reduction".
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Run the trials of the parameters @p prm (whose Output/Directory this
     * changes for each trial and restores) and return the factor of safety:
     * the middle of the last bracket; the Lower or Upper factor if the
     * first trials find the factor outside them (then said in the log and
     * in factor-of-safety.txt).
     */
    double
    run(ParameterHandler &prm);

  private:
    /**
     * The outcome of one trial.
     */
    struct Trial
    {
      double      factor               = 1;
      bool        fails                = false;
      bool        at_rest              = false;
      double      end_time             = 0;
      double      largest_displacement = 0;
      std::string directory;
    };

    /**
     * Run trial number @p number with the strengths divided by @p factor;
     * @p directory is the Output/Directory of the analysis. @p after_setup,
     * if given, is called once the trial's run is set up (its input
     * checked) and before it runs.
     */
    Trial
    run_trial(ParameterHandler            &prm,
              const std::string           &directory,
              const unsigned int           number,
              const double                 factor,
              const std::function<void()> &after_setup = {});

    /**
     * Prepare @p directory for the analysis without writing to it: refuse
     * another run's output unless @p overwrite, and remove the trials of
     * an earlier analysis otherwise. Stops every rank on a problem.
     */
    void
    clear_directory(const std::string &directory, const bool overwrite) const;

    /**
     * Write the analysis' parameters.prm (@p prm) and the header of
     * strength-reduction.csv in @p directory. Stops every rank on a
     * problem.
     */
    void
    start_files(const ParameterHandler &prm,
                const std::string      &directory) const;

    /**
     * Append the row of @p trial (number @p number) to
     * strength-reduction.csv in @p directory (rank 0).
     */
    void
    record(const std::string &directory,
           const unsigned int number,
           const Trial       &trial) const;

    /**
     * Write factor-of-safety.txt in @p directory with @p text (rank 0).
     */
    void
    write_result(const std::string &directory, const std::string &text) const;

    MPI_Comm communicator;
    /// The log, for the trials' runs.
    std::ostream &log;
    /// The log on rank 0, for the analysis' own lines.
    ConditionalOStream pcout;
    bool               root;
    double             lower_factor       = 0.5;
    double             upper_factor       = 3;
    double             tolerance          = 0.01;
    double             displacement_limit = 0;
  };
} // namespace MpmOtm

#endif
