#ifndef mpm_otm_io_output_directory_h
#define mpm_otm_io_output_directory_h

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace MpmOtm
{
  /**
   * The files of a run in its output directory: writing one so that no
   * reader finds it half written, removing the files of an earlier run
   * before a new one, and removing what a resumed run will write again.
   * Each function returns an empty string, or a sentence naming the file
   * or directory that could not be written or removed (the caller stops
   * every rank with it). Not collective: rank 0 calls them.
   */
  namespace OutputDirectory
  {
    /**
     * Write the file @p file_name with @p write under a temporary name and
     * rename it when it is complete, so that no reader (ParaView, or a look
     * after a killed run) ever finds a partial file under its name.
     */
    std::string
    write_file_atomically(const std::string                         &file_name,
                          const std::function<void(std::ostream &)> &write);

    /**
     * Append @p text to the file @p file_name (a row of a table such as
     * statistics.csv); returns "" or the problem, naming the file.
     */
    std::string
    append_to_file(const std::string &file_name, const std::string &text);

    /**
     * Prepare @p directory for a new run: if it holds another run's output
     * (a statistics.csv, monitoring.csv, stages.csv, parameters.prm, .pvd
     * or .xdmf file), refuse unless @p overwrite, and then remove that
     * run's step files, .pvd and .xdmf files, monitoring.csv, stages.csv
     * and checkpoints; nothing
     * else in the directory is touched.
     */
    std::string
    clear_previous_run(const std::string &directory, const bool overwrite);

    /**
     * Prepare @p directory for a run resumed after time step @p step:
     * remove the step files of later steps and unfinished checkpoints, and
     * the rows of statistics.csv, monitoring.csv and stages.csv after that
     * step (and a
     * last row that an interruption cut off).
     */
    std::string
    trim_after_step(const std::string &directory, const unsigned int step);

    /**
     * The steps of the complete checkpoints in @p directory (directories
     * checkpoint-NNNNN, not .tmp, that hold the file @p last_file, which a
     * checkpoint is written with last), ascending.
     */
    std::vector<unsigned int>
    checkpoint_steps(const std::string &directory,
                     const std::string &last_file);
  } // namespace OutputDirectory
} // namespace MpmOtm

#endif
