#ifndef mpm_otm_grid_system_consistent_mass_matrix_h
#define mpm_otm_grid_system_consistent_mass_matrix_h

#include <mpm_otm/grid_system/mass_matrix.h>

namespace MpmOtm
{
  /**
   * The consistent mass matrix (journal Eq. 19), solved with conjugate
   * gradients preconditioned by the lumped masses. No global matrix or
   * sparsity pattern is built. Points with the same functions (the points of
   * one cell, for every family whose functions are fixed per cell) form a
   * group whose dense block sum_p m_p phi phi^T is summed once per step, and
   * a product with the matrix is one pass over the groups. Where groups do
   * not pay (one function set per point, as for max-ent), the product is a
   * pass over the points, sum_p m_p phi_i (sum_j phi_j x_j). Both work for
   * every family and in parallel. A solve that does not converge stops the
   * run.
   */
  template <int dim>
  class ConsistentMassMatrix : public MassMatrix<dim>
  {
  public:
    using VectorType = typename MassMatrix<dim>::VectorType;

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Sum the blocks of the point groups, or choose the point pass.
     */
    void
    assemble(const NodalSystem<dim>       &system,
             const ParticleShapeData<dim> &shape_data) override;

    void
    solve(const NodalSystem<dim>       &system,
          const ParticleShapeData<dim> &shape_data,
          const VectorType             &right_hand_side,
          VectorType                   &solution,
          const unsigned int            component) const override;

  private:
    /// Whether the products use the group blocks.
    bool use_groups = false;
    /// Start of each group's function indices in group_indices.
    std::vector<unsigned int> group_offsets;
    /// Local indices of the functions of each group.
    std::vector<unsigned int> group_indices;
    /// The group of each point.
    std::vector<unsigned int> group_of_point;
    /// Start of each group's dense block in group_blocks (only if used).
    std::vector<std::size_t> block_offsets;
    /// Row-major blocks sum_p m_p phi_a phi_b of the groups.
    std::vector<double> group_blocks;
  };
} // namespace MpmOtm

#endif
