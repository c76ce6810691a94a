#ifndef mpm_otm_materials_point_energy_h
#define mpm_otm_materials_point_energy_h

#include <deal.II/base/array_view.h>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialLibrary;

  /**
   * The kinetic and strain energy of one material point, the terms that the
   * energy statistics (Statistics::compute()) and the instability check
   * (EnergyMonitor::check()) sum over the points.
   */
  struct PointEnergy
  {
    /// 1/2 m |v|^2 (J).
    double kinetic;
    /// The stored strain energy of the point's material (J).
    double strain;
  };

  /**
   * The energy of the material point with the properties @p properties
   * (laid out by PropertyLayout), its strain energy from its material in
   * @p materials.
   */
  template <int dim>
  PointEnergy
  point_energy(const ArrayView<const double> &properties,
               const MaterialLibrary<dim>    &materials);
} // namespace MpmOtm

#endif
