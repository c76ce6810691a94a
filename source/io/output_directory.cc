#include <mpm_otm/io/output_directory.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace MpmOtm
{
  namespace OutputDirectory
  {
    namespace
    {
      namespace fs = std::filesystem;

      /**
       * A file or directory that a run writes at a step, or its temporary
       * name (.tmp) while it is written; the first group that matched holds
       * the step (none for the .pvd and .xdmf files and the Powell-Sabin
       * picture).
       */
      const std::regex step_file(
        "(?:particles-([0-9]+)\\.csv|(?:particles|grid)_([0-9]+)(?:\\.[0-9]+)?"
        "\\.(?:vtu|pvtu|h5)|(?:particles|grid)\\.(?:pvd|xdmf)|"
        "powell-sabin-basis\\.vtu)(?:\\.tmp)?|checkpoint-([0-9]+)(?:\\.tmp)?");

      /**
       * The step files in @p directory with their steps (-1 for files of
       * no step), or a message.
       */
      std::string
      list_step_files(const std::string                      &directory,
                      std::vector<std::pair<fs::path, long>> &files)
      {
        // Non-throwing iteration: an error on rank 0 must reach the other
        // ranks through the caller's broadcast.
        std::error_code error;
        for (fs::directory_iterator entry(directory, error), end;
             !error && entry != end;
             entry.increment(error))
          {
            std::smatch       match;
            const std::string name = entry->path().filename().string();
            if (!std::regex_match(name, match, step_file))
              continue;
            long step = -1;
            for (unsigned int group = 1; group < match.size(); ++group)
              if (match[group].matched)
                step = std::stol(match[group]);
            files.emplace_back(entry->path(), step);
          }
        return error ?
                 "Cannot list <" + directory + ">: " + error.message() + "." :
                 "";
      }

      std::string
      remove_path(const fs::path &path)
      {
        std::error_code error;
        fs::remove_all(path, error);
        return error ? "Cannot remove <" + path.string() +
                         ">: " + error.message() + "." :
                       "";
      }
    } // namespace



    std::string
    write_file_atomically(const std::string                         &file_name,
                          const std::function<void(std::ostream &)> &write)
    {
      const std::string temporary = file_name + ".tmp";
      std::ofstream     file(temporary);
      // A writer that checks its stream itself (deal.II's write_vtu())
      // throws a generic I/O error: the stream's failure says more.
      int write_error = 0;
      try
        {
          if (file)
            write(file);
        }
      catch (const std::exception &)
        {
          write_error = errno;
          file.setstate(std::ios::badbit);
        }
      file.close();
      if (write_error != 0)
        errno = write_error;
      std::error_code error;
      if (file)
        fs::rename(temporary, file_name, error);
      if (file && !error)
        return "";
      const std::string reason =
        error ? error.message() : std::string(std::strerror(errno));
      fs::remove(temporary, error);
      return "Could not write <" + file_name + ">: " + reason + ". ";
    }



    std::string
    append_to_file(const std::string &file_name, const std::string &text)
    {
      std::ofstream file(file_name, std::ios::app);
      file << text;
      file.close();
      return file ? "" :
                    "Could not write <" + file_name +
                      ">: " + std::string(std::strerror(errno)) + ". ";
    }



    std::string
    clear_previous_run(const std::string &directory, const bool overwrite)
    {
      std::error_code error;
      if (!fs::is_directory(directory, error))
        return "";
      std::vector<std::string> found;
      for (const std::string name : {"statistics.csv",
                                     "monitoring.csv",
                                     "stages.csv",
                                     "parameters.prm",
                                     "particles.pvd",
                                     "grid.pvd",
                                     "particles.xdmf",
                                     "grid.xdmf"})
        if (fs::exists(fs::symlink_status(directory + "/" + name, error)))
          found.push_back(name);
      if (found.empty())
        return "";
      if (!overwrite)
        {
          std::string names;
          for (const auto &name : found)
            names += (names.empty() ? "" : ", ") + name;
          return "Output/Directory: <" + directory +
                 "> holds the output of another run (" + names +
                 "). Choose another Output/Directory, remove that one, let "
                 "this run replace it (set Output/Overwrite = true or run "
                 "mpm-otm --overwrite FILE), or continue that run from its "
                 "newest checkpoint (mpm-otm --resume " +
                 directory + ").";
        }
      // The step files and the monitoring and stage tables of the earlier
      // run, which a shorter run or one without monitoring or stages would
      // leave beside its own.
      std::vector<std::pair<fs::path, long>> files;
      std::string problem = list_step_files(directory, files);
      for (const std::string table : {"monitoring.csv", "stages.csv"})
        if (problem.empty())
          problem = remove_path(directory + "/" + table);
      for (unsigned int k = 0; k < files.size() && problem.empty(); ++k)
        problem = remove_path(files[k].first);
      return problem.empty() ? "" : "Output/Overwrite: " + problem;
    }



    std::vector<unsigned int>
    checkpoint_steps(const std::string &directory, const std::string &last_file)
    {
      std::vector<std::pair<fs::path, long>> files;
      list_step_files(directory, files);
      std::vector<unsigned int> steps;
      std::error_code           error;
      for (const auto &[path, step] : files)
        if (path.filename().string().rfind("checkpoint-", 0) == 0 &&
            path.extension() != ".tmp" && fs::exists(path / last_file, error))
          steps.push_back(step);
      std::sort(steps.begin(), steps.end());
      return steps;
    }



    std::string
    trim_after_step(const std::string &directory, const unsigned int step)
    {
      std::vector<std::pair<fs::path, long>> files;
      std::string problem = list_step_files(directory, files);
      for (unsigned int k = 0; k < files.size() && problem.empty(); ++k)
        {
          // An interrupted write: a checkpoint or a file under its
          // temporary name.
          const bool unfinished = files[k].first.extension() == ".tmp";
          if (files[k].second > static_cast<long>(step) || unfinished)
            problem = remove_path(files[k].first);
        }
      if (!problem.empty())
        return problem;

      // The header and the rows up to the step of each table; a last row
      // without its end of line was cut off by the interruption.
      for (const std::string table :
           {"statistics.csv", "monitoring.csv", "stages.csv"})
        {
          const std::string name = directory + "/" + table;
          if (table != "statistics.csv" && !fs::exists(name))
            continue;
          std::ifstream in(name);
          if (!in)
            return "Cannot read <" + name + ">: " + std::strerror(errno) + ".";
          std::ostringstream kept;
          std::string        line;
          bool               header = true;
          while (std::getline(in, line))
            {
              if (in.eof())
                break;
              if (header || std::strtol(line.c_str(), nullptr, 10) <=
                              static_cast<long>(step))
                kept << line << '\n';
              header = false;
            }
          problem = write_file_atomically(name, [&](std::ostream &out) {
            out << kept.str();
          });
          if (!problem.empty())
            return problem;
        }
      return "";
    }
  } // namespace OutputDirectory
} // namespace MpmOtm
