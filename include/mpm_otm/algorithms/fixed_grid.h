#ifndef mpm_otm_algorithms_fixed_grid_h
#define mpm_otm_algorithms_fixed_grid_h

#include <mpm_otm/algorithms/grid_motion.h>

namespace MpmOtm
{
  /**
   * The grid of MPM: the shape functions stay on the initial grid
   * (journal Alg. 1, step 3, phi_i^0); after each step the moved material
   * points are sorted into the cells (and ranks) they have entered.
   */
  template <int dim>
  class FixedGrid : public GridMotion<dim>
  {
  public:
    bool
    moves_vertices() const override;

    bool
    tractions_on_grid_faces() const override;

    void
    add_face_tractions(const Problem<dim> &problem,
                       const double        time,
                       NodalSystem<dim>   &system) const override;

    void
    initialize(BackgroundGrid<dim> &,
               const ShapeFunctions<dim> &,
               const NodalSystem<dim> &,
               const double) override;

    void
    advance(const NodalSystem<dim> &system,
            MaterialPoints<dim>    &material_points,
            const double            dt) override;
  };
} // namespace MpmOtm

#endif
