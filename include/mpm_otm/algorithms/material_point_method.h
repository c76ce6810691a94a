#ifndef mpm_otm_algorithms_material_point_method_h
#define mpm_otm_algorithms_material_point_method_h

#include <mpm_otm/algorithms/method.h>

namespace MpmOtm
{
  /**
   * MPM, the material-point method (journal Alg. 1): the shape functions
   * stay on the fixed background grid while the points move through it; the
   * nodal update is 'Update scheme' (automatic: MUSL).
   */
  template <int dim>
  class MaterialPointMethod : public Method<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    std::unique_ptr<NodalUpdate<dim>>
    create_nodal_update() const override;

    std::unique_ptr<GridMotion<dim>>
    create_grid_motion(ShapeFunctions<dim> &shape_functions) const override;

    bool
    fixed_grid() const override;

  private:
    std::string update_scheme;
  };
} // namespace MpmOtm

#endif
