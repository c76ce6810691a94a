#ifndef mpm_otm_io_checkpoint_h
#define mpm_otm_io_checkpoint_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/base/checkpoint_state.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <string>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialPoints;

  /**
   * Checkpoints of a run and resuming from them (`mpm-otm --resume DIR`).
   * A checkpoint after step N is the directory checkpoint-NNNNN in the
   * output directory, holding
   *  - points-R.bin: the material points of rank R, in the order in which
   *    that rank sums over them (MaterialPoints::write_points());
   *  - state-R.bin: rank R's part of the run's state (CheckpointState);
   *  - shared.bin: the state that is the same on every rank, the step, the
   *    time and the number of ranks, the identity of the run (the value of
   *    every parameter and a fingerprint of the initial grid) and the size
   *    and CRC-32 of every rank's files; it ends with its own CRC-32;
   *  - info.txt: the same for people.
   * It is written as checkpoint-NNNNN.tmp and renamed when every rank's
   * files are complete, so that a run killed while writing leaves the
   * previous checkpoint intact; only the newest `Number kept` are kept.
   * Resuming reads the newest complete checkpoint on any number of ranks.
   * Before anything is decoded or any output removed, it checks every
   * file against its checksum and the identity against the resumed run's
   * (parameters.prm may differ only in the end time and the subsections
   * Output and Checkpoint), and refuses with a message naming the file or
   * the entries. Then every rank reads every rank's files and keeps the
   * points of its cells.
   * On the number of ranks that wrote it, the resumed run repeats the sums
   * of the interrupted one in the same order and so continues bit by bit.
   */
  template <int dim>
  class Checkpoint
  {
  public:
    /**
     * Declare the subsection Checkpoint.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the subsection Checkpoint.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * The entry that holds the end time of the run, @p entry (default
     * Time/End time; the last stage's End time in a staged run), and its
     * value @p time: a resumed run may extend it.
     */
    void
    set_end_time(const std::string &entry, const double time);

    /**
     * Take the fingerprint of the run's grid (BackgroundGrid::fingerprint()),
     * which every checkpoint records and read() compares. Call before
     * write() or read().
     */
    void
    set_grid_fingerprint(const std::uint32_t fingerprint);

    /**
     * Whether a checkpoint is due after time step @p step: every
     * `Interval` steps, or, checked every ten steps, when `Wall-clock
     * interval` minutes have passed on rank 0 since the start or the last
     * checkpoint. Collective.
     */
    bool
    is_due(const unsigned int step, const MPI_Comm communicator) const;

    /**
     * Write the checkpoint after step @p step at time @p time into
     * @p directory: the points of @p material_points and @p state. A write
     * that fails stops every rank with a message naming the file.
     * Collective.
     */
    void
    write(const std::string         &directory,
          const unsigned int         step,
          const double               time,
          const MaterialPoints<dim> &material_points,
          const CheckpointState     &state,
          const MPI_Comm             communicator);

    /**
     * The name of the newest complete checkpoint in @p directory; stops
     * with a message if it holds none. Collective.
     */
    static std::string
    newest(const std::string &directory, const MPI_Comm communicator);

    /**
     * Read the checkpoint @p checkpoint: check its files and its identity
     * (see the class), replace the points of @p material_points by its
     * points, fill @p state and return the step and time after which it was
     * written. Collective.
     */
    std::pair<unsigned int, double>
    read(const std::string   &checkpoint,
         MaterialPoints<dim> &material_points,
         CheckpointState     &state,
         const MPI_Comm       communicator) const;

  private:
    unsigned int step_interval = 0;
    double       minutes       = 0;
    unsigned int n_kept        = 2;
    /// Every entry of the parameters, by its path ("Time/End time").
    std::map<std::string, std::string> parameters;
    /// The end time of this run and the entry that gives it.
    double      end_time  = 0;
    std::string end_entry = "Time/End time";
    /// CRC-32 of the grid (set_grid_fingerprint()).
    std::uint32_t grid_fingerprint = 0;
    /// When the run started or the last checkpoint was written.
    std::chrono::steady_clock::time_point last_write =
      std::chrono::steady_clock::now();
  };
} // namespace MpmOtm

#endif
