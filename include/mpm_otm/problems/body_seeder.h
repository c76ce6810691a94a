#ifndef mpm_otm_problems_body_seeder_h
#define mpm_otm_problems_body_seeder_h

#include <mpm_otm/material_points/seeding_bodies.h>

namespace MpmOtm
{
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class Problem;

  /**
   * The bodies of a problem as the seeding of the material points sees them
   * (SeedingBodies): the problem says which body a point lies in and its
   * initial stress and velocity, the body's material its density and the
   * number of properties. A new point gets X_p, V_p, m_p = rho V_p, v_p =
   * v0(X_p), F_p = I and sigma_p and the out-of-plane stress from the body's
   * initial stress.
   */
  template <int dim>
  class BodySeeder : public SeedingBodies<dim>
  {
  public:
    /**
     * Seed the bodies of @p problem with the materials @p materials (both
     * must outlive this object).
     */
    BodySeeder(const Problem<dim>         &problem,
               const MaterialLibrary<dim> &materials);

    unsigned int
    n_bodies() const override;

    std::string
    body_name(const unsigned int body) const override;

    unsigned int
    body_containing(const Point<dim> &X) const override;

    unsigned int
    n_properties() const override;

    void
    set_properties(const Point<dim>    &X,
                   const unsigned int   body,
                   const double         volume,
                   std::vector<double> &properties) const override;

    std::vector<types::boundary_id>
    traction_boundaries() const override;

    BoundingBox<dim>
    material_region() const override;

  private:
    const Problem<dim>         &problem;
    const MaterialLibrary<dim> &materials;
  };
} // namespace MpmOtm

#endif
