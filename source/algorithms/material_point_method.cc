#include <mpm_otm/algorithms/fixed_grid.h>
#include <mpm_otm/algorithms/material_point_method.h>
#include <mpm_otm/base/plugins.h>

namespace MpmOtm
{
  template <int dim>
  void
  MaterialPointMethod<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  MaterialPointMethod<dim>::MaterialPointMethod()
    : UpdateSchemeMethod<dim>("MUSL")
  {}



  template <int dim>
  std::unique_ptr<GridMotion<dim>>
  MaterialPointMethod<dim>::create_grid_motion(ShapeFunctions<dim> &) const
  {
    return std::make_unique<FixedGrid<dim>>();
  }



  template <int dim>
  bool
  MaterialPointMethod<dim>::fixed_grid() const
  {
    return true;
  }



  template class MaterialPointMethod<1>;
  template class MaterialPointMethod<2>;
  template class MaterialPointMethod<3>;
} // namespace MpmOtm

#define MPM_OTM_MPM_DESCRIPTION                                          \
  "material-point method, shape functions on the fixed background grid " \
  "(journal Alg. 1; nodal update from 'Update scheme', automatic: MUSL)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<1>,
                        MpmOtm::MaterialPointMethod<1>,
                        "MPM",
                        MPM_OTM_MPM_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<2>,
                        MpmOtm::MaterialPointMethod<2>,
                        "MPM",
                        MPM_OTM_MPM_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<3>,
                        MpmOtm::MaterialPointMethod<3>,
                        "MPM",
                        MPM_OTM_MPM_DESCRIPTION)
