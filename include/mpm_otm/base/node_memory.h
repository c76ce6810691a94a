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
   * only std::bad_alloc. The available memory is MemAvailable of
   * /proc/meminfo, read once by the first rank of each node; it is 0 where
   * that file does not exist, and then every check passes.
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

  private:
    MPI_Comm     node;
    unsigned int ranks_on_node;
    bool         first_on_node;
    double       available_bytes;
  };
} // namespace MpmOtm

#endif
