#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/powell_sabin.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace MpmOtm
{
  namespace
  {
    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /**
     * Barycentric coordinates of @p p with respect to the triangle @p t.
     */
    std::array<double, 3>
    barycentric(const std::array<Point<2>, 3> &t, const Point<2> &p)
    {
      const double          d = cross(t[1] - t[0], t[2] - t[0]);
      std::array<double, 3> lambda;
      for (unsigned int q = 0; q < 3; ++q)
        lambda[q] = cross(t[(q + 1) % 3] - p, t[(q + 2) % 3] - p) / d;
      return lambda;
    }

    /**
     * Gradients of the barycentric coordinates of the triangle @p t
     * (thesis Eqs. 3.48-3.49 with the typos of Eqs. 3.50-3.52 corrected).
     */
    std::array<Tensor<1, 2>, 3>
    barycentric_gradients(const std::array<Point<2>, 3> &t)
    {
      const double                d = cross(t[1] - t[0], t[2] - t[0]);
      std::array<Tensor<1, 2>, 3> gradients;
      for (unsigned int q = 0; q < 3; ++q)
        {
          const Point<2> &b = t[(q + 1) % 3], &c = t[(q + 2) % 3];
          gradients[q][0] = (b[1] - c[1]) / d;
          gradients[q][1] = (c[0] - b[0]) / d;
        }
      return gradients;
    }

    double
    area(const std::array<Point<2>, 3> &t)
    {
      return 0.5 * std::abs(cross(t[1] - t[0], t[2] - t[0]));
    }

    bool
    contains_all(const std::array<Point<2>, 3> &t,
                 const std::vector<Point<2>>   &points)
    {
      for (const auto &p : points)
        for (const double lambda : barycentric(t, p))
          if (lambda < -1e-10)
            return false;
      return true;
    }

    /**
     * Intersection of the lines p1 + z v1 and p2 + z v2 (thesis
     * Eqs. 3.20-3.24); none if they are parallel.
     */
    std::optional<Point<2>>
    intersection(const Point<2>     &p1,
                 const Tensor<1, 2> &v1,
                 const Point<2>     &p2,
                 const Tensor<1, 2> &v2)
    {
      const double denominator = cross(v1, v2);
      if (std::abs(denominator) <= 1e-12 * v1.norm() * v2.norm())
        return std::nullopt;
      return p1 + (cross(p2 - p1, v2) / denominator) * v1;
    }

    /**
     * Convex hull of @p points, counter-clockwise from the lexicographically
     * smallest point, collinear points left out (Andrew's monotone chain).
     */
    std::vector<Point<2>>
    convex_hull(std::vector<Point<2>> points, const double tolerance)
    {
      const auto less = [](const Point<2> &a, const Point<2> &b) {
        return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
      };
      std::sort(points.begin(), points.end(), less);
      points.erase(std::unique(points.begin(), points.end()), points.end());
      std::vector<Point<2>> hull;
      const auto            chain = [&](const auto begin, const auto end) {
        const std::size_t start = hull.size();
        for (auto p = begin; p != end; ++p)
          {
            while (hull.size() >= start + 2 &&
                   cross(hull.back() - hull[hull.size() - 2],
                         *p - hull[hull.size() - 2]) <= tolerance)
              hull.pop_back();
            hull.push_back(*p);
          }
        hull.pop_back();
      };
      chain(points.begin(), points.end());
      chain(points.rbegin(), points.rend());
      return hull;
    }

    /**
     * The control triangle of a vertex @p vertex with Powell-Sabin points
     * @p points (thesis Sect. 3.5.2): among the triangles formed by three edges
     * of the points' convex hull, or by two and a third edge orthogonal to
     * their bisector through the farthest point, that contain all points and
     * use every hull edge through the vertex, the one of smallest area
     * (thesis Eq. 3.25). Candidates are enumerated in a fixed order and a
     * later one wins only if it is smaller by a relative 1e-10, so that the
     * choice among equal triangles is reproducible.
     */
    std::array<Point<2>, 3>
    smallest_control_triangle(const Point<2>              &vertex,
                              const std::vector<Point<2>> &points)
    {
      double h = 0;
      for (const auto &p : points)
        h = std::max(h, p.distance(vertex));
      const std::vector<Point<2>> hull = convex_hull(points, 1e-12 * h * h);
      const unsigned int          m    = hull.size();
      AssertThrow(m >= 3, ExcInternalError());
      std::vector<Tensor<1, 2>> direction(m);
      std::vector<bool>         required(m);
      Point<2>                  centre;
      for (unsigned int e = 0; e < m; ++e)
        {
          direction[e] = hull[(e + 1) % m] - hull[e];
          required[e]  = std::abs(cross(direction[e], vertex - hull[e])) <=
                        1e-10 * h * direction[e].norm();
          centre += hull[e] / double(m);
        }
      const auto uses_required = [&](const std::vector<unsigned int> &edges) {
        for (unsigned int e = 0; e < m; ++e)
          if (required[e] &&
              std::find(edges.begin(), edges.end(), e) == edges.end())
            return false;
        return true;
      };

      std::array<Point<2>, 3> best;
      double     best_area = std::numeric_limits<double>::infinity();
      const auto consider  = [&](const std::array<Point<2>, 3> &candidate) {
        const double candidate_area = area(candidate);
        if (candidate_area > 1e-14 * h * h &&
            candidate_area < best_area * (1. - 1e-10) &&
            contains_all(candidate, points))
          {
            best      = candidate;
            best_area = candidate_area;
          }
      };

      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = a + 1; b < m; ++b)
          for (unsigned int c = b + 1; c < m; ++c)
            if (uses_required({a, b, c}))
              {
                const auto ab =
                  intersection(hull[a], direction[a], hull[b], direction[b]);
                const auto bc =
                  intersection(hull[b], direction[b], hull[c], direction[c]);
                const auto ca =
                  intersection(hull[c], direction[c], hull[a], direction[a]);
                if (ab && bc && ca)
                  consider({{*ab, *bc, *ca}});
              }

      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = a + 1; b < m; ++b)
          if (uses_required({a, b}))
            {
              const auto apex =
                intersection(hull[a], direction[a], hull[b], direction[b]);
              if (!apex)
                continue;
              // Unit directions from the apex along both edges towards the
              // hull, their bisector (Eq. 3.26), and the third edge through
              // the point farthest along the bisector.
              std::array<Tensor<1, 2>, 2> u = {
                {direction[a] / direction[a].norm(),
                 direction[b] / direction[b].norm()}};
              for (auto &unit : u)
                if (unit * (centre - *apex) < 0)
                  unit = -unit;
              Tensor<1, 2> bisector = u[0] + u[1];
              if (bisector.norm() < 1e-14)
                continue;
              bisector /= bisector.norm();
              double distance = -std::numeric_limits<double>::infinity();
              for (const auto &p : points)
                distance = std::max(distance, (p - *apex) * bisector);
              if (u[0] * bisector <= 1e-14 || u[1] * bisector <= 1e-14)
                continue;
              consider({{*apex,
                         *apex + (distance / (u[0] * bisector)) * u[0],
                         *apex + (distance / (u[1] * bisector)) * u[1]}});
            }

      AssertThrow(best_area < std::numeric_limits<double>::infinity(),
                  ExcMessage("No Powell-Sabin control triangle found for the "
                             "vertex at " +
                             Utilities::to_string(vertex[0]) + ", " +
                             Utilities::to_string(vertex[1]) + "."));
      return best;
    }

    /**
     * Bernstein polynomials of degree 2 in the barycentric coordinates
     * @p sigma of a triangle, in the order (200, 020, 002, 110, 011, 101),
     * and their gradients from the gradients @p grad_sigma of the
     * coordinates.
     */
    void
    bernstein(const std::array<double, 3>       &sigma,
              const std::array<Tensor<1, 2>, 3> &grad_sigma,
              double *const                      values,
              Tensor<1, 2> *const                gradients)
    {
      const double s0 = sigma[0], s1 = sigma[1], s2 = sigma[2];
      values[0]    = s0 * s0;
      values[1]    = s1 * s1;
      values[2]    = s2 * s2;
      values[3]    = 2. * s0 * s1;
      values[4]    = 2. * s1 * s2;
      values[5]    = 2. * s0 * s2;
      gradients[0] = (2. * s0) * grad_sigma[0];
      gradients[1] = (2. * s1) * grad_sigma[1];
      gradients[2] = (2. * s2) * grad_sigma[2];
      gradients[3] = (2. * s1) * grad_sigma[0] + (2. * s0) * grad_sigma[1];
      gradients[4] = (2. * s2) * grad_sigma[1] + (2. * s1) * grad_sigma[2];
      gradients[5] = (2. * s2) * grad_sigma[0] + (2. * s0) * grad_sigma[2];
    }
  } // namespace



  template <int dim>
  void
  PowellSabin<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  PowellSabin<dim>::parse_parameters(ParameterHandler &)
  {
    AssertThrow(dim == 2,
                ExcMessage(
                  "Shape functions = Powell-Sabin needs Dimension = 2: "
                  "quadratic Powell-Sabin splines are defined on "
                  "triangulations (thesis Sect. 3.5). In 1D use Shape "
                  "functions = B-spline with B-spline degree = 2, their 1D "
                  "counterpart; 3D is not implemented."));
  }



  template <int dim>
  void
  PowellSabin<dim>::initialize(const BackgroundGrid<dim> &grid)
  {
    AssertThrow(grid.is_simplex(),
                ExcMessage("Shape functions = Powell-Sabin need Mesh/Cell "
                           "type = simplex (triangles), or a Mesh/Mesh file "
                           "of triangles."));
    initialize(grid.triangulation());
  }



  template <int dim>
  void
  PowellSabin<dim>::initialize(const Triangulation<dim> &)
  {
    AssertThrow(false, ExcNotImplemented());
  }



  template <>
  void
  PowellSabin<2>::initialize(const Triangulation<2> &triangulation)
  {
    AssertThrow(triangulation.all_reference_cells_are_simplex(),
                ExcMessage("Powell-Sabin splines need a triangulation of "
                           "triangles."));
    fe = std::make_unique<FE_SimplexP<2>>(1);
    vertex_dofs.reinit(triangulation);
    vertex_dofs.distribute_dofs(*fe);

    // Incentres (thesis 3.5.1): a_k = |edge opposite V_k| / perimeter.
    cell_data.resize(triangulation.n_active_cells());
    std::vector<Point<2>> incentre(triangulation.n_active_cells());
    for (const auto &cell : vertex_dofs.active_cell_iterators())
      if (!cell->is_artificial())
        {
          CellData    &data       = cell_data[cell->active_cell_index()];
          double       perimeter  = 0;
          const double lengths[3] = {cell->vertex(1).distance(cell->vertex(2)),
                                     cell->vertex(2).distance(cell->vertex(0)),
                                     cell->vertex(0).distance(cell->vertex(1))};
          for (const double l : lengths)
            perimeter += l;
          Point<2> z;
          for (unsigned int k = 0; k < 3; ++k)
            {
              data.a[k] = lengths[k] / perimeter;
              z += data.a[k] * cell->vertex(k);
            }
          incentre[cell->active_cell_index()] = z;

          // Barycentric gradients from the affine map x = V_0 + J xi.
          Tensor<2, 2> jacobian;
          for (unsigned int d = 0; d < 2; ++d)
            for (unsigned int c = 0; c < 2; ++c)
              jacobian[c][d] = cell->vertex(d + 1)[c] - cell->vertex(0)[c];
          const Tensor<2, 2> inverse_transpose = transpose(invert(jacobian));
          for (unsigned int d = 0; d < 2; ++d)
            {
              Tensor<1, 2> unit;
              unit[d]                    = 1.;
              data.zeta_gradients[d + 1] = inverse_transpose * unit;
            }
          data.zeta_gradients[0] =
            -data.zeta_gradients[1] - data.zeta_gradients[2];

          std::vector<types::global_dof_index> dofs(3);
          cell->get_dof_indices(dofs);
          for (unsigned int j = 0; j < 3; ++j)
            for (unsigned int q = 0; q < 3; ++q)
              data.functions[3 * j + q] = 3 * dofs[j] + q;
        }

    // Split point of each edge, once per edge with the endpoints ordered by
    // their coordinates so that both cells use bit-identical weights:
    // R = P_0 + s (P_1 - P_0), where the segment between the incentres of
    // the two cells crosses the edge, or the midpoint on the boundary.
    const auto lexicographically_less = [](const Point<2> &a,
                                           const Point<2> &b) {
      return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
    };
    std::vector<double> split(triangulation.n_raw_faces(), -1.);
    std::vector<std::array<Point<2>, 3>> split_points(
      triangulation.n_active_cells());
    for (const auto &cell : vertex_dofs.active_cell_iterators())
      if (!cell->is_artificial())
        for (unsigned int k = 0; k < 3; ++k)
          {
            const unsigned int k1 = (k + 1) % 3;
            unsigned int       f  = 0;
            while (
              !((cell->face(f)->vertex_index(0) == cell->vertex_index(k) &&
                 cell->face(f)->vertex_index(1) == cell->vertex_index(k1)) ||
                (cell->face(f)->vertex_index(1) == cell->vertex_index(k) &&
                 cell->face(f)->vertex_index(0) == cell->vertex_index(k1))))
              ++f;
            const bool forward =
              lexicographically_less(cell->vertex(k), cell->vertex(k1));
            const Point<2> &p0 = forward ? cell->vertex(k) : cell->vertex(k1);
            const Point<2> &p1 = forward ? cell->vertex(k1) : cell->vertex(k);
            double         &s  = split[cell->face(f)->index()];
            if (s < 0)
              {
                if (cell->face(f)->at_boundary())
                  s = 0.5;
                else
                  {
                    const auto neighbor = cell->neighbor(f);
                    AssertThrow(!neighbor->is_artificial(), ExcInternalError());
                    const Tensor<1, 2> zz =
                      incentre[neighbor->active_cell_index()] -
                      incentre[cell->active_cell_index()];
                    s = cross(incentre[cell->active_cell_index()] - p0, zz) /
                        cross(p1 - p0, zz);
                    AssertThrow(s > 0. && s < 1., ExcInternalError());
                  }
              }
            CellData &data = cell_data[cell->active_cell_index()];
            data.rho[k]    = forward ? 1. - s : s;
            split_points[cell->active_cell_index()][k] = p0 + s * (p1 - p0);
          }

    // Powell-Sabin points of every vertex (thesis 3.5.2): the vertex, the
    // midpoints to the split points of its edges and to the incentres of
    // its cells (the split point of an edge shared by two cells is the same
    // point in both, and appears twice: the hull ignores duplicates).
    const unsigned int                 n_vertices = triangulation.n_vertices();
    std::vector<std::vector<Point<2>>> points(n_vertices);
    for (const auto &cell : vertex_dofs.active_cell_iterators())
      if (!cell->is_artificial())
        for (unsigned int j = 0; j < 3; ++j)
          {
            const unsigned int v = cell->vertex_index(j);
            const Point<2>    &x = cell->vertex(j);
            const auto        &r = split_points[cell->active_cell_index()];
            if (points[v].empty())
              points[v].push_back(x);
            points[v].push_back(
              x + 0.5 * (incentre[cell->active_cell_index()] - x));
            points[v].push_back(x + 0.5 * (r[j] - x));
            points[v].push_back(x + 0.5 * (r[(j + 2) % 3] - x));
          }

    control_triangles.resize(n_vertices);
    vertex_values.resize(n_vertices);
    std::vector<std::array<Tensor<1, 2>, 3>> vertex_gradients(n_vertices);
    const std::vector<Point<2>> &vertices = triangulation.get_vertices();
    for (unsigned int v = 0; v < n_vertices; ++v)
      if (!points[v].empty())
        {
          control_triangles[v] =
            smallest_control_triangle(vertices[v], points[v]);
          vertex_values[v]    = barycentric(control_triangles[v], vertices[v]);
          vertex_gradients[v] = barycentric_gradients(control_triangles[v]);
        }

    // Ordinates next to each vertex: lambda_q at the Powell-Sabin points
    // (thesis Eqs. 3.54-3.56).
    for (const auto &cell : vertex_dofs.active_cell_iterators())
      if (!cell->is_artificial())
        {
          CellData       &data = cell_data[cell->active_cell_index()];
          const auto     &r    = split_points[cell->active_cell_index()];
          const Point<2> &z    = incentre[cell->active_cell_index()];
          for (unsigned int j = 0; j < 3; ++j)
            {
              const unsigned int v = cell->vertex_index(j);
              const Point<2>    &x = cell->vertex(j);
              for (unsigned int q = 0; q < 3; ++q)
                {
                  const double        alpha    = vertex_values[v][q];
                  const Tensor<1, 2> &gradient = vertex_gradients[v][q];
                  data.ordinates[3 * j + q]    = {
                       {alpha,
                        alpha + 0.5 * gradient * (r[j] - x),
                        alpha + 0.5 * gradient * (r[(j + 2) % 3] - x),
                        alpha + 0.5 * gradient * (z - x)}};
                }
            }
        }
  }



  template <int dim>
  types::global_dof_index
  PowellSabin<dim>::n_functions() const
  {
    return 3 * vertex_dofs.n_dofs();
  }



  template <int dim>
  IndexSet
  PowellSabin<dim>::locally_owned_functions() const
  {
    const IndexSet &owned = vertex_dofs.locally_owned_dofs();
    IndexSet        functions(n_functions());
    if (owned.n_elements() > 0)
      functions.add_range(3 * owned.nth_index_in_set(0),
                          3 * (owned.nth_index_in_set(0) + owned.n_elements()));
    Assert(owned.is_contiguous(), ExcInternalError());
    return functions;
  }



  template <int dim>
  IndexSet
  PowellSabin<dim>::locally_relevant_functions() const
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(vertex_dofs, relevant);
    IndexSet functions(n_functions());
    for (const auto i : relevant)
      functions.add_range(3 * i, 3 * i + 3);
    return functions;
  }



  template <int dim>
  void
  PowellSabin<dim>::evaluate(const MaterialPoints<dim>         &material_points,
                             const Utilities::MPI::Partitioner &partitioner,
                             ParticleShapeData<dim>            &data) const
  {
    const auto        &particles   = material_points.particle_handler();
    const unsigned int n_particles = particles.n_locally_owned_particles();

    data.offsets.resize(n_particles + 1);
    data.indices.resize(n_particles * n_cell_functions);
    data.values.resize(n_particles * n_cell_functions);
    data.gradients.resize(n_particles * n_cell_functions);

    std::array<unsigned int, n_cell_functions>        local_indices;
    typename Triangulation<dim>::active_cell_iterator current_cell;
    unsigned int                                      k = 0;
    for (const auto &particle : particles)
      {
        const auto cell = particle.get_surrounding_cell();
        if (cell != current_cell)
          {
            current_cell          = cell;
            const auto &functions = cell_functions(cell);
            for (unsigned int i = 0; i < n_cell_functions; ++i)
              local_indices[i] = partitioner.global_to_local(functions[i]);
          }
        const unsigned int offset = k * n_cell_functions;
        data.offsets[k]           = offset;
        cell_values(cell,
                    particle.get_reference_location(),
                    &data.values[offset],
                    &data.gradients[offset]);
        std::copy(local_indices.begin(),
                  local_indices.end(),
                  data.indices.begin() + offset);
        ++k;
      }
    data.offsets[n_particles] = n_particles * n_cell_functions;
    Assert(k == n_particles, ExcInternalError());
  }



  template <int dim>
  const std::array<types::global_dof_index, PowellSabin<dim>::n_cell_functions>
    &
    PowellSabin<dim>::cell_functions(
      const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    return cell_data[cell->active_cell_index()].functions;
  }



  template <int dim>
  void
  PowellSabin<dim>::cell_values(
    const typename Triangulation<dim>::active_cell_iterator &,
    const Point<dim> &,
    double *const,
    Tensor<1, dim> *const,
    const unsigned int) const
  {
    AssertThrow(false, ExcNotImplemented());
  }



  template <>
  void
  PowellSabin<2>::cell_values(
    const typename Triangulation<2>::active_cell_iterator &cell,
    const Point<2>                                        &xi,
    double *const                                          values,
    Tensor<1, 2> *const                                    gradients,
    const unsigned int                                     sub_triangle) const
  {
    const CellData             &data = cell_data[cell->active_cell_index()];
    const std::array<double, 3> zeta = {{1. - xi[0] - xi[1], xi[0], xi[1]}};

    // Fan triangle (V_k, V_{k+1}, Z) opposite the vertex m with the smallest
    // zeta_m / a_m, and the coordinates (s, t, w) there.
    unsigned int k, half;
    if (sub_triangle == numbers::invalid_unsigned_int)
      {
        unsigned int m = 0;
        for (unsigned int i = 1; i < 3; ++i)
          if (zeta[i] * data.a[m] < zeta[m] * data.a[i])
            m = i;
        k = (m + 1) % 3;
      }
    else
      k = sub_triangle / 2;
    const unsigned int k1 = (k + 1) % 3, m = (k + 2) % 3;
    const double       w      = zeta[m] / data.a[m];
    const Tensor<1, 2> grad_w = data.zeta_gradients[m] / data.a[m];
    const double       s      = zeta[k] - data.a[k] * w;
    const double       t      = zeta[k1] - data.a[k1] * w;
    const Tensor<1, 2> grad_s = data.zeta_gradients[k] - data.a[k] * grad_w;
    const Tensor<1, 2> grad_t = data.zeta_gradients[k1] - data.a[k1] * grad_w;
    const double       rho    = data.rho[k];
    if (sub_triangle == numbers::invalid_unsigned_int)
      half = (s * (1. - rho) >= rho * t ? 0 : 1);
    else
      half = sub_triangle % 2;

    // Barycentric coordinates in the sub-triangle T_{k,half}.
    std::array<double, 3>       sigma;
    std::array<Tensor<1, 2>, 3> grad_sigma;
    if (half == 0)
      {
        sigma      = {{s - rho * t / (1. - rho), t / (1. - rho), w}};
        grad_sigma = {
          {grad_s - (rho / (1. - rho)) * grad_t, grad_t / (1. - rho), grad_w}};
      }
    else
      {
        sigma      = {{s / rho, t - (1. - rho) * s / rho, w}};
        grad_sigma = {
          {grad_s / rho, grad_t - ((1. - rho) / rho) * grad_s, grad_w}};
      }
    double       b[6];
    Tensor<1, 2> grad_b[6];
    bernstein(sigma, grad_sigma, b, grad_b);

    // On T_{k,half} each function is its four ordinates (f, Lf, Lb, Lt) of
    // the owner vertex times weights made of the six Bernstein polynomials
    // (thesis Eqs. 3.54-3.58). The weights depend only on the owner's place
    // in the sub-triangle: o = 0 for V_k, 1 for V_{k+1}, 2 for the far
    // vertex V_{k+2}, so they are formed once per point for all nine
    // functions.
    const double a_k = data.a[k], a_k1 = data.a[k1], a_m = data.a[m];
    std::array<std::array<double, 4>, 3>       weight;
    std::array<std::array<Tensor<1, 2>, 4>, 3> grad_weight;
    const Tensor<1, 2>                         zero;
    if (half == 0)
      {
        weight[0] = {
          {b[0], rho * b[1] + b[3], 0., a_k * b[2] + rho * b[4] + b[5]}};
        grad_weight[0] = {{grad_b[0],
                           rho * grad_b[1] + grad_b[3],
                           zero,
                           a_k * grad_b[2] + rho * grad_b[4] + grad_b[5]}};
        weight[1]      = {
               {0., 0., (1. - rho) * b[1], a_k1 * b[2] + (1. - rho) * b[4]}};
        grad_weight[1] = {{zero,
                           zero,
                           (1. - rho) * grad_b[1],
                           a_k1 * grad_b[2] + (1. - rho) * grad_b[4]}};
      }
    else
      {
        weight[0]      = {{0., rho * b[0], 0., a_k * b[2] + rho * b[5]}};
        grad_weight[0] = {
          {zero, rho * grad_b[0], zero, a_k * grad_b[2] + rho * grad_b[5]}};
        weight[1]      = {{b[1],
                           0.,
                           (1. - rho) * b[0] + b[3],
                           a_k1 * b[2] + b[4] + (1. - rho) * b[5]}};
        grad_weight[1] = {
          {grad_b[1],
           zero,
           (1. - rho) * grad_b[0] + grad_b[3],
           a_k1 * grad_b[2] + grad_b[4] + (1. - rho) * grad_b[5]}};
      }
    weight[2]      = {{0., 0., 0., a_m * b[2]}};
    grad_weight[2] = {{zero, zero, zero, a_m * grad_b[2]}};

    for (unsigned int j = 0; j < 3; ++j)
      {
        const unsigned int o      = (j + 3 - k) % 3;
        const auto        &c      = weight[o];
        const auto        &c_grad = grad_weight[o];
        if (o == 2)
          {
            // The far vertex's functions reach T_{k,half} only through Lt.
            for (unsigned int q = 0; q < 3; ++q)
              {
                const double lt      = data.ordinates[3 * j + q][3];
                values[3 * j + q]    = lt * c[3];
                gradients[3 * j + q] = lt * c_grad[3];
              }
            continue;
          }
        for (unsigned int q = 0; q < 3; ++q)
          {
            const auto &ordinate = data.ordinates[3 * j + q];
            values[3 * j + q]    = ordinate[0] * c[0] + ordinate[1] * c[1] +
                                ordinate[2] * c[2] + ordinate[3] * c[3];
            gradients[3 * j + q] =
              ordinate[0] * c_grad[0] + ordinate[1] * c_grad[1] +
              ordinate[2] * c_grad[2] + ordinate[3] * c_grad[3];
          }
      }
  }



  template <int dim>
  void
  PowellSabin<dim>::for_each_side_control_point(
    const types::boundary_id,
    const std::function<void(const types::global_dof_index,
                             const Point<dim> &,
                             const Point<dim> &,
                             const Tensor<1, dim> &)> &) const
  {
    AssertThrow(false, ExcNotImplemented());
  }



  template <>
  void
  PowellSabin<2>::for_each_side_control_point(
    const types::boundary_id                         boundary_id,
    const std::function<void(const types::global_dof_index,
                             const Point<2> &,
                             const Point<2> &,
                             const Tensor<1, 2> &)> &action) const
  {
    // The vertices of this rank's cells, whose control triangles are
    // complete: all cells around them are its own or ghost cells.
    const auto       &triangulation = vertex_dofs.get_triangulation();
    std::vector<bool> of_own_cell(triangulation.n_vertices(), false);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          of_own_cell[cell->vertex_index(v)] = true;
    for (const auto &cell : vertex_dofs.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary_id)
            {
              const auto        &face = cell->face(f);
              const Tensor<1, 2> tangent =
                (face->vertex(1) - face->vertex(0)) / face->measure();
              for (unsigned int i = 0; i < 2; ++i)
                {
                  const unsigned int v = face->vertex_index(i);
                  if (!of_own_cell[v])
                    continue;
                  const types::global_dof_index dof =
                    face->vertex_dof_index(i, 0);
                  unsigned int on_line = 0;
                  for (unsigned int q = 0; q < 3; ++q)
                    if (std::abs(
                          cross(tangent,
                                control_triangles[v][q] - face->vertex(i))) <=
                        1e-10 * face->measure())
                      {
                        action(3 * dof + q,
                               face->vertex(i),
                               control_triangles[v][q],
                               tangent);
                        ++on_line;
                      }
                  AssertThrow(
                    on_line >= 2,
                    ExcMessage("The Powell-Sabin control triangle of the "
                               "boundary vertex at " +
                               Utilities::to_string(face->vertex(i)[0]) + ", " +
                               Utilities::to_string(face->vertex(i)[1]) +
                               " has fewer than two points on boundary " +
                               Utilities::to_string(boundary_id) +
                               ": the value and tangential derivative there "
                               "cannot be imposed through its coefficients."));
                }
            }
  }



  template <int dim>
  IndexSet
  PowellSabin<dim>::boundary_functions(const types::boundary_id) const
  {
    AssertThrow(false, ExcNotImplemented());
    return IndexSet();
  }



  template <>
  IndexSet
  PowellSabin<2>::boundary_functions(const types::boundary_id boundary_id) const
  {
    IndexSet functions(n_functions());
    for_each_side_control_point(boundary_id,
                                [&](const types::global_dof_index function,
                                    const Point<2> &,
                                    const Point<2> &,
                                    const Tensor<1, 2> &) {
                                  functions.add_index(function);
                                });
    functions.compress();
    return functions;
  }



  template <int dim>
  void
  PowellSabin<dim>::make_boundary_constraints(
    const types::boundary_id   boundary_id,
    const Function<dim>       &g,
    AffineConstraints<double> &constraints) const
  {
    for_each_side_control_point(boundary_id,
                                [&](const types::global_dof_index function,
                                    const Point<dim>             &vertex,
                                    const Point<dim>             &control_point,
                                    const Tensor<1, dim>         &tangent) {
                                  if (constraints.is_constrained(function))
                                    return;
                                  constraints.add_line(function);
                                  constraints.set_inhomogeneity(
                                    function,
                                    g.value(vertex) +
                                      (g.gradient(vertex) * tangent) *
                                        ((control_point - vertex) * tangent));
                                });
  }



  template <int dim>
  bool
  PowellSabin<dim>::is_linearly_complete() const
  {
    return true;
  }



  template <int dim>
  typename ShapeFunctions<dim>::MovingGrid
  PowellSabin<dim>::moving_grid() const
  {
    return ShapeFunctions<dim>::MovingGrid::not_supported;
  }



  template <int dim>
  std::string
  PowellSabin<dim>::moving_grid_limitation() const
  {
    return "Shape functions = Powell-Sabin run with Method = MPM (Update "
           "scheme = USL or MUSL): their three functions per vertex do not "
           "move with the vertices, which OTM and the unified approach need "
           "(a moving triangulation is future work).";
  }



  template <int dim>
  unsigned int
  PowellSabin<dim>::functions_per_node() const
  {
    return 3;
  }



  template <int dim>
  void
  PowellSabin<dim>::functions_on_cell(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>                    &functions) const
  {
    const auto &cell_functions_of_cell = cell_functions(cell);
    functions.assign(cell_functions_of_cell.begin(),
                     cell_functions_of_cell.end());
  }



  template <int dim>
  types::global_dof_index
  PowellSabin<dim>::vertex_function(
    const typename Triangulation<dim>::active_cell_iterator &,
    const unsigned int) const
  {
    return numbers::invalid_dof_index;
  }



  template <int dim>
  const DoFHandler<dim> &
  PowellSabin<dim>::dof_handler() const
  {
    return vertex_dofs;
  }



  template <int dim>
  void
  PowellSabin<dim>::to_cell_dofs(const VectorType &coefficients,
                                 VectorType       &values) const
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(vertex_dofs, relevant);
    values.reinit(vertex_dofs.locally_owned_dofs(),
                  relevant,
                  vertex_dofs.get_triangulation().get_communicator());
    for (const auto &cell : vertex_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto j : cell->vertex_indices())
          {
            const types::global_dof_index dof = cell->vertex_dof_index(j, 0);
            if (!values.in_local_range(dof))
              continue;
            double value = 0;
            for (unsigned int q = 0; q < 3; ++q)
              value += coefficients(3 * dof + q) *
                       vertex_values[cell->vertex_index(j)][q];
            values(dof) = value;
          }
    values.update_ghost_values();
  }



  template <int dim>
  const std::array<Point<dim>, 3> &
  PowellSabin<dim>::control_triangle(const unsigned int vertex) const
  {
    AssertIndexRange(vertex, control_triangles.size());
    return control_triangles[vertex];
  }



  template <int dim>
  Point<dim>
  PowellSabin<dim>::split_point(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const unsigned int                                       edge) const
  {
    AssertIndexRange(edge, 4);
    const CellData &data = cell_data[cell->active_cell_index()];
    if (edge == 3)
      {
        Point<dim> z;
        for (unsigned int k = 0; k < 3; ++k)
          z += data.a[k] * cell->vertex(k);
        return z;
      }
    return data.rho[edge] * cell->vertex(edge) +
           (1. - data.rho[edge]) * cell->vertex((edge + 1) % 3);
  }



  template class PowellSabin<1>;
  template class PowellSabin<2>;
  template class PowellSabin<3>;
} // namespace MpmOtm

#define MPM_OTM_POWELL_SABIN_DESCRIPTION                                     \
  "quadratic Powell-Sabin splines, three per vertex of a triangle grid, C1 " \
  "(2D, Mesh/Cell type = simplex, Method = MPM)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<1>,
                        MpmOtm::PowellSabin<1>,
                        "Powell-Sabin",
                        MPM_OTM_POWELL_SABIN_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<2>,
                        MpmOtm::PowellSabin<2>,
                        "Powell-Sabin",
                        MPM_OTM_POWELL_SABIN_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<3>,
                        MpmOtm::PowellSabin<3>,
                        "Powell-Sabin",
                        MPM_OTM_POWELL_SABIN_DESCRIPTION)
