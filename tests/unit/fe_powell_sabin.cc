// FE_PowellSabin, the Powell-Sabin splines as a deal.II finite element, on
// the perturbed B4 grid (6 x 6 vertices, every vertex moved by up to 0.2 h,
// so no two cells have the same split points), through deal.II's own
// classes:
// - FEValues at the points of a degree-4 rule: partition of unity, and the
//   six quadratics 1, x, y, x^2, xy, y^2 and their gradients reproduced
//   (thesis Sect. 3.5: the spline with coefficients g(V) + grad g(V) . (Q -
//   V) at the control points Q of vertex V is g), to 1e-12; the values are
//   those of the kernel the time step uses (PowellSabinGeometry::
//   cell_values) at the same points;
// - FEFaceValues from both sides of every interior edge: a spline with
//   random coefficients has the same value and gradient on both sides (C1),
//   to 1e-12;
// - AffineConstraints: make_boundary_constraints() with the inhomogeneous
//   quadratic g = 1 + x + 2 y + x^2 - x y + 3 y^2 on the side x = 0, and
//   random coefficients elsewhere, distributed: the field equals g on that
//   side at FEFaceValues points, to 1e-12;
// - DataOut: the field of the quadratic x y written with the element has
//   the value x y at every patch point, to 1e-6 (DataOut stores floats);
//   the gradient of a random spline, written with a postprocessor, agrees
//   to 1e-5 at every point that several triangles share (C1).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <mpm_otm/shape_functions/l2_projection.h>
#include <mpm_otm/shape_functions/powell_sabin.h>

