#ifndef mpm_otm_algorithms_unified_method_h
#define mpm_otm_algorithms_unified_method_h

#include <mpm_otm/algorithms/update_scheme_method.h>

namespace MpmOtm
{
  /**
   * The unified approach (journal Alg. 3): the grid moves with the material
   * as in OTM (vertices, or the knots of B-splines), the particle update is
   * that of 'Update scheme' (automatic: USL).
   */
  template <int dim>
  class UnifiedMethod : public UpdateSchemeMethod<dim>
  {
  public:
    UnifiedMethod();

    static void
    declare_parameters(ParameterHandler &prm);

    std::unique_ptr<GridMotion<dim>>
    create_grid_motion(ShapeFunctions<dim> &shape_functions) const override;

    bool
    fixed_grid() const override;
  };
} // namespace MpmOtm

#endif
