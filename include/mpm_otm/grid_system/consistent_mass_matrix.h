#ifndef mpm_otm_grid_system_consistent_mass_matrix_h
#define mpm_otm_grid_system_consistent_mass_matrix_h

#include <mpm_otm/grid_system/mass_matrix.h>

namespace MpmOtm
{
  /**
   * The consistent mass matrix (journal Eq. 19), solved with conjugate
   * gradients preconditioned by the lumped masses. The matrix is never
   * stored: its product with a vector is sum_p m_p phi_i (sum_j phi_j x_j)
   * over the shape data of the step, which costs one particle pass, needs no
   * sparsity pattern and works for every shape-function family and in
   * parallel. A solve that does not converge stops the run.
   */
  template <int dim>
  class ConsistentMassMatrix : public MassMatrix<dim>
  {
  public:
    using VectorType = typename MassMatrix<dim>::VectorType;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    solve(const NodalSystem<dim>       &system,
          const ParticleShapeData<dim> &shape_data,
          const VectorType             &right_hand_side,
          VectorType                   &solution,
          const unsigned int            component) const override;
  };
} // namespace MpmOtm

#endif
