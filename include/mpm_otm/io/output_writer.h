#ifndef mpm_otm_io_output_writer_h
#define mpm_otm_io_output_writer_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/io/statistics.h>
#include <mpm_otm/io/time_series.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialPoints;
  template <int dim>
  class NodalSystem;
  template <int dim>
  class ShapeFunctions;
  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class MaterialLibrary;

  /**
   * Everything a run writes to its output directory (ARCHITECTURE.md
   * "Output"): parameters.prm as used; the particle and grid fields as two
   * TimeSeries for ParaView (VTU with .pvtu and .pvd, or HDF5 with .xdmf);
   * statistics.csv with one row per output step; and, when asked,
   * particles-NNNNN.csv with one row per material point sorted by id. NNNNN
   * is the time-step number; output is written at step 0, every Interval
   * steps, in every step that reaches a multiple of Time interval, and at
   * the end time. Files are written under a temporary name and
   * renamed when complete, and an index (.pvtu, .pvd, .xdmf) only after every
   * file it names is complete, so that a run killed at any moment leaves
   * readable output; a failed write (a full disk) stops the run on all
   * ranks with a message naming the file.
   */
  template <int dim>
  class OutputWriter
  {
  public:
    /**
     * Declare subsection "Output".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read subsection "Output".
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Create the directory, write parameters.prm and the header of
     * statistics.csv; the points' materials are those of @p materials.
     * statistics.csv gets the gravitational energy if @p has_gravity and the
     * reaction force and displacement of each boundary condition in
     * @p boundary_names. A run resumed after step @p resumed_step (0: a new
     * run) instead keeps the directory's output up to that step and removes
     * the later steps' (OutputDirectory::trim_after_step()).
     */
    void
    initialize(const ParameterHandler         &prm,
               const bool                      has_displacement_error,
               const bool                      has_stress_error,
               const MPI_Comm                  communicator,
               const MaterialLibrary<dim>     &materials,
               const std::vector<std::string> &boundary_names,
               const bool                      has_gravity,
               const unsigned int              resumed_step = 0);

    /**
     * Save the time series (time and step of every output so far) into
     * @p state, for a checkpoint.
     */
    void
    save(CheckpointState &state) const;

    /**
     * Restore the time series from @p state and write their indices (.pvd
     * or .xdmf) again, so that they list the steps up to the checkpoint's
     * only. Collective.
     */
    void
    load(const CheckpointState &state);

    /**
     * Whether @p step, from @p time_before to @p time_after, is an output
     * step (@p last: the final step).
     */
    bool
    is_output_step(const unsigned int step,
                   const double       time_before,
                   const double       time_after,
                   const bool         last) const;

    /**
     * Write every file of one output step.
     */
    void
    write(const unsigned int         step,
          const double               time,
          const MaterialPoints<dim> &material_points,
          const BackgroundGrid<dim> &grid,
          const ShapeFunctions<dim> &shape_functions,
          NodalSystem<dim>          &system,
          const Statistics<dim>     &statistics);

    /**
     * The output directory.
     */
    const std::string &
    directory() const;

    /**
     * Stop on every rank if Output/Powell-Sabin basis at names a point but
     * no picture can be drawn: @p shape_functions draw none (only
     * Powell-Sabin splines do), the point has the wrong number of
     * coordinates, or the run on @p communicator has more than one rank.
     * Called before anything is written.
     */
    void
    check_basis_picture(const ShapeFunctions<dim> &shape_functions,
                        const MPI_Comm             communicator) const;

    /**
     * If Output/Powell-Sabin basis at names a point: write the family's
     * picture of its functions near it (ShapeFunctions::write_basis_picture(),
     * powell-sabin-basis.vtu). check_basis_picture() has accepted the entry.
     */
    void
    write_basis_picture(const ShapeFunctions<dim> &shape_functions) const;

  private:
    void
    write_particle_fields(const unsigned int         step,
                          const double               time,
                          const MaterialPoints<dim> &material_points);

    void
    write_grid_fields(const unsigned int         step,
                      const double               time,
                      const BackgroundGrid<dim> &grid,
                      const ShapeFunctions<dim> &shape_functions,
                      NodalSystem<dim>          &system);

    /**
     * Write particles-NNNNN.csv (rank 0; the other ranks send their rows).
     * Returns an empty string, or a sentence naming the file if the write
     * failed. Collective.
     */
    std::string
    write_particle_csv(const unsigned int         step,
                       const MaterialPoints<dim> &material_points) const;

    /**
     * Append the row of @p step to statistics.csv (rank 0). Returns an
     * empty string, or a sentence naming the file if the write failed.
     */
    std::string
    write_statistics(const unsigned int     step,
                     const double           time,
                     const Statistics<dim> &statistics) const;

    std::string        output_directory;
    unsigned int       interval      = 0;
    double             time_interval = 0;
    bool               write_csv     = false;
    bool               write_fields  = true;
    TimeSeries::Format field_format  = TimeSeries::Format::vtu;
    bool               overwrite     = false;
    /// Where to show the Powell-Sabin functions (empty: nowhere).
    std::vector<double>         powell_sabin_basis_point;
    MPI_Comm                    mpi_communicator           = MPI_COMM_WORLD;
    const MaterialLibrary<dim> *materials                  = nullptr;
    bool                        write_gravitational_energy = false;
    TimeSeries                  particle_series{"particles"};
    TimeSeries                  grid_series{"grid"};
  };
} // namespace MpmOtm

#endif
