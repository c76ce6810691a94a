#include <mpm_otm/base/node_memory.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <sys/resource.h>

namespace MpmOtm
{
  using namespace dealii;

  namespace
  {
    constexpr double unlimited = std::numeric_limits<double>::infinity();

    /**
     * The number of bytes that the file @p name holds (its first word);
     * infinity if it cannot be read, says "max" (cgroup v2) or is above
     * 2^60 (cgroup v1 writes 2^63 rounded down to a page for no limit).
     */
    double
    bytes_in(const std::string &name)
    {
      std::ifstream file(name);
      std::string   word;
      if (!(file >> word) || word == "max")
        return unlimited;
      char        *end   = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      return (end == word.c_str() || value >= 1.1529215e18) ? unlimited : value;
    }

    /**
     * The memory this process may still take under the address-space
     * limit (RLIMIT_AS, `ulimit -v`): the limit less its size (VmSize of
     * /proc/self/status); infinity if there is no limit.
     */
    double
    address_space_headroom()
    {
      rlimit limit;
      if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
        return unlimited;
      double        size = 0.;
      std::ifstream status("/proc/self/status");
      for (std::string line; std::getline(status, line);)
        if (line.rfind("VmSize:", 0) == 0)
          size = 1024. * std::strtod(line.c_str() + 7, nullptr);
      return static_cast<double>(limit.rlim_cur) - size;
    }
  } // namespace



  double
  NodeMemory::control_group_headroom(const std::string &process_groups,
                                     const std::string &root,
                                     std::string       &limit_file)
  {
    namespace fs           = std::filesystem;
    double        headroom = unlimited;
    std::ifstream groups(process_groups);
    for (std::string line; std::getline(groups, line);)
      {
        // hierarchy-id:controllers:path
        const auto first  = line.find(':');
        const auto second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos)
          continue;
        const std::string controllers =
          "," + line.substr(first + 1, second - first - 1) + ",";
        std::string base, limit_name, usage_name;
        if (controllers == ",,")
          {
            // cgroup v2: mounted at the root, or at root/unified beside v1.
            base       = fs::exists(root + "/cgroup.controllers") ? root :
                                                                    root + "/unified";
            limit_name = "memory.max";
            usage_name = "memory.current";
          }
        else if (controllers.find(",memory,") != std::string::npos)
          {
            base       = root + "/memory";
            limit_name = "memory.limit_in_bytes";
            usage_name = "memory.usage_in_bytes";
          }
        else
          continue;
        // The group and its ancestors; a group not visible under the
        // mount (a container's own namespace) is the mount's root.
        fs::path group = line.substr(second + 1);
        if (!fs::exists(base + group.string()))
          group = "/";
        while (true)
          {
            const std::string directory =
              base + (group == "/" ? std::string() : group.string());
            const double limit = bytes_in(directory + "/" + limit_name);
            if (limit < unlimited)
              {
                double usage = bytes_in(directory + "/" + usage_name);
                if (!(usage < unlimited))
                  usage = 0.;
                if (limit - usage < headroom)
                  {
                    headroom   = limit - usage;
                    limit_file = directory + "/" + limit_name;
                  }
              }
            if (group == "/" || group.empty() || !group.has_parent_path() ||
                group.parent_path() == group)
              break;
            group = group.parent_path();
          }
      }
    return headroom;
  }



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

    // Each process's own limit, the smallest of the node's ranks counting
    // for all of them.
    const double per_rank = Utilities::MPI::min(address_space_headroom(), node);

    double      bytes = 0.;
    std::string where = "MemAvailable in /proc/meminfo";
    if (first_on_node)
      {
        std::ifstream meminfo("/proc/meminfo");
        for (std::string line; std::getline(meminfo, line);)
          if (line.rfind("MemAvailable:", 0) == 0)
            bytes = 1024. * std::strtod(line.c_str() + 13, nullptr);
        std::string  limit_file;
        const double group = control_group_headroom("/proc/self/cgroup",
                                                    "/sys/fs/cgroup",
                                                    limit_file);
        if (group < unlimited && (bytes <= 0. || group < bytes))
          {
            bytes = group;
            where = "the memory limit of the job's control group, " +
                    limit_file + ", less what the group uses";
          }
        if (per_rank < unlimited &&
            (bytes <= 0. || per_rank * ranks_on_node < bytes))
          {
            bytes = per_rank * ranks_on_node;
            where = "the address-space limit of each process, ulimit -v "
                    "(RLIMIT_AS), less its size";
          }
        // Already over a limit: as good as nothing left (0 means unknown).
        if (where != "MemAvailable in /proc/meminfo")
          bytes = std::max(bytes, 1.);
      }
    available_bytes = Utilities::MPI::broadcast(node, bytes, 0);
    source          = Utilities::MPI::broadcast(node, where, 0);
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
            << available_bytes / 1e9 << " GB available (" << source << "). ";
    return message.str();
  }
} // namespace MpmOtm
