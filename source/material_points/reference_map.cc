#include <mpm_otm/material_points/reference_map.h>

#include <algorithm>
#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  ReferenceMap<dim>::reinit(
    const typename Triangulation<dim>::active_cell_iterator &cell)
  {
    simplex = cell->reference_cell().is_simplex();
    Tensor<2, dim> jacobian;
    if (simplex)
      {
        coefficients[0] = cell->vertex(0);
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int a = 0; a < dim; ++a)
            jacobian[a][d] = cell->vertex(d + 1)[a] - cell->vertex(0)[a];
        affine = true;
      }
    else
      {
        // Vertex S of deal.II's hypercube sits at xi_d = 1 for the bits d of
        // S; the differences over the subsets give the coefficients of the
        // multilinear map.
        for (unsigned int s = 0; s < (1u << dim); ++s)
          coefficients[s] = cell->vertex(s);
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int s = 0; s < (1u << dim); ++s)
            if (s & (1u << d))
              coefficients[s] -= coefficients[s ^ (1u << d)];
        double size = 0, twist = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            size = std::max(size, coefficients[1u << d].norm());
            for (unsigned int a = 0; a < dim; ++a)
              jacobian[a][d] = coefficients[1u << d][a];
          }
        for (unsigned int s = 0; s < (1u << dim); ++s)
          if ((s & (s - 1)) != 0)
            twist = std::max(twist, coefficients[s].norm());
        affine = twist <= 1e-14 * size;
      }
    inverse_jacobian = invert(jacobian);
    // |J^-1| sum |c_S| over the products of two or more coordinates: the
    // second derivatives of the map in reference coordinates, twice over
    // for a Jacobian that varies over the cell.
    curvature = 0;
    if (!affine)
      for (unsigned int s = 0; s < (1u << dim); ++s)
        if ((s & (s - 1)) != 0)
          curvature += 2. * inverse_jacobian.norm() * coefficients[s].norm();
  }



  template <int dim>
  Point<dim>
  ReferenceMap<dim>::reference_point(const Point<dim> &point) const
  {
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    return reference_point(point, centre);
  }



  template <int dim>
  Point<dim>
  ReferenceMap<dim>::solve_multilinear(const Point<dim> &point,
                                       const Point<dim> &start) const
  {
    constexpr unsigned int n_terms = 1u << dim;
    Point<dim>             xi      = start;
    for (unsigned int iteration = 0; iteration < 20; ++iteration)
      {
        // The products of the coordinates of each subset of directions.
        std::array<double, n_terms> product;
        product[0] = 1.;
        for (unsigned int s = 1; s < n_terms; ++s)
          {
            const unsigned int d = __builtin_ctz(s);
            product[s]           = product[s ^ (1u << d)] * xi[d];
          }
        Tensor<1, dim> residual = -point;
        Tensor<2, dim> jacobian;
        for (unsigned int s = 0; s < n_terms; ++s)
          {
            residual += product[s] * coefficients[s];
            for (unsigned int d = 0; d < dim; ++d)
              if (s & (1u << d))
                for (unsigned int a = 0; a < dim; ++a)
                  jacobian[a][d] += product[s ^ (1u << d)] * coefficients[s][a];
          }
        const double det = determinant(jacobian);
        if (!(std::abs(det) > 0.))
          break;
        const Tensor<1, dim> step = invert(jacobian) * residual;
        xi -= step;
        double largest = 0;
        for (unsigned int d = 0; d < dim; ++d)
          largest = std::max(largest, std::abs(step[d]));
        // Newton's method converges quadratically: the error after a step
        // is at most about the product of the step's square and the
        // curvature of the map measured in reference coordinates.
        if (curvature * largest * largest < 1e-14 || largest < 1e-14)
          return xi;
        if (!(largest < 1e3))
          break;
      }
    for (unsigned int d = 0; d < dim; ++d)
      xi[d] = -1.;
    return xi;
  }



  template class ReferenceMap<1>;
  template class ReferenceMap<2>;
  template class ReferenceMap<3>;
} // namespace MpmOtm
