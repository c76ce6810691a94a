#ifndef mpm_otm_algorithms_optimal_transportation_method_h
#define mpm_otm_algorithms_optimal_transportation_method_h

#include <mpm_otm/algorithms/method.h>

namespace MpmOtm
{
  /**
   * OTM, the optimal transportation meshfree method (journal Alg. 2): the
   * grid's vertices move with the material every step, the nodal update of
   * Eq. 51 and particle velocities from the displacements; needs linearly
   * complete shape functions.
   */
  template <int dim>
  class OptimalTransportationMethod : public Method<dim>
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

    std::string
    note() const override;

  private:
    /// The family as the user named it, for messages.
    std::string shape_functions_name;
    /// " of degree p" for B-splines, for messages.
    std::string degree;
    /// The entry "Mass matrix", for the note.
    std::string mass_matrix;
  };
} // namespace MpmOtm

#endif
