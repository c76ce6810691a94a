#ifndef mpm_otm_algorithms_energy_monitor_h
#define mpm_otm_algorithms_energy_monitor_h

#include <deal.II/base/mpi.h>

#include <mpm_otm/base/checkpoint_state.h>

#include <string>

namespace MpmOtm
{
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;

  /**
   * Stops a run that gains energy nobody supplied. The kinetic plus strain
   * energy E of the points may not exceed (1 + growth limit) times the
   * energy supplied so far: E at the start plus the work done by gravity,
   * body forces, tractions and prescribed velocities. Only the positive
   * part of each step's work on each rank counts, so friction, damping
   * and plastic flow (which remove energy) never mask a gain. An unstable
   * time step or discretisation shows up this way while every number is
   * still finite: the energy of its fastest mode grows by a fixed factor
   * per step, whereas an explicit scheme that is stable errs on the
   * energy balance by a few per cent.
   */
  template <int dim>
  class EnergyMonitor
  {
  public:
    /**
     * Monitor with the allowed relative gain @p growth_limit, on the points
     * of @p communicator. Energies below 1e-12 of the kinetic energy of all
     * points moving at @p reference_speed (the grid's smallest cell size
     * over the time step, above every wave speed of a stable run) are
     * round-off of a body at rest and never called a gain.
     */
    EnergyMonitor(const double   growth_limit,
                  const double   reference_speed,
                  const MPI_Comm communicator);

    /**
     * Compare the energy of @p material_points with the energy supplied,
     * given the work @p local_supplied_work done on this rank since the
     * start (from TimeStepper::supplied_work()). The first call records
     * the initial energy. Collective; throws on every rank, with the
     * energies in the message, if the energy is above the bound.
     */
    void
    check(const MaterialPoints<dim>  &material_points,
          const MaterialLibrary<dim> &materials,
          const double                local_supplied_work);

    /**
     * Start the balance anew at the next check: a stage that removes or
     * adds material, whose energy no load supplied or took away. The energy
     * then found is the start's, and the work counts from there.
     */
    void
    restart();

    /**
     * The changes that most often cure an instability, most likely first,
     * for the message of every check that finds one.
     */
    static std::string
    advice();

    /**
     * Save the state that this object carries from one time step to the
     * next into @p state, for a checkpoint.
     */
    void
    save(CheckpointState &state) const;

    /**
     * Restore the state saved by save() from @p state (of a run on any
     * number of ranks).
     */
    void
    load(const CheckpointState &state);

  private:
    const double   growth_limit;
    const double   reference_speed;
    const MPI_Comm communicator;
    bool           started        = false;
    double         initial_energy = 0;
    double         energy_floor   = 0;
    /// The work supplied on all ranks before the balance started.
    double work_at_start = 0;
    /// Whether a stage restarted the balance.
    bool stage_started = false;
  };
} // namespace MpmOtm

#endif
