#ifndef mpm_otm_base_checkpoint_state_h
#define mpm_otm_base_checkpoint_state_h

#include <map>
#include <string>
#include <vector>

namespace MpmOtm
{
  /**
   * The state of a run, other than its material points, that a checkpoint
   * keeps: named arrays of numbers that the parts of the simulator with a
   * state between time steps save into it and load from it (the time
   * stepper's work counters, the moved vertices or knots, the energy
   * reference, the boundary displacements, the output's time series). The
   * Checkpoint writes and reads it. There are two kinds of entry:
   *  - shared: the same on every rank (rank 0's copy is written);
   *  - own: this rank's part of something split among the ranks (its part
   *    of a sum, or values of the vertices or functions it owns with their
   *    global indices). After loading, parts() gives the parts of every
   *    rank of the saved run, so that a run resumed on another number of
   *    ranks can put them together; share_of_sums() does that for sums.
   */
  class CheckpointState
  {
  public:
    /**
     * Store @p values under @p name: the same on every rank.
     */
    void
    set_shared(const std::string &name, const std::vector<double> &values);

    /**
     * Store this rank's part @p values under @p name.
     */
    void
    set_own(const std::string &name, const std::vector<double> &values);

    /**
     * The shared values stored under @p name; an error naming the entry if
     * the checkpoint has none (it was written by another version of the
     * program or for another set-up).
     */
    const std::vector<double> &
    shared(const std::string &name) const;

    /**
     * The parts stored under @p name by every rank of the saved run, in the
     * order of the ranks.
     */
    std::vector<std::vector<double>>
    parts(const std::string &name) const;

    /**
     * This rank's share of sums split among the ranks: its own part if the
     * run resumes on the number of ranks that saved it (so that sums are
     * formed in the same order and the run continues bit by bit as it
     * would have), otherwise the sum of all parts on rank 0 and zeros on the
     * other ranks.
     */
    std::vector<double>
    share_of_sums(const std::string &name) const;

    /**
     * Tell a loaded state which rank reads it and whether the saved run had
     * as many ranks (set by the Checkpoint).
     */
    void
    set_reader(const unsigned int rank, const bool same_number_of_ranks);

    /// Shared entries.
    std::map<std::string, std::vector<double>> shared_entries;
    /// This rank's entries, when saving.
    std::map<std::string, std::vector<double>> own_entries;
    /// Every saved rank's entries, when loading.
    std::vector<std::map<std::string, std::vector<double>>> saved_parts;

  private:
    unsigned int reader_rank  = 0;
    bool         same_n_ranks = true;
  };
} // namespace MpmOtm

#endif
