#ifndef mpm_otm_grid_system_mass_matrix_h
#define mpm_otm_grid_system_mass_matrix_h

#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/grid_system/nodal_system.h>

namespace MpmOtm
{
  /**
   * How the mass matrix M_ij = sum_p m_p phi_i(x_p) phi_j(x_p) (journal
   * Eq. 19) is used to turn nodal forces into accelerations and momenta into
   * velocities: consistent, lumped (row sums, journal Eq. 17), or partially
   * lumped (thesis Sect. 5.4). The solves honour affine constraints
   * x_i = b_i (NodalSystem::constraints(), to which boundary conditions add
   * prescribed values).
   */
  template <int dim>
  class MassMatrix
  {
  public:
    using VectorType = typename NodalSystem<dim>::VectorType;

    virtual ~MassMatrix() = default;

    /**
     * Read the treatment's own parameters (declared by the plugin's static
     * declare_parameters()).
     */
    virtual void
    parse_parameters(ParameterHandler &)
    {}

    /**
     * Whether the solves use the consistent matrix itself, lumped in no
     * row. The stable time step of USL and of OTM's update depends on how
     * the matrix of the solves differs from it (StableTimeStep).
     */
    virtual bool
    is_consistent() const
    {
      return false;
    }

    /**
     * Whether the solves divide by the row-sum lumped masses in every row
     * (a_i = f_i / m_i), as APIC's transfer assumes.
     */
    virtual bool
    is_lumped() const
    {
      return false;
    }

    /**
     * Whether the solves need NodalSystem::material_boundary_functions().
     */
    virtual bool
    needs_material_boundary() const
    {
      return false;
    }

    /**
     * Prepare the solves of a step, after the system has been assembled from
     * @p shape_data (the same data every solve of the step gets).
     */
    virtual void
    assemble(const NodalSystem<dim> &, const ParticleShapeData<dim> &)
    {}

    /**
     * @p product = M @p vector on the locally owned entries, with the matrix
     * the solves use (for the reactions of the boundary conditions).
     * Collective.
     */
    virtual void
    vmult(const NodalSystem<dim>       &system,
          const ParticleShapeData<dim> &shape_data,
          const VectorType             &vector,
          VectorType                   &product) const = 0;

    /**
     * Solve M @p solution = @p right_hand_side subject to @p constraints
     * (lines x_i = b_i on locally owned functions): the constrained
     * coefficients get b_i, the others solve their rows with the
     * constrained ones moved to the right-hand side. @p solution has the
     * layout of the system's vectors.
     */
    virtual void
    solve(const NodalSystem<dim>          &system,
          const ParticleShapeData<dim>    &shape_data,
          const VectorType                &right_hand_side,
          VectorType                      &solution,
          const AffineConstraints<double> &constraints) const = 0;
  };
} // namespace MpmOtm

#endif
