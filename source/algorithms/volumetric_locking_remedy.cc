#include <mpm_otm/algorithms/volumetric_locking_remedy.h>

namespace MpmOtm
{
  template <int dim>
  void
  VolumetricLockingRemedy<dim>::after_stress_update(MaterialPoints<dim> &)
  {}



  template class VolumetricLockingRemedy<1>;
  template class VolumetricLockingRemedy<2>;
  template class VolumetricLockingRemedy<3>;
} // namespace MpmOtm
