#include <mpm_otm/grid_system/node_block_preconditioner.h>

#include <cmath>

namespace MpmOtm
{
  NodeBlockPreconditioner::NodeBlockPreconditioner(
    const std::vector<double>       &blocks,
    const unsigned int               block_size,
    const VectorType                &lumped_mass,
    const std::vector<unsigned int> &excluded)
    : block_size(block_size)
    , factors(blocks)
  {
    const unsigned int n_owned = lumped_mass.locally_owned_size();
    Assert(n_owned % block_size == 0,
           ExcMessage("A node's functions must have one owner."));
    std::vector<bool> is_excluded(n_owned, false);
    for (const unsigned int i : excluded)
      is_excluded[i] = true;
    const unsigned int n = block_size;
    for (unsigned int start = 0; start < n_owned; start += n)
      {
        double *L = &factors[start * n];
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            if (is_excluded[start + a] || is_excluded[start + b])
              L[a * n + b] = (a == b ? 1. : 0.);
        if (!cholesky(L))
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int b = 0; b < n; ++b)
              {
                const double m = lumped_mass.local_element(start + a);
                L[a * n + b] =
                  (a != b) ?
                    0. :
                    ((m > 0. && !is_excluded[start + a]) ? std::sqrt(m) : 1.);
              }
      }
  }



  void
  NodeBlockPreconditioner::vmult(VectorType &dst, const VectorType &src) const
  {
    const unsigned int n = block_size;
    for (unsigned int start = 0; start < dst.locally_owned_size(); start += n)
      {
        const double *L = &factors[start * n];
        double       *x = dst.get_values() + start;
        const double *y = src.get_values() + start;
        // L L^T x = y: forward, then backward substitution.
        for (unsigned int a = 0; a < n; ++a)
          {
            double sum = y[a];
            for (unsigned int b = 0; b < a; ++b)
              sum -= L[a * n + b] * x[b];
            x[a] = sum / L[a * n + a];
          }
        for (unsigned int a = n; a-- > 0;)
          {
            double sum = x[a];
            for (unsigned int b = a + 1; b < n; ++b)
              sum -= L[b * n + a] * x[b];
            x[a] = sum / L[a * n + a];
          }
      }
  }



  bool
  NodeBlockPreconditioner::cholesky(double *L) const
  {
    const unsigned int n                = block_size;
    double             largest_diagonal = 0.;
    for (unsigned int a = 0; a < n; ++a)
      largest_diagonal = std::max(largest_diagonal, L[a * n + a]);
    for (unsigned int a = 0; a < n; ++a)
      {
        for (unsigned int b = 0; b <= a; ++b)
          {
            double sum = L[a * n + b];
            for (unsigned int c = 0; c < b; ++c)
              sum -= L[a * n + c] * L[b * n + c];
            if (a == b)
              {
                if (!(sum > 1e-12 * largest_diagonal))
                  return false;
                L[a * n + a] = std::sqrt(sum);
              }
            else
              L[a * n + b] = sum / L[b * n + b];
          }
      }
    return true;
  }
} // namespace MpmOtm
