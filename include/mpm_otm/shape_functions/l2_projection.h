#ifndef mpm_otm_shape_functions_l2_projection_h
#define mpm_otm_shape_functions_l2_projection_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <functional>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The spaces a function can be L2-projected onto by
   * l2_projection_error(): linear Lagrange functions (P1, one per vertex)
   * and quadratic Powell-Sabin splines (three per vertex).
   */
  enum class ProjectionSpace
  {
    linear_lagrange,
    powell_sabin
  };

  /**
   * Size and error of an L2 projection.
   */
  struct ProjectionError
  {
    /// Number of functions of the space (unknowns of the projection).
    types::global_dof_index n_functions;
    /// ||f_h - f||_L2 over the triangulation.
    double l2_error;
  };

  /**
   * The grid of benchmark B4 (BENCHMARKS.md B4, thesis Fig. 3.25): the unit
   * square with @p n x @p n vertices, every square cut by the diagonal from
   * (x_i, y_j) to (x_{i+1}, y_{j+1}). With @p perturbation > 0 each
   * coordinate of every vertex is moved by a uniform random amount in
   * [-perturbation h, perturbation h], h = 1 / (n - 1), except
   * that boundary vertices move only along their side and the corners stay:
   * an unstructured (in geometry, not in connectivity) triangulation of the
   * same square. The random numbers are the raw output of std::mt19937
   * seeded with @p seed, so the grid is the same on every platform. Stops
   * with a message if a triangle would be inverted.
   */
  void
  make_b4_grid(Triangulation<2>  &triangulation,
               const unsigned int n,
               const double       perturbation = 0.,
               const unsigned int seed         = 1);

  /**
   * The L2 projection f_h of @p f onto @p space on @p triangulation
   * (thesis Eqs. 3.66-3.70: consistent mass matrix, no boundary conditions)
   * and its error ||f_h - f||_L2 (thesis Eq. 3.71). Mass matrix and
   * right-hand side are integrated through FEValues (FE_SimplexP(1) or
   * FE_PowellSabin on a DoFHandler) with the 7-point rule of degree 5
   * (Radon) on every triangle (P1) or on each of the six sub-triangles of
   * the Powell-Sabin refinement (where the splines are quadratic; a
   * composite rule per cell, as the sub-triangles differ from cell to
   * cell), so the mass matrix is exact; the error with an 8 x 8 collapsed
   * Gauss rule (QDuffy) on the same pieces. The system is solved with a
   * sparse direct solver (UMFPACK).
   */
  ProjectionError
  l2_projection_error(const Triangulation<2> &triangulation,
                      const ProjectionSpace   space,
                      const std::function<double(const Point<2> &)> &f);
} // namespace MpmOtm

#endif
