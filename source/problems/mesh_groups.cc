#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/numerics/rtree.h>

#include <mpm_otm/grid/gmsh_file.h>
#include <mpm_otm/problems/mesh_groups.h>

namespace MpmOtm
{
  template <int dim>
  MeshGroups<dim>::MeshGroups(const GmshFile &file)
    : file_name(file.name())
    , file_entry(file.entry())
    , simplex(file.is_simplex())
  {
    // A Mesh file is 2D or 3D; MeshGroups<1> exists for the 1D problems'
    // (always empty) pointer to one.
    AssertThrow(dim > 1, ExcInternalError());
    if constexpr (dim > 1)
      {
        file.read(triangulation);
        if (simplex)
          mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
        else
          mapping = std::make_unique<MappingQ<dim>>(1);
        cache =
          std::make_unique<GridTools::Cache<dim, dim>>(triangulation, *mapping);
        names = file.physical_names(dim);
        for (const auto &cell : triangulation.active_cell_iterators())
          ++cells_per_tag[cell->material_id()];
      }
  }



  template <int dim>
  MeshGroups<dim>::~MeshGroups() = default;



  template <int dim>
  types::material_id
  MeshGroups<dim>::tag(const std::string &group, const std::string &entry) const
  {
    types::material_id found = numbers::invalid_material_id;
    for (const auto &[tag, name] : names)
      if (name == group)
        found = tag;
    if (found == numbers::invalid_material_id)
      {
        try
          {
            const int number = Utilities::string_to_int(group);
            if (number >= 0)
              found = number;
          }
        catch (const std::exception &)
          {}
      }
    if (found == numbers::invalid_material_id ||
        cells_per_tag.find(found) == cells_per_tag.end())
      {
        std::string groups;
        for (const auto &[tag, n_cells] : cells_per_tag)
          {
            const auto name = names.find(tag);
            groups += (groups.empty() ? "" : ", ") +
                      (name == names.end() ? "" : "\"" + name->second + "\" ") +
                      "(tag " + std::to_string(tag) + ", " +
                      std::to_string(n_cells) + " cells)";
          }
        AssertThrow(false,
                    ExcMessage(entry + " = " + group + ": " + file_entry +
                               " <" + file_name + "> has no group of " +
                               (dim == 2 ? "surfaces" : "volumes") +
                               " of that name or tag; its cells' groups are " +
                               groups +
                               " (physical groups of Gmsh; cells in none "
                               "have tag 0)."));
      }
    return found;
  }



  template <int dim>
  types::material_id
  MeshGroups<dim>::group_at(const Point<dim> &point) const
  {
    if constexpr (dim > 1)
      {
        const auto contains =
          [&](const typename Triangulation<dim>::active_cell_iterator &cell) {
            try
              {
                return cell->reference_cell().contains_point(
                  mapping->transform_real_to_unit_cell(cell, point),
                  1e-10);
              }
            catch (const ExceptionBase &)
              {
                return false;
              }
          };
        if (hint.state() == IteratorState::valid && contains(hint))
          return hint->material_id();
        // The cells whose bounding box holds the point (the cache's R-tree):
        // a point outside the mesh, such as the air above a slope that a
        // geostatic stress integrates through, costs a query of the tree
        // instead of a test of every cell.
        namespace bgi = boost::geometry::index;
        for (const auto &[box, cell] :
             cache->get_cell_bounding_boxes_rtree() |
               bgi::adaptors::queried(bgi::intersects(point)))
          if (cell != hint && contains(cell))
            {
              hint = cell;
              return cell->material_id();
            }
      }
    return numbers::invalid_material_id;
  }



  template <int dim>
  BoundingBox<dim>
  MeshGroups<dim>::bounding_box(const types::material_id tag) const
  {
    std::vector<Point<dim>> vertices;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->material_id() == tag)
        for (const unsigned int v : cell->vertex_indices())
          vertices.push_back(cell->vertex(v));
    return BoundingBox<dim>(vertices);
  }



  template class MeshGroups<1>;
  template class MeshGroups<2>;
  template class MeshGroups<3>;
} // namespace MpmOtm
