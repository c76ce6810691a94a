#ifndef mpm_otm_io_time_series_h
#define mpm_otm_io_time_series_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/reference_cell.h>

#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/io/hdf5_patches.h>

#include <cstdint>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DataOutInterface;
}

namespace MpmOtm
{
  using namespace dealii;

  /**
   * One time series of field output - the material points or the grid -
   * in the format Output/Format chooses, both of which ParaView opens:
   * - vtu: per step one piece NAME_NNNNN.R.vtu per rank and the index
   *   NAME_NNNNN.pvtu, and over the steps NAME.pvd;
   * - hdf5: per step one file NAME_NNNNN.h5 that all ranks write together
   *   (ParticlePatches::write_hdf5(), GridPatches::write_hdf5()), and over
   *   the steps NAME.xdmf, which points into them.
   * Every file is written under a temporary name and renamed when complete,
   * so an interrupted run leaves the steps written before it intact; a
   * failed write stops all ranks, naming the file (a collective HDF5 write
   * that fails on one rank only may leave the others waiting in HDF5).
   */
  class TimeSeries
  {
  public:
    /**
     * The file formats.
     */
    enum class Format
    {
      vtu,
      hdf5
    };

    /**
     * A series whose files are named @p name (particles or grid).
     */
    explicit TimeSeries(const std::string &name);

    /**
     * Write step @p step at @p time of @p patches (ParticlePatches or
     * GridPatches) to @p directory and add it to the index: in VTU through
     * their DataOutInterface, in HDF5 by their own write_hdf5(). Collective.
     */
    template <typename Patches>
    void
    write(const Patches     &patches,
          const std::string &directory,
          const Format       format,
          const unsigned int step,
          const double       time,
          const MPI_Comm     communicator);

    /**
     * Save the steps written so far into @p state, for a checkpoint.
     */
    void
    save(CheckpointState &state) const;

    /**
     * Restore what save() saved: a run resumed at a checkpoint continues
     * the series it was written with, if it writes @p format; with another
     * format it starts a new series.
     */
    void
    load(const CheckpointState &state, const Format format);

    /**
     * Write the index of @p format over the steps written so far to
     * @p directory (rank 0); a failure stops all ranks. Collective.
     */
    void
    write_index(const std::string &directory,
                const Format       format,
                const MPI_Comm     communicator) const;

  private:
    /**
     * Set #patch_dimension and #space_dimension to those of @p data.
     */
    template <int patch_dim, int spacedim>
    void
    remember_dimensions(const DataOutInterface<patch_dim, spacedim> &data);

    /**
     * Write step @p step of @p data as VTU pieces, one per rank, with their
     * .pvtu record, and add it to the index. Collective.
     */
    template <int patch_dim, int spacedim>
    void
    write_vtu(const DataOutInterface<patch_dim, spacedim> &data,
              const std::string                           &directory,
              const unsigned int                           step,
              const double                                 time,
              const MPI_Comm                               communicator);

    /**
     * One written step; the counts of the whole mesh (summed over the
     * ranks) go into the XDMF index.
     */
    struct Step
    {
      double        time;
      unsigned int  step;
      std::uint64_t n_nodes;
      std::uint64_t n_cells;
    };

    /**
     * Write step @p step at @p time of @p patches to one HDF5 file that all
     * ranks write together, under a temporary name renamed when complete;
     * then add the step to the index. Collective.
     */
    void
    write_hdf5_step(const HDF5Patches &patches,
                    const std::string &directory,
                    const unsigned int step,
                    const double       time,
                    const MPI_Comm     communicator);

    /**
     * Write the index of @p format over #steps to @p directory; the
     * problem, or an empty string.
     */
    std::string
    write_index_file(const std::string &directory, const Format format) const;

    std::string       name;
    std::vector<Step> steps;
    /// Of the XDMF index: the dimensions of the patches and the space, the
    /// reference cell of the patches and the data sets with their numbers
    /// of components, which are the same in every step.
    unsigned int  patch_dimension = 0;
    unsigned int  space_dimension = 0;
    ReferenceCell reference_cell  = ReferenceCells::Vertex;
    std::vector<std::pair<std::string, unsigned int>> data_sets;
    /// The format of #steps.
    Format format_of_steps = Format::vtu;
  };
} // namespace MpmOtm

#endif
