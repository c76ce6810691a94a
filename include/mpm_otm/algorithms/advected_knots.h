#ifndef mpm_otm_algorithms_advected_knots_h
#define mpm_otm_algorithms_advected_knots_h

#include <deal.II/grid/tria.h>

#include <mpm_otm/algorithms/grid_motion.h>

#include <array>
#include <vector>

namespace MpmOtm
{
  template <int dim>
  class BSplines;

  /**
   * The grid motion of the unified approach with B-splines (journal Alg. 3,
   * Sect. 8.3): after every step the knots move with the material and the
   * B-splines are rebuilt on the moved knots. The knots are the distinct
   * cell boundaries of each direction, so the grid stays a tensor product
   * of axis-parallel boxes: knot xi_k of direction d moves by dt w_d(xi_k),
   * where w_d is the one-dimensional spline with the coefficients v_d
   * averaged over the other directions' control points. In 1D this is the
   * velocity field itself; in 2D and 3D it is exact for motions whose
   * component d depends on x_d only (benchmark B3) and an average
   * otherwise. The grid's vertices move alike; points stay in their cells
   * unless the averaged motion lets them cross a knot, in which case they
   * are located anew.
   */
  template <int dim>
  class AdvectedKnots : public GridMotion<dim>
  {
  public:
    /**
     * Move the knots of @p splines.
     */
    explicit AdvectedKnots(BSplines<dim> &splines);

    bool
    moves_vertices() const override;

    bool
    tractions_on_grid_faces() const override;

    /**
     * f_i += t int_face phi_i: on side 2 d or 2 d + 1 the first or last
     * layer of functions, weighted by the integrals of the other
     * directions' B-splines, (U_{i+p+1} - U_i) / (p + 1).
     */
    void
    add_face_tractions(const Problem<dim> &problem,
                       const double        time,
                       NodalSystem<dim>   &system) const override;

    void
    initialize(BackgroundGrid<dim>       &grid,
               const ShapeFunctions<dim> &shape_functions,
               const NodalSystem<dim>    &system,
               const double               stable_cell_size) override;

    /**
     * Move the knots and vertices by dt w, after checking that no knot span
     * inverts or shrinks below c dt; rebuild the B-splines and locate the
     * points.
     */
    void
    advance(const NodalSystem<dim> &system,
            MaterialPoints<dim>    &material_points,
            const double            dt) override;

    void
    save(CheckpointState &state) const override;

    void
    load(const CheckpointState &state) override;

  private:
    /**
     * Integral of the one-dimensional B-spline @p i of direction @p d.
     */
    double
    integral(const unsigned int d, const unsigned int i) const;

    BSplines<dim>      &splines;
    Triangulation<dim> *triangulation = nullptr;
    double              stable_size   = 0;

    /// The vertices of the non-artificial cells and their knot indices.
    std::vector<Point<dim> *>                  vertices;
    std::vector<std::array<unsigned int, dim>> knot_of_vertex;
  };
} // namespace MpmOtm

#endif
