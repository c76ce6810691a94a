#include <mpm_otm/base/node_memory.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace MpmOtm
{
  using namespace dealii;

  NodeMemory::NodeMemory(const MPI_Comm communicator)
  {
    const int error = MPI_Comm_split_type(communicator,
                                          MPI_COMM_TYPE_SHARED,
                                          0,
                                          MPI_INFO_NULL,
                                          &node);
    AssertThrowMPI(error);
    ranks_on_node = Utilities::MPI::n_mpi_processes(node);
    first_on_node = (Utilities::MPI::this_mpi_process(node) == 0);

    double        bytes = 0.;
    std::ifstream meminfo("/proc/meminfo");
    for (std::string line; first_on_node && std::getline(meminfo, line);)
      if (line.rfind("MemAvailable:", 0) == 0)
        bytes = 1024. * std::strtod(line.c_str() + 13, nullptr);
    available_bytes = Utilities::MPI::broadcast(node, bytes, 0);
  }



  NodeMemory::~NodeMemory()
  {
    MPI_Comm_free(&node);
  }



  double
  NodeMemory::available() const
  {
    return available_bytes;
  }



  unsigned int
  NodeMemory::n_ranks_on_node() const
  {
    return ranks_on_node;
  }



  double
  NodeMemory::sum_on_node(const double value) const
  {
    return Utilities::MPI::sum(value, node);
  }



  std::string
  NodeMemory::shortage(const double bytes_on_node) const
  {
    if (!first_on_node || available_bytes <= 0. ||
        bytes_on_node <= available_bytes)
      return "";
    std::ostringstream message;
    message << std::setprecision(3) << bytes_on_node / 1e9 << " GB for the "
            << ranks_on_node << " MPI rank(s) on this node, which has "
            << available_bytes / 1e9
            << " GB available (MemAvailable in /proc/meminfo). ";
    return message.str();
  }
} // namespace MpmOtm
