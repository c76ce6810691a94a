#ifndef mpm_otm_material_points_simplex_search_h
#define mpm_otm_material_points_simplex_search_h

#include <deal.II/base/point.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/grid/tria.h>

#include <utility>

namespace MpmOtm
{
  using namespace dealii;

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
               const typename Triangulation<dim>::active_cell_iterator &hint);
} // namespace MpmOtm

#endif
