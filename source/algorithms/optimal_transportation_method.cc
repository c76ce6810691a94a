#include <mpm_otm/algorithms/moving_grid.h>
#include <mpm_otm/algorithms/optimal_transportation_method.h>
#include <mpm_otm/algorithms/optimal_transportation_update.h>
#include <mpm_otm/base/plugins.h>
#include <mpm_otm/shape_functions/shape_functions.h>

namespace MpmOtm
{
  template <int dim>
  void
  OptimalTransportationMethod<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  OptimalTransportationMethod<dim>::parse_parameters(ParameterHandler &prm)
  {
    AssertThrow(prm.get("Update scheme") == "automatic",
                ExcMessage("Update scheme = " + prm.get("Update scheme") +
                           " applies to Method = MPM or Unified; OTM has "
                           "its own nodal update (journal Eq. 51). Remove "
                           "the entry."));
    shape_functions_name = prm.get("Shape functions");
    // The family's degree, where it has one, for the message on linear
    // completeness.
    degree      = shape_functions_name == "B-spline" ?
                    " of degree " + prm.get("B-spline degree") :
                    std::string();
    mass_matrix = prm.get("Mass matrix");
  }



  template <int dim>
  std::unique_ptr<NodalUpdate<dim>>
  OptimalTransportationMethod<dim>::create_nodal_update() const
  {
    return std::make_unique<OptimalTransportationUpdate<dim>>();
  }



  template <int dim>
  std::unique_ptr<GridMotion<dim>>
  OptimalTransportationMethod<dim>::create_grid_motion(
    ShapeFunctions<dim> &shape_functions) const
  {
    AssertThrow(shape_functions.is_linearly_complete(),
                ExcMessage("Method = OTM needs linearly complete shape "
                           "functions (journal Eq. 47); Shape functions = " +
                           shape_functions_name + degree +
                           " are not. Use Method = MPM or Unified, or "
                           "linearly complete functions (B-spline degree = "
                           "1)."));
    // Knots move with direction-averaged velocities in 2D and 3D, while
    // OTM moves the points with the full field (Alg. 2 needs points that
    // keep their place in the moving discretisation).
    AssertThrow(
      shape_functions.moving_grid() != ShapeFunctions<dim>::MovingGrid::knots ||
        dim == 1,
      ExcMessage("Method = OTM with Shape functions = " + shape_functions_name +
                 " runs in 1D only: in 2D and 3D the knots move "
                 "per direction with averaged velocities, which "
                 "is the unified approach (Method = Unified), "
                 "not OTM. Use Method = Unified, or linear "
                 "functions for OTM."));
    // Functions rebuilt on the moved grid move the points with a field that
    // is not the cells' affine map either.
    AssertThrow(
      shape_functions.moving_grid() != ShapeFunctions<dim>::MovingGrid::rebuilt,
      ExcMessage("Method = OTM with Shape functions = " + shape_functions_name +
                 " is not possible: OTM needs points that keep their place "
                 "in the moving grid, but these functions move the points "
                 "with a field that is not the cells' affine map (they are "
                 "rebuilt on the moved grid every step). Use Method = "
                 "Unified, or linear functions for OTM."));
    return create_moving_grid(shape_functions, "OTM");
  }



  template <int dim>
  bool
  OptimalTransportationMethod<dim>::fixed_grid() const
  {
    return false;
  }



  template <int dim>
  std::string
  OptimalTransportationMethod<dim>::note() const
  {
    if (mass_matrix == "consistent")
      return {};
    return "Note: OTM with Mass matrix = " + mass_matrix +
           " smooths the particle velocities (journal Eq. 57) every step "
           "and is dissipative; Alg. 2 uses the consistent mass matrix "
           "(Eq. 48).";
  }



  template class OptimalTransportationMethod<1>;
  template class OptimalTransportationMethod<2>;
  template class OptimalTransportationMethod<3>;
} // namespace MpmOtm

#define MPM_OTM_OTM_DESCRIPTION                                          \
  "optimal transportation meshfree method (journal Alg. 2): the grid's " \
  "vertices move with the material every step, nodal update of Eq. 51, " \
  "particle velocities from the displacements; needs linearly complete " \
  "shape functions and takes no 'Update scheme'"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<1>,
                        MpmOtm::OptimalTransportationMethod<1>,
                        "OTM",
                        MPM_OTM_OTM_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<2>,
                        MpmOtm::OptimalTransportationMethod<2>,
                        "OTM",
                        MPM_OTM_OTM_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Method<3>,
                        MpmOtm::OptimalTransportationMethod<3>,
                        "OTM",
                        MPM_OTM_OTM_DESCRIPTION)
