#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/base/node_memory.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/cell_locator.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/seeding_bodies.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <numeric>
#include <random>
#include <sstream>

// Seeding the material points (MaterialPoints::seed()): the patterns of
// points in a block or cell, the check of their memory, and the points'
// initial properties.

namespace MpmOtm
{
  namespace
  {
    /**
     * Point @p local of the seeding pattern of a block, in the block's unit
     * coordinates: the centres of the cells of a regular subdivision with
     * @p n_per_direction cells per direction, the first direction fastest.
     */
    template <int dim>
    Point<dim>
    block_reference_point(const std::uint64_t              local,
                          const std::vector<unsigned int> &n_per_direction)
    {
      Point<dim>    reference;
      std::uint64_t rest = local;
      for (unsigned int d = 0; d < dim; ++d)
        {
          reference[d] = (rest % n_per_direction[d] + 0.5) / n_per_direction[d];
          rest /= n_per_direction[d];
        }
      return reference;
    }

    /**
     * The centres of the n^dim squares/cubes of side 1/n that subdivide the
     * reference square/cube, in lexicographic order.
     */
    template <int dim>
    std::vector<Point<dim>>
    hypercube_pattern(const unsigned int n)
    {
      std::vector<Point<dim>> points(Utilities::fixed_power<dim>(n));
      for (unsigned int local = 0; local < points.size(); ++local)
        points[local] =
          block_reference_point<dim>(local, std::vector<unsigned int>(dim, n));
      return points;
    }

    /**
     * The centroids of the n^dim simplices of equal measure that subdivide
     * the reference simplex {xi >= 0, sum xi <= 1} regularly: in 2D the
     * triangles between the lines xi_0 = k/n, xi_1 = k/n and xi_0 + xi_1 =
     * k/n; in 3D Freudenthal's subdivision. Constructed as Kuhn's
     * triangulation of the unit cubes of y-space, where the scaled simplex is
     * n >= y_0 >= y_1 >= ... >= 0 and xi_k = (y_k - y_(k+1)) / n (a map of
     * determinant 1 / n^dim that takes simplices to simplices and centroids
     * to centroids).
     */
    template <int dim>
    std::vector<Point<dim>>
    simplex_pattern(const unsigned int n)
    {
      std::vector<Point<dim>>       points;
      std::array<unsigned int, dim> corner;
      std::array<unsigned int, dim> order;
      // Every corner n > c_0 >= c_1 >= ... >= c_(dim-1) >= 0.
      const std::function<void(unsigned int)> next_corner =
        [&](const unsigned int k) {
          if (k < dim)
            {
              const unsigned int top = (k == 0 ? n - 1 : corner[k - 1]);
              for (corner[k] = 0; corner[k] <= top; ++corner[k])
                next_corner(k + 1);
              return;
            }
          // Kuhn simplex u_order[0] >= u_order[1] >= ...: inside the
          // region if k comes before k + 1 wherever c_k = c_(k+1).
          for (unsigned int d = 0; d < dim; ++d)
            order[d] = d;
          do
            {
              std::array<unsigned int, dim> position;
              for (unsigned int j = 0; j < dim; ++j)
                position[order[j]] = j;
              bool inside = true;
              for (unsigned int d = 0; d + 1 < dim; ++d)
                if (corner[d] == corner[d + 1] && position[d] > position[d + 1])
                  inside = false;
              if (!inside)
                continue;
              std::array<double, dim> y;
              for (unsigned int d = 0; d < dim; ++d)
                y[d] = corner[d] + double(dim - position[d]) / (dim + 1);
              Point<dim> xi;
              for (unsigned int d = 0; d < dim; ++d)
                xi[d] = (d + 1 < dim ? y[d] - y[d + 1] : y[d]) / n;
              points.push_back(xi);
          } while (std::next_permutation(order.begin(), order.end()));
        };
      next_corner(0);
      AssertDimension(points.size(), Utilities::fixed_power<dim>(n));
      return points;
    }
  } // namespace



