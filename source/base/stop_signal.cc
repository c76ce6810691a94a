#include <deal.II/base/mpi.h>

#include <mpm_otm/base/stop_signal.h>

namespace MpmOtm
{
  namespace
  {
    /// The last signal caught (0: none); all a handler may safely touch.
    volatile std::sig_atomic_t caught_signal = 0;

    // The first signal asks the run to stop after its step; a second one
    // ends the program at once, as without the handler.
    extern "C" void
    catch_signal(const int signal)
    {
      if (caught_signal != 0)
        {
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      caught_signal = signal;
    }
  } // namespace



  StopSignal::StopSignal()
  {
    caught_signal      = 0;
    previous_terminate = std::signal(SIGTERM, catch_signal);
    previous_interrupt = std::signal(SIGINT, catch_signal);
  }



  StopSignal::~StopSignal()
  {
    std::signal(SIGTERM, previous_terminate);
    std::signal(SIGINT, previous_interrupt);
  }



  std::string
  StopSignal::received(const MPI_Comm communicator) const
  {
    const int signal =
      dealii::Utilities::MPI::max(static_cast<int>(caught_signal),
                                  communicator);
    if (signal == SIGTERM)
      return "SIGTERM";
    if (signal == SIGINT)
      return "SIGINT";
    return "";
  }



  StoppedBySignal::StoppedBySignal(const std::string &message,
                                   const std::string &signal)
    : std::runtime_error(message)
    , status(128 + (signal == "SIGINT" ? SIGINT : SIGTERM))
  {}



  int
  StoppedBySignal::exit_status() const
  {
    return status;
  }
} // namespace MpmOtm
