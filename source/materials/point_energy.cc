#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/materials/point_energy.h>

namespace MpmOtm
{
  template <int dim>
  PointEnergy
  point_energy(const ArrayView<const double> &properties,
               const MaterialLibrary<dim>    &materials)
  {
    using Layout = PropertyLayout<dim>;
    return {0.5 * properties[Layout::mass] *
              Layout::get_vector(properties, Layout::velocity).norm_square(),
            materials[Layout::get_material_id(properties)].strain_energy(
              Layout::get_deformation_gradient(properties),
              Layout::get_stress(properties),
              properties[Layout::initial_volume],
              Layout::volume(properties))};
  }



  template PointEnergy
  point_energy(const ArrayView<const double> &, const MaterialLibrary<1> &);
  template PointEnergy
  point_energy(const ArrayView<const double> &, const MaterialLibrary<2> &);
  template PointEnergy
  point_energy(const ArrayView<const double> &, const MaterialLibrary<3> &);
} // namespace MpmOtm