  template <int dim>
  void
  MaterialPoints<dim>::seed(const BackgroundGrid<dim> &background,
                            const SeedingBodies<dim>  &bodies)
  {
    grid = &background;
    particles =
      std::make_unique<Particles::ParticleHandler<dim>>(grid->triangulation(),
                                                        grid->mapping(),
                                                        bodies.n_properties());
    particles->signals.particle_lost.connect(
      [this](const typename Particles::ParticleIterator<dim> &particle,
             const typename Triangulation<dim>::active_cell_iterator &) {
        lost_points.emplace_back(particle->get_id(), particle->get_location());
      });
    if (grid->is_simplex() || !grid->is_box())
      locator = std::make_unique<CellLocator<dim>>(grid->triangulation(),
                                                   grid->mapping());
    insert_pattern(bodies);
    if (!grid->is_box())
      return;

    // Every traction boundary must lie on a block boundary and have received
    // boundary points.
    const Point<dim> lower  = grid->box().get_boundary_points().first;
    const auto      &blocks = grid->subdivisions();
    for (const auto id : bodies.traction_boundaries())
      {
        const BoundingBox<dim> region = bodies.material_region();
        const unsigned int     d      = id / 2;
        const double           face   = (id % 2 == 0) ?
                                          region.get_boundary_points().first[d] :
                                          region.get_boundary_points().second[d];
        const double           blocks_to_face =
          (face - lower[d]) / (grid->box().side_length(d) / blocks[d]);
        AssertThrow(
          std::abs(blocks_to_face - std::round(blocks_to_face)) < 1e-8,
          ExcMessage("The material region's side carrying traction boundary " +
                     std::to_string(id) +
                     " must lie on a block boundary of the grid (see "
                     "Mesh/Subdivisions)."));
        unsigned int n = 0;
        for (const auto &particle : *particles)
          {
            const auto properties = particle.get_properties();
            if (properties[PropertyLayout<dim>::traction_measure] > 0. &&
                properties[PropertyLayout<dim>::traction_boundary] == id)
              ++n;
          }
        AssertThrow(Utilities::MPI::sum(n, communicator()) > 0,
                    ExcMessage(
                      "No material point lies next to traction boundary " +
                      std::to_string(id) +
                      ": the material region must end on a block boundary "
                      "of the grid on that side (check the problem's "
                      "material region and Mesh/Subdivisions)."));
      }
  }



  template <int dim>
  void
  MaterialPoints<dim>::add(const SeedingBodies<dim> &bodies)
  {
    Assert(particles, ExcMessage("add() needs seed() first."));
    insert_pattern(bodies);
  }



  template <int dim>
  void
  MaterialPoints<dim>::insert_pattern(const SeedingBodies<dim> &bodies)
  {
    check_memory(bodies);
    points_per_body.assign(bodies.n_bodies(), 0);
    points_outside_bodies = 0;
    if (!grid->is_box())
      {
        insert_points_of_cells(bodies);
        particles->update_cached_numbers();
        Utilities::MPI::sum(points_per_body, communicator(), points_per_body);
        points_outside_bodies =
          Utilities::MPI::sum(points_outside_bodies, communicator());
        check_every_body_has_points(bodies);
        return;
      }

    const Point<dim> lower  = grid->box().get_boundary_points().first;
    const auto      &blocks = grid->subdivisions();

    std::vector<unsigned int> block(dim);
    if (!grid->is_simplex())
      {
        owned_cell_of_block.assign(
          std::accumulate(blocks.begin(),
                          blocks.end(),
                          1u,
                          std::multiplies<unsigned int>()),
          typename Triangulation<dim>::active_cell_iterator());
        for (const auto &cell : grid->triangulation().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const Point<dim> centre = cell->center();
              unsigned int     linear = 0;
              for (unsigned int d = dim; d-- > 0;)
                {
                  block[d] = static_cast<unsigned int>(
                    std::floor((centre[d] - lower[d]) /
                               (grid->box().side_length(d) / blocks[d])));
                  linear = linear * blocks[d] + block[d];
                }
              owned_cell_of_block[linear] = cell;
              insert_points_of_block(block, cell, bodies);
            }
      }
    else
      {
        // The blocks with a cell of this rank (on one rank: all), in order.
        const unsigned int n_blocks =
          std::accumulate(blocks.begin(),
                          blocks.end(),
                          1u,
                          std::multiplies<unsigned int>());
        std::vector<bool> block_has_owned_cell(n_blocks, false);
        for (const auto &cell : grid->triangulation().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const Point<dim> centre = cell->center();
              unsigned int     linear = 0;
              for (unsigned int d = dim; d-- > 0;)
                linear = linear * blocks[d] +
                         std::min(blocks[d] - 1,
                                  static_cast<unsigned int>(std::floor(
                                    (centre[d] - lower[d]) /
                                    (grid->box().side_length(d) / blocks[d]))));
              block_has_owned_cell[linear] = true;
            }
        for (unsigned int linear = 0; linear < n_blocks; ++linear)
          if (block_has_owned_cell[linear])
            {
              unsigned int rest = linear;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  block[d] = rest % blocks[d];
                  rest /= blocks[d];
                }
              insert_points_of_block(
                block,
                typename Triangulation<dim>::active_cell_iterator(),
                bodies);
            }
      }
    particles->update_cached_numbers();

