#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <mpm_otm/shape_functions/l2_projection.h>
#include <mpm_otm/shape_functions/linear_lagrange.h>
#include <mpm_otm/shape_functions/powell_sabin.h>

#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace MpmOtm
{
  namespace
  {
    using Cell = Triangulation<2>::active_cell_iterator;

    /**
     * A rule on the reference triangle: barycentric points and weights that
     * sum to 1.
     */
    struct Rule
    {
      std::vector<std::array<double, 3>> points;
      std::vector<double>                weights;
    };

    /**
     * The 7-point rule of degree 5 (Radon): the centroid and two orbits
     * (a, a, 1 - 2a).
     */
    Rule
    radon_rule()
    {
      const double s  = std::sqrt(15.);
      const double a1 = (6. - s) / 21., a2 = (6. + s) / 21.;
      const double w1 = (155. - s) / 1200., w2 = (155. + s) / 1200.;
      Rule         rule;
      rule.points  = {{{1. / 3, 1. / 3, 1. / 3}}};
      rule.weights = {9. / 40.};
      for (const auto &[a, w] :
           {std::make_pair(a1, w1), std::make_pair(a2, w2)})
        for (unsigned int i = 0; i < 3; ++i)
          {
            std::array<double, 3> point = {{a, a, a}};
            point[i]                    = 1. - 2. * a;
            rule.points.push_back(point);
            rule.weights.push_back(w);
          }
      return rule;
    }

    /**
     * deal.II's collapsed Gauss rule (QDuffy) with @p n points per
     * direction, area-normalised.
     */
    Rule
    collapsed_rule(const unsigned int n)
    {
      const QDuffy quadrature(n, 1.);
      Rule         rule;
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const Point<2> &p = quadrature.point(q);
          rule.points.push_back({{1. - p[0] - p[1], p[0], p[1]}});
          rule.weights.push_back(2. * quadrature.weight(q));
        }
      return rule;
    }

    double
    twice_signed_area(const Point<2> &a, const Point<2> &b, const Point<2> &c)
    {
      return (b - a)[0] * (c - a)[1] - (b - a)[1] * (c - a)[0];
    }

    /**
     * Reference coordinates of @p x in the affine triangle @p cell.
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
     * A space as the projection sees it: the functions of a cell, the
     * triangles (pieces) of the cell on which they are polynomials, and
     * their values on a piece.
     */
    class Space
    {
    public:
      virtual ~Space() = default;

      virtual types::global_dof_index
      n_functions() const = 0;

      virtual unsigned int
      n_cell_functions() const = 0;

      virtual void
      cell_functions(const Cell                           &cell,
                     std::vector<types::global_dof_index> &functions) const = 0;

      virtual std::vector<std::array<Point<2>, 3>>
      pieces(const Cell &cell) const = 0;

      /**
       * Values of the functions of cell_functions() at the point with
       * reference coordinates @p xi, with the polynomial of piece @p piece.
       */
      virtual void
      values(const Cell        &cell,
             const unsigned int piece,
             const Point<2>    &xi,
             double            *values) const = 0;
    };

    /**
     * P1: one function per vertex, numbered as the vertices; one piece, the
     * cell. Values from LinearLagrange.
     */
    class LinearSpace : public Space
    {
    public:
      explicit LinearSpace(const Triangulation<2> &triangulation)
        : size(triangulation.n_vertices())
      {}

      types::global_dof_index
      n_functions() const override
      {
        return size;
      }

      unsigned int
      n_cell_functions() const override
      {
        return 3;
      }

      void
      cell_functions(
        const Cell                           &cell,
        std::vector<types::global_dof_index> &functions) const override
      {
        functions.resize(3);
        for (unsigned int k = 0; k < 3; ++k)
          functions[k] = cell->vertex_index(k);
      }

      std::vector<std::array<Point<2>, 3>>
      pieces(const Cell &cell) const override
      {
        return {{{cell->vertex(0), cell->vertex(1), cell->vertex(2)}}};
      }

      void
      values(const Cell &,
             const unsigned int,
             const Point<2> &xi,
             double         *values) const override
      {
        Tensor<1, 2> gradients[3];
        LinearLagrange<2>::reference_values(true, xi, values, gradients);
      }

    private:
      types::global_dof_index size;
    };

    /**
     * Quadratic Powell-Sabin splines: nine functions per cell, six pieces
     * T_{k,half} = (V_k, R_k, Z) / (R_k, V_{k+1}, Z) numbered 2 k + half.
     */
    class PowellSabinSpace : public Space
    {
    public:
      explicit PowellSabinSpace(const Triangulation<2> &triangulation)
      {
        basis.initialize(triangulation);
      }

      types::global_dof_index
      n_functions() const override
      {
        return basis.n_functions();
      }

      unsigned int
      n_cell_functions() const override
      {
        return PowellSabin<2>::n_cell_functions;
      }

      void
      cell_functions(
        const Cell                           &cell,
        std::vector<types::global_dof_index> &functions) const override
      {
        const auto &indices = basis.cell_functions(cell);
        functions.assign(indices.begin(), indices.end());
      }

      std::vector<std::array<Point<2>, 3>>
      pieces(const Cell &cell) const override
      {
        const Point<2>                       z = basis.split_point(cell, 3);
        std::vector<std::array<Point<2>, 3>> result;
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Point<2> r = basis.split_point(cell, k);
            result.push_back({{cell->vertex(k), r, z}});
            result.push_back({{r, cell->vertex((k + 1) % 3), z}});
          }
        return result;
      }

      void
      values(const Cell        &cell,
             const unsigned int piece,
             const Point<2>    &xi,
             double            *values) const override
      {
        Tensor<1, 2> gradients[PowellSabin<2>::n_cell_functions];
        basis.cell_values(cell, xi, values, gradients, piece);
      }

    private:
      PowellSabin<2> basis;
    };

    /**
     * Call @p at_point(functions, values, x, weight) for every point x of
     * @p rule on every piece of every cell, with the cell's functions and
     * their values at x, and @p after_cell(functions) after the last point
     * of each cell.
     */
    template <typename PointAction, typename CellAction>
    void
    for_each_point(const Space            &space,
                   const Triangulation<2> &triangulation,
                   const Rule             &rule,
                   const PointAction      &at_point,
                   const CellAction       &after_cell)
    {
      std::vector<types::global_dof_index> functions;
      std::vector<double>                  values;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          space.cell_functions(cell, functions);
          values.resize(functions.size());
          const auto pieces = space.pieces(cell);
          for (unsigned int piece = 0; piece < pieces.size(); ++piece)
            {
              const auto  &t = pieces[piece];
              const double area =
                0.5 * std::abs(twice_signed_area(t[0], t[1], t[2]));
              for (unsigned int q = 0; q < rule.points.size(); ++q)
                {
                  const auto    &l = rule.points[q];
                  const Point<2> x = l[0] * t[0] + l[1] * t[1] + l[2] * t[2];
                  space.values(cell,
                               piece,
                               reference_point(cell, x),
                               values.data());
                  at_point(functions, values, x, rule.weights[q] * area);
                }
            }
          after_cell(functions);
        }
    }
  } // namespace



  void
  make_b4_grid(Triangulation<2>  &triangulation,
               const unsigned int n,
               const double       perturbation,
               const unsigned int seed)
  {
    AssertThrow(n >= 2,
                ExcMessage("The B4 grid needs n >= 2 vertices per side."));
    AssertThrow(perturbation >= 0. && perturbation < 0.5,
                ExcMessage("The B4 grid perturbation must be in [0, 0.5)."));
    const double             h = 1. / (n - 1);
    std::mt19937             generator(seed);
    std::vector<Point<2>>    vertices;
    std::vector<CellData<2>> cells;
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          // Both numbers are drawn for every vertex, so that vertex (i, j)
          // gets the same ones whichever vertices move.
          double shift[2];
          for (double &s : shift)
            s = perturbation * h * (2. * generator() / 4294967296. - 1.);
          vertices.emplace_back(i * h + (i > 0 && i + 1 < n ? shift[0] : 0.),
                                j * h + (j > 0 && j + 1 < n ? shift[1] : 0.));
        }
    for (unsigned int j = 0; j + 1 < n; ++j)
      for (unsigned int i = 0; i + 1 < n; ++i)
        {
          const unsigned int a = j * n + i;
          CellData<2>        first(3), second(3);
          first.vertices  = {a, a + 1, a + n + 1};
          second.vertices = {a, a + n + 1, a + n};
          for (const auto &cell : {first, second})
            AssertThrow(twice_signed_area(vertices[cell.vertices[0]],
                                          vertices[cell.vertices[1]],
                                          vertices[cell.vertices[2]]) > 0.,
                        ExcMessage("The B4 grid perturbation " +
                                   std::to_string(perturbation) +
                                   " inverts a triangle: choose a smaller "
                                   "one or another seed."));
          cells.push_back(first);
          cells.push_back(second);
        }
    triangulation.clear();
    triangulation.create_triangulation(vertices, cells, SubCellData());
  }



  ProjectionError
  l2_projection_error(const Triangulation<2> &triangulation,
                      const ProjectionSpace   space_type,
                      const std::function<double(const Point<2> &)> &f)
  {
    AssertThrow(triangulation.all_reference_cells_are_simplex(),
                ExcMessage("The L2 projection needs a triangulation of "
                           "triangles."));
    std::unique_ptr<Space> space;
    if (space_type == ProjectionSpace::powell_sabin)
      space = std::make_unique<PowellSabinSpace>(triangulation);
    else
      space = std::make_unique<LinearSpace>(triangulation);
    const types::global_dof_index size = space->n_functions();

    DynamicSparsityPattern               couplings(size);
    std::vector<types::global_dof_index> functions;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        space->cell_functions(cell, functions);
        for (const auto i : functions)
          for (const auto j : functions)
            couplings.add(i, j);
      }
    SparsityPattern sparsity;
    sparsity.copy_from(couplings);
    SparseMatrix<double> mass(sparsity);
    Vector<double>       coefficients(size);

    // Cell by cell: the local mass matrix, then one sparse addition.
    const unsigned int m = space->n_cell_functions();
    FullMatrix<double> local_mass(m, m);
    Vector<double>     local_rhs(m);
    for_each_point(
      *space,
      triangulation,
      radon_rule(),
      [&](const std::vector<types::global_dof_index> &,
          const std::vector<double> &values,
          const Point<2>            &x,
          const double               weight) {
        const double fx = f(x);
        for (unsigned int i = 0; i < m; ++i)
          {
            local_rhs(i) += weight * fx * values[i];
            for (unsigned int j = 0; j < m; ++j)
              local_mass(i, j) += weight * values[i] * values[j];
          }
      },
      [&](const std::vector<types::global_dof_index> &functions) {
        mass.add(functions, local_mass);
        for (unsigned int i = 0; i < m; ++i)
          coefficients(functions[i]) += local_rhs(i);
        local_mass = 0.;
        local_rhs  = 0.;
      });
    SparseDirectUMFPACK solver;
    solver.initialize(mass);
    solver.solve(coefficients);

    double error = 0;
    for_each_point(
      *space,
      triangulation,
      collapsed_rule(8),
      [&](const std::vector<types::global_dof_index> &functions,
          const std::vector<double>                  &values,
          const Point<2>                             &x,
          const double                                weight) {
        double difference = -f(x);
        for (unsigned int i = 0; i < m; ++i)
          difference += coefficients(functions[i]) * values[i];
        error += weight * difference * difference;
      },
      [](const std::vector<types::global_dof_index> &) {});
    return {size, std::sqrt(error)};
  }
} // namespace MpmOtm
