#ifndef mpm_otm_simulator_simulator_h
#define mpm_otm_simulator_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>

#include <mpm_otm/base/subsection_names.h>
#include <mpm_otm/io/statistics.h>

#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class ShapeFunctions;
  template <int dim>
  class NodalSystem;
  template <int dim>
  class MassMatrix;
  template <int dim>
  class NodalUpdate;
  template <int dim>
  class ParticleTransfer;
  template <int dim>
  class GridMotion;
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class Problem;
  template <int dim>
  class OutputWriter;
  template <int dim>
  class MonitoringPoints;
  template <int dim>
  class BoundaryConditions;
  template <int dim>
  class LocalDamping;
  template <int dim>
  class Checkpoint;
  template <int dim>
  class TimeStepper;
  template <int dim>
  class EnergyMonitor;
  template <int dim>
  class VolumetricLockingRemedy;
  template <int dim>
  class SofteningRegularisation;
  template <int dim>
  class QuasiStaticEnd;
  template <int dim>
  class StagePlan;
  class CheckpointState;

  /**
   * Read the entry "Dimension" of a parameter file (1 when @p filename is
   * empty: the default benchmark).
   */
  unsigned int
  read_dimension(const std::string &filename);

  /**
   * The application: declares and reads every parameter, builds the grid,
   * material points, shape functions, strategies and output from them, and
   * runs the time loop, reporting progress on rank 0 and timings at the end.
   */
  template <int dim>
  class Simulator
  {
  public:
    /**
     * @p log receives the progress lines and the timing summary (rank 0).
     */
    Simulator(const MPI_Comm communicator, std::ostream &log);

    ~Simulator();

    /**
     * Declare every parameter of the application, including those of every
     * registered plugin and the named subsections listed in @p names
     * (SubsectionNames::read() finds them in a parameter file).
     */
    static void
    declare_parameters(ParameterHandler      &prm,
                       const SubsectionNames &names = SubsectionNames());

    /**
     * Read and check all parameters; stops with a message naming the entry
     * on bad input.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Build everything and write the initial output; checks the time step
     * against the stable one. With @p resume, continue instead the run in
     * Output/Directory from its newest checkpoint (`mpm-otm --resume`):
     * the grid and points are built as for its start (which gives the same
     * time step), then replaced by the checkpoint's, and the output of the
     * steps after the checkpoint is removed.
     */
    void
    setup(const ParameterHandler &prm, const bool resume = false);

    /**
     * Run all time steps to the end time; returns the statistics at the end.
     * @p observer, if given, is called with the step number and the
     * statistics after the output of every output step (step 0 included).
     */
    Statistics<dim>
    run(const std::function<void(unsigned int, const Statistics<dim> &)>
          &observer = {});

    /**
     * Divide the strength of every material by @p factor
     * (Material::reduce_strength()) at the start of the last stage (of the
     * run, without Stages), the earlier stages and the initial stresses
     * (e.g. a geostatic K0) keeping the full strengths: a trial of a
     * strength reduction. Call after setup() and before run(); once per run.
     */
    void
    reduce_strength(const double factor);

    /**
     * The state from which the trials of a strength reduction start: with
     * @p write, run() writes it, as a checkpoint into @p directory, at the
     * start of the last stage (after the earlier stages, before the last
     * stage's changes and the divided strengths; without Stages, before the
     * first step); otherwise setup() reads it from there in place of the
     * seeded points, and run() goes on with the last stage as the run that
     * wrote it did. The two runs must have the same parameters but for the
     * subsections Output and Checkpoint. Call before setup().
     */
    void
    share_state_before_last_stage(const std::string &directory,
                                  const bool         write);

    /**
     * The largest distance of a material point from its initial position,
     * over all ranks (collective).
     */
    double
    largest_displacement() const;

    /**
     * Whether the run ends when it comes to rest (subsection "Quasi-static
     * end" on; with Stages: the last stage's End at rest).
     */
    bool
    ends_at_rest() const;

    /**
     * The material points (for tests and post-processing).
     */
    const MaterialPoints<dim> &
    material_points() const;

    /**
     * The background grid (moved with the material in OTM and unified runs).
     */
    const BackgroundGrid<dim> &
    background_grid() const;

    /**
     * The shape functions (their numbering and the cells' finite element).
     */
    const ShapeFunctions<dim> &
    shape_function_family() const;

    /**
     * The nodal system of the last step.
     */
    const NodalSystem<dim> &
    nodal_system() const;

    /**
     * The materials.
     */
    const MaterialLibrary<dim> &
    material_library() const;

    /**
     * The problem.
     */
    const Problem<dim> &
    problem() const;

    /**
     * Current time.
     */
    double
    time() const;

    /**
     * Whether the run ended at rest by its quasi-static end (subsection
     * "Quasi-static end"; false if that is off).
     */
    bool
    at_rest() const;

    /**
     * The time step of the run (Time step, or with Time step = auto the
     * Courant factor times the stable one); set by setup().
     */
    double
    time_step_size() const;

    /**
     * The stable time step 2 / omega_max estimated by setup()
     * (StableTimeStep).
     */
    double
    stable_time_step() const;

  private:
    /**
     * The names of the named boundary conditions and then of the surface
     * loads: the forces and displacements of statistics.csv.
     */
    std::vector<std::string>
    reaction_names() const;

    /**
     * Whether this run starts from the state before the last stage that
     * another run wrote (share_state_before_last_stage() without write).
     */
    bool
    starts_from_stored_state() const;

    /**
     * Write a checkpoint after step @p step with the state of every part of
     * the run, including @p stepper's and @p energy_monitor's, and the
     * stage: its number @p stage, first step and start time, into
     * @p directory (the output directory, or the directory of the state
     * before the last stage).
     */
    void
    write_checkpoint(const std::string         &directory,
                     const unsigned int         step,
                     const TimeStepper<dim>    &stepper,
                     const EnergyMonitor<dim>  &energy_monitor,
                     const std::vector<double> &stage);

    /**
     * Stop with a message naming the stage @p stage_name if the time step
     * exceeds the stable time step of the points now there (after a stage
     * has added bodies). Collective.
     */
    void
    check_time_step_after_adding(const std::string &stage_name) const;

    /**
     * Append the row of a stage that has ended to stages.csv in the output
     * directory (rank 0): its number @p stage, first and last step, start
     * and end time and how it ended, @p ending.
     */
    void
    record_stage(const unsigned int stage,
                 const unsigned int first_step,
                 const double       start_time,
                 const unsigned int last_step,
                 const std::string &ending) const;

    MPI_Comm           communicator;
    ConditionalOStream pcout;

    double end_time  = 0;
    double time_step = 0;
    /// Time step = auto: Courant factor x the stable time step.
    bool   automatic_time_step = false;
    double courant_factor      = 0.5;
    /// Allowed gain of energy over the energy supplied (EnergyMonitor).
    double energy_growth_limit = 0.25;
    /// The stable time step found at the start.
    double stable_step  = 0;
    double current_time = 0;
    /// Functions with a smaller diagonal mass are deactivated (thesis 5.2).
    double deactivation_threshold = 0;

    std::unique_ptr<BackgroundGrid<dim>>     grid;
    std::unique_ptr<MaterialPoints<dim>>     points;
    std::unique_ptr<ShapeFunctions<dim>>     shape_functions;
    std::unique_ptr<NodalSystem<dim>>        system;
    std::unique_ptr<MassMatrix<dim>>         mass_matrix;
    std::unique_ptr<NodalUpdate<dim>>        nodal_update;
    std::unique_ptr<ParticleTransfer<dim>>   particle_transfer;
    std::unique_ptr<GridMotion<dim>>         grid_motion;
    std::unique_ptr<MaterialLibrary<dim>>    materials;
    std::unique_ptr<Problem<dim>>            problem_description;
    std::unique_ptr<OutputWriter<dim>>       output;
    std::unique_ptr<MonitoringPoints<dim>>   monitoring;
    std::unique_ptr<BoundaryConditions<dim>> boundary_conditions;
    std::unique_ptr<LocalDamping<dim>>       damping;
    std::unique_ptr<Checkpoint<dim>>         checkpoint;
    /// Subsection "Quasi-static end".
    std::unique_ptr<QuasiStaticEnd<dim>> quasi_static_end;
    /// The stages (one for a run without Stages).
    std::unique_ptr<StagePlan<dim>> stage_plan;
    /// The factor that reduce_strength() leaves for the start of the last
    /// stage (1: none).
    double pending_strength_factor = 1;
    /// share_state_before_last_stage(): the directory of the state before
    /// the last stage (empty: none), and whether run() writes it (or
    /// setup() has read it).
    std::string state_before_last_stage;
    bool        writes_state_before_last_stage = false;
    /// Volumetric locking remedy = automatic: the remedy is dropped where
    /// the shape functions leave it nothing to do.
    bool automatic_locking_remedy = false;
    /// Null for Volumetric locking remedy = none.
    std::unique_ptr<VolumetricLockingRemedy<dim>> locking_remedy;
    /// Null for Softening regularisation = none.
    std::unique_ptr<SofteningRegularisation<dim>> softening_regularisation;
    /// The step after which the checkpoint resumed from was written (0: a
    /// new run).
    unsigned int resumed_step = 0;
    /// Its state, until run() has handed it to the time stepper and the
    /// energy monitor.
    std::unique_ptr<CheckpointState> resumed_state;
  };
} // namespace MpmOtm

#endif
