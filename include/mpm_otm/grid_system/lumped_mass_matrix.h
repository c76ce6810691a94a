#ifndef mpm_otm_grid_system_lumped_mass_matrix_h
#define mpm_otm_grid_system_lumped_mass_matrix_h

#include <mpm_otm/grid_system/mass_matrix.h>

namespace MpmOtm
{
  /**
   * The row-sum lumped mass matrix (journal Eq. 17): a_i = f_i / m_i.
   */
  template <int dim>
  class LumpedMassMatrix : public MassMatrix<dim>
  {
  public:
    using VectorType = typename MassMatrix<dim>::VectorType;

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * True: every row is lumped.
     */
    bool
    is_lumped() const override;

    void
    vmult(const NodalSystem<dim>       &system,
          const ParticleShapeData<dim> &shape_data,
          const VectorType             &vector,
          VectorType                   &product) const override;

    void
    solve(const NodalSystem<dim>          &system,
          const ParticleShapeData<dim>    &shape_data,
          const VectorType                &right_hand_side,
          VectorType                      &solution,
          const AffineConstraints<double> &constraints) const override;
  };
} // namespace MpmOtm

#endif
