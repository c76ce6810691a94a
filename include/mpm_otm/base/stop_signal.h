#ifndef mpm_otm_base_stop_signal_h
#define mpm_otm_base_stop_signal_h

#include <deal.II/base/mpi.h>

#include <csignal>
#include <string>

namespace MpmOtm
{
  /**
   * Catches SIGTERM and SIGINT (what batch schedulers send before they kill
   * a job at its time limit, and Ctrl-C) while it exists, so that a run can
   * end after a complete step with that step's output written instead of
   * being cut off in the middle of one. A second signal ends the program
   * at once, as it would without the handlers. The handlers that were
   * installed before are restored on destruction.
   */
  class StopSignal
  {
  public:
    /**
     * Install the handlers.
     */
    StopSignal();

    /**
     * Restore the previous handlers.
     */
    ~StopSignal();

    StopSignal(const StopSignal &) = delete;
    StopSignal &
    operator=(const StopSignal &) = delete;

    /**
     * The name of the signal that any rank of @p communicator received
     * ("SIGTERM" or "SIGINT"), or an empty string. Collective.
     */
    std::string
    received(const MPI_Comm communicator) const;

  private:
    using Handler = void (*)(int);
    Handler previous_terminate;
    Handler previous_interrupt;
  };
} // namespace MpmOtm

#endif
