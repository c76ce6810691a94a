#ifndef mpm_otm_base_stop_signal_h
#define mpm_otm_base_stop_signal_h

#include <deal.II/base/mpi.h>

#include <csignal>
#include <stdexcept>
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

  /**
   * The exception that ends a run stopped by a signal, thrown on every rank
   * at once: main() prints its message and exits with 128 plus the signal's
   * number (143 for SIGTERM, 130 for SIGINT), as a shell reports a program
   * that the signal ended, so that a job script can tell such a stop from
   * an error (status 1).
   */
  class StoppedBySignal : public std::runtime_error
  {
  public:
    /**
     * The run stopped because of @p signal ("SIGTERM" or "SIGINT"), as
     * @p message says.
     */
    StoppedBySignal(const std::string &message, const std::string &signal);

    /**
     * 128 plus the number of the signal.
     */
    int
    exit_status() const;

  private:
    int status;
  };
} // namespace MpmOtm

#endif
