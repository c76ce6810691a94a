// Local max-ent shape functions (journal Sect. 6.3, Eqs. 77-89) with the
// cubic-spline prior, d_max = 2, on the vertices of box grids in 1D, 2D and
// 3D, checked at random points inside
// the convex hull of the nodes against properties that hold exactly:
// - partition of unity and linear reproduction, sum_i phi_i x_i = x
//   (journal Eqs. 46-47), to 1e-12;
// - non-negativity;
// - gradients against central finite differences;
// - the weak Kronecker-delta property: the functions of the nodes off a
//   face of the hull vanish on it, linearly in the distance delta (linear
//   reproduction balances their weight, about delta / h, against the face
//   nodes'): at delta = 1e-3 h they sum to below 2e-3, so on the face the
//   field is that of the face's nodes alone and Dirichlet conditions on
//   boundary nodes act on the boundary;
// - the evaluation of all material points (evaluate(): each cell's list of
//   candidate nodes, or the R-tree for a point that has left its cell's
//   bounding box, as OTM points may) equals the evaluation point by point
//   (evaluate_at()), and the padded functions of a cell's list are zero;
// - on nodes of the hull's boundary (the end nodes in 1D; a face node and a
//   corner in 2D and 3D, and an edge node in 3D), reached with first guesses
//   from elsewhere: the functions of the nodes off the boundary vanish (weak
//   Kronecker delta; in 1D the end node's function is 1), and the gradients are
//   the limits from inside. In 1D these are exact: next to an end node x_e, at
//   distance delta inside, linear reproduction sum_k phi_k (x_k - x) = 0 leaves
//   phi_n = delta / h + O(delta^2) for the neighbour x_n at distance h, and
//   the functions beyond it are O(delta^2), so d phi_n / dx = -d phi_e / dx
//   = 1 / (x_n - x_e), whatever the prior. Checked against these values and
//   against one-sided second-order finite differences from inside.

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/max_ent.h>

