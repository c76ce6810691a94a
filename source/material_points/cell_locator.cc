#include <deal.II/grid/grid_tools.h>

#include <mpm_otm/material_points/cell_locator.h>

#include <algorithm>

namespace MpmOtm
{
  template <int dim>
  CellLocator<dim>::CellLocator(const Triangulation<dim> &triangulation,
                                const Mapping<dim>       &mapping)
    : cache(triangulation, mapping)
    , maps(triangulation.n_active_cells())
    , ready(triangulation.n_active_cells(), false)
  {
    // The maps are set up anew after a move (the unified approach) or a
    // change of the grid.
    grid_moved   = triangulation.signals.mesh_movement.connect([this]() {
      ready.assign(ready.size(), false);
    });
    grid_changed = triangulation.signals.any_change.connect([this]() {
      maps.resize(cache.get_triangulation().n_active_cells());
      ready.assign(maps.size(), false);
    });
  }



  template <int dim>
  const ReferenceMap<dim> &
  CellLocator<dim>::map(const CellIterator &cell) const
  {
    const unsigned int index = cell->active_cell_index();
    if (!ready[index])
      {
        maps[index].reinit(cell);
        ready[index] = true;
      }
    return maps[index];
  }



  template <int dim>
  bool
  CellLocator<dim>::contains(const CellIterator &cell,
                             const Point<dim>   &point,
                             Point<dim>         &reference,
                             const Point<dim>   *start) const
  {
    const ReferenceMap<dim> &cell_map = map(cell);
    reference = start != nullptr ? cell_map.reference_point(point, *start) :
                                   cell_map.reference_point(point);
    return cell_map.contains(reference);
  }



  template <int dim>
  std::pair<typename CellLocator<dim>::CellIterator, Point<dim>>
  CellLocator<dim>::find(const Point<dim>   &point,
                         const CellIterator &hint,
                         const Point<dim>   *reference_in_hint) const
  {
    const auto try_vertex_neighbours =
      [&](const CellIterator &cell, CellIterator &found, Point<dim> &xi) {
        const auto &vertex_to_cells = cache.get_vertex_to_cell_map();
        for (const unsigned int v : cell->vertex_indices())
          for (const auto &neighbour : vertex_to_cells[cell->vertex_index(v)])
            if (neighbour != cell && contains(neighbour, point, xi))
              {
                found = neighbour;
                return true;
              }
        return false;
      };

    Point<dim>   xi;
    CellIterator found;
    if (hint.state() == IteratorState::valid)
      {
        if (reference_in_hint != nullptr)
          xi = *reference_in_hint;
        else if (contains(hint, point, xi))
          return {hint, xi};
        // A point that has left a hypercube through one face, the usual
        // case, is in the cell behind it, near the same place of that face
        // (where Newton's method starts: exact for cells of the same
        // orientation).
        if (hint->reference_cell().is_hyper_cube())
          {
            unsigned int face = numbers::invalid_unsigned_int, n_out = 0;
            for (unsigned int d = 0; d < dim; ++d)
              if (xi[d] < 0. || xi[d] > 1.)
                {
                  face = 2 * d + (xi[d] > 1. ? 1 : 0);
                  ++n_out;
                }
            if (n_out == 1 && !hint->at_boundary(face) &&
                hint->neighbor(face)->is_active())
              {
                Point<dim> start;
                for (unsigned int d = 0; d < dim; ++d)
                  start[d] = std::clamp(d != face / 2 ? xi[d] :
                                        face % 2 == 1 ? xi[d] - 1. :
                                                        xi[d] + 1.,
                                        0.,
                                        1.);
                const CellIterator neighbour = hint->neighbor(face);
                if (contains(neighbour, point, xi, &start))
                  return {neighbour, xi};
              }
          }
        if (try_vertex_neighbours(hint, found, xi))
          return {found, xi};
      }
    const auto guess = GridTools::find_active_cell_around_point(cache, point);
    if (guess.first.state() == IteratorState::valid)
      {
        if (contains(guess.first, point, xi))
          return {guess.first, xi};
        if (try_vertex_neighbours(guess.first, found, xi))
          return {found, xi};
      }
    for (const auto &cell : cache.get_triangulation().active_cell_iterators())
      if (contains(cell, point, xi))
        return {cell, xi};
    return {CellIterator(), xi};
  }



  template <int dim>
  std::pair<typename CellLocator<dim>::CellIterator, Point<dim>>
  CellLocator<dim>::owning(
    const Point<dim>                          &point,
    const std::pair<CellIterator, Point<dim>> &found) const
  {
    std::pair<CellIterator, Point<dim>> owner = found;
    if (found.first.state() != IteratorState::valid ||
        map(found.first).contains(found.second, -1e-9))
      return owner;
    const auto &vertex_to_cells = cache.get_vertex_to_cell_map();
    for (const unsigned int v : found.first->vertex_indices())
      for (const auto &neighbour :
           vertex_to_cells[found.first->vertex_index(v)])
        if (neighbour->id() < owner.first->id())
          {
            Point<dim> xi;
            if (contains(neighbour, point, xi))
              owner = {neighbour, xi};
          }
    return owner;
  }



  template class CellLocator<1>;
  template class CellLocator<2>;
  template class CellLocator<3>;
} // namespace MpmOtm
