#include <deal.II/grid/tria.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <map>

// The material points in the files of a checkpoint (MaterialPoints::
// write_points() and read_points()).

namespace MpmOtm
{
  template <int dim>
  bool
  MaterialPoints<dim>::write_points(std::ostream &out) const
  {
    const std::array<std::uint64_t, 3> header{
      {dim,
       particles->n_properties_per_particle(),
       particles->n_locally_owned_particles()}};
    out.write(reinterpret_cast<const char *>(header.data()), sizeof(header));
    for (const auto &particle : *particles)
      {
        const CellId::binary_type cell =
          particle.get_surrounding_cell()->id().template to_binary<dim>();
        const std::uint64_t id         = particle.get_id();
        const Point<dim>    x          = particle.get_location();
        const Point<dim>    xi         = particle.get_reference_location();
        const auto          properties = particle.get_properties();
        out.write(reinterpret_cast<const char *>(cell.data()), sizeof(cell));
        out.write(reinterpret_cast<const char *>(&id), sizeof(id));
        for (const Point<dim> &p : {x, xi})
          for (unsigned int d = 0; d < dim; ++d)
            out.write(reinterpret_cast<const char *>(&p[d]), sizeof(double));
        out.write(reinterpret_cast<const char *>(properties.data()),
                  properties.size() * sizeof(double));
      }
    return static_cast<bool>(out);
  }



  template <int dim>
  void
  MaterialPoints<dim>::read_points(const std::vector<std::string> &files)
  {
    particles->clear_particles();
    const unsigned int  n_properties = particles->n_properties_per_particle();
    std::vector<double> properties(n_properties);
    std::uint64_t       n_saved = 0;
    std::string         problem;
    const Triangulation<dim> &triangulation = grid->triangulation();
    // This rank's cells by id: a fully distributed triangulation does not
    // hold the cells of the other ranks.
    std::map<CellId, typename Triangulation<dim>::active_cell_iterator> owned;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        owned.emplace(cell->id(), cell);
    for (const auto &file_name : files)
      {
        std::ifstream                file(file_name, std::ios::binary);
        std::array<std::uint64_t, 3> header{};
        file.read(reinterpret_cast<char *>(header.data()), sizeof(header));
        if (!file || header[0] != dim || header[1] != n_properties)
          {
            problem = "<" + file_name +
                      "> is not a file of material points of this run (" +
                      std::to_string(dim) + "D, " +
                      std::to_string(n_properties) + " properties per point). ";
            break;
          }
        n_saved += header[2];
        for (std::uint64_t k = 0; k < header[2] && file; ++k)
          {
            CellId::binary_type cell;
            std::uint64_t       id;
            Point<dim>          x, xi;
            file.read(reinterpret_cast<char *>(cell.data()), sizeof(cell));
            file.read(reinterpret_cast<char *>(&id), sizeof(id));
            for (Point<dim> *p : {&x, &xi})
              for (unsigned int d = 0; d < dim; ++d)
                file.read(reinterpret_cast<char *>(&(*p)[d]), sizeof(double));
            file.read(reinterpret_cast<char *>(properties.data()),
                      n_properties * sizeof(double));
            if (!file)
              break;
            const CellId cell_id(cell);
            if (cell_id.get_coarse_cell_id() >=
                triangulation.n_global_coarse_cells())
              {
                problem = "<" + file_name +
                          "> holds a point in a cell that "
                          "the grid of this run does not have. ";
                break;
              }
            const auto found = owned.find(cell_id);
            if (found != owned.end())
              particles->insert_particle(x,
                                         xi,
                                         id,
                                         found->second,
                                         ArrayView<const double>(properties));
          }
        if (problem.empty() && !file)
          problem = "<" + file_name + "> ends before its last point. ";
        if (!problem.empty())
          break;
      }
    stop_if_any_rank_failed(communicator(),
                            problem,
                            "Cannot resume from the checkpoint: ",
                            "Resume from another checkpoint or start anew.");
    particles->update_cached_numbers();
    AssertThrow(particles->n_global_particles() == n_saved,
                ExcMessage("Cannot resume from the checkpoint: of its " +
                           std::to_string(n_saved) + " material points, " +
                           std::to_string(particles->n_global_particles()) +
                           " lie in cells of this run's ranks."));
  }



  template bool
  MaterialPoints<1>::write_points(std::ostream &) const;
  template bool
  MaterialPoints<2>::write_points(std::ostream &) const;
  template bool
  MaterialPoints<3>::write_points(std::ostream &) const;
  template void
  MaterialPoints<1>::read_points(const std::vector<std::string> &);
  template void
  MaterialPoints<2>::read_points(const std::vector<std::string> &);
  template void
  MaterialPoints<3>::read_points(const std::vector<std::string> &);
} // namespace MpmOtm
