// B-spline shape functions (journal Sect. 6.2) of degree p = 1, 2, 3 on
// non-uniform open knot vectors in 1D, 2D and 3D, checked against
// properties that hold exactly for B-splines:
// - partition of unity and non-negativity at random points;
// - Marsden's identity sum_i xi*_i N_i(x) = x with the Greville abscissae
//   xi*_i = (U_{i+1} + ... + U_{i+p}) / p (linear reproduction);
// - gradients against central finite differences;
// - C^(p-1) continuity across every interior knot (values, first and, for
//   p = 3, second derivatives from one-sided differences);
// - the Bernstein coefficients written for output (FE_Bernstein cells)
//   give the same field as the splines;
// - the L2 projection of a smooth function converges at rate p + 1 in 1D
//   and 2D.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/shape_functions/b_splines.h>

#include <random>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  /**
   * Knots 0 < ... < 1 with cell sizes varying by a factor of about 3.
   */
  std::vector<double>
  non_uniform_knots(const unsigned int n_cells)
  {
    std::vector<double> knots(n_cells + 1);
    for (unsigned int k = 0; k <= n_cells; ++k)
      {
        const double s = double(k) / n_cells;
        knots[k]       = s + 0.25 * std::sin(numbers::PI * s) * (1. - s);
      }
    return knots;
  }

  template <int dim>
  double
  greville(const BSplines<dim> &splines, const unsigned int d, unsigned int i)
  {
    const auto        &knots = splines.breakpoints(d);
    const unsigned int p     = splines.degree();
    double             sum   = 0;
    for (unsigned int k = i + 1; k <= i + p; ++k)
      sum += knots[std::clamp<int>(int(k) - int(p), 0, knots.size() - 1)];
    return sum / p;
  }

  /**
   * Point properties on non-uniform knots.
   */
  template <int dim>
  void
  check_point_properties(const unsigned int p)
  {
    const unsigned int n_cells = 5;
    auto               simulator =
      make_unit_box_simulator<dim>(n_cells, "output-b-spline-grid");
    BSplines<dim> splines(p);
    splines.initialize(simulator->background_grid());
    std::array<std::vector<double>, dim> knots;
    for (unsigned int d = 0; d < dim; ++d)
      knots[d] = non_uniform_knots(n_cells);
    splines.move_breakpoints(knots);

    const unsigned int n_local = Utilities::fixed_power<dim>(p + 1);
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values(n_local), shifted(n_local);
    std::vector<Tensor<1, dim>>          gradients(n_local), unused(n_local);
    std::mt19937                         random(42);
    std::uniform_real_distribution<>     uniform(0.01, 0.99);

    double unity = 0, reproduction = 0, fd = 0, negative = 0;
    for (const auto &cell :
         simulator->background_grid().triangulation().active_cell_iterators())
      {
        splines.functions_on_cell(cell, indices);
        const auto &first = splines.first_function(cell);
        for (unsigned int sample = 0; sample < 4; ++sample)
          {
            Point<dim> xi;
            for (unsigned int d = 0; d < dim; ++d)
              xi[d] = uniform(random);
            splines.cell_values(cell, xi, values.data(), gradients.data());
            double         sum = 0;
            Tensor<1, dim> marsden;
            for (unsigned int a = 0; a < n_local; ++a)
              {
                sum += values[a];
                negative          = std::min(negative, values[a]);
                unsigned int rest = a;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    marsden[d] +=
                      values[a] *
                      greville(splines, d, first[d] + rest % (p + 1));
                    rest /= p + 1;
                  }
              }
            unity = std::max(unity, std::abs(sum - 1.));
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double h = knots[d][first[d] + 1] - knots[d][first[d]];
                const double x = knots[d][first[d]] + xi[d] * h;
                reproduction = std::max(reproduction, std::abs(marsden[d] - x));

                // Central difference in x_d with step eps.
                const double eps  = 1e-6;
                Point<dim>   plus = xi, minus = xi;
                plus[d] += eps / h;
                minus[d] -= eps / h;
                splines.cell_values(cell, plus, shifted.data(), unused.data());
                std::vector<double> backward(n_local);
                splines.cell_values(cell,
                                    minus,
                                    backward.data(),
                                    unused.data());
                for (unsigned int a = 0; a < n_local; ++a)
                  fd =
                    std::max(fd,
                             std::abs((shifted[a] - backward[a]) / (2 * eps) -
                                      gradients[a][d]));
              }
          }
      }
    deallog << dim << "D p = " << p << ": |sum - 1| " << (unity < 1e-14)
            << ", min value >= 0 " << (negative >= 0.) << ", Marsden identity "
            << (reproduction < 1e-14) << ", finite differences " << (fd < 1e-6)
            << std::endl;
    check(unity < 1e-14, "partition of unity: " + rounded(unity));
    check(negative >= 0., "non-negativity: " + rounded(negative));
    check(reproduction < 1e-14, "Marsden identity: " + rounded(reproduction));
    check(fd < 1e-6, "gradients vs finite differences: " + rounded(fd));
  }

  /**
   * C^(p-1) continuity across the interior knots of a 1D non-uniform knot
   * vector: the functions of span j at t = 1 against those of span j + 1 at
   * t = 0.
   */
  void
  check_continuity(const unsigned int p)
  {
    const unsigned int n_cells = 6;
    auto               simulator =
      make_unit_box_simulator<1>(n_cells, "output-b-spline-grid");
    BSplines<1> splines(p);
    splines.initialize(simulator->background_grid());
    splines.move_breakpoints({{non_uniform_knots(n_cells)}});
    const auto &knots = splines.breakpoints(0);

    // Values and first derivatives of all functions at x from span j.
    const auto all = [&](const unsigned int j, const double t) {
      std::vector<double> values(p + 1), derivatives(p + 1);
      splines.values_1d(0, j, t, values.data(), derivatives.data());
      std::vector<double> value(n_cells + p), derivative(n_cells + p);
      for (unsigned int a = 0; a <= p; ++a)
        {
          value[j + a]      = values[a];
          derivative[j + a] = derivatives[a];
        }
      return std::make_pair(value, derivative);
    };
    double jump_value = 0, jump_derivative = 0, jump_second = 0,
           largest_first = 0, largest_second = 0;
    for (unsigned int j = 0; j + 1 < n_cells; ++j)
      {
        const auto   left     = all(j, 1.);
        const auto   right    = all(j + 1, 0.);
        const double eps      = 1e-5;
        const auto   left_in  = all(j, 1. - eps / (knots[j + 1] - knots[j]));
        const auto   right_in = all(j + 1, eps / (knots[j + 2] - knots[j + 1]));
        for (unsigned int i = 0; i < n_cells + p; ++i)
          {
            jump_value =
              std::max(jump_value, std::abs(left.first[i] - right.first[i]));
            largest_first = std::max(largest_first, std::abs(left.second[i]));
            jump_derivative =
              std::max(jump_derivative,
                       std::abs(left.second[i] - right.second[i]));
            const double second_left =
              (left.second[i] - left_in.second[i]) / eps;
            const double second_right =
              (right_in.second[i] - right.second[i]) / eps;
            largest_second = std::max(largest_second, std::abs(second_left));
            jump_second =
              std::max(jump_second, std::abs(second_left - second_right));
          }
      }
    deallog << "1D p = " << p << ": value jump " << (jump_value < 1e-14);
    check(jump_value < 1e-14, "C0: " + rounded(jump_value));
    if (p >= 2)
      {
        deallog << ", derivative jump " << (jump_derivative < 1e-12);
        check(jump_derivative < 1e-12 * largest_first,
              "C1: " + rounded(jump_derivative));
      }
    else
      {
        // Linear B-splines have kinks: the derivative must jump.
        deallog << ", derivative jumps " << (jump_derivative > 1.);
        check(jump_derivative > 1., "P1 kinks: " + rounded(jump_derivative));
      }
    if (p >= 3)
      {
        // One-sided differences of the derivative: O(eps) error.
        deallog << ", second-derivative jump small "
                << (jump_second < 1e-3 * largest_second);
        check(jump_second < 1e-3 * largest_second,
              "C2: " + rounded(jump_second));
      }
    else if (p == 2)
      {
        deallog << ", second derivative jumps "
                << (jump_second > 0.1 * largest_second);
        check(jump_second > 0.1 * largest_second,
              "quadratic splines are only C1: " + rounded(jump_second));
      }
    deallog << std::endl;
  }

  /**
   * L2 projection of f = prod_d sin(pi x_d + 0.3) onto the splines on
   * uniform knots with n cells per direction: returns the L2 error. Also
   * checks that the Bernstein form written for output (to_cell_dofs) is the
   * same field.
   */
  template <int dim>
  double
  projection_error(const unsigned int p, const unsigned int n_cells)
  {
    auto simulator =
      make_unit_box_simulator<dim>(n_cells, "output-b-spline-grid");
    const auto   &tria = simulator->background_grid().triangulation();
    BSplines<dim> splines(p);
    splines.initialize(simulator->background_grid());
    const auto f = [](const Point<dim> &x) {
      double value = 1.;
      for (unsigned int d = 0; d < dim; ++d)
        value *= std::sin(numbers::PI * x[d] + 0.3);
      return value;
    };

    const unsigned int          n = splines.n_functions();
    FullMatrix<double>          mass(n, n);
    dealii::Vector<double>      rhs(n), coefficients(n);
    const QGauss<dim>           quadrature(p + 2);
    const MappingCartesian<dim> mapping;
    const unsigned int          n_local = Utilities::fixed_power<dim>(p + 1);
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values(n_local);
    std::vector<Tensor<1, dim>>          gradients(n_local);

    const auto integrate = [&](const auto &visit) {
      for (const auto &cell : tria.active_cell_iterators())
        {
          splines.functions_on_cell(cell, indices);
          const double volume = cell->measure();
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<dim> xi = quadrature.point(q);
              splines.cell_values(cell, xi, values.data(), gradients.data());
              const Point<dim> x =
                mapping.transform_unit_to_real_cell(cell, xi);
              visit(cell, q, x, quadrature.weight(q) * volume);
            }
        }
    };
    integrate([&](const auto &, unsigned int, const Point<dim> &x, double JxW) {
      for (unsigned int a = 0; a < n_local; ++a)
        {
          rhs(indices[a]) += values[a] * f(x) * JxW;
          for (unsigned int b = 0; b < n_local; ++b)
            mass(indices[a], indices[b]) += values[a] * values[b] * JxW;
        }
    });
    mass.gauss_jordan();
    mass.vmult(coefficients, rhs);

    double error = 0;
    integrate([&](const auto &, unsigned int, const Point<dim> &x, double JxW) {
      double value = 0;
      for (unsigned int a = 0; a < n_local; ++a)
        value += values[a] * coefficients(indices[a]);
      error += (value - f(x)) * (value - f(x)) * JxW;
    });

    // The Bernstein form of the projection on the cells' FE_Bernstein(p).
    typename ShapeFunctions<dim>::VectorType distributed(complete_index_set(n),
                                                         complete_index_set(n),
                                                         MPI_COMM_SELF);
    for (unsigned int i = 0; i < n; ++i)
      distributed(i) = coefficients(i);
    typename ShapeFunctions<dim>::VectorType bernstein;
    splines.to_cell_dofs(distributed, bernstein);
    FEValues<dim>       fe_values(mapping,
                            splines.dof_handler().get_fe(),
                            quadrature,
                            update_values);
    std::vector<double> field(quadrature.size());
    double              difference = 0;
    for (const auto &cell : splines.dof_handler().active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values.get_function_values(bernstein, field);
        splines.functions_on_cell(cell, indices);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            splines.cell_values(cell,
                                quadrature.point(q),
                                values.data(),
                                gradients.data());
            double value = 0;
            for (unsigned int a = 0; a < n_local; ++a)
              value += values[a] * coefficients(indices[a]);
            difference = std::max(difference, std::abs(value - field[q]));
          }
      }
    check(difference < 1e-12,
          "Bernstein output differs from the spline field by " +
            rounded(difference));
    return std::sqrt(error);
  }

  template <int dim>
  void
  check_projection(const unsigned int p, const std::vector<unsigned int> &cells)
  {
    std::vector<double> errors;
    deallog << dim << "D p = " << p << " L2 projection errors:";
    for (const unsigned int n : cells)
      {
        errors.push_back(projection_error<dim>(p, n));
        deallog << " " << rounded(errors.back(), 2);
      }
    const double rate = std::log2(errors[errors.size() - 2] / errors.back());
    deallog << ", last rate " << std::fixed << std::setprecision(1) << rate
            << std::defaultfloat << std::endl;
    check(std::abs(rate - (p + 1.)) < 0.15,
          "projection rate " + std::to_string(rate) + " instead of " +
            std::to_string(p + 1));
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (unsigned int p = 1; p <= 3; ++p)
    {
      check_point_properties<1>(p);
      check_point_properties<2>(p);
      check_point_properties<3>(p);
      check_continuity(p);
    }
  for (unsigned int p = 1; p <= 3; ++p)
    check_projection<1>(p, {8, 16, 32});
  for (unsigned int p = 1; p <= 3; ++p)
    check_projection<2>(p, {4, 8, 16});
}
