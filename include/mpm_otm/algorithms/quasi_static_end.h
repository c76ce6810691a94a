#ifndef mpm_otm_algorithms_quasi_static_end_h
#define mpm_otm_algorithms_quasi_static_end_h

#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/base/checkpoint_state.h>

#include <string>
#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class NodalSystem;

  /**
   * The quasi-static end of a run: geotechnical runs want the state at
   * rest, and a body that fails must be told from one that has come to
   * rest. The measure is the kinetic energy of the grid's motion,
   * E_k = sum_i m_i |v_i|^2 / 2 (NodalSystem::kinetic_energy()), not that
   * of the points: particle velocities that project to zero on the grid
   * (two points of a cell moving against each other, left over from the
   * release of a slope) move nothing and never decay under local damping,
   * which acts on the nodal forces; they kept the points' kinetic energy
   * constant and a few points at a slope's crest at 0.45 m/s while the
   * slope stood (doc/benchmarks.md, G5). The body is at rest when
   * E_k <= tolerance x E_ref at every check (every 10 steps) over
   * "Checks" checks in a row, E_ref the largest E_k of the run so far or
   * the work supplied by the loads, whichever is larger. A run that
   * reaches rest ends there (at_rest()); one that reaches its end time
   * moving is reported with the trend of E_k over the last tenth of the
   * run (summary()): a motion that does not decay is a failing body (or
   * too short a run).
   */
  template <int dim>
  class QuasiStaticEnd
  {
  public:
    /**
     * Declare subsection "Quasi-static end".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read subsection "Quasi-static end".
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Whether a tolerance is set (0 switches the end off).
     */
    bool
    enabled() const;

    /**
     * Record the state after a step ending at @p time: the grid's kinetic
     * energy of @p system and the work @p supplied_work done by the loads
     * since the start (of all ranks). Collective. Returns whether the body
     * is at rest by the criterion.
     */
    bool
    check(const NodalSystem<dim> &system,
          const double            time,
          const double            supplied_work);

    /**
     * Start anew at the start of a stage, the work @p supplied_work (of all
     * ranks) done by the loads so far: the reference E_ref and the trend
     * then count from here.
     */
    void
    restart(const double supplied_work);

    /**
     * Whether the last check found the body at rest.
     */
    bool
    at_rest() const;

    /**
     * One sentence on the state at the last check: at rest, or moving with
     * E_k / E_ref and whether the motion decays over the last tenth of the
     * checks.
     */
    std::string
    summary() const;

    /**
     * Save what the criterion carries from step to step into @p state.
     */
    void
    save(CheckpointState &state) const;

    /**
     * Restore what save() saved.
     */
    void
    load(const CheckpointState &state);

  private:
    /// E_k <= tolerance x E_ref is rest; 0: off.
    double tolerance = 0;
    /// Number of consecutive checks at rest that end the run.
    unsigned int required_checks = 10;
    /// Consecutive checks at rest so far.
    unsigned int checks_at_rest = 0;
    /// The largest grid kinetic energy so far.
    double largest_kinetic_energy = 0;
    /// The work of the loads at the last check, since work_at_start.
    double work = 0;
    /// The work of the loads before the stage began.
    double work_at_start = 0;
    /// (time, E_k) at every check, for the trend of summary().
    std::vector<std::pair<double, double>> history;
  };
} // namespace MpmOtm

#endif
