// Quadratic Powell-Sabin splines (thesis Sect. 3.5) on the unit square cut
// into triangles by parallel diagonals (the B4 grid) and on a perturbed,
// unstructured triangulation (interior vertices moved by up to 30 % of the
// spacing, boundary vertices slid along their side by up to 25 %, random
// diagonals), checked against properties that hold exactly, at random
// points in every cell and at points on every macro edge:
// - non-negativity, partition of unity (values and gradients);
// - reproduction of 1, x, y, x^2, xy, y^2 (values and gradients, 1e-12)
//   with the coefficients c_v^q = g(V) + grad g(V) . (Q_v^q - V) (the
//   tangent plane of g at V at the control points; thesis Eqs. 3.38-3.46);
// - gradients against central finite differences (of the quadratic of
//   every sub-triangle, so that no difference straddles a sub-edge);
// - C1 continuity: value and gradient jumps of every function below 1e-10
//   across every interior macro edge (the point evaluated in both cells)
//   and every sub-triangle edge inside a cell (the two neighbouring
//   quadratics evaluated on it);
// - every control triangle contains its vertex's Powell-Sabin points;
// - Dirichlet conditions (thesis Sect. 3.5.4): make_boundary_constraints()
//   constrains exactly the functions of boundary_functions(), two per
//   vertex of a side; with the constrained coefficients set to their
//   inhomogeneities for a quadratic g (all others random) the field and its
//   tangential derivative equal g's along the whole side (g = 0 is the
//   homogeneous case the simulator uses);
// - the control triangle of the centre vertex of the 3 x 3 grid and the
//   values of its functions at (0.4, 0.45) equal those of an independent
//   implementation of the same rule (a Python prototype written when this
//   class was designed, not part of the repository), to 1e-6
//   and 1e-10.
// Through the simulator (Shape functions = Powell-Sabin on the B5 grid of
// four triangles per block, 4 x 1 blocks on 25 x 2), evaluate() at the
// material points gives the same partition of unity and quadratic
// reproduction.

#include <deal.II/grid/tria.h>

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/powell_sabin.h>

#include <map>
#include <random>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

using Cell = Triangulation<2>::active_cell_iterator;

/**
 * Dirichlet data g = 1 + 2x - y + x^2 + 3xy - 2y^2 with its gradient.
 */
class QuadraticBoundaryValues : public Function<2>
{
public:
  double
  value(const Point<2> &x, const unsigned int = 0) const override
  {
    return 1 + 2 * x[0] - x[1] + x[0] * x[0] + 3 * x[0] * x[1] -
           2 * x[1] * x[1];
  }

  Tensor<1, 2>
  gradient(const Point<2> &x, const unsigned int = 0) const override
  {
    return Tensor<1, 2>({2 + 2 * x[0] + 3 * x[1], -1 + 3 * x[0] - 4 * x[1]});
  }
};

/**
 * n x n vertices on the unit square, squares cut along the diagonal from
 * lower left to upper right, or (perturbed) along a random diagonal with
 * the vertices moved; boundary ids 0..3 for x = 0, x = 1, y = 0, y = 1.
 */
void
make_grid(Triangulation<2> &tria, const unsigned int n, const bool perturbed)
{
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  const double                           h = 1. / (n - 1);
  std::vector<Point<2>>                  vertices;
  for (unsigned int j = 0; j < n; ++j)
    for (unsigned int i = 0; i < n; ++i)
      {
        Point<2>   x(i * h, j * h);
        const bool side_x = (i == 0 || i == n - 1),
                   side_y = (j == 0 || j == n - 1);
        if (perturbed && !side_x)
          x[0] += (side_y ? 0.25 : 0.3) * h * uniform(random);
        if (perturbed && !side_y)
          x[1] += (side_x ? 0.25 : 0.3) * h * uniform(random);
        vertices.push_back(x);
      }
  std::vector<CellData<2>> cells;
  for (unsigned int j = 0; j + 1 < n; ++j)
    for (unsigned int i = 0; i + 1 < n; ++i)
      {
        const unsigned int a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
        CellData<2>        first(3), second(3);
        if (!perturbed || uniform(random) > 0)
          {
            first.vertices  = {a, b, c};
            second.vertices = {a, c, d};
          }
        else
          {
            first.vertices  = {a, b, d};
            second.vertices = {b, c, d};
          }
        cells.push_back(first);
        cells.push_back(second);
      }
  tria.clear();
  tria.create_triangulation(vertices, cells, SubCellData());
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        {
          const Point<2> c = cell->face(f)->center();
          cell->face(f)->set_boundary_id(c[0] < 1e-12      ? 0 :
                                         c[0] > 1. - 1e-12 ? 1 :
                                         c[1] < 1e-12      ? 2 :
                                                             3);
        }
}

