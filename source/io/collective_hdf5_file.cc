#include <deal.II/base/utilities.h>

#include <mpm_otm/io/collective_hdf5_file.h>

#include <algorithm>
#include <numeric>

namespace MpmOtm
{
  CollectiveHDF5File::CollectiveHDF5File(const std::string &file_name,
                                         const MPI_Comm     communicator)
    : communicator(communicator)
    , file(file_name, HDF5::File::FileAccessMode::create, communicator)
  {}



  template <typename Number>
  std::uint64_t
  CollectiveHDF5File::write(const std::string         &name,
                            const std::vector<Number> &values,
                            const unsigned int         n_columns)
  {
    const hsize_t              n_local = values.size() / n_columns;
    const std::vector<hsize_t> counts =
      Utilities::MPI::all_gather(communicator, n_local);
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    const hsize_t      first =
      std::accumulate(counts.begin(), counts.begin() + rank, hsize_t(0));
    const hsize_t n_total =
      std::accumulate(counts.begin(), counts.end(), hsize_t(0));
    auto dataset =
      file.create_dataset<Number>(name, {n_total, hsize_t(n_columns)});
    if (n_local > 0)
      dataset.write_hyperslab(values, {first, 0}, {n_local, n_columns});
    else
      dataset.template write_none<Number>();
    return first;
  }



  std::vector<std::pair<std::string, unsigned int>>
  xdmf_data_sets(
    const std::vector<std::string> &names,
    const std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      &vector_ranges)
  {
    std::vector<std::pair<std::string, unsigned int>> result;
    for (unsigned int k = 0; k < names.size();)
      {
        const auto range = std::find_if(vector_ranges.begin(),
                                        vector_ranges.end(),
                                        [&](const auto &r) {
                                          return std::get<0>(r) == k;
                                        });
        if (range != vector_ranges.end())
          {
            result.emplace_back(std::get<2>(*range), 3);
            k = std::get<1>(*range) + 1;
          }
        else
          result.emplace_back(names[k++], 1);
      }
    return result;
  }



  template std::uint64_t
  CollectiveHDF5File::write(const std::string &,
                            const std::vector<double> &,
                            const unsigned int);
  template std::uint64_t
  CollectiveHDF5File::write(const std::string &,
                            const std::vector<float> &,
                            const unsigned int);
  template std::uint64_t
  CollectiveHDF5File::write(const std::string &,
                            const std::vector<unsigned int> &,
                            const unsigned int);
} // namespace MpmOtm
