#include <mpm_otm/algorithms/advected_grid.h>
#include <mpm_otm/algorithms/advected_knots.h>
#include <mpm_otm/algorithms/moving_grid.h>
#include <mpm_otm/shape_functions/b_splines.h>

namespace MpmOtm
{
  template <int dim>
  std::unique_ptr<GridMotion<dim>>
  create_moving_grid(ShapeFunctions<dim> &shape_functions,
                     const std::string   &method)
  {
    using MovingGrid = typename ShapeFunctions<dim>::MovingGrid;
    switch (shape_functions.moving_grid())
      {
        case MovingGrid::vertices:
          return std::make_unique<AdvectedGrid<dim>>();
        case MovingGrid::rebuilt:
          return std::make_unique<AdvectedGrid<dim>>(&shape_functions);
        case MovingGrid::knots:
          {
            // Only B-splines say that their functions live on knots.
            auto *splines = dynamic_cast<BSplines<dim> *>(&shape_functions);
            AssertThrow(splines != nullptr, ExcInternalError());
            return std::make_unique<AdvectedKnots<dim>>(*splines);
          }
        default:
          AssertThrow(false,
                      ExcMessage("Method = " + method + ": " +
                                 shape_functions.moving_grid_limitation()));
          return nullptr;
      }
  }



  template std::unique_ptr<GridMotion<1>>
  create_moving_grid(ShapeFunctions<1> &, const std::string &);
  template std::unique_ptr<GridMotion<2>>
  create_moving_grid(ShapeFunctions<2> &, const std::string &);
  template std::unique_ptr<GridMotion<3>>
  create_moving_grid(ShapeFunctions<3> &, const std::string &);
} // namespace MpmOtm
