#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_bernstein.h>
#include <deal.II/fe/fe_tools.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/b_splines.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace MpmOtm
{
  namespace
  {
    /**
     * Highest degree offered: fixed-size arrays hold p + 1 values.
     */
    constexpr unsigned int max_degree = 6;

    /**
     * The p + 1 B-splines of degree p that do not vanish on the knot span
     * [U[i], U[i+1]) of the full knot vector @p U, at @p x (Cox-de Boor
     * recursion in the triangular form of Piegl and Tiller, Alg. A2.2).
     */
    void
    cox_de_boor(const std::vector<double> &U,
                const unsigned int         i,
                const unsigned int         p,
                const double               x,
                double                    *values)
    {
      AssertIndexRange(p, max_degree + 1);
      double left[max_degree + 1], right[max_degree + 1];
      values[0] = 1.;
      for (unsigned int j = 1; j <= p; ++j)
        {
          left[j]      = x - U[i + 1 - j];
          right[j]     = U[i + j] - x;
          double saved = 0.;
          for (unsigned int r = 0; r < j; ++r)
            {
              const double temp = values[r] / (right[r + 1] + left[j - r]);
              values[r]         = saved + right[r + 1] * temp;
              saved             = left[j - r] * temp;
            }
          values[j] = saved;
        }
    }
  } // namespace



  template <int dim>
  void
  BSplines<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("B-spline degree",
                      "2",
                      Patterns::Integer(1, max_degree),
                      "Degree p of the B-splines (Shape functions = "
                      "B-spline): C^(p-1) functions, p + 1 per direction on "
                      "every cell. Method = OTM needs p = 1.");
  }



  template <int dim>
  BSplines<dim>::BSplines(const unsigned int degree)
    : p(degree)
  {}



  template <int dim>
  BSplines<dim>::~BSplines() = default;



  template <int dim>
  void
  BSplines<dim>::parse_parameters(ParameterHandler &prm)
  {
    p = prm.get_integer("B-spline degree");
  }



  template <int dim>
  void
  BSplines<dim>::initialize(const BackgroundGrid<dim> &grid)
  {
    AssertThrow(p >= 1 && p <= max_degree,
                ExcMessage("B-spline degree must be between 1 and " +
                           std::to_string(max_degree) + "."));
    AssertThrow(grid.is_box(),
                ExcMessage("Shape functions = B-spline need a box grid "
                           "(tensor-product knot spans from Mesh/Lower "
                           "corner, Upper corner and Subdivisions), not a "
                           "Mesh/Mesh file; use Shape functions = linear "
                           "there."));
    AssertThrow(!grid.is_simplex(),
                ExcMessage("Shape functions = B-spline need Mesh/Cell type = "
                           "hypercube (tensor-product knot spans)."));
    triangulation = &grid.triangulation();

    // The distinct knots of direction d are the distinct vertex
    // coordinates on all ranks (a fully distributed 1D grid holds only its
    // own part); the cells must form a tensor-product grid.
    const auto  &vertices = triangulation->get_vertices();
    const auto  &used     = triangulation->get_used_vertices();
    const double tolerance =
      1e-10 * grid.box().get_boundary_points().first.distance(
                grid.box().get_boundary_points().second);
    types::global_cell_index n_tensor_cells = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<double> coordinates;
        for (unsigned int v = 0; v < vertices.size(); ++v)
          if (used[v])
            coordinates.push_back(vertices[v][d]);
        std::sort(coordinates.begin(), coordinates.end());
        coordinates.erase(std::unique(coordinates.begin(), coordinates.end()),
                          coordinates.end());
        const auto parts =
          Utilities::MPI::all_gather(triangulation->get_communicator(),
                                     coordinates);
        coordinates.clear();
        for (const auto &part : parts)
          coordinates.insert(coordinates.end(), part.begin(), part.end());
        std::sort(coordinates.begin(), coordinates.end());
        knots[d].clear();
        for (const double x : coordinates)
          if (knots[d].empty() || x > knots[d].back() + tolerance)
            knots[d].push_back(x);
        n_per_direction[d] = knots[d].size() - 1 + p;
        n_tensor_cells *= knots[d].size() - 1;
        compute_extraction(d);
      }
    AssertThrow(n_tensor_cells == triangulation->n_global_active_cells(),
                ExcMessage("Shape functions = B-spline need a tensor-product "
                           "grid of boxes (Mesh/Subdivisions, no "
                           "refinement)."));

    local_multi_index.resize(Utilities::fixed_power<dim>(p + 1));
    for (unsigned int local = 0; local < local_multi_index.size(); ++local)
      for (unsigned int d = 0, rest = local; d < dim; ++d, rest /= p + 1)
        local_multi_index[local][d] = rest % (p + 1);

    binomial.assign(p + 1, 1.);
    for (unsigned int b = 1; b <= p; ++b)
      binomial[b] = binomial[b - 1] * (p - b + 1) / b;

    span_of_cell.resize(triangulation->n_active_cells());
    for (const auto &cell : triangulation->active_cell_iterators())
      if (!cell->is_artificial())
        {
          const Point<dim> centre = cell->center();
          for (unsigned int d = 0; d < dim; ++d)
            span_of_cell[cell->active_cell_index()][d] =
              std::upper_bound(knots[d].begin(), knots[d].end(), centre[d]) -
              knots[d].begin() - 1;
        }
    distribute_functions();

    std::vector<types::global_dof_index> relevant_indices;
    std::vector<types::global_dof_index> indices;
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          functions_on_cell(cell, indices);
          relevant_indices.insert(relevant_indices.end(),
                                  indices.begin(),
                                  indices.end());
        }
    std::sort(relevant_indices.begin(), relevant_indices.end());
    relevant_indices.erase(std::unique(relevant_indices.begin(),
                                       relevant_indices.end()),
                           relevant_indices.end());
    relevant = owned;
    relevant.add_indices(relevant_indices.begin(), relevant_indices.end());

    fe = std::make_unique<FE_Bernstein<dim>>(p);
    dofs.reinit(*triangulation);
    dofs.distribute_dofs(*fe);
    hierarchic_of_lexicographic =
      FETools::lexicographic_to_hierarchic_numbering<dim>(p);
  }



  template <int dim>
  void
  BSplines<dim>::distribute_functions()
  {
    const types::global_dof_index n    = n_functions();
    const MPI_Comm                comm = triangulation->get_communicator();
    global_of_lexicographic.clear();
    lexicographic_of_global.clear();
    owned.clear();
    owned.set_size(n);
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      {
        owned.add_range(0, n);
        return;
      }

    // The functions whose anchor cell is one of this rank's cells.
    const auto anchor = [&](const unsigned int d, const unsigned int i) {
      const unsigned int n_spans = knots[d].size() - 1;
      return std::min(i - std::min(i, p / 2), n_spans - 1);
    };
    const unsigned int                   q = p + 1;
    std::vector<types::global_dof_index> own;
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &span = span_of_cell[cell->active_cell_index()];
          for (unsigned int local = 0; local < Utilities::fixed_power<dim>(q);
               ++local)
            {
              types::global_dof_index       lexicographic = 0;
              bool                          anchored_here = true;
              unsigned int                  rest          = local;
              std::array<unsigned int, dim> i;
              for (unsigned int d = 0; d < dim; ++d, rest /= q)
                {
                  i[d]          = span[d] + rest % q;
                  anchored_here = anchored_here && anchor(d, i[d]) == span[d];
                }
              if (!anchored_here)
                continue;
              for (unsigned int d = dim; d-- > 0;)
                lexicographic = lexicographic * n_per_direction[d] + i[d];
              own.push_back(lexicographic);
            }
        }
    std::sort(own.begin(), own.end());

    // Rank after rank, each rank's functions in lexicographic order.
    const std::vector<std::vector<types::global_dof_index>> all =
      Utilities::MPI::all_gather(comm, own);
    global_of_lexicographic.assign(n, numbers::invalid_dof_index);
    lexicographic_of_global.resize(n);
    types::global_dof_index next = 0;
    for (unsigned int rank = 0; rank < all.size(); ++rank)
      {
        if (rank == Utilities::MPI::this_mpi_process(comm) && !own.empty())
          owned.add_range(next, next + own.size());
        for (const auto lexicographic : all[rank])
          {
            global_of_lexicographic[lexicographic] = next;
            lexicographic_of_global[next]          = lexicographic;
            ++next;
          }
      }
    AssertThrow(next == n && std::find(global_of_lexicographic.begin(),
                                       global_of_lexicographic.end(),
                                       numbers::invalid_dof_index) ==
                               global_of_lexicographic.end(),
                ExcInternalError());
  }



  template <int dim>
  std::array<unsigned int, dim>
  BSplines<dim>::multi_index(const types::global_dof_index global) const
  {
    types::global_dof_index       rest = lexicographic_of_global.empty() ?
                                           global :
                                           lexicographic_of_global[global];
    std::array<unsigned int, dim> i;
    for (unsigned int d = 0; d < dim; ++d)
      {
        i[d] = rest % n_per_direction[d];
        rest /= n_per_direction[d];
      }
    return i;
  }



  template <int dim>
  void
  BSplines<dim>::compute_extraction(const unsigned int d)
  {
    const unsigned int  n_spans = knots[d].size() - 1;
    std::vector<double> U(p, knots[d].front());
    U.insert(U.end(), knots[d].begin(), knots[d].end());
    U.insert(U.end(), p, knots[d].back());

    // On span j, N(t_k) = C B(t_k) at p + 1 points t_k: C = N B^-1.
    FullMatrix<double> bernstein(p + 1, p + 1), inverse(p + 1, p + 1);
    for (unsigned int k = 0; k <= p; ++k)
      {
        const double t = (k + 0.5) / (p + 1);
        for (unsigned int b = 0; b <= p; ++b)
          {
            double value = 1.;
            for (unsigned int e = 0; e < b; ++e)
              value *= t * (p - e) / (e + 1);
            for (unsigned int e = b; e < p; ++e)
              value *= 1. - t;
            bernstein(b, k) = value;
          }
      }
    inverse.invert(bernstein);

    extraction[d].resize(n_spans * (p + 1) * (p + 1));
    std::vector<double> values(p + 1);
    FullMatrix<double>  sampled(p + 1, p + 1);
    for (unsigned int j = 0; j < n_spans; ++j)
      {
        const double h = knots[d][j + 1] - knots[d][j];
        AssertThrow(h > 0., ExcInternalError());
        for (unsigned int k = 0; k <= p; ++k)
          {
            cox_de_boor(U,
                        j + p,
                        p,
                        knots[d][j] + (k + 0.5) / (p + 1) * h,
                        values.data());
            for (unsigned int a = 0; a <= p; ++a)
              sampled(a, k) = values[a];
          }
        double *C = &extraction[d][j * (p + 1) * (p + 1)];
        for (unsigned int a = 0; a <= p; ++a)
          for (unsigned int b = 0; b <= p; ++b)
            {
              double sum = 0.;
              for (unsigned int k = 0; k <= p; ++k)
                sum += sampled(a, k) * inverse(k, b);
              C[a * (p + 1) + b] = sum;
            }
      }
  }



  template <int dim>
  types::global_dof_index
  BSplines<dim>::n_functions() const
  {
    types::global_dof_index n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= n_per_direction[d];
    return n;
  }



  template <int dim>
  IndexSet
  BSplines<dim>::locally_owned_functions() const
  {
    return owned;
  }



  template <int dim>
  IndexSet
  BSplines<dim>::locally_relevant_functions() const
  {
    return relevant;
  }



  template <int dim>
  const std::array<unsigned int, dim> &
  BSplines<dim>::first_function(
    const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    Assert(!cell->is_artificial(),
           ExcMessage("B-splines know the spans of owned and ghost cells "
                      "only."));
    return span_of_cell[cell->active_cell_index()];
  }



  template <int dim>
  void
  BSplines<dim>::functions_on_cell(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>                    &indices) const
  {
    const auto        &first = first_function(cell);
    const unsigned int q     = p + 1;
    indices.resize(Utilities::fixed_power<dim>(q));
    for (unsigned int local = 0; local < indices.size(); ++local)
      {
        types::global_dof_index global = 0;
        unsigned int            rest   = local;
        unsigned int            a[dim];
        for (unsigned int d = 0; d < dim; ++d)
          {
            a[d] = rest % q;
            rest /= q;
          }
        for (unsigned int d = dim; d-- > 0;)
          global = global * n_per_direction[d] + first[d] + a[d];
        indices[local] = global_of_lexicographic.empty() ?
                           global :
                           global_of_lexicographic[global];
      }
  }



  template <int dim>
  void
  BSplines<dim>::values_1d(const unsigned int d,
                           const unsigned int span,
                           const double       t,
                           double            *values,
                           double            *derivatives) const
  {
    // Bernstein polynomials B_b = binom(p, b) t^b (1-t)^(p-b) and their
    // t-derivatives, then the extraction operator.
    double t_power[max_degree + 1], s_power[max_degree + 1];
    t_power[0] = s_power[0] = 1.;
    for (unsigned int b = 1; b <= p; ++b)
      {
        t_power[b] = t_power[b - 1] * t;
        s_power[b] = s_power[b - 1] * (1. - t);
      }
    double bernstein[max_degree + 1], bernstein_derivative[max_degree + 1];
    for (unsigned int b = 0; b <= p; ++b)
      {
        bernstein[b]      = binomial[b] * t_power[b] * s_power[p - b];
        double derivative = 0.;
        if (b > 0)
          derivative += b * t_power[b - 1] * s_power[p - b];
        if (b < p)
          derivative -= (p - b) * t_power[b] * s_power[p - b - 1];
        bernstein_derivative[b] = binomial[b] * derivative;
      }
    const double  inverse_h = 1. / (knots[d][span + 1] - knots[d][span]);
    const double *C         = &extraction[d][span * (p + 1) * (p + 1)];
    for (unsigned int a = 0; a <= p; ++a)
      {
        double value = 0., derivative = 0.;
        for (unsigned int b = 0; b <= p; ++b)
          {
            value += C[a * (p + 1) + b] * bernstein[b];
            derivative += C[a * (p + 1) + b] * bernstein_derivative[b];
          }
        values[a]      = value;
        derivatives[a] = derivative * inverse_h;
      }
  }



  template <int dim>
  void
  BSplines<dim>::cell_values(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const Point<dim>                                        &xi,
    double                                                  *values,
    Tensor<1, dim>                                          *gradients) const
  {
    const auto &first = first_function(cell);
    double      value_1d[dim][max_degree + 1];
    double      derivative_1d[dim][max_degree + 1];
    for (unsigned int d = 0; d < dim; ++d)
      values_1d(d, first[d], xi[d], value_1d[d], derivative_1d[d]);

    const unsigned int n = local_multi_index.size();
    for (unsigned int local = 0; local < n; ++local)
      {
        const auto &a     = local_multi_index[local];
        double      value = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          value *= value_1d[d][a[d]];
        values[local] = value;
        for (unsigned int e = 0; e < dim; ++e)
          {
            double derivative = derivative_1d[e][a[e]];
            for (unsigned int d = 0; d < dim; ++d)
              if (d != e)
                derivative *= value_1d[d][a[d]];
            gradients[local][e] = derivative;
          }
      }
  }



  template <int dim>
  void
  BSplines<dim>::evaluate(const MaterialPoints<dim>         &material_points,
                          const Utilities::MPI::Partitioner &partitioner,
                          ParticleShapeData<dim>            &data) const
  {
    const auto        &particles   = material_points.particle_handler();
    const unsigned int n_local     = Utilities::fixed_power<dim>(p + 1);
    const unsigned int n_particles = particles.n_locally_owned_particles();

    data.reinit(n_particles, n_local);

    std::vector<types::global_dof_index>              global_indices(n_local);
    std::vector<unsigned int>                         local_indices(n_local);
    typename Triangulation<dim>::active_cell_iterator current_cell;

    for (const auto &particle : particles)
      {
        const auto cell = particle.get_surrounding_cell();
        if (cell != current_cell)
          {
            current_cell = cell;
            functions_on_cell(cell, global_indices);
            for (unsigned int i = 0; i < n_local; ++i)
              local_indices[i] = partitioner.global_to_local(global_indices[i]);
            data.start_batch(local_indices.data(), n_local);
          }
        const std::size_t offset = data.add_particle();
        cell_values(cell,
                    particle.get_reference_location(),
                    &data.values[offset],
                    &data.gradients[offset]);
      }
    data.finish();
  }



  template <int dim>
  IndexSet
  BSplines<dim>::boundary_functions(const types::boundary_id boundary_id) const
  {
    AssertThrow(boundary_id < 2 * dim,
                ExcMessage("B-splines know the sides 0 to 2 dim - 1 of the "
                           "box grid only."));
    const unsigned int direction = boundary_id / 2;
    const unsigned int layer =
      (boundary_id % 2 == 0) ? 0 : n_per_direction[direction] - 1;
    IndexSet result(n_functions());
    for (types::global_dof_index i = 0; i < n_functions(); ++i)
      if (multi_index(i)[direction] == layer)
        result.add_index(i);
    result.compress();
    return result;
  }



  template <int dim>
  bool
  BSplines<dim>::is_linearly_complete() const
  {
    return p == 1;
  }



  template <int dim>
  typename ShapeFunctions<dim>::MovingGrid
  BSplines<dim>::moving_grid() const
  {
    return ShapeFunctions<dim>::MovingGrid::knots;
  }



  template <int dim>
  bool
  BSplines<dim>::functions_in_box(
    const BoundingBox<dim>               &box,
    std::vector<types::global_dof_index> &functions) const
  {
    functions.clear();
    for (const auto global : locally_owned_functions())
      if (box.point_inside(greville_point(global), 1e-10))
        functions.push_back(global);
    return true;
  }



  template <int dim>
  bool
  BSplines<dim>::function_points(const Utilities::MPI::Partitioner &partitioner,
                                 std::vector<Point<dim>> &points) const
  {
    points.resize(partitioner.locally_owned_size() +
                  partitioner.n_ghost_indices());
    for (unsigned int local = 0; local < points.size(); ++local)
      points[local] = greville_point(partitioner.local_to_global(local));
    return true;
  }



  template <int dim>
  bool
  BSplines<dim>::boundary_integrals(const types::boundary_id boundary_id,
                                    VectorType              &integrals) const
  {
    const unsigned int direction = boundary_id / 2;
    AssertThrow(direction < dim, ExcInternalError());
    const auto knot = [&](const unsigned int d, const unsigned int k) {
      const unsigned int last = knots[d].size() - 1;
      return knots[d][std::min(k < p ? 0u : k - p, last)];
    };
    const unsigned int layer =
      (boundary_id % 2 == 0) ? 0 : n_functions_in_direction(direction) - 1;
    for (const auto global : locally_owned_functions())
      {
        const auto i = multi_index(global);
        if (i[direction] != layer)
          continue;
        double integral = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          if (d != direction)
            integral *= (knot(d, i[d] + p + 1) - knot(d, i[d])) / (p + 1);
        integrals[global] += integral;
      }
    return true;
  }



  template <int dim>
  Point<dim>
  BSplines<dim>::greville_point(const types::global_dof_index global) const
  {
    // The open knot vector of direction d repeats its end knots p times
    // more: U = (k_0, ..., k_0, k_0, k_1, ..., k_n, k_n, ..., k_n).
    // Function i has the knots U_i, ..., U_{i+p+1}.
    const auto knot = [&](const unsigned int d, const unsigned int k) {
      const unsigned int last = knots[d].size() - 1;
      return knots[d][std::min(k < p ? 0u : k - p, last)];
    };
    const auto i = multi_index(global);
    Point<dim> greville;
    for (unsigned int d = 0; d < dim; ++d)
      {
        for (unsigned int k = 1; k <= p; ++k)
          greville[d] += knot(d, i[d] + k);
        greville[d] /= p;
      }
    return greville;
  }



  template <int dim>
  types::global_dof_index
  BSplines<dim>::vertex_function(
    const typename Triangulation<dim>::active_cell_iterator &,
    const unsigned int) const
  {
    return numbers::invalid_dof_index;
  }



  template <int dim>
  const DoFHandler<dim> &
  BSplines<dim>::dof_handler() const
  {
    return dofs;
  }



  template <int dim>
  void
  BSplines<dim>::to_cell_dofs(const VectorType &coefficients,
                              VectorType       &values) const
  {
    IndexSet relevant_dofs;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant_dofs);
    values.reinit(dofs.locally_owned_dofs(),
                  relevant_dofs,
                  triangulation->get_communicator());

    const unsigned int                   q = p + 1;
    const unsigned int                   n = Utilities::fixed_power<dim>(q);
    std::vector<types::global_dof_index> functions(n), cell_dofs(n);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          functions_on_cell(cell, functions);
          cell->get_dof_indices(cell_dofs);
          const auto &first = first_function(cell);
          // beta_b = sum_a prod_d C^d[a_d][b_d] c_a.
          for (unsigned int b = 0; b < n; ++b)
            {
              const types::global_dof_index dof =
                cell_dofs[hierarchic_of_lexicographic[b]];
              if (!values.in_local_range(dof))
                continue;
              double sum = 0.;
              for (unsigned int a = 0; a < n; ++a)
                {
                  double       weight = coefficients(functions[a]);
                  unsigned int rest_a = a, rest_b = b;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      weight *= extraction[d][first[d] * q * q +
                                              (rest_a % q) * q + rest_b % q];
                      rest_a /= q;
                      rest_b /= q;
                    }
                  sum += weight;
                }
              values(dof) = sum;
            }
        }
    values.update_ghost_values();
  }



  template <int dim>
  unsigned int
  BSplines<dim>::degree() const
  {
    return p;
  }



  template <int dim>
  const std::vector<double> &
  BSplines<dim>::breakpoints(const unsigned int d) const
  {
    return knots[d];
  }



  template <int dim>
  unsigned int
  BSplines<dim>::n_functions_in_direction(const unsigned int d) const
  {
    return n_per_direction[d];
  }



  template <int dim>
  void
  BSplines<dim>::move_breakpoints(
    const std::array<std::vector<double>, dim> &breaks)
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        AssertDimension(breaks[d].size(), knots[d].size());
        knots[d] = breaks[d];
        compute_extraction(d);
      }
  }



  template class BSplines<1>;
  template class BSplines<2>;
  template class BSplines<3>;
} // namespace MpmOtm

#define MPM_OTM_B_SPLINE_DESCRIPTION                                   \
  "tensor-product B-splines of degree 'B-spline degree' on open knot " \
  "vectors, by Bezier extraction onto FE_Bernstein cells"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<1>,
                        MpmOtm::BSplines<1>,
                        "B-spline",
                        MPM_OTM_B_SPLINE_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<2>,
                        MpmOtm::BSplines<2>,
                        "B-spline",
                        MPM_OTM_B_SPLINE_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<3>,
                        MpmOtm::BSplines<3>,
                        "B-spline",
                        MPM_OTM_B_SPLINE_DESCRIPTION)
