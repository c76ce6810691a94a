#include <mpm_otm/shape_functions/shape_functions.h>

#include <algorithm>

namespace MpmOtm
{
  template <int dim>
  bool
  ShapeFunctions<dim>::functions_in_box(
    const BoundingBox<dim>               &box,
    std::vector<types::global_dof_index> &functions) const
  {
    functions.clear();
    const IndexSet owned = locally_owned_functions();
    for (const auto &cell :
         dof_handler().get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (box.point_inside(cell->vertex(v), 1e-10))
            {
              const auto function = vertex_function(cell, v);
              Assert(function != numbers::invalid_dof_index,
                     ExcMessage("A family without vertex functions must "
                                "override functions_in_box()."));
              if (owned.is_element(function))
                functions.push_back(function);
            }
    std::sort(functions.begin(), functions.end());
    functions.erase(std::unique(functions.begin(), functions.end()),
                    functions.end());
    return true;
  }



  template <int dim>
  bool
  ShapeFunctions<dim>::function_points(
    const Utilities::MPI::Partitioner &partitioner,
    std::vector<Point<dim>>           &points) const
  {
    const unsigned int n_local =
      partitioner.locally_owned_size() + partitioner.n_ghost_indices();
    points.assign(n_local, Point<dim>());
    std::vector<bool> found(n_local, false);
    for (const auto &cell :
         dof_handler().get_triangulation().active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto function = vertex_function(cell, v);
            if (function == numbers::invalid_dof_index)
              return false;
            if (partitioner.in_local_range(function) ||
                partitioner.is_ghost_entry(function))
              {
                const unsigned int local =
                  partitioner.global_to_local(function);
                points[local] = cell->vertex(v);
                found[local]  = true;
              }
          }
    return std::find(found.begin(), found.end(), false) == found.end();
  }



  template <int dim>
  bool
  ShapeFunctions<dim>::boundary_integrals(const types::boundary_id boundary_id,
                                          VectorType &integrals) const
  {
    // The first locally owned cell tells whether the functions belong to
    // vertices; a rank without cells asks the others.
    const auto  &triangulation        = dof_handler().get_triangulation();
    unsigned int has_vertex_functions = 1;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          has_vertex_functions =
            (vertex_function(cell, 0) != numbers::invalid_dof_index);
          break;
        }
    if (Utilities::MPI::min(has_vertex_functions,
                            triangulation.get_communicator()) == 0)
      return false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary_id)
            {
              const auto face  = cell->face(f);
              double     share = 1.;
              if constexpr (dim > 1)
                share = face->measure() / face->n_vertices();
              for (const unsigned int w : face->vertex_indices())
                for (const unsigned int v : cell->vertex_indices())
                  if (cell->vertex_index(v) == face->vertex_index(w))
                    integrals[vertex_function(cell, v)] += share;
            }
    integrals.compress(VectorOperation::add);
    return true;
  }



  template class ShapeFunctions<1>;
  template class ShapeFunctions<2>;
  template class ShapeFunctions<3>;
} // namespace MpmOtm