/**
 * The reference coordinates of @p x in @p cell (also outside it).
 */
Point<2>
reference_point(const Cell &cell, const Point<2> &x)
{
  Tensor<2, 2> jacobian;
  for (unsigned int d = 0; d < 2; ++d)
    for (unsigned int c = 0; c < 2; ++c)
      jacobian[c][d] = cell->vertex(d + 1)[c] - cell->vertex(0)[c];
  return Point<2>(invert(jacobian) * (x - cell->vertex(0)));
}

/**
 * Coefficients of the quadratic g_i, by global function index.
 */
std::vector<double>
quadratic_coefficients(const PowellSabin<2>   &basis,
                       const Triangulation<2> &tria,
                       const unsigned int      i)
{
  std::vector<double> coefficients(basis.n_functions());
  for (const auto &cell : tria.active_cell_iterators())
    for (unsigned int j = 0; j < 3; ++j)
      {
        const Point<2> &vertex   = cell->vertex(j);
        const auto [value, grad] = quadratic(i, vertex);
        for (unsigned int q = 0; q < 3; ++q)
          coefficients[basis.cell_functions(cell)[3 * j + q]] =
            value + grad * (basis.geometry().control_triangle(
                              cell->vertex_index(j))[q] -
                            vertex);
      }
  return coefficients;
}

/**
 * Worst deviations found by check_point().
 */
struct Deviations
{
  double       negative = 0, unity = 0, reproduction = 0, derivative = 0;
  unsigned int n_points = 0;
};

/**
 * The pointwise properties at @p x in @p cell.
 */
void
check_point(const PowellSabin<2>                   &basis,
            const std::vector<std::vector<double>> &quadratics,
            const Cell                             &cell,
            const Point<2>                         &x,
            Deviations                             &deviations)
{
  const unsigned int n = PowellSabin<2>::n_cell_functions;
  double             values[n];
  Tensor<1, 2>       gradients[n];
  basis.geometry().cell_values(cell,
                               reference_point(cell, x),
                               values,
                               gradients);
  const auto &functions = basis.cell_functions(cell);

  double       sum = 0;
  Tensor<1, 2> gradient_sum;
  for (unsigned int i = 0; i < n; ++i)
    {
      deviations.negative = std::max(deviations.negative, -values[i]);
      sum += values[i];
      gradient_sum += gradients[i];
    }
  deviations.unity =
    std::max({deviations.unity, std::abs(sum - 1.), gradient_sum.norm()});

  for (unsigned int g = 0; g < quadratics.size(); ++g)
    {
      double       value = 0;
      Tensor<1, 2> gradient;
      for (unsigned int i = 0; i < n; ++i)
        {
          value += quadratics[g][functions[i]] * values[i];
          gradient += quadratics[g][functions[i]] * gradients[i];
        }
      const auto [exact, exact_gradient] = quadratic(g, x);
      deviations.reproduction            = std::max({deviations.reproduction,
                                                     std::abs(value - exact),
                                                     (gradient - exact_gradient).norm()});
    }

  // Central differences with step delta of the quadratic of each
  // sub-triangle (extended beyond it): exact up to round-off (1e-16 / delta).
  const double delta = 1e-6;
  for (unsigned int sub = 0; sub < 6; ++sub)
    {
      double       unused[n];
      Tensor<1, 2> sub_gradients[n];
      basis.geometry().cell_values(cell,
                                   reference_point(cell, x),
                                   unused,
                                   sub_gradients,
                                   sub);
      for (unsigned int d = 0; d < 2; ++d)
        {
          double       plus[n], minus[n];
          Tensor<1, 2> ignored[n];
          Point<2>     shifted = x;
          shifted[d] += delta;
          basis.geometry().cell_values(cell,
                                       reference_point(cell, shifted),
                                       plus,
                                       ignored,
                                       sub);
          shifted[d] -= 2. * delta;
          basis.geometry().cell_values(cell,
                                       reference_point(cell, shifted),
                                       minus,
                                       ignored,
                                       sub);
          for (unsigned int i = 0; i < n; ++i)
            deviations.derivative =
              std::max(deviations.derivative,
                       std::abs((plus[i] - minus[i]) / (2. * delta) -
                                sub_gradients[i][d]));
        }
    }
  ++deviations.n_points;
}

