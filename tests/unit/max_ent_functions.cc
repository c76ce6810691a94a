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
//   (evaluate_at()), and the padded functions of a cell's list are zero.

#include <mpm_otm/grid_system/background_grid.h>
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
        for (const auto &particle : particles)
          {
            const std::string failure =
              functions.evaluate_at(particle.get_location(),
                                    indices,
                                    values,
                                    gradients);
            check(failure.empty(), failure);
            for (unsigned int e = data.offsets[k]; e < data.offsets[k + 1]; ++e)
              {
                const types::global_dof_index index =
                  partitioner.local_to_global(data.indices[e]);
                const auto found =
                  std::find(indices.begin(), indices.end(), index);
                if (found == indices.end())
                  padded = std::max({padded,
                                     std::abs(data.values[e]),
                                     data.gradients[e].norm()});
                else
                  {
                    const unsigned int j = found - indices.begin();
                    difference           = std::max(
                      {difference,
                                 std::abs(data.values[e] - values[j]),
                                 (data.gradients[e] - gradients[j]).norm() / n_cells});
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
  check_properties<1>(8, 2.);
  check_properties<1>(8, 3.);
  check_properties<2>(6, 2.);
  check_properties<2>(6, 3.);
  check_properties<3>(4, 2.);
  check_point_pass<1>(8);
  check_point_pass<2>(6);
}
