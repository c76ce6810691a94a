#ifndef mpm_otm_material_points_cell_locator_h
#define mpm_otm_material_points_cell_locator_h

#include <deal.II/base/point.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/grid/tria.h>

#include <mpm_otm/material_points/reference_map.h>

#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * Finds the cell of a point on a grid of simplices or of cells that are
   * not axis-parallel boxes (a Mesh file), starting from a cell near it:
   * the point location of every step. Keeps the inverse map of each cell
   * (ReferenceMap) from its first use until the grid moves or changes, so
   * that a point still in its cell costs one evaluation of that map.
   */
  template <int dim>
  class CellLocator
  {
  public:
    using CellIterator = typename Triangulation<dim>::active_cell_iterator;

    CellLocator(const Triangulation<dim> &triangulation,
                const Mapping<dim>       &mapping);

    /**
     * The inverse map of @p cell.
     */
    const ReferenceMap<dim> &
    map(const CellIterator &cell) const;

    /**
     * The cell that contains @p point and the point's reference coordinates
     * there: the hint, across the face through which the point left it (a
     * hypercube), the cells that share a vertex with it, deal.II's search
     * (whose inside test is the one of quadrilaterals in 9.4, so its answer
     * is checked), its vertex neighbours, and at last every cell. An invalid
     * iterator if no cell contains the point. @p reference_in_hint, if
     * given, are the point's reference coordinates in the hint, which does
     * not contain it.
     */
    std::pair<CellIterator, Point<dim>>
    find(const Point<dim>   &point,
         const CellIterator &hint,
         const Point<dim>   *reference_in_hint = nullptr) const;

    /**
     * Of the cells that contain @p point - that of @p found (an answer of
     * find()) and those that share a vertex with it - the one with the lowest
     * CellId, with the point's reference coordinates there. A point on a
     * face between cells (the seeding pattern puts points on the diagonals
     * of the blocks of simplex grids) so lies in the same cell whatever the
     * number of ranks, and belongs to that cell's owner: every rank that
     * owns one of these cells sees all of them (as its own or ghost cells).
     * A point well inside @p found is in no other cell.
     */
    std::pair<CellIterator, Point<dim>>
    owning(const Point<dim>                          &point,
           const std::pair<CellIterator, Point<dim>> &found) const;

  private:
    /**
     * True, with @p reference, if @p cell contains @p point; Newton's method
     * starts at @p start, or at the cell's centre.
     */
    bool
    contains(const CellIterator &cell,
             const Point<dim>   &point,
             Point<dim>         &reference,
             const Point<dim>   *start = nullptr) const;

    GridTools::Cache<dim, dim> cache;
    /// The maps by active cell index, and whether each is set up.
    mutable std::vector<ReferenceMap<dim>> maps;
    mutable std::vector<bool>              ready;
    boost::signals2::scoped_connection     grid_moved, grid_changed;
  };
} // namespace MpmOtm

#endif