/**
 * Largest value and gradient jump over all functions at @p x between
 * (cell_a, sub_a) and (cell_b, sub_b); a function of one cell that the other
 * does not have must vanish with its gradient.
 */
std::pair<double, double>
jump(const PowellSabin<2> &basis,
     const Cell           &cell_a,
     const unsigned int    sub_a,
     const Cell           &cell_b,
     const unsigned int    sub_b,
     const Point<2>       &x)
{
  const unsigned int n = PowellSabin<2>::n_cell_functions;
  std::map<types::global_dof_index, std::pair<double, Tensor<1, 2>>> difference;
  for (const auto &[cell, sub, sign] : {std::make_tuple(cell_a, sub_a, 1.),
                                        std::make_tuple(cell_b, sub_b, -1.)})
    {
      double       values[n];
      Tensor<1, 2> gradients[n];
      basis.geometry().cell_values(cell,
                                   reference_point(cell, x),
                                   values,
                                   gradients,
                                   sub);
      for (unsigned int i = 0; i < n; ++i)
        {
          auto &entry = difference[basis.cell_functions(cell)[i]];
          entry.first += sign * values[i];
          entry.second += sign * gradients[i];
        }
    }
  std::pair<double, double> largest(0., 0.);
  for (const auto &[function, entry] : difference)
    {
      largest.first  = std::max(largest.first, std::abs(entry.first));
      largest.second = std::max(largest.second, entry.second.norm());
    }
  return largest;
}

