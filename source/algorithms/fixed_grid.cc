#include <mpm_otm/algorithms/fixed_grid.h>
#include <mpm_otm/material_points/material_points.h>

namespace MpmOtm
{
  template <int dim>
  bool
  FixedGrid<dim>::moves_vertices() const
  {
    return false;
  }



  template <int dim>
  bool
  FixedGrid<dim>::tractions_on_grid_faces() const
  {
    return false;
  }



  template <int dim>
  void
  FixedGrid<dim>::add_face_tractions(const Problem<dim> &,
                                     const double,
                                     NodalSystem<dim> &) const
  {}



  template <int dim>
  void
  FixedGrid<dim>::initialize(BackgroundGrid<dim> &,
                             const ShapeFunctions<dim> &,
                             const NodalSystem<dim> &,
                             const double)
  {}



  template <int dim>
  void
  FixedGrid<dim>::advance(const NodalSystem<dim> &,
                          MaterialPoints<dim> &material_points,
                          const double)
  {
    material_points.locate();
  }



  template class FixedGrid<1>;
  template class FixedGrid<2>;
  template class FixedGrid<3>;
} // namespace MpmOtm
