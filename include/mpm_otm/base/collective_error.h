#ifndef mpm_otm_base_collective_error_h
#define mpm_otm_base_collective_error_h

#include <deal.II/base/mpi.h>

#include <string>

namespace MpmOtm
{
  /**
   * Stop the run on every rank of @p communicator if any rank reports a
   * problem: each rank passes its own description @p local_problem (empty if
   * it has none), and the message is @p prefix, the descriptions of all
   * ranks and @p advice. Collective, so that no rank is left waiting while
   * the others stop (used for points that leave the grid, unstable points
   * and cells of a moving grid).
   */
  void
  stop_if_any_rank_failed(const MPI_Comm     communicator,
                          const std::string &local_problem,
                          const std::string &prefix,
                          const std::string &advice);
} // namespace MpmOtm

#endif
