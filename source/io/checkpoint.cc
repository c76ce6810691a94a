#include <deal.II/base/utilities.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/io/checkpoint.h>
#include <mpm_otm/io/output_directory.h>
#include <mpm_otm/material_points/material_points.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/crc.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    namespace fs = std::filesystem;

    /// First words of shared.bin; a new layout gets a new number.
    const std::string format = "mpm-otm checkpoint 2";

    /// The size and CRC-32 of a file, as recorded in shared.bin.
    struct FileChecksum
    {
      std::uint64_t size = 0;
      std::uint32_t crc  = 0;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &size &crc;
      }
    };

    /// The size and CRC-32 of the file @p name; size -1 if it cannot be
    /// read.
    FileChecksum
    checksum_of(const std::string &name)
    {
      FileChecksum       result;
      std::ifstream      file(name, std::ios::binary);
      boost::crc_32_type crc;
      std::vector<char>  buffer(1 << 20);
      while (file)
        {
          file.read(buffer.data(), buffer.size());
          crc.process_bytes(buffer.data(), file.gcount());
          result.size += file.gcount();
        }
      if (!file.eof())
        result.size = static_cast<std::uint64_t>(-1);
      result.crc = crc.checksum();
      return result;
    }

    /// Every entry of @p prm by its path ("Time/End time").
    std::map<std::string, std::string>
    entries_of(const ParameterHandler &prm)
    {
      std::ostringstream listing;
      prm.print_parameters(listing, ParameterHandler::ShortPRM);
      std::istringstream                 lines(listing.str());
      std::map<std::string, std::string> entries;
      std::vector<std::string>           path;
      std::string                        line;
      while (std::getline(lines, line))
        {
          line = Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(Utilities::trim(line.substr(11)));
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.rfind("set ", 0) == 0)
            {
              const auto  equals = line.find('=');
              std::string name;
              for (const auto &section : path)
                name += section + "/";
              name += Utilities::trim(line.substr(4, equals - 4));
              entries[name] = Utilities::trim(line.substr(equals + 1));
            }
        }
      return entries;
    }

    /// Whether the entry @p name may differ between a run and its resumed
    /// continuation: it does not change the result (@p end_entry: the end
    /// time of the run, which may be extended).
    bool
    may_change_on_resume(const std::string &name, const std::string &end_entry)
    {
      return name.rfind("Output/", 0) == 0 ||
             name.rfind("Checkpoint/", 0) == 0 || name == end_entry;
    }

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
    prm.declare_entry(
      "Interval",
      "0",
      Patterns::Integer(0),
      "Write a checkpoint every this many time steps (0: "
      "none), into checkpoint-NNNNN in Output/Directory. "
      "mpm-otm --resume DIRECTORY continues the run from the "
      "newest one, on any number of MPI ranks; its "
      "parameters.prm may then differ from the run's only in "
      "Time/End time (with Stages: the last stage's End time) and "
      "the Output and Checkpoint entries.");
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
    parameters = entries_of(prm);
    prm.enter_subsection("Time");
    end_time = prm.get_double("End time");
    prm.leave_subsection();
  }



  template <int dim>
  void
  Checkpoint<dim>::set_end_time(const std::string &entry, const double time)
  {
    end_entry = entry;
    end_time  = time;
  }



  template <int dim>
  void
  Checkpoint<dim>::set_grid_fingerprint(const std::uint32_t fingerprint)
  {
    grid_fingerprint = fingerprint;
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

    // The checksums of every rank's files, read back from the disk.
    const auto checksums = Utilities::MPI::gather(
      communicator,
      std::vector<FileChecksum>{
        checksum_of(rank_file(temporary, "points", rank)),
        checksum_of(rank_file(temporary, "state", rank))},
      0);

    if (rank == 0)
      {
        const std::string shared_file = temporary + "/shared.bin";
        {
          std::ostringstream contents;
          {
            boost::archive::binary_oarchive archive(contents);
            const unsigned int              dimension = dim;
            archive << format << dimension << step << time << n_ranks
                    << parameters << grid_fingerprint << checksums
                    << state.shared_entries;
          }
          const std::string  bytes = contents.str();
          boost::crc_32_type crc;
          crc.process_bytes(bytes.data(), bytes.size());
          const std::uint32_t trailer = crc.checksum();
          std::ofstream       file(shared_file, std::ios::binary);
          file.write(bytes.data(), bytes.size());
          file.write(reinterpret_cast<const char *>(&trailer), sizeof(trailer));
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
                        const MPI_Comm       communicator) const
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const std::string  shared_file = checkpoint + "/shared.bin";
    const std::string  damaged =
      " The checkpoint is damaged (a disk error, or a file changed or copied "
      "in from elsewhere). Resume from another checkpoint (remove <" +
      checkpoint +
      ">, and --resume takes the newest of the others) or start "
      "anew. ";
    unsigned int                           step        = 0;
    double                                 time        = 0;
    unsigned int                           saved_ranks = 0;
    std::map<std::string, std::string>     saved_parameters;
    std::uint32_t                          saved_grid = 0;
    std::vector<std::vector<FileChecksum>> checksums;
    std::string                            problem;

    // shared.bin: its own checksum first, then its contents.
    std::string bytes;
    {
      std::ifstream      file(shared_file, std::ios::binary);
      std::ostringstream contents;
      contents << file.rdbuf();
      bytes = contents.str();
    }
    std::uint32_t trailer = 0;
    if (bytes.size() >= sizeof(trailer))
      {
        std::memcpy(&trailer,
                    bytes.data() + bytes.size() - sizeof(trailer),
                    sizeof(trailer));
        bytes.resize(bytes.size() - sizeof(trailer));
      }
    boost::crc_32_type crc;
    crc.process_bytes(bytes.data(), bytes.size());
    if (bytes.empty() || crc.checksum() != trailer)
      problem = "<" + shared_file + "> does not match its checksum." + damaged;
    else
      try
        {
          std::istringstream              contents(bytes);
          boost::archive::binary_iarchive archive(contents);
          std::string                     saved_format;
          unsigned int                    dimension = 0;
          archive >> saved_format;
          if (saved_format != format)
            problem =
              "<" + shared_file +
              "> was written by another version of mpm-otm. Start the run anew. ";
          else
            {
              archive >> dimension >> step >> time >> saved_ranks >>
                saved_parameters >> saved_grid >> checksums >>
                state.shared_entries;
              if (dimension != dim)
                problem = "<" + checkpoint + "> is of a " +
                          std::to_string(dimension) +
                          "D run. Start the run anew. ";
              else if (checksums.size() != saved_ranks)
                problem = "<" + shared_file + "> is inconsistent." + damaged;
            }
        }
      catch (const std::exception &error)
        {
          problem = "<" + shared_file + "> cannot be read (" + error.what() +
                    ")." + damaged;
        }

    // The identity: the same parameters, except what does not change the
    // result, and the same grid.
    if (problem.empty())
      {
        std::vector<std::string> differences;
        std::set<std::string>    names;
        for (const auto &entries : {parameters, saved_parameters})
          for (const auto &[name, value] : entries)
            names.insert(name);
        for (const auto &name : names)
          {
            const auto        now    = parameters.find(name);
            const auto        before = saved_parameters.find(name);
            const std::string value_now =
              now == parameters.end() ? "(none)" : "<" + now->second + ">";
            const std::string value_before = before == saved_parameters.end() ?
                                               "(none)" :
                                               "<" + before->second + ">";
            if (value_now != value_before &&
                !may_change_on_resume(name, end_entry))
              differences.push_back(name + " = " + value_now +
                                    " (the run that wrote it: " + value_before +
                                    ")");
          }
        if (!differences.empty())
          {
            problem = "it was written by a run with other parameters than "
                      "the parameters.prm of the resumed run: ";
            for (unsigned int k = 0; k < differences.size() && k < 10; ++k)
              problem += (k > 0 ? "; " : "") + differences[k];
            if (differences.size() > 10)
              problem +=
                "; and " + std::to_string(differences.size() - 10) + " more";
            problem +=
              ". A resumed run continues the run it was started as: only " +
              end_entry +
              " (to a time after the checkpoint's) and the "
              "entries of the subsections Output and Checkpoint may change. "
              "Restore the entries, or start a new run with them. ";
          }
        else if (saved_grid != grid_fingerprint)
          problem = "it was written on another grid than the resumed run's "
                    "(the same parameters, but the cells or boundary ids "
                    "differ: a changed Mesh/Mesh file?). Restore the grid or "
                    "start a new run on it. ";
        else if (!(end_time > time))
          problem = end_entry + " = " + parameters.at(end_entry) +
                    " is not after the checkpoint's time " +
                    std::to_string(time) + ". ";
      }
    // What every rank found alike, rank 0 tells.
    const std::string problem_of_rank_0 =
      Utilities::MPI::broadcast(communicator, problem, 0);
    if (rank > 0 && problem == problem_of_rank_0)
      problem.clear();
    const bool identity_confirmed =
      Utilities::MPI::max(problem.empty() ? 0 : 1, communicator) == 0;

    // Every rank's files against their checksums, shared among the ranks.
    if (identity_confirmed)
      for (unsigned int r = rank; r < saved_ranks; r += n_ranks)
        for (const auto &[kind, k] :
             {std::pair<std::string, unsigned int>{"points", 0}, {"state", 1}})
          {
            const std::string file   = rank_file(checkpoint, kind, r);
            const auto        actual = checksum_of(file);
            if ((actual.size != checksums[r][k].size ||
                 actual.crc != checksums[r][k].crc) &&
                problem.empty())
              problem = "<" + file +
                        "> does not match the size and checksum that " +
                        shared_file + " records for it." + damaged;
          }

    stop_if_any_rank_failed(communicator,
                            problem,
                            "Cannot resume from <" + checkpoint + ">: ",
                            "");

    try
      {
        state.saved_parts.resize(saved_ranks);
        for (unsigned int r = 0; r < saved_ranks; ++r)
          {
            std::ifstream part(rank_file(checkpoint, "state", r),
                               std::ios::binary);
            boost::archive::binary_iarchive part_archive(part);
            part_archive >> state.saved_parts[r];
          }
      }
    catch (const std::exception &error)
      {
        problem = "a state file cannot be read (" + std::string(error.what()) +
                  ")." + damaged;
      }
    stop_if_any_rank_failed(communicator,
                            problem,
                            "Cannot resume from <" + checkpoint + ">: ",
                            "");
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
