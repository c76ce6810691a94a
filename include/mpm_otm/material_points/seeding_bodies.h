#ifndef mpm_otm_material_points_seeding_bodies_h
#define mpm_otm_material_points_seeding_bodies_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * What the seeding of the material points (MaterialPoints::seed()) asks
   * of the simulated bodies: which body a point of the seeding pattern lies
   * in, and the properties of a new point there. MaterialPoints knows where
   * the pattern's points are (blocks, cells, reference positions, volumes)
   * but no body, material or problem; the problems room implements this
   * interface (BodySeeder) over a problem and its materials, so that the
   * storage of the points stays below the rooms that give them meaning.
   */
  template <int dim>
  class SeedingBodies
  {
  public:
    virtual ~SeedingBodies() = default;

    /**
     * The number of bodies.
     */
    virtual unsigned int
    n_bodies() const = 0;

    /**
     * The name of body @p body, for messages.
     */
    virtual std::string
    body_name(const unsigned int body) const = 0;

    /**
     * The body that contains @p X, numbers::invalid_unsigned_int if none.
     */
    virtual unsigned int
    body_containing(const Point<dim> &X) const = 0;

    /**
     * The number of properties of every point (PropertyLayout and the
     * materials' internal variables).
     */
    virtual unsigned int
    n_properties() const = 0;

    /**
     * Set @p properties (n_properties() of them) to those of a new point at
     * @p X in body @p body with the volume @p volume: material, mass, initial
     * stress and velocity, F = I, traction data zero.
     */
    virtual void
    set_properties(const Point<dim>    &X,
                   const unsigned int   body,
                   const double         volume,
                   std::vector<double> &properties) const = 0;

    /**
     * The box grid's sides that carry a traction on the boundary points
     * (thesis Sect. 2.4.1), empty if none.
     */
    virtual std::vector<types::boundary_id>
    traction_boundaries() const = 0;

    /**
     * The box of the material region whose sides the traction boundaries
     * are (only asked for if there are traction boundaries).
     */
    virtual BoundingBox<dim>
    material_region() const = 0;
  };
} // namespace MpmOtm

#endif