#include <map>
#include <random>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  /**
   * The coefficients of a quadratic with value and gradient @p g at every
   * vertex: g(V) + grad g(V) . (Q - V) for the control point Q of each of
   * V's functions.
   */
  Vector<double>
  spline_coefficients(
    const PowellSabin<2> &basis,
    const std::function<std::pair<double, Tensor<1, 2>>(const Point<2> &)> &g)
  {
    const DoFHandler<2> &dof_handler = basis.dof_handler();
    Vector<double>       coefficients(dof_handler.n_dofs());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int j : cell->vertex_indices())
        {
          const auto [value, gradient] = g(cell->vertex(j));
          const auto &control =
            basis.geometry().control_triangle(cell->vertex_index(j));
          for (unsigned int q = 0; q < 3; ++q)
            coefficients(cell->vertex_dof_index(j, q)) =
              value + gradient * (control[q] - cell->vertex(j));
        }
    return coefficients;
  }

  /**
   * The Dirichlet data g = 1 + x + 2 y + x^2 - x y + 3 y^2 with its
   * gradient.
   */
  class SideData : public Function<2>
  {
  public:
    double
    value(const Point<2> &x, const unsigned int = 0) const override
    {
      return 1. + x[0] + 2. * x[1] + x[0] * x[0] - x[0] * x[1] +
             3. * x[1] * x[1];
    }

    Tensor<1, 2>
    gradient(const Point<2> &x, const unsigned int = 0) const override
    {
      return Tensor<1, 2>({1. + 2. * x[0] - x[1], 2. - x[0] + 6. * x[1]});
    }
  };

  /**
   * The gradient of a scalar field, for DataOut.
   */
  class Gradient : public DataPostprocessorVector<2>
  {
  public:
    Gradient()
      : DataPostprocessorVector<2>("gradient", update_gradients)
    {}

    void
    evaluate_scalar_field(
      const DataPostprocessorInputs::Scalar<2> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override
    {
      for (unsigned int q = 0; q < computed_quantities.size(); ++q)
        for (unsigned int d = 0; d < 2; ++d)
          computed_quantities[q](d) = inputs.solution_gradients[q][d];
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  Triangulation<2> triangulation;
  make_b4_grid(triangulation, 6, 0.2);
  PowellSabin<2> basis;
  basis.initialize(triangulation);
  const DoFHandler<2>                 &dof_handler = basis.dof_handler();
  const FiniteElement<2>              &fe          = dof_handler.get_fe();
  const MappingFE<2>                   mapping(FE_SimplexP<2>(1));
  const unsigned int                   n = fe.n_dofs_per_cell();
  std::vector<types::global_dof_index> dofs(n);
  check(fe.get_name() == "FE_PowellSabin" && n == 9 &&
          fe.n_dofs_per_vertex() == 3,
        "FE_PowellSabin: 9 functions per cell, 3 per vertex");
  check(dof_handler.n_dofs() == 3 * triangulation.n_vertices(),
        "three degrees of freedom per vertex");
  deallog << "FE_PowellSabin on " << triangulation.n_active_cells()
          << " triangles: " << dof_handler.n_dofs() << " functions"
          << std::endl;

  // FEValues: partition of unity, quadratic reproduction, the kernel.
  std::vector<Vector<double>> quadratics;
  for (unsigned int i = 0; i < 6; ++i)
    quadratics.push_back(spline_coefficients(basis, [i](const Point<2> &x) {
      return quadratic(i, x);
    }));
  {
    const QGaussSimplex<2> rule(4);
    FEValues<2>            fe_values(mapping,
                          fe,
                          rule,
                          update_values | update_gradients |
                            update_quadrature_points);
    double       unity = 0, reproduction = 0, derivative = 0, kernel = 0;
    unsigned int n_points = 0;
    double       values[9];
    Tensor<1, 2> gradients[9];
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
        for (unsigned int q = 0; q < rule.size(); ++q, ++n_points)
          {
            double sum = 0;
            for (unsigned int i = 0; i < n; ++i)
              sum += fe_values.shape_value(i, q);
            unity = std::max(unity, std::abs(sum - 1.));
            for (unsigned int g = 0; g < 6; ++g)
              {
                double       value = 0;
                Tensor<1, 2> gradient;
                for (unsigned int i = 0; i < n; ++i)
                  {
                    value +=
                      quadratics[g](dofs[i]) * fe_values.shape_value(i, q);
                    gradient +=
                      quadratics[g](dofs[i]) * fe_values.shape_grad(i, q);
                  }
                const auto [exact, exact_gradient] =
                  quadratic(g, fe_values.quadrature_point(q));
                reproduction = std::max(reproduction, std::abs(value - exact));
                derivative =
                  std::max(derivative, (gradient - exact_gradient).norm());
              }
            basis.geometry().cell_values(cell,
                                         rule.point(q),
                                         values,
                                         gradients);
            for (unsigned int i = 0; i < n; ++i)
              kernel =
                std::max({kernel,
                          std::abs(values[i] - fe_values.shape_value(i, q)),
                          (gradients[i] - fe_values.shape_grad(i, q)).norm()});
          }
      }
    check(unity < 1e-12, "partition of unity: " + rounded(unity, 2));
    check(reproduction < 1e-12 && derivative < 1e-12,
          "quadratic reproduction: " + rounded(reproduction, 2) + ", " +
            rounded(derivative, 2));
    check(kernel < 1e-12, "FEValues and the kernel: " + rounded(kernel, 2));
    deallog << "FEValues at " << n_points
            << " points: partition of unity, quadratics and their gradients "
               "reproduced, the kernel's values: all within 1e-12"
            << std::endl;
  }

  // FEFaceValues from both sides of every interior edge: C1.
  {
    std::mt19937   generator(3);
    Vector<double> coefficients(dof_handler.n_dofs());
    for (auto &c : coefficients)
      c = generator() / 4294967296.;
    const QGaussSimplex<1>               rule(3);
    FEFaceValues<2>                      here(mapping,
                         fe,
                         rule,
                         update_values | update_gradients |
                           update_quadrature_points);
    FEFaceValues<2>                      there(mapping,
                          fe,
                          rule,
                          update_values | update_gradients |
                            update_quadrature_points);
    std::vector<types::global_dof_index> neighbor_dofs(n);
    double                               jump = 0, gradient_jump = 0, scale = 0;
    unsigned int                         n_faces = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (!cell->at_boundary(f) && cell->index() < cell->neighbor(f)->index())
          {
            const auto neighbor = cell->neighbor(f);
            here.reinit(cell, f);
            there.reinit(neighbor, cell->neighbor_of_neighbor(f));
            cell->get_dof_indices(dofs);
            neighbor->get_dof_indices(neighbor_dofs);
            ++n_faces;
            for (unsigned int q = 0; q < rule.size(); ++q)
              {
                // The same point on the other side (the faces' orientations
                // may differ).
                unsigned int p = 0;
                while (here.quadrature_point(q).distance(
                         there.quadrature_point(p)) > 1e-12)
                  ++p;
                double       value[2] = {0., 0.};
                Tensor<1, 2> gradient[2];
                for (unsigned int i = 0; i < n; ++i)
                  {
                    value[0] += coefficients(dofs[i]) * here.shape_value(i, q);
                    gradient[0] +=
                      coefficients(dofs[i]) * here.shape_grad(i, q);
                    value[1] +=
                      coefficients(neighbor_dofs[i]) * there.shape_value(i, p);
                    gradient[1] +=
                      coefficients(neighbor_dofs[i]) * there.shape_grad(i, p);
                  }
                jump = std::max(jump, std::abs(value[0] - value[1]));
                gradient_jump =
                  std::max(gradient_jump, (gradient[0] - gradient[1]).norm());
                scale = std::max(scale, gradient[0].norm());
              }
          }
    check(jump < 1e-12 && gradient_jump < 1e-12 * scale,
          "C1 across edges: jumps " + rounded(jump, 2) + ", " +
            rounded(gradient_jump, 2));
    check(scale > 1., "the random field has gradients");
    deallog << "FEFaceValues on " << n_faces
            << " interior edges: value and gradient continuous (C1) within "
               "1e-12"
            << std::endl;
  }

  // Inhomogeneous Dirichlet data on the side x = 0 (given boundary id 7).
  {
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(face->center()[0] < 1e-12 ? 7 : 0);
    const SideData            g;
    AffineConstraints<double> constraints;
    basis.make_boundary_constraints(7, g, constraints);
    constraints.close();
    check(constraints.n_constraints() == 2 * 6,
          "two functions per vertex of the side are constrained");
    std::mt19937   generator(5);
    Vector<double> coefficients(dof_handler.n_dofs());
    for (auto &c : coefficients)
      c = generator() / 4294967296.;
    constraints.distribute(coefficients);

    const QGauss<1> rule(4);
    FEFaceValues<2> fe_values(mapping,
                              fe,
                              rule,
                              update_values | update_quadrature_points);
    double          error    = 0;
    unsigned int    n_points = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 7)
          {
            fe_values.reinit(cell, f);
            cell->get_dof_indices(dofs);
            for (unsigned int q = 0; q < rule.size(); ++q, ++n_points)
              {
                double value = 0;
                for (unsigned int i = 0; i < n; ++i)
                  value += coefficients(dofs[i]) * fe_values.shape_value(i, q);
                error =
                  std::max(error,
                           std::abs(value -
                                    g.value(fe_values.quadrature_point(q))));
              }
          }
    check(n_points == 5 * rule.size(), "points on the side x = 0");
    check(error < 1e-12, "Dirichlet data on x = 0: error " + rounded(error, 2));
    deallog << "AffineConstraints: g = 1 + x + 2 y + x^2 - x y + 3 y^2 on x "
               "= 0 through "
            << constraints.n_constraints()
            << " constrained coefficients, reproduced at " << n_points
            << " points within 1e-12" << std::endl;
  }

  // DataOut of the field x y (exact at every patch point) and of a field
  // with random coefficients with its gradient: at every point that
  // several patches share (the vertices and edge midpoints), value and
  // gradient agree (C1).
  {
    std::mt19937   generator(7);
    Vector<double> random_field(dof_handler.n_dofs());
    for (auto &c : random_field)
      c = generator() / 4294967296.;
    const Gradient gradient;
    DataOut<2>     data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(quadratics[4], "xy");
    data_out.add_data_vector(random_field, gradient);
    data_out.build_patches(mapping, 2);

    // Rows: xy, the gradient's two components, then the point.
    double                                          error = 0, jump = 0;
    unsigned int                                    n_points = 0;
    std::map<std::pair<float, float>, Tensor<1, 2>> gradient_at;
    for (const auto &patch : data_out.get_patches())
      for (unsigned int j = 0; j < patch.data.n_cols(); ++j, ++n_points)
        {
          const Point<2> x(patch.data(3, j), patch.data(4, j));
          error = std::max(error, std::abs(patch.data(0, j) - x[0] * x[1]));
          const Tensor<1, 2> g({patch.data(1, j), patch.data(2, j)});
          const auto [entry, is_new] =
            gradient_at.emplace(std::make_pair(patch.data(3, j),
                                               patch.data(4, j)),
                                g);
          if (!is_new)
            jump = std::max(jump, (entry->second - g).norm());
        }
    // DataOut keeps its points and data in single precision.
    check(n_points == 6 * triangulation.n_active_cells(),
          "six points per triangle");
    check(gradient_at.size() ==
            triangulation.n_vertices() + triangulation.n_active_faces(),
          "the patches share the vertices and edge midpoints");
    check(error < 1e-6, "DataOut of x y: error " + rounded(error, 2));
    check(jump < 1e-5, "DataOut gradient jump " + rounded(jump, 2));
    deallog << "DataOut: " << n_points << " points, x y exact within 1e-6 "
            << "(single precision); at the " << gradient_at.size()
            << " distinct points the gradient of a random spline agrees "
               "between patches within 1e-5"
            << std::endl;
  }
}
