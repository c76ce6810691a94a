#include <deal.II/grid/grid_tools.h>

#include <mpm_otm/material_points/simplex_search.h>

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
  } // namespace



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



  template <int dim>
  std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
  owning_simplex(const GridTools::Cache<dim, dim>                        &cache,
                 const Point<dim>                                        &point,
                 const typename Triangulation<dim>::active_cell_iterator &found)
  {
    std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
      owning(found, Point<dim>());
    if (found.state() != IteratorState::valid)
      return owning;
    owning.second               = barycentric<dim>(found, point);
    const auto &vertex_to_cells = cache.get_vertex_to_cell_map();
    for (const unsigned int v : found->vertex_indices())
      for (const auto &neighbour : vertex_to_cells[found->vertex_index(v)])
        if (neighbour->id() < owning.first->id())
          {
            const Point<dim> xi = barycentric<dim>(neighbour, point);
            if (inside_simplex(xi))
              owning = {neighbour, xi};
          }
    return owning;
  }



  template std::pair<Triangulation<1>::active_cell_iterator, Point<1>>
  find_simplex(const GridTools::Cache<1, 1> &,
               const Point<1> &,
               const Triangulation<1>::active_cell_iterator &);
  template std::pair<Triangulation<2>::active_cell_iterator, Point<2>>
  find_simplex(const GridTools::Cache<2, 2> &,
               const Point<2> &,
               const Triangulation<2>::active_cell_iterator &);
  template std::pair<Triangulation<3>::active_cell_iterator, Point<3>>
  find_simplex(const GridTools::Cache<3, 3> &,
               const Point<3> &,
               const Triangulation<3>::active_cell_iterator &);
  template std::pair<Triangulation<1>::active_cell_iterator, Point<1>>
  owning_simplex(const GridTools::Cache<1, 1> &,
                 const Point<1> &,
                 const Triangulation<1>::active_cell_iterator &);
  template std::pair<Triangulation<2>::active_cell_iterator, Point<2>>
  owning_simplex(const GridTools::Cache<2, 2> &,
                 const Point<2> &,
                 const Triangulation<2>::active_cell_iterator &);
  template std::pair<Triangulation<3>::active_cell_iterator, Point<3>>
  owning_simplex(const GridTools::Cache<3, 3> &,
                 const Point<3> &,
                 const Triangulation<3>::active_cell_iterator &);
} // namespace MpmOtm
