#ifndef mpm_otm_algorithms_particle_transfer_h
#define mpm_otm_algorithms_particle_transfer_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/partitioner.h>

#include <mpm_otm/algorithms/nodal_update.h>
#include <mpm_otm/shape_functions/particle_shape_data.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class NodalSystem;
  template <int dim>
  class ShapeFunctions;

  /**
   * How the material points' velocities travel between the points and the
   * grid in MPM and the unified approach (entry "Particle velocity"):
   *
   * - FLIP: v_p += dt sum_i phi_i a_i (journal Eq. 27), the sources'
   *   rule, which keeps the kinetic energy but also the grid's
   *   unresolved (ringing) modes;
   * - PIC: v_p = sum_i phi_i v_i, the nodal velocity at the point, which
   *   damps every mode the grid cannot carry (strongly: each transfer loses
   *   kinetic energy, by Jensen's inequality);
   * - blend: alpha FLIP + (1 - alpha) PIC with alpha = "FLIP fraction"
   *   (Stomakhin et al. 2013, alpha = 0.95-0.99);
   * - APIC (Jiang, Schroeder, Selle, Teran & Stomakhin 2015, "The affine
   *   particle-in-cell method"): PIC's velocity plus an affine velocity
   *   field per point, B_p = sum_i phi_i v_i (x_i - x_p)^T after the step,
   *   which the next particle-to-grid transfer adds to the momenta,
   *   m_p phi_i B_p D_p^-1 (x_i - x_p) with D_p = sum_i phi_i (x_i - x_p)
   *   (x_i - x_p)^T; x_i are the points of the functions
   *   (ShapeFunctions::function_points()). Both transfers conserve the
   *   angular momentum sum_p m_p (x_p x v_p + the axial part of B_p), and
   *   the rotation of a body is not damped as with PIC.
   *
   * v_i are the grid's own nodal velocities M^-1 q + dt a (with USL those
   * that move the points; MUSL computes them for PIC's part before it
   * projects the points' new velocities, adding APIC's affine momenta).
   * OTM's points take the velocity of their displacement, so OTM takes
   * only FLIP; APIC needs a grid that stays where it is and the lumped mass
   * matrix: a consistent mass matrix projects the points' velocities onto
   * the functions, which reproduces affine fields already, and APIC's
   * affine momenta on top of it made the vibrating bar B1b blow up.
   */
  template <int dim>
  class ParticleTransfer
  {
  public:
    /**
     * Declare "Particle velocity" and "FLIP fraction".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the entries.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Stop with a message naming the entries if the rule cannot work with
     * the nodal update @p nodal_update of Method = @p method or, for APIC,
     * with a grid that moves (@p fixed_grid false) or a mass matrix that is
     * not lumped in every row (@p lumped_mass false).
     */
    void
    check(const NodalUpdate<dim> &nodal_update,
          const std::string      &method,
          const bool              fixed_grid,
          const bool              lumped_mass) const;

    /**
     * For APIC: reserve the points' slots for B_p in @p materials. Before
     * the points are seeded.
     */
    void
    reserve_point_variables(MaterialLibrary<dim> &materials);

    /**
     * For APIC: take the points of the functions of @p shape_functions for
     * the nodal vectors of @p partitioner, or stop with a message if the
     * family has none. Collective.
     */
    void
    initialize(const ShapeFunctions<dim>         &shape_functions,
               const Utilities::MPI::Partitioner &partitioner);

    /**
     * The weight alpha of FLIP's velocity in the point's new velocity: 1
     * for FLIP, 0 for PIC and APIC, "FLIP fraction" for blend.
     */
    double
    flip_fraction() const;

    /**
     * True for APIC.
     */
    bool
    is_affine() const;

    /**
     * The particle velocity the stable time step is estimated for with the
     * nodal update's own @p particle_velocity: PIC moves the points with the
     * nodal velocities as OTM does (from_displacement); a blend or APIC is
     * given FLIP's estimate, the smaller time step of the two.
     */
    typename NodalUpdate<dim>::ParticleVelocity
    velocity_for_stability(const typename NodalUpdate<dim>::ParticleVelocity
                             particle_velocity) const;

    /**
     * One line for the run's log.
     */
    std::string
    description() const;

    /**
     * For APIC, in the particle-to-grid transfer (before the nodal vectors
     * are compressed): add m_p phi_i B_p D_p^-1 (x_i - x_p) of every point
     * to system.momentum.
     */
    void
    add_affine_momentum(const MaterialPoints<dim>    &material_points,
                        const ParticleShapeData<dim> &shape_data,
                        NodalSystem<dim>             &system) const;

    /**
     * For APIC, in the grid-to-particle transfer, before the point moves:
     * store B_p = sum_i phi_i v_i (x_i - x_p)^T with the point's functions
     * @p point, the nodal velocities @p nodal_velocities of its functions
     * (in the order of @p point) and its location @p location.
     */
    void
    store_affine_velocity(
      const ArrayView<double>                               &properties,
      const Point<dim>                                      &location,
      const typename ParticleShapeData<dim>::PointFunctions &point,
      const Tensor<1, dim> *nodal_velocities) const;

    /**
     * For APIC: add the angular momentum of the points' affine motion about
     * their centres, sum_p m_p sum_i phi_i (x_i - x_p) x v_i (the axial
     * vector of B_p - B_p^T), to @p angular_momentum (x, y, z; only z in
     * 2D). Collective; nothing without APIC.
     */
    void
    add_affine_angular_momentum(const MaterialPoints<dim> &material_points,
                                double angular_momentum[3]) const;

    /**
     * The matrix B_p of a point's properties @p properties (APIC; zero
     * otherwise).
     */
    Tensor<2, dim>
    affine_velocity(const ArrayView<const double> &properties) const;

  private:
    std::string  rule        = "FLIP";
    double       flip_weight = 1.;
    unsigned int first_slot  = numbers::invalid_unsigned_int;
    /// The point of each locally relevant function (APIC).
    std::vector<Point<dim>> function_points;
  };
} // namespace MpmOtm

#endif
