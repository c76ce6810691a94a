#ifndef mpm_otm_problems_surface_loads_h
#define mpm_otm_problems_surface_loads_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class ParsedExpression;

  /**
   * Loads on parts of the bodies' surfaces (entry "Surface loads", one
   * subsection "Surface load <name>" each): a pressure, which follows the
   * deforming surface, and a traction per unit initial area of fixed
   * direction, on a flat part of the initial surface - a segment in 2D, an
   * axis-parallel rectangle in 3D, a point in 1D. The load acts through
   * the material points of the outermost layer beside that part: at the
   * start each such point gets its share of the part's measure as an area
   * vector A_p = a_p N (N the outward unit normal; the shares sum to the
   * part's length or area, so that the total load is exact) and its offset
   * D_p from the point to the surface. In a step the point's load is
   * f_p = -p cof(F_p) A_p + |A_p| t (Nanson's formula, cof(F) = det(F)
   * F^-T), applied at the surface point x_p + F_p D_p: the nodal shares
   * are phi_i(x_p) + grad phi_i(x_p) . F_p D_p, exact for linear functions
   * on the point's cell, so that the cell under the surface carries the
   * whole load (at x_p itself a part of it would act below the cell).
   *
   * The per-point data live in point variables (MaterialLibrary::
   * add_point_variables(), written out as surface_load, surface_area_* and
   * surface_offset_*), so they move with the points and are part of every
   * checkpoint.
   */
  template <int dim>
  class SurfaceLoads
  {
  public:
    /**
     * The load on one point and the offset F_p D_p of the surface point
     * where it acts.
     */
    struct PointLoad
    {
      Tensor<1, dim> force;
      Tensor<1, dim> offset;
    };

    SurfaceLoads();

    ~SurfaceLoads();

    /**
     * Declare the entries of subsections "Surface load <name>" for the
     * names @p names (the entry "Surface loads" is SubsectionNames').
     */
    static void
    declare_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &names);

    /**
     * Read the loads the entry "Surface loads" names; stops naming the
     * entry if a region is not flat or a load is zero.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Whether there is no load.
     */
    bool
    empty() const;

    /**
     * The names of the loads, in the order of "Surface loads".
     */
    const std::vector<std::string> &
    names() const;

    /**
     * Reserve the point variables of the loads (nothing without loads).
     * Call before the points are seeded.
     */
    void
    reserve_point_variables(MaterialLibrary<dim> &materials);

    /**
     * Give the points of the outermost layer beside each load's region their
     * area vectors and offsets. Stops, naming the load, if no point lies
     * within one point spacing of the region (it is not on a body's
     * surface), if points lie on both sides of it (it runs through a body),
     * if the points beside it cover less than 70 % of it (part of it is off
     * the surface), or if a point lies beside two regions. Collective.
     */
    void
    assign_points(MaterialPoints<dim> &points) const;

    /**
     * Let the loads with @p acting true act and the others not (one flag
     * per load, in the order of Surface loads): a load that does not act
     * gives no force, also in the statistics, and its points keep their
     * share of the surface. Every load acts until this is called (by a
     * stage: Stage NAME/Surface loads).
     */
    void
    set_acting(const std::vector<bool> &acting);

    /**
     * Whether the point with @p properties carries a load.
     */
    bool
    carries_load(const ArrayView<const double> &properties) const
    {
      return first_slot != numbers::invalid_unsigned_int &&
             properties[first_slot] > 0.;
    }

    /**
     * The load at @p time on the point with @p properties, which must carry
     * one (carries_load()).
     */
    PointLoad
    load_on(const ArrayView<const double> &properties, const double time) const;

    /**
     * Per load, its total force on the points of all ranks at @p time and
     * the mean displacement of its points, weighted by their shares of the
     * surface. Collective.
     */
    std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>>
    forces_and_displacements(const MaterialPoints<dim> &points,
                             const double               time) const;

    /**
     * Evaluate the loads at @p time on every loaded point of this rank, so
     * that an expression that does not evaluate stops the run with its
     * message. Not collective.
     */
    void
    check_expressions(const MaterialPoints<dim> &points,
                      const double               time) const;

  private:
    /**
     * One load: its region and its expressions.
     */
    struct Load
    {
      std::string                            name;
      Point<dim>                             from;
      Point<dim>                             to;
      std::unique_ptr<ParsedExpression<dim>> pressure;
      std::unique_ptr<ParsedExpression<dim>> traction;
      /// A unit normal of the region (either side).
      Tensor<1, dim> normal;
      /// Its length (2D), area (3D) or 1 (1D).
      double measure = 0;
      /// Whether it acts (set_acting()).
      bool acting = true;
    };

    /**
     * Whether @p X lies, along the region of @p load, within it; the
     * distance to its plane is not checked.
     */
    bool
    beside(const Load &load, const Point<dim> &X) const;

    std::vector<std::string> load_names;
    std::vector<Load>        loads;
    /// The first of the point variables: the number of the point's load
    /// plus one (0: none), then A_p and D_p (dim components each).
    unsigned int first_slot = numbers::invalid_unsigned_int;
  };
} // namespace MpmOtm

#endif
