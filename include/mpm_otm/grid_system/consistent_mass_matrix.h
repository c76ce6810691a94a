#ifndef mpm_otm_grid_system_consistent_mass_matrix_h
#define mpm_otm_grid_system_consistent_mass_matrix_h

#include <deal.II/lac/diagonal_matrix.h>

#include <mpm_otm/grid_system/mass_matrix.h>

#include <memory>
#include <utility>
#include <vector>

namespace dealii::TrilinosWrappers
{
  class PreconditionBase;
  class SparseMatrix;
  namespace MPI
  {
    class Vector;
  }
} // namespace dealii::TrilinosWrappers

namespace MpmOtm
{
  /**
   * The consistent mass matrix (journal Eq. 19), solved with conjugate
   * gradients. Points with the same functions (the points of one cell, for
   * every family but max-ent) form a group; the entries
   * sum_p m_p phi_i phi_j are summed once per step, group by group, into a
   * distributed Trilinos matrix whose pattern (the pairs of functions that
   * share a group) is rebuilt only when the groups change. Where that does
   * not pay (few points per set of functions, as with max-ent or OTM) and
   * the preconditioner needs no matrix, a product is a pass over the points,
   * sum_p m_p phi_i (sum_j phi_j x_j), instead.
   *
   * The preconditioner is the parameter 'Mass matrix preconditioner': the
   * lumped masses, or the inverses of the nodes' diagonal blocks for
   * families with several functions per node (Powell-Sabin, whose three
   * functions of a vertex are far from orthogonal), factorised per solve
   * with the prescribed coefficients at the identity and the lumped masses
   * for a block that is not positive definite (Ifpack's block relaxation
   * has no such fallback, and the deactivation remedy of thesis Sect. 5.2
   * leaves singular blocks); or algebraic multigrid (Trilinos ML) or a
   * sparse direct factorisation of each rank's rows (Ifpack with Amesos),
   * set up once per step from the matrix with the identity in the rows and
   * columns of the functions every solve prescribes (no material,
   * deactivated), and applied to the coefficients that are not prescribed.
   * A solve that does not converge stops the run.
   */
  template <int dim>
  class ConsistentMassMatrix : public MassMatrix<dim>
  {
  public:
    using VectorType = typename MassMatrix<dim>::VectorType;

    ConsistentMassMatrix();

    ~ConsistentMassMatrix() override;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    bool
    is_consistent() const override;

    /**
     * Assemble the matrix from the point groups, or choose the point pass,
     * and set up the preconditioner. Collective.
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
     * The preconditioners of 'Mass matrix preconditioner'.
     */
    enum class Preconditioner
    {
      diagonal,
      direct_per_rank,
      algebraic_multigrid
    };

    /**
     * Find the groups of consecutive points with the same functions; return
     * whether they differ from the previous step's.
     */
    bool
    find_groups(const ParticleShapeData<dim> &shape_data);

    /**
     * Build the matrix's pattern from the groups: every pair of functions of
     * a group, and the diagonal of every locally owned row. Collective.
     */
    void
    build_sparsity(const NodalSystem<dim> &system);

    /**
     * Sum the entries of the matrix from the points of each group.
     * Collective.
     */
    void
    assemble_matrix(const NodalSystem<dim>       &system,
                    const ParticleShapeData<dim> &shape_data);

    /**
     * Copy the nodes' diagonal blocks of the matrix into node_blocks.
     */
    void
    extract_node_blocks(const NodalSystem<dim> &system);

    /**
     * Set up the algebraic multigrid or direct preconditioner of the
     * matrix, after build_sparsity() if @p pattern_changed. Collective;
     * every rank stops if the set-up fails on one.
     */
    void
    initialize_matrix_preconditioner(const NodalSystem<dim> &system,
                                     const bool              pattern_changed);

    Preconditioner preconditioner_type = Preconditioner::diagonal;
    /// Whether the products use the assembled matrix (or a point pass).
    bool use_matrix = false;
    /// Whether the matrix has the pattern of the current groups.
    bool has_pattern = false;
    /// Start of each group's function indices in group_indices.
    std::vector<unsigned int> group_offsets;
    /// Local indices of the functions of each group.
    std::vector<unsigned int> group_indices;
    /// The first point of each group; the last entry is the number of
    /// points.
    std::vector<unsigned int> group_first_point;
    /// The matrix, on the locally owned rows.
    std::unique_ptr<TrilinosWrappers::SparseMatrix> matrix;
    /// The matrix with the identity in the rows and columns of the
    /// functions that every solve prescribes, from which
    /// matrix_preconditioner is built.
    std::unique_ptr<TrilinosWrappers::SparseMatrix> preconditioner_matrix;
    /// 1 for those functions, on the matrix's columns.
    std::unique_ptr<TrilinosWrappers::MPI::Vector> excluded_columns;
    /// The preconditioner built from the matrix, if it needs one.
    std::unique_ptr<TrilinosWrappers::PreconditionBase> matrix_preconditioner;
    /// With several functions per node and the diagonal preconditioner:
    /// for every locally owned function i, the row of i's node block,
    /// M_ij for the n functions j of i's node.
    std::vector<double> node_blocks;
    /// 1 / lumped mass (1 where it vanishes), the diagonal preconditioner
    /// with one function per node.
    DiagonalMatrix<VectorType> inverse_lumped_mass;
  };
} // namespace MpmOtm

#endif
