#ifndef mpm_otm_io_monitoring_points_h
#define mpm_otm_io_monitoring_points_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/particles/property_pool.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  class CheckpointState;
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;

  /**
   * Named monitoring points (subsection "Monitoring"): each follows the
   * material point whose initial position is nearest to the coordinates
   * given for it, and its displacement, velocity, stress (with sigma_zz of
   * plane strain), mean stress, von Mises stress and equivalent plastic
   * strain are written to monitoring.csv, one row per monitored step with
   * the columns of every point side by side, as statistics.csv. The
   * material point is chosen from the initial positions, so that a run
   * resumed from a checkpoint, on any number of ranks, follows the same
   * one; a point whose nearest material point is farther than the diagonal
   * of that point's initial share of the body (sqrt(dim) V_p^0^(1/dim)) is
   * outside every body and stops the run before anything is written.
   * Rank 0 writes the file, a row at a time; a resumed run keeps the rows
   * up to the checkpoint's step (OutputDirectory::trim_after_step()).
   */
  template <int dim>
  class MonitoringPoints
  {
  public:
    /**
     * Declare subsection "Monitoring".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read subsection "Monitoring"; stops naming the entry if a point is
     * not NAME: x, y[, z] or a name repeats.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Whether any point is monitored.
     */
    bool
    enabled() const;

    /**
     * Find the material point of each monitoring point among
     * @p material_points; returns a line per point naming it, for the log.
     * Collective; stops every rank with the same message if a point is
     * outside every body.
     */
    std::string
    locate(const MaterialPoints<dim> &material_points,
           const MPI_Comm             communicator);

    /**
     * Store the material points that the monitoring points follow in
     * @p state.
     */
    void
    save(CheckpointState &state) const;

    /**
     * Follow the material points stored in @p state (in place of locate()
     * for a run that continues from a checkpoint: the points it followed
     * may have been removed by a stage since, or others added nearer).
     */
    void
    load(const CheckpointState &state);

    /**
     * Write the header of monitoring.csv in @p directory (rank 0). A run
     * @p resumed from a checkpoint keeps the file it finds, if its header
     * names the same points, and stops otherwise. Collective: a failure
     * stops every rank.
     */
    void
    write_header(const std::string &directory,
                 const bool         resumed,
                 const MPI_Comm     communicator) const;

    /**
     * Whether step @p step is monitored: every Interval steps, or with
     * Interval = 0 when @p output_step (the field output's steps), and
     * always at step 0 and when @p last.
     */
    bool
    is_due(const unsigned int step,
           const bool         output_step,
           const bool         last) const;

    /**
     * Append the row of step @p step at @p time to monitoring.csv in
     * @p directory (nothing without monitoring points). Collective: the
     * rank that owns a monitored point sends its values to rank 0.
     */
    void
    write(const unsigned int          step,
          const double                time,
          const MaterialPoints<dim>  &material_points,
          const MaterialLibrary<dim> &materials,
          const std::string          &directory,
          const MPI_Comm              communicator) const;

  private:
    /**
     * The header line of monitoring.csv.
     */
    std::string
    header() const;

    /**
     * The values written per monitoring point: x, u and v (dim each), the
     * six stress components (dim = 3; in 2D the four of plane strain, in
     * 1D sxx and the lateral stress), mean and von Mises stress, and the
     * equivalent plastic strain.
     */
    static unsigned int
    n_values();

    std::vector<std::string>           names;
    std::vector<Point<dim>>            locations;
    std::vector<types::particle_index> ids;
    unsigned int                       interval = 0;
  };
} // namespace MpmOtm

#endif
