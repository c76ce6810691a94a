#include <deal.II/base/exceptions.h>

#include <mpm_otm/base/collective_error.h>

namespace MpmOtm
{
  void
  stop_if_any_rank_failed(const MPI_Comm     communicator,
                          const std::string &local_problem,
                          const std::string &prefix,
                          const std::string &advice)
  {
    using namespace dealii;
    if (Utilities::MPI::max(local_problem.empty() ? 0 : 1, communicator) == 0)
      return;
    std::string all;
    for (const auto &part :
         Utilities::MPI::all_gather(communicator, local_problem))
      all += part;
    AssertThrow(false, ExcMessage(prefix + all + advice));
  }
} // namespace MpmOtm
