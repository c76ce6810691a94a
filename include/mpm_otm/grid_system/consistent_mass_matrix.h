#ifndef mpm_otm_grid_system_consistent_mass_matrix_h
#define mpm_otm_grid_system_consistent_mass_matrix_h

#include <mpm_otm/grid_system/mass_matrix.h>

namespace MpmOtm
{
  /**
   * The consistent mass matrix (journal Eq. 19), solved with conjugate
   * gradients preconditioned by the lumped masses, or, for families with
   * several functions per node (Powell-Sabin), by the inverses of the
   * nodes' diagonal blocks. Points with the same
   * functions (the points of one cell, for every family) form a group; the
   * entries sum_p m_p phi_i phi_j are summed once per step into one matrix in
   * compressed rows on the locally stored coefficients, whose pattern (the
   * pairs of functions that share a group) is rebuilt only when the groups
   * change. Where that does not pay (few points per set of functions), a
   * product is a pass over the points, sum_p m_p phi_i (sum_j phi_j x_j).
   * Both work for every family and in parallel. A solve that does not
   * converge stops the run.
   */
  template <int dim>
  class ConsistentMassMatrix : public MassMatrix<dim>
  {
  public:
    using VectorType = typename MassMatrix<dim>::VectorType;

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Assemble the matrix from the point groups, or choose the point pass.
     */
    void
    assemble(const NodalSystem<dim>       &system,
             const ParticleShapeData<dim> &shape_data) override;

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

  protected:
    /**
     * Solve M @p solution = @p right_hand_side with the coefficients of
     * @p prescribed (pairs of a local index and its value, sorted by index)
     * set to their values: the other rows
     * solve M_ff x_f = b_f - M_fp x_p by CG; stops the run if CG does not
     * converge.
     */
    void
    solve_prescribed(
      const NodalSystem<dim>                             &system,
      const ParticleShapeData<dim>                       &shape_data,
      const VectorType                                   &right_hand_side,
      VectorType                                         &solution,
      const std::vector<std::pair<unsigned int, double>> &prescribed) const;

  private:
    /**
     * Sum the entries of the matrix from the points, rebuilding its pattern
     * if the groups differ from @p previous_offsets and @p previous_indices.
     */
    void
    assemble_matrix(const NodalSystem<dim>          &system,
                    const ParticleShapeData<dim>    &shape_data,
                    const std::vector<unsigned int> &previous_offsets,
                    const std::vector<unsigned int> &previous_indices);

    /**
     * Fill node_block_entries, summed over the ranks.
     */
    void
    assemble_node_blocks(const NodalSystem<dim>       &system,
                         const ParticleShapeData<dim> &shape_data);

    /**
     * The compressed rows of the matrix on @p n_rows locally stored
     * coefficients and, for every entry of every group's block, the matrix
     * entry it adds to.
     */
    void
    build_sparsity(const unsigned int n_rows);

    /// Whether the products use the assembled matrix (or a point pass).
    bool use_matrix = false;
    /// Start of each group's function indices in group_indices.
    std::vector<unsigned int> group_offsets;
    /// Local indices of the functions of each group.
    std::vector<unsigned int> group_indices;
    /// The group of each point.
    std::vector<unsigned int> group_of_point;
    /// Start of each group's row-major block in entry_of_block.
    std::vector<std::size_t> block_offsets;
    /// The matrix entry of each group's block entry (a, b).
    std::vector<unsigned int> entry_of_block;
    /// The matrix in compressed rows on the local coefficients (ghosts
    /// included; their rows are added to the owners in a product).
    std::vector<unsigned int> row_offsets;
    std::vector<unsigned int> columns;
    std::vector<double>       entries;
    /// One group's dense block while its points are summed (reused).
    std::vector<double> group_block;
    /// Global index of every local coefficient, for the node blocks.
    std::vector<types::global_dof_index> global_of_local;
    /// With n > 1 functions per node: entry i of vector q is M_ij with j
    /// the function q of i's node; empty otherwise.
    std::vector<VectorType> node_block_entries;
  };
} // namespace MpmOtm

#endif
