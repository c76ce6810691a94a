#include <deal.II/base/mpi.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/cell_locator.h>
#include <mpm_otm/material_points/material_points.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

namespace MpmOtm
{
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
  MaterialPoints<dim>::locate()
  {
    lost_points.clear();
    // Cells of a Mesh file are not axis-parallel boxes: each point is
    // searched for from its cell.
    if (grid->is_simplex() || !grid->is_box())
      locate_in_cells();
    else if (!locate_in_boxes())
      particles->sort_particles_into_subdomains_and_cells();

    // The first few points of each rank: a body that leaves the grid at
    // once would otherwise give a message of thousands of lines.
    const unsigned int listed = 3;
    std::ostringstream message;
    for (unsigned int i = 0;
         i < std::min<std::size_t>(lost_points.size(), listed);
         ++i)
      message << "material point " << lost_points[i].first << " at ("
              << lost_points[i].second << ") left the background grid. ";
    if (lost_points.size() > listed)
      message << "So did " << lost_points.size() - listed
              << (lost_points.size() - listed == 1 ? " more material point" :
                                                     " more material points")
              << " of MPI rank "
              << Utilities::MPI::this_mpi_process(communicator()) << ". ";
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
  MaterialPoints<dim>::locate_in_cells()
  {
    // deal.II 9.4's own sorting uses a quadrilateral inside test and puts
    // points into wrong triangles, and so does its Cache search with a hint;
    // on quadrilaterals and hexahedra it inverts the generic mapping for
    // every point. Points are located with CellLocator, whose inverse maps
    // are set up once per cell, and sent to their new rank here; a point
    // still in its cell starts Newton's method from its reference
    // coordinates before the move. A point moves at most into a cell next to
    // its own in one step, which is an own or a ghost cell; points that moved
    // further are searched for on every rank.
    struct Moved
    {
      Point<dim>                                        location;
      Point<dim>                                        reference;
      types::particle_index                             id;
      typename Triangulation<dim>::active_cell_iterator cell;
    };
    std::vector<Moved> moved;
    // The properties of the moved points, one after the other.
    std::vector<double> moved_properties;
    std::vector<typename Particles::ParticleHandler<dim>::particle_iterator>
      to_remove;
    // Points for other ranks, each as its cell, id, location and properties,
    // and points in no cell of this rank, each as id, location, properties.
    const unsigned int cell_size = std::tuple_size<CellId::binary_type>::value;
    const unsigned int point_size =
      1 + dim + particles->n_properties_per_particle();
    std::map<unsigned int, std::vector<double>> leaving;
    std::vector<double>                         unfound;
    const auto location_of = [](const double *packed) {
      Point<dim> location;
      for (unsigned int d = 0; d < dim; ++d)
        location[d] = packed[1 + d];
      return location;
    };
    const auto pack =
      [&](const typename Particles::ParticleHandler<dim>::particle_iterator
                              &particle,
          std::vector<double> &buffer) {
        buffer.push_back(particle->get_id());
        for (unsigned int d = 0; d < dim; ++d)
          buffer.push_back(particle->get_location()[d]);
        const auto properties = particle->get_properties();
        buffer.insert(buffer.end(), properties.begin(), properties.end());
      };

    // The points of a cell come one after the other: its map is looked up
    // once.
    typename Triangulation<dim>::active_cell_iterator current_cell;
    const ReferenceMap<dim>                          *map = nullptr;
    for (auto particle = particles->begin(); particle != particles->end();
         ++particle)
      {
        const auto cell = particle->get_surrounding_cell();
        if (cell != current_cell)
          {
            current_cell = cell;
            map          = &locator->map(cell);
          }
        const Point<dim> location = particle->get_location();
        const Point<dim> reference =
          map->reference_point(location, particle->get_reference_location());
        if (map->contains(reference))
          {
            particle->set_reference_location(reference);
            continue;
          }
        const auto found =
          locator->owning(location, locator->find(location, cell, &reference));
        to_remove.push_back(particle);
        if (found.first.state() != IteratorState::valid)
          pack(particle, unfound);
        else if (found.first->is_locally_owned())
          {
            const auto properties = particle->get_properties();
            moved.push_back(
              {location, found.second, particle->get_id(), found.first});
            moved_properties.insert(moved_properties.end(),
                                    properties.begin(),
                                    properties.end());
          }
        else
          {
            std::vector<double> &buffer = leaving[found.first->subdomain_id()];
            const auto binary = found.first->id().template to_binary<dim>();
            buffer.insert(buffer.end(), binary.begin(), binary.end());
            pack(particle, buffer);
          }
      }

    // One collective check per step: did a point change cell on any rank,
    // and is any point in no cell of its rank?
    const std::array<unsigned int, 2> local = {
      {to_remove.empty() ? 0u : 1u, unfound.empty() ? 0u : 1u}};
    std::array<unsigned int, 2> global{};
    Utilities::MPI::max(ArrayView<const unsigned int>(local.data(), 2),
                        communicator(),
                        ArrayView<unsigned int>(global.data(), 2));
    if (global[0] == 0)
      return;
    particles->remove_particles(to_remove);
    const unsigned int n_properties = particles->n_properties_per_particle();
    for (unsigned int k = 0; k < moved.size(); ++k)
      particles->insert_particle(
        moved[k].location,
        moved[k].reference,
        moved[k].id,
        moved[k].cell,
        ArrayView<const double>(&moved_properties[k * n_properties],
                                n_properties));

    const auto insert =
      [&](const double                                            *packed,
          const typename Triangulation<dim>::active_cell_iterator &cell,
          const Point<dim>                                        &reference) {
        particles->insert_particle(
          location_of(packed),
          reference,
          static_cast<types::particle_index>(packed[0]),
          cell,
          ArrayView<const double>(packed + 1 + dim, point_size - 1 - dim));
      };
    if (Utilities::MPI::n_mpi_processes(communicator()) > 1)
      {
        for (const auto &[rank, buffer] :
             Utilities::MPI::some_to_some(communicator(), leaving))
          for (std::size_t k = 0; k < buffer.size();
               k += cell_size + point_size)
            {
              CellId::binary_type binary;
              for (unsigned int i = 0; i < cell_size; ++i)
                binary[i] = static_cast<unsigned int>(buffer[k + i]);
              const typename Triangulation<dim>::active_cell_iterator cell(
                grid->triangulation().create_cell_iterator(CellId(binary)));
              const double *packed = &buffer[k + cell_size];
              insert(packed,
                     cell,
                     locator->find(location_of(packed), cell).second);
            }
      }

    // Points in no cell of their rank: the rank that owns their cell (by
    // the rule of CellLocator::owning(), so that only one takes a point on the
    // boundary between ranks) takes them; the others have left the grid.
    std::vector<unsigned int> taken;
    if (global[1] > 0)
      {
        const auto all = Utilities::MPI::all_gather(communicator(), unfound);
        for (const auto &part : all)
          for (std::size_t k = 0; k < part.size(); k += point_size)
            {
              const Point<dim> location = location_of(&part[k]);
              const auto       found    = locator->owning(
                location,
                locator->find(
                  location,
                  typename Triangulation<dim>::active_cell_iterator()));
              const bool mine = found.first.state() == IteratorState::valid &&
                                found.first->is_locally_owned();
              if (mine)
                insert(&part[k], found.first, found.second);
              taken.push_back(mine ? 1 : 0);
            }
        Utilities::MPI::sum(taken, communicator(), taken);
        std::size_t        first_own = 0;
        const unsigned int rank =
          Utilities::MPI::this_mpi_process(communicator());
        for (unsigned int r = 0; r < rank; ++r)
          first_own += all[r].size() / point_size;
        for (std::size_t k = 0; k < unfound.size(); k += point_size)
          if (taken[first_own + k / point_size] == 0)
            lost_points.emplace_back(static_cast<types::particle_index>(
                                       unfound[k]),
                                     location_of(&unfound[k]));
      }
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
