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

  /**
   * Of the simplices that contain @p point - @p found (an answer of
   * find_simplex()) and those that share a vertex with it - the one with
   * the lowest CellId, with the point's barycentric coordinates there. A
   * point on a face between cells, which the seeding pattern puts on the
   * diagonals of its blocks, so lies in the same cell whatever the number
   * of ranks, and belongs to that cell's owner: every rank that owns one of
   * these cells sees all of them (as its own or ghost cells).
   */
  template <int dim>
  std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
  owning_simplex(
    const GridTools::Cache<dim, dim>                        &cache,
    const Point<dim>                                        &point,
    const typename Triangulation<dim>::active_cell_iterator &found);
} // namespace MpmOtm

#endif
