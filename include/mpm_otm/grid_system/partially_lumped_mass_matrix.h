#ifndef mpm_otm_grid_system_partially_lumped_mass_matrix_h
#define mpm_otm_grid_system_partially_lumped_mass_matrix_h

#include <mpm_otm/grid_system/consistent_mass_matrix.h>

namespace MpmOtm
{
  /**
   * Partial lumping (thesis Sect. 5.4): the rows of the functions at the
   * edge of the material - those that do not vanish on a cell with material
   * points and on a cell without - are lumped, the rest of the system is
   * solved with the consistent mass matrix. Those functions are the ones
   * whose mass-matrix rows become tiny when their cells empty, which makes
   * the consistent matrix ill-conditioned (thesis Sect. 5.1).
   *
   * With B the lumped rows and I the others, the system is block
   * triangular: m_B a_B = f_B, then M_II a_I = f_I - M_IB a_B, solved by CG
   * like the consistent matrix. The edge is found every step from the
   * cells' occupation, so the grid must reach beyond the material where a
   * free surface is (the thesis adds a layer of empty cells on top of the
   * soil column).
   */
  template <int dim>
  class PartiallyLumpedMassMatrix : public ConsistentMassMatrix<dim>
  {
  public:
    using VectorType = typename ConsistentMassMatrix<dim>::VectorType;

    static void
    declare_parameters(ParameterHandler &prm);

    bool
    is_consistent() const override;

    bool
    needs_material_boundary() const override;

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
