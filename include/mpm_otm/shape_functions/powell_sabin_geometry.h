#ifndef mpm_otm_shape_functions_powell_sabin_geometry_h
#define mpm_otm_shape_functions_powell_sabin_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The Powell-Sabin refinement of a conforming triangulation and the
   * numbers that define the quadratic Powell-Sabin splines on it (thesis
   * Sect. 3.5, after Dierckx), with the one kernel that evaluates them. The
   * functions' numbering and distribution belong to FE_PowellSabin's
   * DoFHandler; the time step evaluates them through PowellSabin, and
   * FEValues through FE_PowellSabin, both with cell_values().
   *
   * Every triangle is split into six sub-triangles T_{k,0} = (V_k, R_k, Z),
   * T_{k,1} = (R_k, V_{k+1}, Z) (k = 0, 1, 2) by its incentre Z and one
   * point R_k on each edge k = (V_k, V_{k+1}): where the segment between the
   * incentres of the two triangles at the edge crosses it, or the edge's
   * midpoint on the domain boundary (thesis 3.5.1). Each vertex V gets a
   * control triangle Q^0 Q^1 Q^2 that contains its Powell-Sabin points (V,
   * the midpoints between V and the split points of its edges and the
   * incentres of its triangles), chosen by the thesis's near-optimal rule
   * (3.5.2: the smallest triangle among those formed by three edges of the
   * points' convex hull, or by two and a third edge orthogonal to their
   * bisector), with one restriction: a candidate must use every hull edge
   * that passes through V, so at a boundary vertex on a straight side two
   * control points lie on that side and at a convex corner V itself is one
   * (homogeneous Dirichlet conditions then fix whole coefficients). The
   * triplets of the three functions of V are the barycentric coordinates
   * lambda_q of the control triangle and their gradients (Eqs. 3.47-3.49),
   * and a function's Bezier ordinates next to V are lambda_q at the
   * Powell-Sabin points (Eqs. 3.54-3.56; the other ordinates follow from
   * C1 continuity). The functions are non-negative, a partition of unity,
   * reproduce quadratics and are C1.
   *
   * Function q of a cell's vertex j is the cell's function 3 j + q. Only
   * per-cell numbers (incentre, split points and four ordinates per
   * function) and per-vertex control triangles are stored, for the cells
   * that are not artificial; a vertex of such a cell has a complete control
   * triangle if all cells around it are present (locally owned or ghost).
   */
  class PowellSabinGeometry
  {
  public:
    /**
     * Number of functions that do not vanish on a cell: three per vertex.
     */
    static constexpr unsigned int n_cell_functions = 9;

    /**
     * Build the refinement and the functions on @p triangulation (all
     * triangles); again after its vertices moved (the unified approach),
     * where each vertex's control points keep their labels as far as
     * possible: those on the boundary first, then the nearest. Returns an
     * empty string, or which vertex has no control triangle (a degenerate
     * grid).
     */
    std::string
    reinit(const Triangulation<2> &triangulation);

    /**
     * Values and gradients of the nine functions of @p cell at the point
     * with reference coordinates @p xi (barycentric coordinates
     * (1 - xi_0 - xi_1, xi_0, xi_1)): vertex 0's functions q = 0, 1, 2, then
     * vertex 1's and vertex 2's. The point's sub-triangle is found from
     * @p xi; with @p sub_triangle (2 k + half for T_{k,half}) that
     * sub-triangle's quadratic is evaluated instead, also outside it.
     */
    void
    cell_values(
      const Triangulation<2>::cell_iterator &cell,
      const Point<2>                        &xi,
      double *const                          values,
      Tensor<1, 2> *const                    gradients,
      const unsigned int sub_triangle = numbers::invalid_unsigned_int) const;

    /**
     * The control triangle of the vertex with index @p vertex in the
     * triangulation.
     */
    const std::array<Point<2>, 3> &
    control_triangle(const unsigned int vertex) const;

    /**
     * alpha_v^q = lambda_q(V), the values of the three functions of the
     * vertex @p vertex at the vertex (the other vertices' functions vanish
     * there).
     */
    const std::array<double, 3> &
    vertex_values(const unsigned int vertex) const;

    /**
     * The point on edge @p edge (from vertex @p edge to vertex
     * @p edge + 1 mod 3) of @p cell where the refinement splits it, and the
     * cell's split point (incentre) for @p edge = 3.
     */
    Point<2>
    split_point(const Triangulation<2>::cell_iterator &cell,
                const unsigned int                     edge) const;

  private:
    /**
     * What a cell needs to evaluate its functions: incentre barycentric
     * coordinates a_k, split weights rho_k (R_k = rho_k V_k + (1 - rho_k)
     * V_{k+1}), gradients of the barycentric coordinates, and per function
     * the ordinates f, Lf, Lb, Lt of the owner vertex V_j at V_j,
     * mid(V_j, R_j), mid(V_j, R_{j-1}) and mid(V_j, Z) (thesis Eqs. 3.54-3.56).
     */
    struct CellData
    {
      std::array<double, 3>                               a;
      std::array<double, 3>                               rho;
      std::array<Tensor<1, 2>, 3>                         zeta_gradients;
      std::array<std::array<double, 4>, n_cell_functions> ordinates;
    };

    /// Per active cell index.
    std::vector<CellData> cell_data;
    /// Control triangle of each vertex (by vertex index).
    std::vector<std::array<Point<2>, 3>> control_triangles;
    /// alpha_v^q = lambda_q(V) of each vertex (by vertex index).
    std::vector<std::array<double, 3>> values_at_vertices;
  };
} // namespace MpmOtm

#endif