void
test_grid(const unsigned int n, const bool perturbed)
{
  Triangulation<2> tria;
  make_grid(tria, n, perturbed);
  PowellSabin<2> basis;
  basis.initialize(tria);
  check(basis.n_functions() == 3 * tria.n_vertices(),
        "three functions per vertex");

  std::vector<std::vector<double>> quadratics;
  for (unsigned int g = 0; g < 6; ++g)
    quadratics.push_back(quadratic_coefficients(basis, tria, g));

  // Random points in every cell, and points along every macro edge
  // (including its split point).
  std::mt19937                           random(3);
  std::uniform_real_distribution<double> uniform(0., 1.);
  Deviations                             deviations;
  double       macro_value_jump = 0, macro_gradient_jump = 0;
  double       sub_value_jump = 0, sub_gradient_jump = 0;
  unsigned int n_macro_points = 0, n_sub_points = 0;
  for (const auto &cell : tria.active_cell_iterators())
    {
      for (unsigned int p = 0; p < 20; ++p)
        {
          double a = uniform(random), b = uniform(random);
          if (a + b > 1.)
            {
              a = 1. - a;
              b = 1. - b;
            }
          check_point(basis,
                      quadratics,
                      cell,
                      cell->vertex(0) +
                        a * (cell->vertex(1) - cell->vertex(0)) +
                        b * (cell->vertex(2) - cell->vertex(0)),
                      deviations);
        }

      const Point<2> z = basis.geometry().split_point(cell, 3);
      for (unsigned int k = 0; k < 3; ++k)
        {
          const Point<2> &v0 = cell->vertex(k), &v1 = cell->vertex((k + 1) % 3);
          const Point<2>  r = basis.geometry().split_point(cell, k);
          // Macro edge k: points on it, in this cell and its neighbour.
          std::vector<Point<2>> edge_points = {r};
          for (unsigned int p = 0; p < 7; ++p)
            edge_points.push_back(v0 + ((p + 0.5) / 7.) * (v1 - v0));
          unsigned int f = 0;
          while (
            !(cell->face(f)->center().distance(v0 + 0.5 * (v1 - v0)) < 1e-12))
            ++f;
          for (const auto &x : edge_points)
            {
              check_point(basis, quadratics, cell, x, deviations);
              if (!cell->face(f)->at_boundary())
                {
                  const auto [value, gradient] =
                    jump(basis,
                         cell,
                         numbers::invalid_unsigned_int,
                         cell->neighbor(f),
                         numbers::invalid_unsigned_int,
                         x);
                  macro_value_jump    = std::max(macro_value_jump, value);
                  macro_gradient_jump = std::max(macro_gradient_jump, gradient);
                  ++n_macro_points;
                }
            }

          // Sub-edges inside the cell: V_k Z between T_{k-1,1} and T_{k,0},
          // R_k Z between T_{k,0} and T_{k,1}.
          const std::array<std::tuple<Point<2>, unsigned int, unsigned int>, 2>
            sub_edges = {
              {{v0, 2 * ((k + 2) % 3) + 1, 2 * k}, {r, 2 * k, 2 * k + 1}}};
          for (const auto &[start, sub_a, sub_b] : sub_edges)
            for (unsigned int p = 0; p < 5; ++p)
              {
                const auto [value, gradient] =
                  jump(basis,
                       cell,
                       sub_a,
                       cell,
                       sub_b,
                       start + ((p + 0.5) / 5.) * (z - start));
                sub_value_jump    = std::max(sub_value_jump, value);
                sub_gradient_jump = std::max(sub_gradient_jump, gradient);
                ++n_sub_points;
              }
        }
    }

  // Every control triangle contains its vertex's Powell-Sabin points.
  bool contained = true;
  for (const auto &cell : tria.active_cell_iterators())
    for (unsigned int j = 0; j < 3; ++j)
      {
        const auto &t =
          basis.geometry().control_triangle(cell->vertex_index(j));
        const Point<2> &v = cell->vertex(j);
        const Point<2>  z = basis.geometry().split_point(cell, 3);
        for (const Point<2> &p :
             {v,
              v + 0.5 * (z - v),
              v + 0.5 * (basis.geometry().split_point(cell, j) - v),
              v + 0.5 * (basis.geometry().split_point(cell, (j + 2) % 3) - v)})
          {
            const Tensor<2, 2> map({{t[1][0] - t[0][0], t[2][0] - t[0][0]},
                                    {t[1][1] - t[0][1], t[2][1] - t[0][1]}});
            const Tensor<1, 2> l = invert(map) * (p - t[0]);
            contained = contained && l[0] >= -1e-10 && l[1] >= -1e-10 &&
                        l[0] + l[1] <= 1. + 1e-10;
          }
      }

  // Dirichlet conditions u = g for a quadratic g, side by side: the
  // constrained coefficients are those of boundary_functions(id) (two per
  // vertex), the others random; along the side the field and its tangential
  // derivative must be g's.
  const QuadraticBoundaryValues g;
  double                        boundary_field = 0;
  bool                          two_per_vertex = true;
  for (types::boundary_id id = 0; id < 4; ++id)
    {
      const IndexSet            fixed = basis.boundary_functions(id);
      AffineConstraints<double> constraints;
      basis.make_boundary_constraints(id, g, constraints);
      constraints.close();
      std::vector<double> coefficients(basis.n_functions());
      bool same_set = constraints.n_constraints() == fixed.n_elements();
      for (unsigned int i = 0; i < coefficients.size(); ++i)
        {
          same_set =
            same_set && (constraints.is_constrained(i) == fixed.is_element(i));
          coefficients[i] = constraints.is_constrained(i) ?
                              constraints.get_inhomogeneity(i) :
                              uniform(random) - 0.5;
        }
      two_per_vertex =
        two_per_vertex && same_set && (fixed.n_elements() == 2 * n);
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
            {
              const Point<2> v0          = cell->face(f)->vertex(0),
                             v1          = cell->face(f)->vertex(1);
              const Tensor<1, 2> tangent = (v1 - v0) / v0.distance(v1);
              for (unsigned int p = 0; p <= 8; ++p)
                {
                  const Point<2> x = v0 + (p / 8.) * (v1 - v0);
                  double         values[PowellSabin<2>::n_cell_functions];
                  Tensor<1, 2>   gradients[PowellSabin<2>::n_cell_functions];
                  basis.geometry().cell_values(cell,
                                               reference_point(cell, x),
                                               values,
                                               gradients);
                  double value = 0, derivative = 0;
                  for (unsigned int i = 0; i < 9; ++i)
                    {
                      const double c =
                        coefficients[basis.cell_functions(cell)[i]];
                      value += c * values[i];
                      derivative += c * (gradients[i] * tangent);
                    }
                  boundary_field =
                    std::max({boundary_field,
                              std::abs(value - g.value(x)),
                              std::abs(derivative - g.gradient(x) * tangent)});
                }
            }
    }

  const std::string name = std::to_string(n) + " x " + std::to_string(n) +
                           (perturbed ? " perturbed" : " diagonal") + " grid";
  check(deviations.negative <= 1e-14, name + ": negative function");
  check(deviations.unity <= 1e-12, name + ": no partition of unity");
  check(deviations.reproduction <= 1e-12,
        name + ": quadratic not reproduced, error " +
          std::to_string(deviations.reproduction));
  check(deviations.derivative <= 1e-8,
        name + ": gradient differs from finite differences by " +
          std::to_string(deviations.derivative));
  check(macro_value_jump <= 1e-10 && macro_gradient_jump <= 1e-10,
        name + ": jump across a macro edge " + rounded(macro_value_jump) +
          ", gradient " + rounded(macro_gradient_jump));
  check(sub_value_jump <= 1e-10 && sub_gradient_jump <= 1e-10,
        name + ": jump across a sub-edge " + rounded(sub_value_jump) +
          ", gradient " + rounded(sub_gradient_jump));
  check(contained, name + ": Powell-Sabin point outside its control triangle");
  check(two_per_vertex, name + ": not two boundary functions per vertex");
  check(boundary_field <= 1e-12,
        name +
          ": boundary field or its tangential derivative differs from "
          "the Dirichlet data by " +
          rounded(boundary_field));
  deallog << name << ": " << deviations.n_points
          << " points: min phi >= -1e-14, partition of unity, quadratic "
             "reproduction to 1e-12, finite differences; C1 at "
          << n_macro_points << " macro-edge and " << n_sub_points
          << " sub-edge points (jumps <= 1e-10); control triangles contain "
             "their points; Dirichlet constraints: 2 per vertex, field and "
             "tangential derivative equal to the quadratic data on the side"
          << std::endl;

  if (n == 3 && !perturbed)
    {
      // Centre vertex (0.5, 0.5): vertex 4. Its two smallest candidates are
      // mirror images of equal area; the tie-break keeps the first in the
      // enumeration order, here a three-edge candidate with a corner at the
      // upper right. The
      // prototype's numbers: its values at the mirror point (0.6, 0.55) for
      // the mirror-image triangle.
      const auto    &t           = basis.geometry().control_triangle(4);
      const Point<2> expected[3] = {Point<2>(0.469670, 0.280330),
                                    Point<2>(0.926777, 0.926777),
                                    Point<2>(0.280330, 0.469670)};
      for (unsigned int q = 0; q < 3; ++q)
        check(t[q].distance(expected[q]) < 1e-6,
              "control triangle of (0.5, 0.5) differs from the prototype's");
      const double   expected_values[3] = {0.315000000000,
                                           0.111005050634,
                                           0.516923881554};
      const Point<2> x(0.4, 0.45);
      for (const auto &cell : tria.active_cell_iterators())
        {
          const Point<2> xi = reference_point(cell, x);
          if (xi[0] < 0 || xi[1] < 0 || xi[0] + xi[1] > 1)
            continue;
          double       values[PowellSabin<2>::n_cell_functions];
          Tensor<1, 2> gradients[PowellSabin<2>::n_cell_functions];
          basis.geometry().cell_values(cell, xi, values, gradients);
          for (unsigned int j = 0; j < 3; ++j)
            if (cell->vertex_index(j) == 4)
              for (unsigned int q = 0; q < 3; ++q)
                check(std::abs(values[3 * j + q] - expected_values[q]) < 1e-10,
                      "value at (0.4, 0.45) differs from the prototype's");
        }
      deallog << name
              << ": control triangle of (0.5, 0.5) and its functions at "
                 "(0.4, 0.45) as in the prototype"
              << std::endl;
    }
}

