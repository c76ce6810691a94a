#ifndef mpm_otm_material_points_reference_map_h
#define mpm_otm_material_points_reference_map_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <array>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The inverse of the map of one cell of a first-order grid, for the
   * point location of every step: the barycentric coordinates of a point in
   * a triangle or tetrahedron (deal.II's reference coordinates of a
   * simplex), or the reference coordinates of the bilinear (trilinear) map
   * of a quadrilateral (hexahedron), the map of deal.II's MappingQ1 (on a
   * parallelogram by its affine inverse, otherwise by Newton's method). Set
   * up once per cell, used for all its points.
   */
  template <int dim>
  class ReferenceMap
  {
  public:
    /**
     * Take the vertices of @p cell.
     */
    void
    reinit(const typename Triangulation<dim>::active_cell_iterator &cell);

    /**
     * The reference coordinates of @p point; for a hypercube Newton's method
     * starts at @p start (the cell's centre if not given; a point's
     * reference coordinates before it moved take two or three steps). Where
     * it has not converged (a point far outside a distorted cell), a point
     * outside the reference cell.
     */
    Point<dim>
    reference_point(const Point<dim> &point) const;

    Point<dim>
    reference_point(const Point<dim> &point, const Point<dim> &start) const
    {
      if (affine)
        return Point<dim>(inverse_jacobian * (point - coefficients[0]));
      return solve_multilinear(point, start);
    }

    /**
     * True if @p reference (an answer of reference_point()) lies in the
     * reference cell, up to @p tolerance.
     */
    bool
    contains(const Point<dim> &reference, const double tolerance = 1e-12) const
    {
      double sum = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (!(reference[d] >= -tolerance))
            return false;
          if (!simplex && !(reference[d] <= 1. + tolerance))
            return false;
          sum += reference[d];
        }
      return !simplex || sum <= 1. + tolerance;
    }

  private:
    /**
     * Newton's method for the multilinear map of a hypercube that is no
     * parallelogram (parallelepiped).
     */
    Point<dim>
    solve_multilinear(const Point<dim> &point, const Point<dim> &start) const;

    bool simplex = false;
    /// True for a simplex or a parallelogram (parallelepiped).
    bool affine = false;
    /// The coefficients of the multilinear map, x = sum_S c_S prod_{d in
    /// S} xi_d over the subsets S of the directions (bit d of S for
    /// direction d); for a simplex only c_0, vertex 0.
    std::array<Tensor<1, dim>, (1u << dim)> coefficients;
    /// The inverse Jacobian of the affine part (at xi = 0; for a simplex
    /// that of its edges from vertex 0).
    Tensor<2, dim> inverse_jacobian;
    /// A bound of the second derivatives of the map in reference
    /// coordinates, for the error of Newton's method.
    double curvature = 0;
  };
} // namespace MpmOtm

#endif
