#ifndef mpm_otm_grid_system_node_block_preconditioner_h
#define mpm_otm_grid_system_node_block_preconditioner_h

#include <deal.II/lac/la_parallel_vector.h>

#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * Block Jacobi preconditioner for families with several functions per
   * node (ShapeFunctions::functions_per_node()): the inverse of each
   * node's diagonal block of the mass matrix, which holds the strong
   * coupling of functions with one support (a Powell-Sabin vertex's three
   * functions are far from orthogonal, and a diagonal preconditioner
   * leaves CG four times the iterations of the linear family). Excluded
   * coefficients get the identity; a block that is not numerically
   * positive definite gets its lumped masses.
   */
  class NodeBlockPreconditioner
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /**
     * Factorize the blocks: @p blocks holds, row by row, the n x n
     * diagonal block of the matrix of each node, whose n = @p block_size
     * functions are consecutive locally owned coefficients. The rows and
     * columns of the @p excluded coefficients (local indices) become the
     * identity; a block that is not numerically positive definite is
     * replaced by the diagonal of its @p lumped_mass entries.
     */
    NodeBlockPreconditioner(const std::vector<double>       &blocks,
                            const unsigned int               block_size,
                            const VectorType                &lumped_mass,
                            const std::vector<unsigned int> &excluded);

    /**
     * @p dst = the blocks' inverses times @p src, on the locally owned
     * entries.
     */
    void
    vmult(VectorType &dst, const VectorType &src) const;

  private:
    /**
     * Overwrite the lower triangle of the row-major block @p L with its
     * Cholesky factor; false if a pivot is not clearly positive.
     */
    bool
    cholesky(double *L) const;

    const unsigned int  block_size;
    std::vector<double> factors;
  };
} // namespace MpmOtm

#endif