void
test_material_points()
{
  auto        simulator = make_simulator<2>("",
                                     R"(
set Dimension = 2
set Problem = custom
set Shape functions = Powell-Sabin
subsection Mesh
  set Cell type = simplex
  set Lower corner = 0, 0
  set Upper corner = 25, 2
  set Subdivisions = 4, 1
end
subsection Particles
  set Particles per cell = 4, 3
end
subsection Time
  set Time step = 1e-4
end
)",
                                     "output-material-points");
  const auto &basis =
    dynamic_cast<const PowellSabin<2> &>(simulator->shape_function_family());
  const auto          &tria = simulator->background_grid().triangulation();
  const auto          &partitioner = simulator->nodal_system().partitioner();
  const auto          &points      = simulator->material_points();
  ParticleShapeData<2> data;
  basis.evaluate(points, partitioner, data);

  double error = 0;
  for (unsigned int g = 0; g < 6; ++g)
    {
      // Scaled to the bar: g((x - 12.5) / 12.5, y / 2).
      std::vector<double> global(basis.n_functions());
      for (const auto &cell : tria.active_cell_iterators())
        for (unsigned int j = 0; j < 3; ++j)
          {
            const auto scale = [](const Point<2> &x) {
              return Point<2>((x[0] - 12.5) / 12.5, x[1] / 2.);
            };
            const Point<2> &vertex   = cell->vertex(j);
            const auto [value, grad] = quadratic(g, scale(vertex));
            for (unsigned int q = 0; q < 3; ++q)
              global[basis.cell_functions(cell)[3 * j + q]] =
                value + grad * (scale(basis.geometry().control_triangle(
                                  cell->vertex_index(j))[q]) -
                                scale(vertex));
          }
      ParticleShapeData<2>::Cursor cursor(data);
      for (const auto &particle : points.particle_handler())
        {
          double     value = 0, unity = 0;
          const auto point = cursor.next();
          for (unsigned int e = 0; e < point.n; ++e)
            {
              value += point.values[e] *
                       global[partitioner.local_to_global(point.indices[e])];
              unity += point.values[e];
            }
          const Point<2> x = particle.get_location();
          error            = std::max(
            {error,
                        std::abs(unity - 1.),
                        std::abs(
               value -
               quadratic(g, Point<2>((x[0] - 12.5) / 12.5, x[1] / 2.)).first)});
        }
    }
  check(error < 1e-12,
        "evaluate() at the material points: error " + rounded(error));
  deallog << "B5 grid, 4 x 1 blocks: evaluate() at " << points.n_global_points()
          << " material points: partition of unity, quadratic reproduction"
          << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  test_grid(3, false);
  test_grid(6, false);
  test_grid(7, true);
  test_material_points();
}
