#ifndef mpm_otm_base_node_memory_h
#define mpm_otm_base_node_memory_h

#include <deal.II/base/mpi.h>

#include <string>

namespace MpmOtm
{
  /**
   * The memory of the compute node an MPI rank runs on, for checks made
   * before a large allocation (the grid, the material points): the kernel
   * would otherwise kill the run without a message, or deal.II would say
   * only std::bad_alloc. The available memory is the least of MemAvailable
   * of /proc/meminfo, the headroom under the memory limit of the control
   * group of the job (cgroup v1 or v2, the group and its ancestors; a batch
   * system's per-job limit) and, times the ranks on the node, under the
   * smallest address-space limit of its ranks (RLIMIT_AS, `ulimit -v`). It
   * is 0 where none of these is known, and then every check passes.
   *
   * The constructor and sum_on_node() are collective over the ranks of the
   * communicator given to the constructor.
   */
  class NodeMemory
  {
  public:
    /**
     * Find the ranks of @p communicator that share this rank's node and the
     * memory the node has available now.
     */
    explicit NodeMemory(const MPI_Comm communicator);

    ~NodeMemory();

    NodeMemory(const NodeMemory &) = delete;
    NodeMemory &
    operator=(const NodeMemory &) = delete;

    /**
     * Bytes available on this node (0 if unknown).
     */
    double
    available() const;

    /**
     * Number of ranks of the communicator on this node.
     */
    unsigned int
    n_ranks_on_node() const;

    /**
     * Sum of @p value over the ranks on this node. Collective over the
     * ranks of the node.
     */
    double
    sum_on_node(const double value) const;

    /**
     * If @p bytes_on_node (the sum over this node's ranks) exceed the
     * available memory, the end of a message: "... GB for
     * the k MPI rank(s) on this node, which has ... GB available
     * (MemAvailable in /proc/meminfo). ". Empty otherwise, and on every rank
     * but the first of each node, so that one rank per node says it.
     */
    std::string
    shortage(const double bytes_on_node) const;

    /**
     * The memory the control group of this process may still take: the
     * least, over the groups of @p process_groups (the format of
     * /proc/self/cgroup) with a memory limit and their ancestors, of limit
     * less usage, read under the mount @p root (/sys/fs/cgroup): cgroup v2's
     * memory.max and memory.current, or v1's memory.limit_in_bytes and
     * memory.usage_in_bytes under root/memory. Infinity if no group has a
     * limit; @p limit_file is then left alone, otherwise set to the file of
     * the limit that binds.
     */
    static double
    control_group_headroom(const std::string &process_groups,
                           const std::string &root,
                           std::string       &limit_file);

  private:
    MPI_Comm     node;
    unsigned int ranks_on_node;
    bool         first_on_node;
    double       available_bytes;
    /// Which limit available_bytes comes from, for messages.
    std::string source;
  };
} // namespace MpmOtm

#endif
