#ifndef mpm_otm_algorithms_moving_grid_h
#define mpm_otm_algorithms_moving_grid_h

#include <mpm_otm/algorithms/grid_motion.h>

#include <memory>
#include <string>

namespace MpmOtm
{
  /**
   * The grid motion that makes @p shape_functions follow the material, as
   * the family says (ShapeFunctions::moving_grid()): advected vertices
   * (AdvectedGrid), vertices with functions rebuilt on the moved grid
   * (AdvectedGrid too) or knots (AdvectedKnots). For a family that cannot
   * follow a moving grid, stops with its own message; @p method names the
   * method that asked for the moving grid. The only place that knows which
   * grid motion belongs to which family.
   */
  template <int dim>
  std::unique_ptr<GridMotion<dim>>
  create_moving_grid(ShapeFunctions<dim> &shape_functions,
                     const std::string   &method);
} // namespace MpmOtm

#endif
