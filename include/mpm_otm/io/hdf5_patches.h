#ifndef mpm_otm_io_hdf5_patches_h
#define mpm_otm_io_hdf5_patches_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/reference_cell.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * Field output of one step (ParticlePatches, GridPatches) that writes
   * itself into one HDF5 file for all ranks, in the layout an XDMF index
   * points into: datasets nodes and cells, and one per data set of
   * data_sets(). TimeSeries writes the index from what this interface
   * tells.
   */
  class HDF5Patches
  {
  public:
    virtual ~HDF5Patches() = default;

    /**
     * Write the patches of all ranks into the HDF5 file @p file_name, each
     * rank its rows of every dataset. Collective.
     */
    virtual void
    write_hdf5(const std::string &file_name,
               const MPI_Comm     communicator) const = 0;

    /**
     * The number of nodes of this rank in write_hdf5().
     */
    virtual std::uint64_t
    n_nodes() const = 0;

    /**
     * The number of cells of this rank in write_hdf5().
     */
    virtual std::uint64_t
    n_cells() const = 0;

    /**
     * The kind of these cells.
     */
    virtual ReferenceCell
    reference_cell() const = 0;

    /**
     * The data sets of write_hdf5() with their numbers of columns (a vector
     * has three, padded with zeros in 2D).
     */
    virtual std::vector<std::pair<std::string, unsigned int>>
    data_sets() const = 0;
  };
} // namespace MpmOtm

#endif
