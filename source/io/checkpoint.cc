#include <deal.II/base/utilities.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/io/checkpoint.h>
#include <mpm_otm/io/output_directory.h>
#include <mpm_otm/material_points/material_points.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace MpmOtm
{
  namespace
  {
    namespace fs = std::filesystem;

    /// First words of shared.bin; a new layout gets a new number.
    const std::string format = "mpm-otm checkpoint 1";

    std::string
    rank_file(const std::string &checkpoint,
              const std::string &kind,
              const unsigned int rank)
    {
      return checkpoint + "/" + kind + "-" + Utilities::int_to_string(rank, 4) +
             ".bin";
    }

    std::string
    write_failure(const std::string &file)
    {
      return "Could not write the checkpoint file <" + file +
             ">: " + std::strerror(errno) + ". ";
    }

    std::string
    checkpoint_directory(const std::string &directory, const unsigned int step)
    {
      return directory + "/checkpoint-" + Utilities::int_to_string(step, 5);
    }
  } // namespace



  template <int dim>
  void
  Checkpoint<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry("Interval",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint every this many time steps (0: "
                      "none), into checkpoint-NNNNN in Output/Directory. "
                      "mpm-otm --resume DIRECTORY continues the run from the "
                      "newest one, on any number of MPI ranks.");
    prm.declare_entry("Wall-clock interval",
                      "0",
                      Patterns::Double(0),
                      "Also write a checkpoint when this many minutes of "
                      "wall-clock time have passed since the start or the "
                      "last checkpoint (0: not by time). SIGTERM and SIGINT "
                      "always write one before the run stops.");
    prm.declare_entry("Number kept",
                      "2",
                      Patterns::Integer(1),
                      "How many of the newest checkpoints are kept; older "
                      "ones are removed.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  Checkpoint<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    step_interval = prm.get_integer("Interval");
    minutes       = prm.get_double("Wall-clock interval");
    n_kept        = prm.get_integer("Number kept");
    prm.leave_subsection();
  }



  template <int dim>
  bool
  Checkpoint<dim>::is_due(const unsigned int step,
                          const MPI_Comm     communicator) const
  {
    if (step_interval > 0 && step % step_interval == 0)
      return true;
    if (minutes <= 0. || step % 10 != 0)
      return false;
    const double elapsed = std::chrono::duration<double>(
                             std::chrono::steady_clock::now() - last_write)
                             .count();
    return Utilities::MPI::broadcast(communicator, elapsed >= 60. * minutes, 0);
  }



  template <int dim>
  void
  Checkpoint<dim>::write(const std::string         &directory,
                         const unsigned int         step,
                         const double               time,
                         const MaterialPoints<dim> &material_points,
                         const CheckpointState     &state,
                         const MPI_Comm             communicator)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const std::string  final_name = checkpoint_directory(directory, step);
    const std::string  temporary  = final_name + ".tmp";
    const std::string  advice =
      "Free space on the disk of Output/Directory, or set Checkpoint/Interval "
      "= 0 and Checkpoint/Wall-clock interval = 0 to write none.";

    std::string problem;
    if (rank == 0)
      {
        std::error_code error;
        fs::remove_all(temporary, error);
        fs::create_directories(temporary, error);
        if (error)
          problem = "Could not create the checkpoint directory <" + temporary +
                    ">: " + error.message() + ". ";
      }
    stop_if_any_rank_failed(communicator, problem, "", advice);

    {
      const std::string points_file = rank_file(temporary, "points", rank);
      std::ofstream     points(points_file, std::ios::binary);
      const bool written = points && material_points.write_points(points);
      points.close();
      if (!written || !points)
        problem = write_failure(points_file);
      const std::string state_file = rank_file(temporary, "state", rank);
      if (problem.empty())
        {
          std::ofstream file(state_file, std::ios::binary);
          {
            boost::archive::binary_oarchive archive(file);
            archive << state.own_entries;
          }
          file.close();
          if (!file)
            problem = write_failure(state_file);
        }
    }
    stop_if_any_rank_failed(communicator, problem, "", advice);

    if (rank == 0)
      {
        const std::string shared_file = temporary + "/shared.bin";
        {
          std::ofstream file(shared_file, std::ios::binary);
          {
            boost::archive::binary_oarchive archive(file);
            const unsigned int              dimension = dim;
            archive << format << dimension << step << time << n_ranks
                    << state.shared_entries;
          }
          file.close();
          if (!file)
            problem = write_failure(shared_file);
        }
        if (problem.empty())
          {
            std::ofstream info(temporary + "/info.txt");
            info << "mpm-otm checkpoint after time step " << step
                 << "\ntime = " << std::setprecision(17) << time
                 << "\ndimension = " << dim << "\nMPI ranks = " << n_ranks
                 << "\nContinue the run with: mpm-otm --resume " << directory
                 << "\n";
            info.close();
            if (!info)
              problem = write_failure(temporary + "/info.txt");
          }
        std::error_code error;
        if (problem.empty())
          {
            fs::remove_all(final_name, error);
            fs::rename(temporary, final_name, error);
            if (error)
              problem = "Could not rename <" + temporary + "> to <" +
                        final_name + ">: " + error.message() + ". ";
          }
        if (problem.empty())
          {
            const auto steps =
              OutputDirectory::checkpoint_steps(directory, "shared.bin");
            for (unsigned int k = 0; k + n_kept < steps.size(); ++k)
              fs::remove_all(checkpoint_directory(directory, steps[k]), error);
          }
      }
    stop_if_any_rank_failed(communicator, problem, "", advice);
    last_write = std::chrono::steady_clock::now();
  }



  template <int dim>
  std::string
  Checkpoint<dim>::newest(const std::string &directory,
                          const MPI_Comm     communicator)
  {
    std::string name;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const auto steps =
          OutputDirectory::checkpoint_steps(directory, "shared.bin");
        if (!steps.empty())
          name = checkpoint_directory(directory, steps.back());
      }
    name = Utilities::MPI::broadcast(communicator, name, 0);
    AssertThrow(!name.empty(),
                ExcMessage("--resume: <" + directory +
                           "> holds no checkpoint (a directory "
                           "checkpoint-NNNNN with a shared.bin). A run writes "
                           "checkpoints into its Output/Directory every "
                           "Checkpoint/Interval steps and when it receives "
                           "SIGTERM or SIGINT."));
    return name;
  }



  template <int dim>
  std::pair<unsigned int, double>
  Checkpoint<dim>::read(const std::string   &checkpoint,
                        MaterialPoints<dim> &material_points,
                        CheckpointState     &state,
                        const MPI_Comm       communicator)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    unsigned int       step    = 0;
    double             time    = 0;
    unsigned int       saved_ranks = 0;
    std::string        problem;
    try
      {
        std::ifstream file(checkpoint + "/shared.bin", std::ios::binary);
        boost::archive::binary_iarchive archive(file);
        std::string                     saved_format;
        unsigned int                    dimension = 0;
        archive >> saved_format;
        if (saved_format != format)
          problem = "<" + checkpoint +
                    "/shared.bin> was written by another version of mpm-otm. ";
        else
          {
            archive >> dimension >> step >> time >> saved_ranks >>
              state.shared_entries;
            if (dimension != dim)
              problem = "<" + checkpoint + "> is of a " +
                        std::to_string(dimension) + "D run. ";
          }
        state.saved_parts.resize(saved_ranks);
        for (unsigned int r = 0; r < saved_ranks && problem.empty(); ++r)
          {
            std::ifstream part(rank_file(checkpoint, "state", r),
                               std::ios::binary);
            boost::archive::binary_iarchive part_archive(part);
            part_archive >> state.saved_parts[r];
          }
      }
    catch (const std::exception &error)
      {
        problem =
          "<" + checkpoint + "> cannot be read (" + error.what() + "). ";
      }
    stop_if_any_rank_failed(communicator,
                            problem,
                            "Cannot resume from the checkpoint: ",
                            "Resume from another checkpoint or start anew.");
    state.set_reader(rank, saved_ranks == n_ranks);

    std::vector<std::string> point_files;
    for (unsigned int r = 0; r < saved_ranks; ++r)
      point_files.push_back(rank_file(checkpoint, "points", r));
    material_points.read_points(point_files);
    return {step, time};
  }



  template class Checkpoint<1>;
  template class Checkpoint<2>;
  template class Checkpoint<3>;
} // namespace MpmOtm
