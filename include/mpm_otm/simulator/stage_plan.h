#ifndef mpm_otm_simulator_stage_plan_h
#define mpm_otm_simulator_stage_plan_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class BoundaryConditions;
  template <int dim>
  class LocalDamping;
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class NodalSystem;
  template <int dim>
  class Problem;

  /**
   * The stages of a run (entry "Stages", subsections "Stage <name>"): a
   * sequence of named periods, each with its end (an End time, or rest by
   * the quasi-static end) and what changes at its start: bodies removed
   * (an excavation) or added (a fill, seeded in its own initial state),
   * displacements reset to zero, the local damping, the boundary conditions
   * and surface loads that act, gravity. Everything else (grid, shape
   * functions, method, materials, what each condition and load does) is
   * that of the whole run, so a stage subsection has no entry for it. A run
   * without Stages is one unnamed stage from t = 0 to Time/End time that ends
   * at rest if the quasi-static end is on, so the time loop knows only stages.
   *
   * Staged runs keep each point's body in a point variable "body" (its
   * number in Bodies), which tells the points of a removed body.
   */
  template <int dim>
  class StagePlan
  {
  public:
    /**
     * One stage.
     */
    struct Stage
    {
      /// Its name (empty in a run without Stages).
      std::string name;
      /// The time at which it ends at the latest (s).
      double end_time = 0;
      /// Whether it ends as soon as the body is at rest (subsection
      /// "Quasi-static end").
      bool end_at_rest = false;
      /// The bodies (numbers in Bodies) whose points are removed at its
      /// start.
      std::vector<unsigned int> removed_bodies;
      /// The bodies seeded at its start (absent before).
      std::vector<unsigned int> added_bodies;
      /// Whether the displacements restart from zero at its start.
      bool reset_displacements = false;
      /// The local damping coefficient from its start; negative: unchanged.
      double damping_coefficient = -1;
      /// Whether each surface load acts from its start; empty: unchanged.
      std::vector<bool> acting_loads;
      /// Whether each boundary condition acts from its start; empty:
      /// unchanged.
      std::vector<bool> acting_conditions;
      /// The gravitational acceleration from its start; empty: unchanged.
      std::vector<double> gravity;
    };

    /**
     * Declare the subsections "Stage <name>" for each of @p names.
     */
    static void
    declare_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &names);

    /**
     * Read the stages. @p fixed_grid: whether the method keeps the grid
     * fixed (bodies can be removed and added only then);
     * @p quasi_static_end: whether subsection "Quasi-static end" is on.
     * Stops with a message naming the entry on bad input.
     */
    void
    parse_parameters(ParameterHandler &prm,
                     const bool        fixed_grid,
                     const bool        quasi_static_end);

    /**
     * Whether the run has named stages.
     */
    bool
    staged() const;

    /**
     * The stages, at least one.
     */
    const std::vector<Stage> &
    stages() const;

    /**
     * Whether some stage sets a gravity other than zero.
     */
    bool
    sets_gravity() const;

    /**
     * The entry that gives the end time of the last stage ("Time/End time",
     * or "Stage <last>/End time"): the one a resumed run may extend.
     */
    std::string
    end_time_entry() const;

    /**
     * Reserve the point variable "body" in @p materials (staged runs).
     */
    void
    reserve_point_variables(MaterialLibrary<dim> &materials);

    /**
     * Seed @p points on @p grid with the bodies of @p problem that exist at
     * the start (those that no stage adds), of the materials @p materials;
     * a geostatic initial stress counts the weight of these bodies only.
     */
    void
    seed(MaterialPoints<dim>        &points,
         const BackgroundGrid<dim>  &grid,
         Problem<dim>               &problem,
         const MaterialLibrary<dim> &materials) const;

    /**
     * Make the changes of stage @p stage at its start: remove the points of
     * its removed bodies, seed its added bodies (of @p problem, in their
     * initial state, a geostatic stress from the weight of the bodies then
     * present under the stage's gravity), reset the displacements, set the
     * damping of @p damping, the surface loads of @p problem that act and
     * its gravity, and the @p conditions that act (with the Dirichlet lists
     * of @p system).
     * Collective. Returns a sentence on what changed, for the log.
     */
    std::string
    begin(const unsigned int          stage,
          MaterialPoints<dim>        &points,
          Problem<dim>               &problem,
          const MaterialLibrary<dim> &materials,
          LocalDamping<dim>          &damping,
          BoundaryConditions<dim>    &conditions,
          NodalSystem<dim>           &system) const;

    /**
     * Set @p damping, the surface loads of @p problem that act and its
     * gravity, and the @p conditions that act (with the Dirichlet lists of
     * @p system) as the stages up to and including @p stage left them: for a
     * run resumed inside @p stage, or started from the state before it.
     */
    void
    restore(const unsigned int       stage,
            LocalDamping<dim>       &damping,
            Problem<dim>            &problem,
            BoundaryConditions<dim> &conditions,
            NodalSystem<dim>        &system) const;

  private:
    /**
     * Let the @p conditions act that @p acting says, and make the Dirichlet
     * lists of @p system those of @p problem and of the acting conditions.
     */
    void
    set_acting_conditions(const std::vector<bool> &acting,
                          const Problem<dim>      &problem,
                          BoundaryConditions<dim> &conditions,
                          NodalSystem<dim>        &system) const;

    std::vector<Stage> stage_list;
    bool               named = false;
    /// Whether each body exists at the start.
    std::vector<bool> present_at_start;
    /// Whether each body exists in each stage (after its changes).
    std::vector<std::vector<bool>> present_in_stage;
    /// The place of the point variable "body" (staged runs).
    unsigned int body_slot = 0;
  };
} // namespace MpmOtm

#endif
