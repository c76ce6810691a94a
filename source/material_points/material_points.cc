#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/problem.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * Barycentric coordinates (the reference coordinates of deal.II's
     * simplex) of @p point in the affine simplex @p cell.
     */
    template <int dim>
    Point<dim>
    barycentric(const typename Triangulation<dim>::active_cell_iterator &cell,
                const Point<dim>                                        &point)
    {
      Tensor<2, dim> jacobian;
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int a = 0; a < dim; ++a)
          jacobian[a][d] = cell->vertex(d + 1)[a] - cell->vertex(0)[a];
      return Point<dim>(invert(jacobian) * (point - cell->vertex(0)));
    }

    template <int dim>
    bool
    inside_simplex(const Point<dim> &xi)
    {
      double sum = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (xi[d] < -1e-12)
            return false;
          sum += xi[d];
        }
      return sum <= 1. + 1e-12;
    }

    /**
     * The simplex that contains @p point and the point's barycentric
     * coordinates there: the hint, the cells that share a vertex with it,
     * deal.II's search (whose inside test is the one of quadrilaterals in
     * 9.4, so its answer is checked), its vertex neighbours, and at last
     * every cell. An invalid iterator if no cell contains the point.
     */
    template <int dim>
    std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
    find_simplex(const GridTools::Cache<dim, dim>                        &cache,
                 const Point<dim>                                        &point,
                 const typename Triangulation<dim>::active_cell_iterator &hint)
    {
      using Iterator      = typename Triangulation<dim>::active_cell_iterator;
      const auto try_cell = [&](const Iterator &cell, Point<dim> &xi) {
        xi = barycentric<dim>(cell, point);
        return inside_simplex(xi);
      };
      const auto try_vertex_neighbours =
        [&](const Iterator &cell, Iterator &found, Point<dim> &xi) {
          const auto &vertex_to_cells = cache.get_vertex_to_cell_map();
          for (const unsigned int v : cell->vertex_indices())
            for (const auto &neighbour : vertex_to_cells[cell->vertex_index(v)])
              if (try_cell(neighbour, xi))
                {
                  found = neighbour;
                  return true;
                }
          return false;
        };

      Point<dim> xi;
      Iterator   found;
      if (hint.state() == IteratorState::valid)
        {
          if (try_cell(hint, xi))
            return {hint, xi};
          if (try_vertex_neighbours(hint, found, xi))
            return {found, xi};
        }
      const auto guess = GridTools::find_active_cell_around_point(cache, point);
      if (guess.first.state() == IteratorState::valid)
        {
          if (try_cell(guess.first, xi))
            return {guess.first, xi};
          if (try_vertex_neighbours(guess.first, found, xi))
            return {found, xi};
        }
      for (const auto &cell : cache.get_triangulation().active_cell_iterators())
        if (try_cell(cell, xi))
          return {cell, xi};
      return {Iterator(), xi};
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
        for (unsigned int d = 0, rest = local; d < dim; ++d, rest /= n)
          points[local][d] = (rest % n + 0.5) / n;
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
  MaterialPoints<dim>::MaterialPoints() = default;



  template <int dim>
  MaterialPoints<dim>::~MaterialPoints() = default;



  template <int dim>
  void
  MaterialPoints<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Particles");
    // 12 in 1D is the default benchmark's (B1b); 2 x 2 or 2 x 2 x 2 per
    // cell is the common choice of MPM codes and of G1-G4.
    prm.declare_entry("Particles per cell",
                      dim == 1 ? "12" : "2",
                      Patterns::List(Patterns::Integer(1)),
                      "Material points per direction in each block of the "
                      "background grid (a cell for hypercubes, a block of "
                      "four triangles for simplices), placed at the centres "
                      "of a regular subdivision of the block. One value for "
                      "all directions or one per direction, e.g. '16, 14'. "
                      "Default: 12 in 1D (benchmark B1b), 2 in 2D and 3D "
                      "(4 or 8 points per cell).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  MaterialPoints<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Particles");
    const auto values = Utilities::string_to_int(
      Utilities::split_string_list(prm.get("Particles per cell")));
    prm.leave_subsection();
    AssertThrow(values.size() == 1 || values.size() == dim,
                ExcMessage("Particles/Particles per cell needs one value or " +
                           std::to_string(dim) +
                           " values (one per direction)."));
    n_per_direction.assign(dim, values[0]);
    if (values.size() == dim)
      n_per_direction.assign(values.begin(), values.end());
  }



  template <int dim>
  void
  MaterialPoints<dim>::seed(const BackgroundGrid<dim>  &background,
                            const MaterialLibrary<dim> &materials,
                            const Problem<dim>         &problem)
  {
    grid      = &background;
    particles = std::make_unique<Particles::ParticleHandler<dim>>(
      grid->triangulation(),
      grid->mapping(),
      materials.n_properties());
    particles->signals.particle_lost.connect(
      [this](const typename Particles::ParticleIterator<dim> &particle,
             const typename Triangulation<dim>::active_cell_iterator &) {
        lost_points.emplace_back(particle->get_id(), particle->get_location());
      });
    if (grid->is_simplex())
      cache =
        std::make_unique<GridTools::Cache<dim, dim>>(grid->triangulation(),
                                                     grid->mapping());

    points_per_body.assign(problem.n_bodies(), 0);
    points_outside_bodies = 0;
    if (!grid->is_box())
      {
        insert_points_of_cells(materials, problem);
        particles->update_cached_numbers();
        Utilities::MPI::sum(points_per_body, communicator(), points_per_body);
        points_outside_bodies =
          Utilities::MPI::sum(points_outside_bodies, communicator());
        check_every_body_has_points(problem);
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
              insert_points_of_block(block, cell, materials, problem);
            }
      }
    else
      {
        const unsigned int n_blocks =
          std::accumulate(blocks.begin(),
                          blocks.end(),
                          1u,
                          std::multiplies<unsigned int>());
        for (unsigned int linear = 0; linear < n_blocks; ++linear)
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
              materials,
              problem);
          }
      }
    particles->update_cached_numbers();

    Utilities::MPI::sum(points_per_body, communicator(), points_per_body);
    points_outside_bodies =
      Utilities::MPI::sum(points_outside_bodies, communicator());
    check_every_body_has_points(problem);

    // Every traction boundary must lie on a block boundary and have received
    // boundary points.
    for (const auto id : problem.traction_boundaries())
      {
        const BoundingBox<dim> region = problem.material_region();
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
  MaterialPoints<dim>::check_every_body_has_points(
    const Problem<dim> &problem) const
  {
    for (unsigned int body = 0; body < points_per_body.size(); ++body)
      AssertThrow(points_per_body[body] > 0,
                  ExcMessage(problem.body_name(body) +
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
  MaterialPoints<dim>::set_point_properties(
    const Point<dim>           &X,
    const unsigned int          body,
    const double                volume,
    const MaterialLibrary<dim> &materials,
    const Problem<dim>         &problem,
    std::vector<double>        &properties) const
  {
    using Layout = PropertyLayout<dim>;
    std::fill(properties.begin(), properties.end(), 0.);
    const unsigned int material_id  = problem.material_id(body);
    properties[Layout::material_id] = material_id;
    properties[Layout::mass]        = materials[material_id].density() * volume;
    const auto [sigma, out_of_plane] = problem.initial_stress(X, body);
    Layout::set_stress(ArrayView<double>(properties), sigma);
    if (dim < 3)
      properties[Layout::out_of_plane_stress] = out_of_plane;
    properties[Layout::initial_volume] = volume;
    const Tensor<1, dim> v0            = problem.initial_velocity(X);
    for (unsigned int d = 0; d < dim; ++d)
      {
        properties[Layout::initial_position + d]               = X[d];
        properties[Layout::velocity + d]                       = v0[d];
        properties[Layout::deformation_gradient + d * dim + d] = 1.;
      }
  }



  template <int dim>
  void
  MaterialPoints<dim>::insert_points_of_cells(
    const MaterialLibrary<dim> &materials,
    const Problem<dim>         &problem)
  {
    const std::string file = "Mesh/Mesh file (<" + grid->mesh_file() + ">)";
    AssertThrow(problem.traction_boundaries().empty(),
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

    std::vector<double> properties(materials.n_properties(), 0.);
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
              const unsigned int body = problem.body_containing(X);
              if (body == numbers::invalid_unsigned_int)
                {
                  ++points_outside_bodies;
                  continue;
                }
              ++points_per_body[body];
              set_point_properties(X,
                                   body,
                                   measure * pattern.JxW(q) / sum,
                                   materials,
                                   problem,
                                   properties);
              particles->insert_particle(X,
                                         reference[q],
                                         static_cast<types::particle_index>(
                                           cell->global_active_cell_index()) *
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
    const MaterialLibrary<dim>                              &materials,
    const Problem<dim>                                      &problem)
  {
    using Layout             = PropertyLayout<dim>;
    const auto &blocks       = grid->subdivisions();
    const auto  grid_lower   = grid->box().get_boundary_points().first;
    const auto  traction_ids = problem.traction_boundaries();
    const auto  region =
      traction_ids.empty() ? BoundingBox<dim>() : problem.material_region();

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

    std::vector<double> properties(materials.n_properties(), 0.);
    typename Triangulation<dim>::active_cell_iterator hint;
    for (unsigned int local = 0; local < points_per_block; ++local)
      {
        Point<dim>   reference;
        unsigned int rest = local;
        for (unsigned int d = 0; d < dim; ++d)
          {
            reference[d] =
              (rest % n_per_direction[d] + 0.5) / n_per_direction[d];
            rest /= n_per_direction[d];
          }
        Point<dim> X;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = block_lower[d] + reference[d] * block_size[d];
        const unsigned int body = problem.body_containing(X);
        if (body == numbers::invalid_unsigned_int)
          {
            ++points_outside_bodies;
            continue;
          }
        ++points_per_body[body];

        // On hypercube grids the block is the cell and the reference
        // coordinates are those within the block.
        typename Triangulation<dim>::active_cell_iterator cell = block_cell;
        if (grid->is_simplex())
          {
            const auto found = find_simplex<dim>(*cache, X, hint);
            AssertThrow(found.first.state() == IteratorState::valid,
                        ExcInternalError());
            cell      = found.first;
            reference = found.second;
            hint      = cell;
          }

        set_point_properties(X, body, volume, materials, problem, properties);
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



  template <int dim>
  void
  MaterialPoints<dim>::locate()
  {
    lost_points.clear();
    // Cells of a Mesh file are not axis-parallel boxes: deal.II's sort,
    // which is correct on quadrilaterals and hexahedra.
    if (grid->is_simplex())
      locate_on_simplices();
    else if (!grid->is_box() || !locate_in_boxes())
      particles->sort_particles_into_subdomains_and_cells();

    std::ostringstream message;
    for (const auto &[id, location] : lost_points)
      message << "material point " << id << " at (" << location
              << ") left the background grid. ";
    stop_if_any_rank_failed(communicator(),
                            message.str(),
                            "",
                            grid->is_box() ?
                              "Enlarge the grid (Mesh/Lower corner, "
                              "Mesh/Upper corner) or reduce the time step." :
                              "Enlarge the mesh of Mesh/Mesh file (<" +
                                grid->mesh_file() +
                                ">) or reduce the time step.");
  }



  template <int dim>
  void
  MaterialPoints<dim>::locate_on_simplices()
  {
    // deal.II 9.4's own sorting uses a quadrilateral inside test and puts
    // points into wrong triangles, and so does its Cache search with a hint.
    struct Moved
    {
      Point<dim>                                        location;
      Point<dim>                                        reference;
      types::particle_index                             id;
      typename Triangulation<dim>::active_cell_iterator cell;
      std::vector<double>                               properties;
    };
    std::vector<Moved> moved;
    std::vector<typename Particles::ParticleHandler<dim>::particle_iterator>
      to_remove;

    for (auto particle = particles->begin(); particle != particles->end();
         ++particle)
      {
        const auto       cell     = particle->get_surrounding_cell();
        const Point<dim> location = particle->get_location();
        const auto       found    = find_simplex<dim>(*cache, location, cell);
        if (found.first == cell)
          {
            particle->set_reference_location(found.second);
            continue;
          }
        if (found.first.state() != IteratorState::valid)
          {
            lost_points.emplace_back(particle->get_id(), location);
            to_remove.push_back(particle);
            continue;
          }
        const auto properties = particle->get_properties();
        moved.push_back(
          {location,
           found.second,
           particle->get_id(),
           found.first,
           std::vector<double>(properties.begin(), properties.end())});
        to_remove.push_back(particle);
      }
    // Every rank updates the global numbers (a collective call) if a point
    // moved on any rank.
    if (Utilities::MPI::max(to_remove.empty() ? 0u : 1u, communicator()) == 0)
      return;
    particles->remove_particles(to_remove);
    for (const auto &point : moved)
      particles->insert_particle(point.location,
                                 point.reference,
                                 point.id,
                                 point.cell,
                                 ArrayView<const double>(point.properties));
    particles->update_cached_numbers();
  }



  template <int dim>
  bool
  MaterialPoints<dim>::locate_in_boxes()
  {
    const Point<dim> lower  = grid->box().get_boundary_points().first;
    const auto      &blocks = grid->subdivisions();
    double           block_size[dim];
    for (unsigned int d = 0; d < dim; ++d)
      block_size[d] = grid->box().side_length(d) / blocks[d];

    struct Moved
    {
      typename Particles::ParticleHandler<dim>::particle_iterator particle;
      typename Triangulation<dim>::active_cell_iterator           cell;
    };
    std::vector<Moved> moved;
    bool               all_local = true;
    // The points of a cell come one after the other: its corner and sizes
    // are looked up once.
    typename Triangulation<dim>::active_cell_iterator current_cell;
    Point<dim>                                        origin;
    std::array<double, dim>                           inverse_size{};
    for (auto particle = particles->begin(); particle != particles->end();
         ++particle)
      {
        const auto cell = particle->get_surrounding_cell();
        if (cell != current_cell)
          {
            current_cell = cell;
            origin       = cell->vertex(0);
            for (unsigned int d = 0; d < dim; ++d)
              inverse_size[d] = 1. / (cell->vertex(1u << d)[d] - origin[d]);
          }
        const Point<dim> location = particle->get_location();
        Point<dim>       reference;
        bool             inside = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            reference[d] = (location[d] - origin[d]) * inverse_size[d];
            inside       = inside && reference[d] >= 0. && reference[d] <= 1.;
          }
        if (inside)
          {
            particle->set_reference_location(reference);
            continue;
          }
        unsigned int linear = 0;
        for (unsigned int d = dim; d-- > 0 && all_local;)
          {
            const double index =
              std::floor((location[d] - lower[d]) / block_size[d]);
            // A point on the upper face of the grid belongs to the last
            // block; beyond it, or not finite, it has left the grid.
            if (!(index >= 0. && index <= blocks[d]))
              all_local = false;
            else
              linear =
                linear * blocks[d] +
                std::min(static_cast<unsigned int>(index), blocks[d] - 1);
          }
        if (!all_local ||
            owned_cell_of_block[linear].state() != IteratorState::valid)
          {
            all_local = false;
            break;
          }
        // On a grid whose knots have moved (unified approach with
        // B-splines) the block arithmetic is only a guess: check it.
        const auto      &candidate = owned_cell_of_block[linear];
        const Point<dim> corner    = candidate->vertex(0);
        inside                     = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            reference[d] = (location[d] - corner[d]) /
                           (candidate->vertex(1u << d)[d] - corner[d]);
            inside =
              inside && reference[d] >= -1e-12 && reference[d] <= 1. + 1e-12;
          }
        if (!inside)
          {
            all_local = false;
            break;
          }
        moved.push_back({particle, candidate});
      }
    // One collective call decides for all ranks: whether some point left
    // its rank (then deal.II's sort, which every rank enters), and whether
    // some point changed cell on any rank (then every rank updates the
    // particle handler's global numbers, which is collective too, also a
    // rank whose points all stayed).
    const std::array<unsigned int, 2> local_decision{
      {all_local ? 0u : 1u, moved.empty() ? 0u : 1u}};
    std::array<unsigned int, 2> decision;
    Utilities::MPI::max(ArrayView<const unsigned int>(local_decision.data(), 2),
                        communicator(),
                        ArrayView<unsigned int>(decision.data(), 2));
    if (decision[0] == 1)
      return false;
    if (decision[1] == 0)
      return true;

    // Move the points that entered another cell of this rank.
    std::vector<Point<dim>>            locations;
    std::vector<types::particle_index> ids;
    std::vector<double>                properties;
    std::vector<typename Particles::ParticleHandler<dim>::particle_iterator>
      to_remove;
    for (const auto &point : moved)
      {
        locations.push_back(point.particle->get_location());
        ids.push_back(point.particle->get_id());
        const auto values = point.particle->get_properties();
        properties.insert(properties.end(), values.begin(), values.end());
        to_remove.push_back(point.particle);
      }
    particles->remove_particles(to_remove);
    const unsigned int n_properties = particles->n_properties_per_particle();
    for (unsigned int k = 0; k < moved.size(); ++k)
      {
        const auto      &cell   = moved[k].cell;
        const Point<dim> origin = cell->vertex(0);
        Point<dim>       reference;
        for (unsigned int d = 0; d < dim; ++d)
          reference[d] = std::clamp((locations[k][d] - origin[d]) /
                                      (cell->vertex(1u << d)[d] - origin[d]),
                                    0.,
                                    1.);
        particles->insert_particle(
          locations[k],
          reference,
          ids[k],
          cell,
          ArrayView<const double>(&properties[k * n_properties], n_properties));
      }
    particles->update_cached_numbers();
    return true;
  }



  template <int dim>
  Particles::ParticleHandler<dim> &
  MaterialPoints<dim>::particle_handler()
  {
    return *particles;
  }



  template <int dim>
  const Particles::ParticleHandler<dim> &
  MaterialPoints<dim>::particle_handler() const
  {
    return *particles;
  }



  template <int dim>
  MPI_Comm
  MaterialPoints<dim>::communicator() const
  {
    return grid->triangulation().get_communicator();
  }



  template <int dim>
  types::particle_index
  MaterialPoints<dim>::n_global_points() const
  {
    return particles->n_global_particles();
  }



  template <int dim>
  types::particle_index
  MaterialPoints<dim>::n_pattern_points_outside_bodies() const
  {
    return points_outside_bodies;
  }



  template class MaterialPoints<1>;
  template class MaterialPoints<2>;
  template class MaterialPoints<3>;
} // namespace MpmOtm
