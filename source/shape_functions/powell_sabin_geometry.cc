#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/shape_functions/powell_sabin_geometry.h>

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
     * Convex hull of @p points, counter-clockwise from the lowest of its
     * leftmost corners (Andrew's monotone chain with exact
     * orientation tests), then without the corners that lie within
     * @p tolerance (a cross product) of the line through their neighbours.
     * The tolerance is applied to the finished polygon only: inside the
     * chain it would make the result depend on the order of points whose x
     * differ by round-off, as on a vertical line of a grid that moved.
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
                         *p - hull[hull.size() - 2]) <= 0.)
              hull.pop_back();
            hull.push_back(*p);
          }
        hull.pop_back();
      };
      chain(points.begin(), points.end());
      chain(points.rbegin(), points.rend());

      for (bool removed = true; removed && hull.size() > 3;)
        {
          removed = false;
          for (unsigned int i = 0; i < hull.size() && hull.size() > 3; ++i)
            {
              const Point<2> &before =
                hull[(i + hull.size() - 1) % hull.size()];
              const Point<2> &after = hull[(i + 1) % hull.size()];
              if (std::abs(cross(hull[i] - before, after - before)) <=
                  tolerance)
                {
                  hull.erase(hull.begin() + i);
                  removed = true;
                  break;
                }
            }
        }
      // Start at the lowest of the leftmost corners, with x that differ by
      // round-off counted as equal: the order of the corners decides among
      // candidate triangles of equal area, and must not change when the
      // grid only moved.
      double extent = 0;
      for (const auto &p : hull)
        extent = std::max(extent, p.distance(hull.front()));
      double left = hull.front()[0];
      for (const auto &p : hull)
        left = std::min(left, p[0]);
      auto start = hull.end();
      for (auto p = hull.begin(); p != hull.end(); ++p)
        if ((*p)[0] <= left + 1e-9 * extent &&
            (start == hull.end() || (*p)[1] < (*start)[1]))
          start = p;
      std::rotate(hull.begin(), start, hull.end());
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
     * choice among equal triangles is reproducible. None if the points are
     * collinear or no candidate contains them.
     */
    std::optional<std::array<Point<2>, 3>>
    smallest_control_triangle(const Point<2>              &vertex,
                              const std::vector<Point<2>> &points)
    {
      double h = 0;
      for (const auto &p : points)
        h = std::max(h, p.distance(vertex));
      const std::vector<Point<2>> hull = convex_hull(points, 1e-12 * h * h);
      const unsigned int          m    = hull.size();
      if (m < 3)
        return std::nullopt;
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

      if (!(best_area < std::numeric_limits<double>::infinity()))
        return std::nullopt;
      return best;
    }

    /**
     * The bits q of the points @p t[q] that lie on one of @p lines (unit
     * tangent and length of the boundary faces through @p vertex).
     */
    unsigned int
    on_boundary(const std::array<Point<2>, 3>                      &t,
                const Point<2>                                     &vertex,
                const std::vector<std::pair<Tensor<1, 2>, double>> &lines)
    {
      unsigned int bits = 0;
      for (unsigned int q = 0; q < 3; ++q)
        for (const auto &[tangent, length] : lines)
          if (std::abs(cross(tangent, t[q] - vertex)) <= 1e-10 * length)
            bits |= 1u << q;
      return bits;
    }

    /**
     * The points of @p t in the order that keeps the labels of the control
     * points on the boundary (@p lines through @p vertex) of @p previous, and
     * among those orders the one closest to @p previous: the functions of a
     * vertex then keep their labels while the grid moves, and with them the
     * boundary conditions set on them.
     */
    std::array<Point<2>, 3>
    closest_labelling(const std::array<Point<2>, 3> &t,
                      const std::array<Point<2>, 3> &previous,
                      const Point<2>                &vertex,
                      const std::vector<std::pair<Tensor<1, 2>, double>> &lines)
    {
      const unsigned int previous_bits  = on_boundary(previous, vertex, lines);
      std::array<unsigned int, 3> order = {{0, 1, 2}};
      std::array<Point<2>, 3>     best  = t;
      std::pair<bool, double>     best_key(true,
                                       std::numeric_limits<double>::infinity());
      do
        {
          const std::array<Point<2>, 3> candidate = {
            {t[order[0]], t[order[1]], t[order[2]]}};
          double distance = 0;
          for (unsigned int q = 0; q < 3; ++q)
            distance += candidate[q].distance_square(previous[q]);
          const std::pair<bool, double> key(on_boundary(candidate,
                                                        vertex,
                                                        lines) != previous_bits,
                                            distance);
          if (key < best_key)
            {
              best     = candidate;
              best_key = key;
            }
      } while (std::next_permutation(order.begin(), order.end()));
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



  std::string
  PowellSabinGeometry::reinit(const Triangulation<2> &triangulation)
  {
    AssertThrow(triangulation.all_reference_cells_are_simplex(),
                ExcMessage("Powell-Sabin splines need a triangulation of "
                           "triangles."));
    const bool rebuilding = !control_triangles.empty();

    // Incentres (thesis 3.5.1): a_k = |edge opposite V_k| / perimeter.
    cell_data.resize(triangulation.n_active_cells());
    std::vector<Point<2>> incentre(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
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
    for (const auto &cell : triangulation.active_cell_iterators())
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
    for (const auto &cell : triangulation.active_cell_iterators())
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
    values_at_vertices.resize(n_vertices);
    std::vector<std::array<Tensor<1, 2>, 3>> vertex_gradients(n_vertices);
    const std::vector<Point<2>> &vertices = triangulation.get_vertices();
    // On a moved grid: the boundary faces through each vertex, by which
    // the control points keep their labels.
    std::vector<std::vector<std::pair<Tensor<1, 2>, double>>> lines(
      rebuilding ? n_vertices : 0);
    if (rebuilding)
      for (const auto &cell : triangulation.active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              for (unsigned int i = 0; i < 2; ++i)
                lines[face->vertex_index(i)].emplace_back(
                  (face->vertex(1) - face->vertex(0)) / face->measure(),
                  face->measure());
    // The vertices of locally owned cells, whose cells are all present: a
    // vertex of ghost cells only may lack Powell-Sabin points of the cells
    // beyond the ghost layer, and its functions are not evaluated here.
    std::vector<bool> complete(n_vertices, false);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          complete[cell->vertex_index(v)] = true;
    for (unsigned int v = 0; v < n_vertices; ++v)
      if (!points[v].empty())
        {
          const auto triangle =
            smallest_control_triangle(vertices[v], points[v]);
          if (!triangle && complete[v])
            return "no Powell-Sabin control triangle contains the "
                   "Powell-Sabin points of the vertex at " +
                   Utilities::to_string(vertices[v][0]) + ", " +
                   Utilities::to_string(vertices[v][1]) +
                   " (its cells are degenerate).";
          if (!triangle)
            continue;
          control_triangles[v] = rebuilding ?
                                   closest_labelling(*triangle,
                                                     control_triangles[v],
                                                     vertices[v],
                                                     lines[v]) :
                                   *triangle;
          values_at_vertices[v] =
            barycentric(control_triangles[v], vertices[v]);
          vertex_gradients[v] = barycentric_gradients(control_triangles[v]);
        }

    // Ordinates next to each vertex: lambda_q at the Powell-Sabin points
    // (thesis Eqs. 3.54-3.56).
    for (const auto &cell : triangulation.active_cell_iterators())
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
                  const double        alpha    = values_at_vertices[v][q];
                  const Tensor<1, 2> &gradient = vertex_gradients[v][q];
                  data.ordinates[3 * j + q]    = {
                       {alpha,
                        alpha + 0.5 * gradient * (r[j] - x),
                        alpha + 0.5 * gradient * (r[(j + 2) % 3] - x),
                        alpha + 0.5 * gradient * (z - x)}};
                }
            }
        }
    return {};
  }



  void
  PowellSabinGeometry::cell_values(const Triangulation<2>::cell_iterator &cell,
                                   const Point<2>                        &xi,
                                   double *const       values,
                                   Tensor<1, 2> *const gradients,
                                   const unsigned int  sub_triangle) const
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



  const std::array<Point<2>, 3> &
  PowellSabinGeometry::control_triangle(const unsigned int vertex) const
  {
    AssertIndexRange(vertex, control_triangles.size());
    return control_triangles[vertex];
  }



  const std::array<double, 3> &
  PowellSabinGeometry::vertex_values(const unsigned int vertex) const
  {
    AssertIndexRange(vertex, values_at_vertices.size());
    return values_at_vertices[vertex];
  }



  Point<2>
  PowellSabinGeometry::split_point(const Triangulation<2>::cell_iterator &cell,
                                   const unsigned int edge) const
  {
    AssertIndexRange(edge, 4);
    const CellData &data = cell_data[cell->active_cell_index()];
    if (edge == 3)
      {
        Point<2> z;
        for (unsigned int k = 0; k < 3; ++k)
          z += data.a[k] * cell->vertex(k);
        return z;
      }
    return data.rho[edge] * cell->vertex(edge) +
           (1. - data.rho[edge]) * cell->vertex((edge + 1) % 3);
  }
} // namespace MpmOtm
