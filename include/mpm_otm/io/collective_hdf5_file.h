#ifndef mpm_otm_io_collective_hdf5_file_h
#define mpm_otm_io_collective_hdf5_file_h

#include <deal.II/base/hdf5.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_component_interpretation.h>

#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * An HDF5 file that all ranks create and write together, as the field
   * output of one step: every dataset is a table whose rows are the rows of
   * rank 0, then those of rank 1, and so on, each rank writing its own block
   * with one collective hyperslab write. This is the layout of deal.II's
   * DataOutBase::write_hdf5_parallel, which an XDMF index points into
   * (datasets nodes, cells and one per field), without its DataOutFilter.
   */
  class CollectiveHDF5File
  {
  public:
    /**
     * Create (or truncate) @p file_name on all ranks of @p communicator.
     */
    CollectiveHDF5File(const std::string &file_name,
                       const MPI_Comm     communicator);

    /**
     * Write the dataset @p name of @p n_columns columns, whose rows on this
     * rank are @p values (row by row); returns the index of this rank's
     * first row in the dataset. Collective.
     */
    template <typename Number>
    std::uint64_t
    write(const std::string         &name,
          const std::vector<Number> &values,
          const unsigned int         n_columns);

    /**
     * Write one dataset per field of @p data_sets (name and number of
     * columns, as xdmf_data_sets() gives them: a vector of
     * @p vector_components components padded to 3 columns with zeros, or a
     * scalar), with @p n_rows rows on this rank; @p value(row, component)
     * is the value of the component, counted over the components of all
     * fields in their order. Collective.
     */
    template <typename Number, typename ValueFunction>
    void
    write_fields(
      const std::vector<std::pair<std::string, unsigned int>> &data_sets,
      const std::size_t                                        n_rows,
      const unsigned int   vector_components,
      const ValueFunction &value)
    {
      unsigned int        first_component = 0;
      std::vector<Number> column;
      for (const auto &[name, n_columns] : data_sets)
        {
          const unsigned int n_components =
            n_columns == 1 ? 1 : vector_components;
          column.assign(n_rows * n_columns, Number());
          for (std::size_t row = 0; row < n_rows; ++row)
            for (unsigned int c = 0; c < n_components; ++c)
              column[row * n_columns + c] = value(row, first_component + c);
          write(name, column, n_columns);
          first_component += n_components;
        }
    }

  private:
    MPI_Comm   communicator;
    HDF5::File file;
  };



  /**
   * The datasets of the fields @p names (one per scalar component, as a
   * DataOutInterface names them) with @p vector_ranges (first and last
   * component, name and interpretation, as get_nonscalar_data_ranges()
   * gives them) in an XDMF index: each vector, with three columns (padded
   * with zeros in 2D), or scalar, with one, in the order of the components.
   */
  std::vector<std::pair<std::string, unsigned int>>
  xdmf_data_sets(
    const std::vector<std::string> &names,
    const std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      &vector_ranges);
} // namespace MpmOtm

#endif