    Utilities::MPI::sum(points_per_body, communicator(), points_per_body);
    points_outside_bodies =
      Utilities::MPI::sum(points_outside_bodies, communicator());
    check_every_body_has_points(bodies);
  }



  template <int dim>
  void
  MaterialPoints<dim>::check_memory(const SeedingBodies<dim> &bodies) const
  {
    // What a point takes at least in deal.II's particle handler: its
    // location, reference location, id, properties and handle. The whole
    // run takes 320 to 370 bytes per point with linear functions and 18
    // properties (doc/performance.md, "Memory of the grid").
    const double bytes_per_point =
      sizeof(double) * (2 * dim + bodies.n_properties()) +
      sizeof(types::particle_index) + sizeof(unsigned int);
    const NodeMemory memory(communicator());

    const bool          box     = grid->is_box();
    const bool          simplex = grid->is_simplex();
    const std::uint64_t pattern_per_cell =
      std::accumulate(n_per_direction.begin(),
                      n_per_direction.end(),
                      std::uint64_t(1),
                      std::multiplies<std::uint64_t>());
    // The seeded cells: blocks of a box grid (of simplices: an equal share
    // of all blocks per rank), else the locally owned cells.
    const std::vector<unsigned int> blocks =
      box ? grid->subdivisions() : std::vector<unsigned int>();
    std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
    for (const auto &cell : grid->triangulation().active_cell_iterators())
      if (cell->is_locally_owned() && !(box && simplex))
        cells.push_back(cell);
    const double n_cells = (box && simplex) ?
                             std::accumulate(blocks.begin(),
                                             blocks.end(),
                                             1.,
                                             std::multiplies<double>()) :
                             cells.size();
    const double n_pattern =
      n_cells * pattern_per_cell /
      ((box && simplex) ? Utilities::MPI::n_mpi_processes(communicator()) : 1);

    // If the whole pattern could not fit, estimate the fraction of it that
    // lies in the bodies from pattern points drawn at random (counting them
    // all could take minutes): the estimate of the bytes errs by a few per
    // cent, far less than the factor of about two between bytes_per_point
    // and what a point takes in a run.
    const unsigned int n_samples = 1u << 18;
    double             n_points  = n_pattern;
    bool               estimated = false;
    std::string        too_long;
    if (memory.available() > 0. &&
        memory.sum_on_node(n_pattern * bytes_per_point) > memory.available())
      {
        estimated = true;
        std::vector<Point<dim>> simplex_points;
        if (simplex && !box)
          {
            if (pattern_per_cell * sizeof(Point<dim>) < memory.available() / 4)
              simplex_points = simplex_pattern<dim>(n_per_direction[0]);
            else
              too_long = "Particles/Particles per cell: the seeding pattern "
                         "of a simplex has " +
                         Utilities::to_string(double(pattern_per_cell)) +
                         " points, whose list alone needs a quarter or more "
                         "of the memory available on this node. ";
          }
        const Point<dim> lower = grid->box().get_boundary_points().first;
        std::mt19937_64  random(2026);
        std::uniform_int_distribution<std::uint64_t> pick_cell(
          0,
          std::uint64_t(n_cells) - 1);
        std::uniform_int_distribution<std::uint64_t> pick_point(
          0,
          pattern_per_cell - 1);
        unsigned int inside = 0;
        for (unsigned int sample = 0;
             n_cells > 0 && too_long.empty() && sample < n_samples;
             ++sample)
          {
            const std::uint64_t cell_index = pick_cell(random);
            const std::uint64_t q          = pick_point(random);
            Point<dim>          X;
            if (box)
              {
                // The block of the cell and the point in it.
                std::uint64_t rest = cell_index;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    double block;
                    if (simplex)
                      {
                        block = rest % blocks[d];
                        rest /= blocks[d];
                      }
                    else
                      block =
                        std::floor((cells[cell_index]->center()[d] - lower[d]) /
                                   (grid->box().side_length(d) / blocks[d]));
                    X[d] = lower[d] +
                           (block +
                            block_reference_point<dim>(q, n_per_direction)[d]) *
                             grid->box().side_length(d) / blocks[d];
                  }
              }
            else
              X = grid->mapping().transform_unit_to_real_cell(
                cells[cell_index],
                simplex ? simplex_points[q] :
                          block_reference_point<dim>(q, n_per_direction));
            if (bodies.body_containing(X) != numbers::invalid_unsigned_int)
              ++inside;
          }
        n_points = n_pattern * inside / n_samples;
      }

    const double       on_node  = memory.sum_on_node(n_points);
    const std::string  shortage = memory.shortage(on_node * bytes_per_point);
    std::ostringstream message;
    message << std::setprecision(3) << too_long;
    if (too_long.empty() && !shortage.empty())
      message << "Particles/Particles per cell: " << (estimated ? "about " : "")
              << on_node << " points of the seeding pattern lie in the bodies"
              << (estimated ? " (estimated from " + std::to_string(n_samples) +
                                " pattern points per rank drawn at random)" :
                              "")
              << "; at " << bytes_per_point
              << " bytes or more each (position, reference position, id and "
              << bodies.n_properties() << " properties) they need about "
              << shortage;
    stop_if_any_rank_failed(communicator(),
                            message.str(),
                            "",
                            "Use fewer Particles per cell, a coarser grid or "
                            "smaller bodies, or run on more nodes.");
  }



  template <int dim>
  void
  MaterialPoints<dim>::check_every_body_has_points(
    const SeedingBodies<dim> &bodies) const
  {
    for (unsigned int body = 0; body < points_per_body.size(); ++body)
      AssertThrow(points_per_body[body] > 0,
                  ExcMessage(bodies.body_name(body) +
                             " received no material point: no point of the "
                             "seeding pattern (Particles/Particles per cell "
                             "per direction in each " +
                             (grid->is_box() ? "block of the grid" :
                                               "cell of the Mesh file") +
                             ") lies in it. Check that it lies inside the "
                             "grid (Mesh) and is larger than the point "
                             "spacing, or seed more points."));
  }



  template <int dim>
  void
  MaterialPoints<dim>::insert_points_of_cells(const SeedingBodies<dim> &bodies)
  {
    const std::string file = "Mesh/Mesh file (<" + grid->mesh_file() + ">)";
    AssertThrow(bodies.traction_boundaries().empty(),
                ExcMessage("Custom problem/Traction boundary ids: tractions "
                           "act on the sides of a box material region on a "
                           "box grid, not on a " +
                           file +
                           "; prescribe a velocity (a Boundary of Type = "
                           "velocity) or a body force instead."));
    for (unsigned int d = 1; d < dim; ++d)
      AssertThrow(n_per_direction[d] == n_per_direction[0],
                  ExcMessage("Particles/Particles per cell: with a " + file +
                             " give one value (n points per direction of "
                             "each cell's reference cell, whose directions "
                             "are not the coordinate directions), not one "
                             "per direction."));
    const unsigned int      n       = n_per_direction[0];
    const bool              simplex = grid->is_simplex();
    std::vector<Point<dim>> reference =
      simplex ? simplex_pattern<dim>(n) : hypercube_pattern<dim>(n);
    const unsigned int                  n_pattern = reference.size();
    std::unique_ptr<FiniteElement<dim>> fe;
    if (simplex)
      fe = std::make_unique<FE_SimplexP<dim>>(1);
    else
      fe = std::make_unique<FE_Q<dim>>(1);
    FEValues<dim> pattern(grid->mapping(),
                          *fe,
                          Quadrature<dim>(reference,
                                          std::vector<double>(n_pattern,
                                                              1. / n_pattern)),
                          update_quadrature_points | update_JxW_values);

    std::vector<double> properties(bodies.n_properties(), 0.);
    for (const auto &cell : grid->triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          pattern.reinit(cell);
          // V_p = |J(xi_p)| |cell| / sum_q |J(xi_q)|: the measure of the
          // point's part of the cell (exact for bilinear quadrilaterals,
          // whose |J| is affine), and |cell| / n^dim on affine cells.
          double sum = 0;
          for (unsigned int q = 0; q < n_pattern; ++q)
            sum += pattern.JxW(q);
          const double measure = cell->measure();
          for (unsigned int q = 0; q < n_pattern; ++q)
            {
              const Point<dim>   X    = pattern.quadrature_point(q);
              const unsigned int body = bodies.body_containing(X);
              if (body == numbers::invalid_unsigned_int)
                {
                  ++points_outside_bodies;
                  continue;
                }
              ++points_per_body[body];
              bodies.set_properties(X,
                                    body,
                                    measure * pattern.JxW(q) / sum,
                                    properties);
              // Numbered by the cell of the coarse mesh, so that the
              // numbers do not depend on the number of ranks.
              particles->insert_particle(X,
                                         reference[q],
                                         static_cast<types::particle_index>(
                                           cell->id().get_coarse_cell_id()) *
                                             n_pattern +
                                           q,
                                         cell,
                                         ArrayView<const double>(properties));
            }
        }
  }



  template <int dim>
  void
  MaterialPoints<dim>::insert_points_of_block(
    const std::vector<unsigned int>                         &block,
    const typename Triangulation<dim>::active_cell_iterator &block_cell,
    const SeedingBodies<dim>                                &bodies)
  {
    using Layout             = PropertyLayout<dim>;
    const auto &blocks       = grid->subdivisions();
    const auto  grid_lower   = grid->box().get_boundary_points().first;
    const auto  traction_ids = bodies.traction_boundaries();
    const auto  region =
      traction_ids.empty() ? BoundingBox<dim>() : bodies.material_region();

    unsigned int   points_per_block = 1;
    double         block_volume     = 1;
    unsigned int   block_index      = 0;
    Point<dim>     block_lower;
    Tensor<1, dim> block_size;
    for (int d = dim - 1; d >= 0; --d)
      {
        points_per_block *= n_per_direction[d];
        block_size[d] = grid->box().side_length(d) / blocks[d];
        block_volume *= block_size[d];
        block_lower[d] = grid_lower[d] + block[d] * block_size[d];
        block_index    = block_index * blocks[d] + block[d];
      }
    const double volume = block_volume / points_per_block;

    std::vector<double> properties(bodies.n_properties(), 0.);
    typename Triangulation<dim>::active_cell_iterator hint;
    for (unsigned int local = 0; local < points_per_block; ++local)
      {
        Point<dim> reference =
          block_reference_point<dim>(local, n_per_direction);
        Point<dim> X;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = block_lower[d] + reference[d] * block_size[d];

        // On hypercube grids the block is the cell and the reference
        // coordinates are those within the block. Of the simplices of a
        // block, a point belongs to the rank that owns it.
        typename Triangulation<dim>::active_cell_iterator cell = block_cell;
        if (grid->is_simplex())
          {
            const auto found = locator->owning(X, locator->find(X, hint));
            AssertThrow(found.first.state() == IteratorState::valid,
                        ExcInternalError());
            hint = found.first;
            if (!found.first->is_locally_owned())
              continue;
            cell      = found.first;
            reference = found.second;
          }

        const unsigned int body = bodies.body_containing(X);
        if (body == numbers::invalid_unsigned_int)
          {
            ++points_outside_bodies;
            continue;
          }
        ++points_per_body[body];

        bodies.set_properties(X, body, volume, properties);
        // Boundary particles (thesis Sect. 2.4.1): the outermost layer next
        // to a traction boundary represents the boundary measure V_p / spacing.
        for (const auto id : traction_ids)
          {
            const unsigned int d       = id / 2;
            const double       spacing = block_size[d] / n_per_direction[d];
            const double       face    = (id % 2 == 0) ?
                                           region.get_boundary_points().first[d] :
                                           region.get_boundary_points().second[d];
            if (std::abs(X[d] - face) < 0.5001 * spacing &&
                properties[Layout::traction_measure] == 0.)
              {
                properties[Layout::traction_measure]  = volume / spacing;
                properties[Layout::traction_boundary] = id;
              }
          }

        particles->insert_particle(
          X,
          reference,
          static_cast<types::particle_index>(block_index) * points_per_block +
            local,
          cell,
          ArrayView<const double>(properties));
      }
  }



  template void
  MaterialPoints<1>::seed(const BackgroundGrid<1> &, const SeedingBodies<1> &);
  template void
  MaterialPoints<2>::seed(const BackgroundGrid<2> &, const SeedingBodies<2> &);
  template void
  MaterialPoints<3>::seed(const BackgroundGrid<3> &, const SeedingBodies<3> &);
  template void
  MaterialPoints<1>::add(const SeedingBodies<1> &);
  template void
  MaterialPoints<2>::add(const SeedingBodies<2> &);
  template void
  MaterialPoints<3>::add(const SeedingBodies<3> &);
} // namespace MpmOtm
