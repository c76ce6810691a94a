#include <mpm_otm/algorithms/moving_grid.h>
#include <mpm_otm/algorithms/unified_method.h>
#include <mpm_otm/base/plugins.h>

namespace MpmOtm
{
  template <int dim>
  void
  UnifiedMethod<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  UnifiedMethod<dim>::UnifiedMethod()
    : UpdateSchemeMethod<dim>("USL")
  {}



  template <int dim>
  std::unique_ptr<GridMotion<dim>>
  UnifiedMethod<dim>::create_grid_motion(
    ShapeFunctions<dim> &shape_functions) const
  {
    return create_moving_grid(shape_functions, "Unified");
  }



  template <int dim>
  bool
  UnifiedMethod<dim>::fixed_grid() const
  {
    return false;
  }



  template class UnifiedMethod<1>;
  template class UnifiedMethod<2>;
  template class UnifiedMethod<3>;
} // namespace MpmOtm

#define MPM_OTM_UNIFIED_DESCRIPTION                                          \
  "the unified approach (journal Alg. 3): the grid moves with the material " \
  "as in OTM (its vertices, or the knots of B-splines), the particle "       \
  "update is that of 'Update scheme' (automatic: USL); the journal uses it " \
  "with Mass matrix = consistent"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<1>,
                        MpmOtm::UnifiedMethod<1>,
                        "Unified",
                        MPM_OTM_UNIFIED_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<2>,
                        MpmOtm::UnifiedMethod<2>,
                        "Unified",
                        MPM_OTM_UNIFIED_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<3>,
                        MpmOtm::UnifiedMethod<3>,
                        "Unified",
                        MPM_OTM_UNIFIED_DESCRIPTION)
