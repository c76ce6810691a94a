#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <mpm_otm/shape_functions/fe_powell_sabin.h>
#include <mpm_otm/shape_functions/l2_projection.h>

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
     * A space as the projection sees it: a finite element on the
     * triangulation (FE_SimplexP(1) or FE_PowellSabin) and the triangles
     * (pieces) of a cell on which its functions are polynomials: the cell,
     * or the six sub-triangles T_{k,half} = (V_k, R_k, Z) / (R_k, V_{k+1},
     * Z) of the Powell-Sabin refinement.
     */
    class Space
    {
    public:
      Space(const Triangulation<2> &triangulation, const ProjectionSpace type)
      {
        if (type == ProjectionSpace::powell_sabin)
          {
            auto              splines = std::make_shared<PowellSabinGeometry>();
            const std::string problem = splines->reinit(triangulation);
            AssertThrow(problem.empty(),
                        ExcMessage("Powell-Sabin: " + problem));
            geometry = splines;
            fe       = std::make_unique<FE_PowellSabin>(splines);
          }
        else
          fe = std::make_unique<FE_SimplexP<2>>(1);
        dof_handler.reinit(triangulation);
        dof_handler.distribute_dofs(*fe);
      }

      std::vector<std::array<Point<2>, 3>>
      pieces(const Triangulation<2>::cell_iterator &cell) const
      {
        if (geometry == nullptr)
          return {{{cell->vertex(0), cell->vertex(1), cell->vertex(2)}}};
        const Point<2>                       z = geometry->split_point(cell, 3);
        std::vector<std::array<Point<2>, 3>> result;
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Point<2> r = geometry->split_point(cell, k);
            result.push_back({{cell->vertex(k), r, z}});
            result.push_back({{r, cell->vertex((k + 1) % 3), z}});
          }
        return result;
      }

      std::shared_ptr<const PowellSabinGeometry> geometry;
      std::unique_ptr<FiniteElement<2>>          fe;
      DoFHandler<2>                              dof_handler;
    };

    /**
     * Call @p at_point(functions, fe_values, q) for every point q of
     * @p rule on every piece of every cell, with the cell's functions and
     * their values in @p fe_values (an FEValues object on the cell's
     * composite rule), and @p after_cell(functions) after the last point
     * of each cell.
     */
    template <typename PointAction, typename CellAction>
    void
    for_each_point(const Space       &space,
                   const Rule        &rule,
                   const PointAction &at_point,
                   const CellAction  &after_cell)
    {
      const MappingFE<2>                   mapping(FE_SimplexP<2>(1));
      std::vector<types::global_dof_index> functions(
        space.fe->n_dofs_per_cell());
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        {
          // The rule on every piece, in the cell's reference coordinates,
          // with the weights of the reference triangle (area 1/2).
          const double cell_area = 0.5 * twice_signed_area(cell->vertex(0),
                                                           cell->vertex(1),
                                                           cell->vertex(2));
          std::vector<Point<2>> points;
          std::vector<double>   weights;
          for (const auto &t : space.pieces(cell))
            {
              const double area =
                0.5 * std::abs(twice_signed_area(t[0], t[1], t[2]));
              for (unsigned int q = 0; q < rule.points.size(); ++q)
                {
                  const auto &l = rule.points[q];
                  points.push_back(
                    reference_point(cell,
                                    l[0] * t[0] + l[1] * t[1] + l[2] * t[2]));
                  weights.push_back(rule.weights[q] * area / (2. * cell_area));
                }
            }
          FEValues<2> fe_values(mapping,
                                *space.fe,
                                Quadrature<2>(points, weights),
                                update_values | update_JxW_values |
                                  update_quadrature_points);
          fe_values.reinit(cell);
          cell->get_dof_indices(functions);
          for (unsigned int q = 0; q < points.size(); ++q)
            at_point(functions, fe_values, q);
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
    const Space                   space(triangulation, space_type);
    const types::global_dof_index size = space.dof_handler.n_dofs();

    DynamicSparsityPattern couplings(size);
    DoFTools::make_sparsity_pattern(space.dof_handler, couplings);
    SparsityPattern sparsity;
    sparsity.copy_from(couplings);
    SparseMatrix<double> mass(sparsity);
    Vector<double>       coefficients(size);

    // Cell by cell: the local mass matrix, then one sparse addition.
    const unsigned int m = space.fe->n_dofs_per_cell();
    FullMatrix<double> local_mass(m, m);
    Vector<double>     local_rhs(m);
    for_each_point(
      space,
      radon_rule(),
      [&](const std::vector<types::global_dof_index> &,
          const FEValues<2> &fe_values,
          const unsigned int q) {
        const double weight = fe_values.JxW(q);
        const double fx     = f(fe_values.quadrature_point(q));
        for (unsigned int i = 0; i < m; ++i)
          {
            const double phi_i = fe_values.shape_value(i, q);
            local_rhs(i) += weight * fx * phi_i;
            for (unsigned int j = 0; j < m; ++j)
              local_mass(i, j) += weight * phi_i * fe_values.shape_value(j, q);
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
      space,
      collapsed_rule(8),
      [&](const std::vector<types::global_dof_index> &functions,
          const FEValues<2>                          &fe_values,
          const unsigned int                          q) {
        double difference = -f(fe_values.quadrature_point(q));
        for (unsigned int i = 0; i < m; ++i)
          difference +=
            coefficients(functions[i]) * fe_values.shape_value(i, q);
        error += fe_values.JxW(q) * difference * difference;
      },
      [](const std::vector<types::global_dof_index> &) {});
    return {size, std::sqrt(error)};
  }
} // namespace MpmOtm
