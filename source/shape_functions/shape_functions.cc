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



  template class ShapeFunctions<1>;
  template class ShapeFunctions<2>;
  template class ShapeFunctions<3>;
} // namespace MpmOtm