#include <random>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  template <int dim>
  void
  check_properties(const unsigned int n_cells, const double support_factor)
  {
    auto simulator =
      make_unit_box_simulator<dim>(n_cells, "output-max-ent-grid");
    MaxEnt<dim> functions(support_factor);
    functions.initialize(simulator->background_grid());

    std::vector<types::global_dof_index> indices, shifted_indices;
    std::vector<double>                  values, shifted_values;
    std::vector<Tensor<1, dim>>          gradients, unused;
    std::mt19937                         random(7);
    std::uniform_real_distribution<>     uniform(0.01, 0.99);

    // Node positions, to check linear reproduction.
    std::vector<Point<dim>> node(functions.n_functions());
    for (const auto &cell : functions.dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        node[cell->vertex_dof_index(v, 0)] = cell->vertex(v);

    double unity = 0, reproduction = 0, fd = 0, negative = 0;
    for (unsigned int sample = 0; sample < 200; ++sample)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = uniform(random);
        const std::string failure =
          functions.evaluate_at(x, indices, values, gradients);
        check(failure.empty(), failure);
        double     sum = 0;
        Point<dim> first_moment;
        for (unsigned int k = 0; k < indices.size(); ++k)
          {
            sum += values[k];
            first_moment += values[k] * node[indices[k]];
            negative = std::min(negative, values[k]);
          }
        unity        = std::max(unity, std::abs(sum - 1.));
        reproduction = std::max(reproduction, first_moment.distance(x));

        const double eps = 1e-6;
        for (unsigned int d = 0; d < dim; ++d)
          {
            std::vector<double> plus(functions.n_functions()),
              minus(functions.n_functions());
            Point<dim> y = x;
            y[d] += eps;
            functions.evaluate_at(y, shifted_indices, shifted_values, unused);
            for (unsigned int k = 0; k < shifted_indices.size(); ++k)
              plus[shifted_indices[k]] = shifted_values[k];
            y[d] -= 2 * eps;
            functions.evaluate_at(y, shifted_indices, shifted_values, unused);
            for (unsigned int k = 0; k < shifted_indices.size(); ++k)
              minus[shifted_indices[k]] = shifted_values[k];
            for (unsigned int k = 0; k < indices.size(); ++k)
              fd = std::max(fd,
                            std::abs((plus[indices[k]] - minus[indices[k]]) /
                                       (2 * eps) -
                                     gradients[k][d]));
          }
      }
    // Weak Kronecker delta near the face x_0 = 0, at delta = 1e-3 h.
    double off_face = 0;
    for (unsigned int sample = 0; sample < 20; ++sample)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = uniform(random);
        x[0] = 1e-3 / n_cells;
        const std::string failure =
          functions.evaluate_at(x, indices, values, gradients);
        check(failure.empty(), failure);
        double sum = 0;
        for (unsigned int k = 0; k < indices.size(); ++k)
          if (node[indices[k]][0] > 1e-12)
            sum += values[k];
        off_face = std::max(off_face, sum);
      }

    deallog << dim << "D, " << n_cells
            << " cells per direction, d_max = " << std::fixed
            << std::setprecision(1) << support_factor << ": |sum - 1| < 1e-12 "
            << (unity < 1e-12) << ", linear reproduction < 1e-12 "
            << (reproduction < 1e-12) << ", min value >= 0 " << (negative >= 0.)
            << ", finite differences " << (fd < 1e-5)
            << ", weak Kronecker delta " << (off_face < 2e-3) << std::endl;
    check(off_face < 2e-3 && off_face > 0.,
          "weak Kronecker delta: " + rounded(off_face));
    check(unity < 1e-12, "partition of unity: " + rounded(unity));
    check(reproduction < 1e-12,
          "linear reproduction: " + rounded(reproduction));
    check(negative >= 0., "non-negativity: " + rounded(negative));
    check(fd < 1e-5, "gradients vs finite differences: " + rounded(fd));
  }

  /**
   * evaluate() on the material points of a unit box against evaluate_at(),
   * first with every point in its cell, then with the points of the lower
   * half moved 0.6 h in x off their cells (their cells stay), which takes
   * the R-tree path.
   */
  template <int dim>
  void
  check_point_pass(const unsigned int n_cells)
  {
    auto simulator =
      make_unit_box_simulator<dim>(n_cells, "output-max-ent-grid");
    MaxEnt<dim> functions(2.);
    functions.initialize(simulator->background_grid());
    const Utilities::MPI::Partitioner partitioner(
      functions.locally_owned_functions(),
      functions.locally_relevant_functions(),
      MPI_COMM_WORLD);
    // The test moves points off their cells as OTM's update may.
    auto &particles =
      const_cast<MaterialPoints<dim> &>(simulator->material_points())
        .particle_handler();

    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    std::vector<Tensor<1, dim>>          gradients;
    for (const bool moved : {false, true})
      {
        unsigned int n_moved = 0;
        if (moved)
          for (auto &particle : particles)
            {
              Point<dim> x = particle.get_location();
              if (x[0] < 0.5)
                {
                  x[0] += 0.6 / n_cells;
                  particle.set_location(x);
                  ++n_moved;
                }
            }
        ParticleShapeData<dim> data;
        functions.evaluate(simulator->material_points(), partitioner, data);
        double       difference = 0, padded = 0;
        unsigned int k = 0, n_entries = 0, missing = 0;
        typename ParticleShapeData<dim>::Cursor cursor(data);
        for (const auto &particle : particles)
          {
            const std::string failure =
              functions.evaluate_at(particle.get_location(),
                                    indices,
                                    values,
                                    gradients);
            check(failure.empty(), failure);
            const auto point = cursor.next();
            for (unsigned int e = 0; e < point.n; ++e)
              {
                const types::global_dof_index index =
                  partitioner.local_to_global(point.indices[e]);
                const auto found =
                  std::find(indices.begin(), indices.end(), index);
                if (found == indices.end())
                  padded = std::max({padded,
                                     std::abs(point.values[e]),
                                     point.gradients[e].norm()});
                else
                  {
                    const unsigned int j = found - indices.begin();
                    difference           = std::max(
                      {difference,
                                 std::abs(point.values[e] - values[j]),
                                 (point.gradients[e] - gradients[j]).norm() / n_cells});
                    ++n_entries;
                  }
              }
            // Every function that does not vanish at the point is listed.
            missing += indices.size() - n_entries;
            n_entries = 0;
            ++k;
          }
        deallog << dim << "D, "
                << (moved ? "points of the lower half moved "
                            "off their cells" :
                            "points in their cells")
                << ": evaluate() equals evaluate_at() to 1e-10 "
                << (difference < 1e-10) << ", padded functions zero "
                << (padded == 0.) << ", none missing " << (missing == 0)
                << std::endl;
        check(k == data.n_particles() && (!moved || n_moved > 0),
              "point count");
        check(difference < 1e-10,
              "evaluate() against evaluate_at(): " + rounded(difference));
        check(padded == 0., "padded function not zero: " + rounded(padded));
        check(missing == 0, "functions missing from a point's list");
      }
  }



  /**
   * The functions at a point @p x on the boundary of the hull against
   * one-sided second-order finite differences in the directions @p inward
   * (+1 or -1 per coordinate: the side of the hull), and the identities
   * sum_k grad phi_k = 0, sum_k x_k (grad phi_k)^T = I. Returns the largest
   * deviation relative to 1/h; the values and gradients at x are left in
   * @p indices, @p values, @p gradients.
   */
  template <int dim>
  double
  boundary_deviation(const MaxEnt<dim>                    &functions,
                     const Point<dim>                     &x,
                     const Tensor<1, dim>                 &inward,
                     const double                          h,
                     std::vector<types::global_dof_index> &indices,
                     std::vector<double>                  &values,
                     std::vector<Tensor<1, dim>>          &gradients)
  {
    const std::string failure =
      functions.evaluate_at(x, indices, values, gradients);
    check(failure.empty(), failure);
    double         deviation = 0;
    Tensor<1, dim> gradient_sum;
    Tensor<2, dim> moment;
    for (unsigned int k = 0; k < indices.size(); ++k)
      {
        gradient_sum += gradients[k];
        moment += outer_product(functions.node(indices[k]), gradients[k]);
      }
    deviation = std::max({deviation,
                          gradient_sum.norm() * h,
                          (moment - unit_symmetric_tensor<dim>()).norm()});

    // f'(x) = (-3 f(x) + 4 f(x + e) - f(x + 2 e)) / (2 e) + O(e^2); with
    // e = 1e-5 h the truncation error is about 1e-10 / h and the values'
    // error of 1e-12 (Newton's tolerance) adds 1e-7 / h.
    const double                         e = 1e-5 * h;
    std::vector<types::global_dof_index> shifted_indices;
    std::vector<double>                  shifted_values;
    std::vector<Tensor<1, dim>>          unused;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<double> one(functions.n_functions()),
          two(functions.n_functions());
        for (const unsigned int steps : {1u, 2u})
          {
            Point<dim> y = x;
            y[d] += steps * e * inward[d];
            const std::string shifted_failure =
              functions.evaluate_at(y, shifted_indices, shifted_values, unused);
            check(shifted_failure.empty(), shifted_failure);
            for (unsigned int k = 0; k < shifted_indices.size(); ++k)
              (steps == 1 ? one : two)[shifted_indices[k]] = shifted_values[k];
          }
        // The unshifted evaluation again: the shifted ones overwrote the
        // work arrays of evaluate_at() but not our copies.
        for (unsigned int k = 0; k < indices.size(); ++k)
          {
            const double fd =
              inward[d] *
              (-3. * values[k] + 4. * one[indices[k]] - two[indices[k]]) /
              (2. * e);
            deviation = std::max(deviation, std::abs(fd - gradients[k][d]) * h);
          }
      }
    return deviation;
  }



  /**
   * Max-ent functions with d_max = 2 on nodes of the unit box's boundary:
   * in the middle of the face x_0 = 0, on the edge x_0 = x_1 = 0 (3D) and
   * at the corner 0. Gradients against one-sided finite differences and
   * the consistency identities (sum grad phi = 0, sum x_i grad phi_i = I);
   * the functions of the nodes off the node's face, edge or corner vanish
   * (weak Kronecker delta).
   */
  template <int dim>
  void
  check_boundary_nodes_on_box(const unsigned int n_cells)
  {
    auto simulator =
      make_unit_box_simulator<dim>(n_cells, "output-max-ent-grid");
    MaxEnt<dim> functions(2.);
    functions.initialize(simulator->background_grid());
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    std::vector<Tensor<1, dim>>          gradients;
    Tensor<1, dim>                       inward;
    Point<dim>                           far_corner;
    for (unsigned int d = 0; d < dim; ++d)
      {
        inward[d]     = 1.;
        far_corner[d] = 1.;
      }
    double deviation = 0;
    // The node with the first n_zero coordinates 0 and the others 0.5.
    for (unsigned int n_zero = 1; n_zero <= dim; ++n_zero)
      {
        Point<dim> x;
        for (unsigned int d = n_zero; d < dim; ++d)
          x[d] = 0.5;
        check(
          functions.evaluate_at(far_corner, indices, values, gradients).empty(),
          "evaluation at the far corner failed");
        deviation = std::max(deviation,
                             boundary_deviation(functions,
                                                x,
                                                inward,
                                                1. / n_cells,
                                                indices,
                                                values,
                                                gradients));
        for (unsigned int k = 0; k < indices.size(); ++k)
          for (unsigned int d = 0; d < n_zero; ++d)
            if (functions.node(indices[k])[d] > 1e-12)
              deviation = std::max(deviation, values[k]);
      }
    deallog << dim << "D, " << n_cells << " cells per direction, on a face node"
            << (dim == 3 ? ", an edge node" : "")
            << " and a corner node: functions off them vanish, gradients "
               "against one-sided finite differences and the consistency "
               "identities to 1e-5/h "
            << (deviation < 1e-5) << std::endl;
    check(deviation < 1e-5,
          std::to_string(dim) + "D boundary nodes: " + rounded(deviation));
  }



  /**
   * Max-ent functions exactly on nodes of the hull's boundary: 1D end nodes
   * against the exact limits (see the top of the file), a side node and a
   * corner in 2D and 3D against one-sided finite differences. Each point is
   * evaluated right after a point elsewhere, whose multipliers are the
   * first guess (from the other end they are far off: this once gave H = 0
   * and NaN gradients).
   */
  void
  check_boundary_nodes()
  {
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    std::vector<Tensor<1, 1>>            gradients;
    for (const double support_factor : {2., 3.})
      {
        const unsigned int n_cells = 10;
        const double       h       = 1. / n_cells;
        auto               simulator =
          make_unit_box_simulator<1>(n_cells, "output-max-ent-grid");
        MaxEnt<1> functions(support_factor);
        functions.initialize(simulator->background_grid());
        double value_error = 0, exact_error = 0, fd_error = 0;
        for (const double start : {0.5, 1., 0.})
          for (const double end : {0., 1.})
            {
              std::vector<double>       unused_values;
              std::vector<Tensor<1, 1>> unused_gradients;
              check(functions
                      .evaluate_at(Point<1>(start),
                                   indices,
                                   unused_values,
                                   unused_gradients)
                      .empty(),
                    "evaluation at the first point failed");
              const double inward = (end == 0.) ? 1. : -1.;
              fd_error            = std::max(fd_error,
                                  boundary_deviation(functions,
                                                     Point<1>(end),
                                                     Tensor<1, 1>({inward}),
                                                     h,
                                                     indices,
                                                     values,
                                                     gradients));
              // Exact limits: the end node's function is 1 with slope
              // -inward / h, its neighbour's slope is inward / h, every
              // other function and slope vanishes.
              for (unsigned int k = 0; k < indices.size(); ++k)
                {
                  const double distance =
                    std::abs(functions.node(indices[k])[0] - end);
                  const double exact_value = (distance < 1e-12) ? 1. : 0.;
                  const double exact_slope = (distance < 1e-12) ? -inward / h :
                                             (std::abs(distance - h) < 1e-12) ?
                                                                  inward / h :
                                                                  0.;
                  value_error =
                    std::max(value_error, std::abs(values[k] - exact_value));
                  exact_error =
                    std::max(exact_error,
                             std::abs(gradients[k][0] - exact_slope) * h);
                }
            }
        deallog << "1D, " << n_cells << " cells, d_max = " << std::fixed
                << std::setprecision(1) << support_factor
                << ", on the end nodes: values 1 and 0 to 1e-11 "
                << (value_error < 1e-11)
                << ", slopes -+1/h and +-1/h of the end node and its "
                   "neighbour, 0 else, to 1e-9/h "
                << (exact_error < 1e-9)
                << ", one-sided finite differences to 1e-5/h "
                << (fd_error < 1e-5) << std::endl;
        check(value_error < 1e-11,
              "value on an end node: " + rounded(value_error));
        check(exact_error < 1e-9,
              "slope on an end node against the exact limit: " +
                rounded(exact_error));
        check(fd_error < 1e-5,
              "slope on an end node against finite differences: " +
                rounded(fd_error));
      }

    check_boundary_nodes_on_box<2>(6);
    check_boundary_nodes_on_box<3>(4);
  }



  /**
   * Bad input is reported, never a NaN: a point that too few supports
   * reach, and a point outside the convex hull of the nodes.
   */
  void
  check_errors()
  {
    auto      simulator = make_unit_box_simulator<1>(4, "output-max-ent-grid");
    MaxEnt<1> narrow(1.);
    narrow.initialize(simulator->background_grid());
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    std::vector<Tensor<1, 1>>            gradients;
    // With d_max = 1 a node's neighbours lie exactly on the edge of its
    // support (r = 1, zero weight): only one function reaches the node.
    const std::string too_few =
      narrow.evaluate_at(Point<1>(0.5), indices, values, gradients);
    deallog << "at a node with d_max = 1: " << too_few << std::endl;
    check(too_few.find("fewer than dim + 1") != std::string::npos &&
            too_few.find("Max-ent support factor") != std::string::npos,
          "no clear message for too few neighbours");

    MaxEnt<1> functions(2.);
    functions.initialize(simulator->background_grid());
    const std::string outside =
      functions.evaluate_at(Point<1>(1.01), indices, values, gradients);
    deallog << "outside the nodes: " << outside << std::endl;
    check(outside.find("convex hull") != std::string::npos,
          "no clear message outside the convex hull");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  check_errors();
  check_boundary_nodes();
  check_properties<1>(8, 2.);
  check_properties<1>(8, 3.);
  check_properties<2>(6, 2.);
  check_properties<2>(6, 3.);
  check_properties<3>(4, 2.);
  check_point_pass<1>(8);
  check_point_pass<2>(6);
}
