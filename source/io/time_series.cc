#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/io/grid_patches.h>
#include <mpm_otm/io/output_directory.h>
#include <mpm_otm/io/particle_patches.h>
#include <mpm_otm/io/time_series.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace MpmOtm
{
  namespace
  {
    const std::string disk_advice =
      "Free space on the disk of Output/Directory or choose another one.";

    std::string
    step_file(const std::string &name, const unsigned int step)
    {
      return name + "_" + Utilities::int_to_string(step, 5);
    }

    /**
     * The reference cell of dimension @p dim with @p n_vertices vertices.
     */
    ReferenceCell
    reference_cell_of(const unsigned int dim, const unsigned int n_vertices)
    {
      for (const ReferenceCell &cell : {ReferenceCells::Vertex,
                                        ReferenceCells::Line,
                                        ReferenceCells::Triangle,
                                        ReferenceCells::Quadrilateral,
                                        ReferenceCells::Tetrahedron,
                                        ReferenceCells::Hexahedron})
        if (cell.get_dimension() == dim && cell.n_vertices() == n_vertices)
          return cell;
      AssertThrow(false, ExcMessage("A checkpoint names an unknown cell."));
      return ReferenceCells::Vertex;
    }
  } // namespace



  TimeSeries::TimeSeries(const std::string &name)
    : name(name)
  {}



  template <typename Patches>
  void
  TimeSeries::write(const Patches     &patches,
                    const std::string &directory,
                    const Format       format,
                    const unsigned int step,
                    const double       time,
                    const MPI_Comm     communicator)
  {
    reference_cell = patches.reference_cell();
    remember_dimensions(patches);
    if (format == Format::vtu)
      {
        write_vtu(patches, directory, step, time, communicator);
        return;
      }
    write_hdf5_step(patches, directory, step, time, communicator);
  }



  template <int patch_dim, int spacedim>
  void
  TimeSeries::remember_dimensions(const DataOutInterface<patch_dim, spacedim> &)
  {
    patch_dimension = patch_dim;
    space_dimension = spacedim;
  }



  template <int patch_dim, int spacedim>
  void
  TimeSeries::write_vtu(const DataOutInterface<patch_dim, spacedim> &data,
                        const std::string                           &directory,
                        const unsigned int                           step,
                        const double                                 time,
                        const MPI_Comm communicator)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const std::string  base    = step_file(name, step);
    const unsigned int digits  = Utilities::needed_digits(n_ranks - 1);
    const auto         piece   = [&](const unsigned int r) {
      return base + "." + Utilities::int_to_string(r, digits) + ".vtu";
    };
    stop_if_any_rank_failed(
      communicator,
      OutputDirectory::write_file_atomically(directory + "/" + piece(rank),
                                             [&](std::ostream &out) {
                                               data.write_vtu(out);
                                             }),
      "",
      disk_advice);
    std::string problem;
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          pieces.push_back(piece(r));
        problem = OutputDirectory::write_file_atomically(
          directory + "/" + base + ".pvtu",
          [&](std::ostream &out) {
            data.write_pvtu_record(out, pieces);
          });
      }
    stop_if_any_rank_failed(communicator, problem, "", disk_advice);
    format_of_steps = Format::vtu;
    steps.push_back({time, step, 0, 0});
    write_index(directory, Format::vtu, communicator);
  }



  void
  TimeSeries::write_hdf5_step(const HDF5Patches &patches,
                              const std::string &directory,
                              const unsigned int step,
                              const double       time,
                              const MPI_Comm     communicator)
  {
    // All ranks write one file together, under a temporary name that rank
    // 0 renames once every rank is done.
    const std::string file = directory + "/" + step_file(name, step) + ".h5";
    const std::string temporary = file + ".tmp";
    std::string       problem;
    try
      {
        patches.write_hdf5(temporary, communicator);
      }
    catch (const std::exception &error)
      {
        problem = "Could not write <" + file + ">: " + error.what();
      }
    stop_if_any_rank_failed(communicator, problem, "", disk_advice);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code error;
        std::filesystem::rename(temporary, file, error);
        if (error)
          problem = "Could not write <" + file + ">: " + error.message() + ".";
      }
    stop_if_any_rank_failed(communicator, problem, "", disk_advice);
    format_of_steps = Format::hdf5;
    data_sets       = patches.data_sets();
    steps.push_back({time,
                     step,
                     Utilities::MPI::sum(patches.n_nodes(), communicator),
                     Utilities::MPI::sum(patches.n_cells(), communicator)});
    write_index(directory, Format::hdf5, communicator);
  }



  void
  TimeSeries::write_index(const std::string &directory,
                          const Format       format,
                          const MPI_Comm     communicator) const
  {
    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      problem = write_index_file(directory, format);
    stop_if_any_rank_failed(communicator, problem, "", disk_advice);
  }



  std::string
  TimeSeries::write_index_file(const std::string &directory,
                               const Format       format) const
  {
    if (format == Format::vtu)
      {
        std::vector<std::pair<double, std::string>> records;
        for (const Step &s : steps)
          records.emplace_back(s.time, step_file(name, s.step) + ".pvtu");
        return OutputDirectory::write_file_atomically(
          directory + "/" + name + ".pvd",
          [&](std::ostream &out) {
            DataOutBase::write_pvd_record(out, records);
          });
      }
    return OutputDirectory::write_file_atomically(
      directory + "/" + name + ".xdmf",
      [&](std::ostream &out) {
        out << "<?xml version=\"1.0\" ?>\n"
            << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
            << "<Xdmf Version=\"2.0\">\n"
            << "  <Domain>\n"
            << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
               "CollectionType=\"Temporal\">\n";
        for (const Step &s : steps)
          {
            const std::string file = step_file(name, s.step) + ".h5";
            XDMFEntry         entry(file,
                            file,
                            s.time,
                            s.n_nodes,
                            s.n_cells,
                            patch_dimension,
                            space_dimension);
            for (const auto &[set_name, n_components] : data_sets)
              entry.add_attribute(set_name, n_components);
            out << entry.get_xdmf_content(3, reference_cell);
          }
        out << "    </Grid>\n"
            << "  </Domain>\n"
            << "</Xdmf>\n";
      });
  }



  void
  TimeSeries::save(CheckpointState &state) const
  {
    // Per step its time, number, nodes and cells; then the patches, the
    // format (1: hdf5) and the data sets, each as its number of components, the
    // length of its name and the name's characters.
    std::vector<double> numbers;
    for (const Step &s : steps)
      numbers.insert(
        numbers.end(),
        {s.time, double(s.step), double(s.n_nodes), double(s.n_cells)});
    state.set_shared("output/" + name + " steps", numbers);
    std::vector<double> layout = {double(patch_dimension),
                                  double(space_dimension),
                                  double(reference_cell.n_vertices()),
                                  double(format_of_steps == Format::hdf5)};
    for (const auto &[set_name, n_components] : data_sets)
      {
        layout.push_back(n_components);
        layout.push_back(set_name.size());
        layout.insert(layout.end(), set_name.begin(), set_name.end());
      }
    state.set_shared("output/" + name + " layout", layout);
  }



  void
  TimeSeries::load(const CheckpointState &state, const Format format)
  {
    const auto &numbers = state.shared("output/" + name + " steps");
    steps.clear();
    for (unsigned int k = 0; k + 3 < numbers.size(); k += 4)
      steps.push_back({numbers[k],
                       static_cast<unsigned int>(numbers[k + 1]),
                       static_cast<std::uint64_t>(numbers[k + 2]),
                       static_cast<std::uint64_t>(numbers[k + 3])});
    const auto &layout = state.shared("output/" + name + " layout");
    AssertThrow(layout.size() >= 4,
                ExcMessage("The checkpoint lacks the layout of the " + name +
                           " output."));
    patch_dimension = static_cast<unsigned int>(layout[0]);
    space_dimension = static_cast<unsigned int>(layout[1]);
    reference_cell =
      reference_cell_of(patch_dimension, static_cast<unsigned int>(layout[2]));
    format_of_steps = layout[3] > 0. ? Format::hdf5 : Format::vtu;
    if (format_of_steps != format)
      steps.clear();
    data_sets.clear();
    for (std::size_t k = 4; k + 1 < layout.size();)
      {
        const auto        n_components = static_cast<unsigned int>(layout[k]);
        const std::size_t length = static_cast<std::size_t>(layout[k + 1]);
        std::string       set_name;
        for (std::size_t c = 0; c < length; ++c)
          set_name.push_back(static_cast<char>(layout[k + 2 + c]));
        data_sets.emplace_back(set_name, n_components);
        k += 2 + length;
      }
  }



#define MPM_OTM_INSTANTIATE_WRITE(dim)                          \
  template void TimeSeries::write(const ParticlePatches<dim> &, \
                                  const std::string &,          \
                                  const Format,                 \
                                  const unsigned int,           \
                                  const double,                 \
                                  const MPI_Comm);              \
  template void TimeSeries::write(const GridPatches<dim> &,     \
                                  const std::string &,          \
                                  const Format,                 \
                                  const unsigned int,           \
                                  const double,                 \
                                  const MPI_Comm);
  MPM_OTM_INSTANTIATE_WRITE(1)
  MPM_OTM_INSTANTIATE_WRITE(2)
  MPM_OTM_INSTANTIATE_WRITE(3)
#undef MPM_OTM_INSTANTIATE_WRITE
} // namespace MpmOtm
