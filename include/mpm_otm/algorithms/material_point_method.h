#ifndef mpm_otm_algorithms_material_point_method_h
#define mpm_otm_algorithms_material_point_method_h

#include <mpm_otm/algorithms/update_scheme_method.h>

namespace MpmOtm
{
  /**
   * MPM, the material-point method (journal Alg. 1): the shape functions
   * stay on the fixed background grid while the points move through it; the
   * nodal update is 'Update scheme' (automatic: MUSL).
   */
  template <int dim>
  class MaterialPointMethod : public UpdateSchemeMethod<dim>
  {
  public:
    MaterialPointMethod();

    static void
    declare_parameters(ParameterHandler &prm);

    std::unique_ptr<GridMotion<dim>>
    create_grid_motion(ShapeFunctions<dim> &shape_functions) const override;

    bool
    fixed_grid() const override;
  };
} // namespace MpmOtm

#endif
