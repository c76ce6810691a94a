#ifndef mpm_otm_io_statistics_h
#define mpm_otm_io_statistics_h

#include <deal.II/base/tensor.h>

#include <string>
#include <utility>
#include <vector>

namespace MpmOtm
{
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class Problem;

  /**
   * Global measures of the material points at one time: energies and, where
   * the problem knows its exact solution, the error norms of the benchmarks:
   * the RMS displacement error sqrt(1/M sum_p |u_p - u(X_p)|^2) (journal
   * Eq. 102 with the square restored), the L2 displacement error
   * sqrt(sum_p V_p |u_p - u(X_p)|^2) (thesis Eq. 4.4) and the RMS stress
   * error sqrt(1/M sum_p |sigma_p - sigma(X_p)|^2) (conference paper).
   */
  template <int dim>
  struct Statistics
  {
    double kinetic_energy         = 0;
    double strain_energy          = 0;
    double total_mass             = 0;
    double momentum[3]            = {0, 0, 0};
    bool   has_displacement_error = false;
    double displacement_rms_error = 0;
    double displacement_l2_error  = 0;
    bool   has_stress_error       = false;
    double stress_rms_error       = 0;
    /// Potential energy of the points in the gravity field,
    /// -sum_p m_p g . (x_p - X_p).
    double gravitational_energy = 0;
    /// Work done on the points since the start by gravity, body forces,
    /// tractions and prescribed velocities (the positive part of each
    /// step's work on all ranks, TimeStepper::supplied_work()); with the
    /// energy at the start, the bound of the EnergyMonitor.
    double supplied_work = 0;
    /// Kinetic energy of the grid's motion, sum_i m_i |v_i|^2 / 2
    /// (NodalSystem::kinetic_energy(); the measure of the quasi-static
    /// end), set by the simulator.
    double grid_kinetic_energy = 0;
    /// Angular momentum about the origin, sum_p m_p x_p x v_p (its z
    /// component in 2D, 0 in 1D); with Particle velocity = APIC the points'
    /// affine motion adds its part (ParticleTransfer), set by the
    /// simulator.
    double angular_momentum[3] = {0, 0, 0};
    /// Names of the named boundary conditions.
    std::vector<std::string> boundary_names;
    /// Their reactions (mean over the steps since the last output) and the
    /// displacements of their prescribed components.
    std::vector<std::pair<dealii::Tensor<1, dim>, dealii::Tensor<1, dim>>>
      boundary_reactions;

    /**
     * Compute all measures over the points of every rank at @p time.
     */
    void
    compute(const MaterialPoints<dim>  &material_points,
            const MaterialLibrary<dim> &materials,
            const Problem<dim>         &problem,
            const double                time);
  };
} // namespace MpmOtm

#endif
