#ifndef mpm_otm_grid_system_local_damping_h
#define mpm_otm_grid_system_local_damping_h

#include <deal.II/base/parameter_handler.h>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class NodalSystem;

  /**
   * Local (Cundall) non-viscous damping of the nodal forces, used to bring a
   * body to static equilibrium (e.g. under its own weight) before a dynamic
   * phase: every component of a nodal force is reduced by alpha times its
   * magnitude against the direction of the nodal velocity,
   * f_i <- f_i - alpha |f_i| sign(v_i), with v_i = q_i / m_i (Cundall 1987,
   * as in PFC/FLAC and Anura3D). Read from subsection "Damping"; it acts
   * until the entry "End time". alpha = 0 (the default) leaves the forces
   * unchanged.
   */
  template <int dim>
  class LocalDamping
  {
  public:
    /**
     * Declare subsection "Damping".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read subsection "Damping".
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Whether damping acts at @p time.
     */
    bool
    is_active(const double time) const;

    /**
     * Set the local damping coefficient alpha, in [0, 1) (a stage that
     * changes it).
     */
    void
    set_coefficient(const double alpha);

    /**
     * Damp the locally owned nodal forces of @p system (after assembly),
     * and keep the damping's share in NodalSystem::damping_force.
     */
    void
    apply(NodalSystem<dim> &system) const;

  private:
    double coefficient = 0;
    double end_time    = 0;
  };
} // namespace MpmOtm

#endif
