#ifndef mpm_otm_algorithms_f_bar_h
#define mpm_otm_algorithms_f_bar_h

#include <mpm_otm/algorithms/volumetric_locking_remedy.h>

namespace MpmOtm
{
  /**
   * The F-bar method (de Souza Neto, Peric, Dutko & Owen 1996) for material
   * points: each point's deformation gradient keeps its isochoric part, and
   * its Jacobian J = det F is replaced by an average over its neighbours.
   * In a step, with the point's velocity gradient L_p, its trial Jacobian
   * is J_p = det(F_p^n) det(I + dt L_p); the average Jbar of the J of the
   * points around it (below) sets the increment of the deformation
   * gradient to dFbar_p = (Jbar / J_p)^(1/dim) (I + dt L_p), so that
   * F_p^{n+1} = dFbar_p F_p^n has det = Jbar, and the velocity gradient
   * that the stress update sees to Lbar_p = (dFbar_p - I) / dt (the rate
   * form for the hypo-elastic and plastic models). In 2D the points are in
   * plane strain, so the exponent is 1/2.
   *
   * The average is taken over the total Jacobians, not over the increments
   * of one step (Coombs, Charlton, Cortis & Augarde 2018, CMAME 333, average
   * the increments on a cell): material points move from cell to cell and
   * bring their own history, and an average of increments keeps the
   * differences between the points of a cell forever, while an average of
   * J removes them (G3 on 32 cells per footing half-width: 8 % below
   * Prandtl's load with increments, 3 % with J; doc/benchmarks.md).
   *
   * With the averaged dilatation goes a smoothed mean stress: after the
   * models have updated the stresses, the mean stresses p = tr(sigma) / 3
   * (of the three-dimensional stress) of the same points are replaced by
   * their volume-weighted least-squares fit p = a + b . (x - x_c) (their
   * mean if they do not span the cell), the deviators kept. A cell's
   * points cannot all change their volumes on their own, so neither can
   * their pressures: what a point's pressure differs from the cell's linear
   * fit (the checkerboard of the pressure) would have nothing to relax it,
   * and the nodal forces sum_p V_p sigma_p grad phi_i would do work on it
   * that the points do not take (the power of the forces,
   * sum_p V_p p_p div v(x_p), against sum_p V_p p_p dJbar/dt / Jbar); the
   * fit removes that part (manual, "Volumetric locking", for what it does
   * to a dilatant flow). A linear pressure, as the weight of
   * the soil above a point gives, is kept (a fit to a constant, as the
   * Q1/P0 element's, would make a geostatic stress a staircase, 1.8 %
   * off on 0.5 m cells). The fit is a projection in the weighted norm, so
   * it only takes elastic energy away.
   *
   * Points that have lost contact (Material::is_disconnected(): a granular
   * point opened beyond the density at which it lost contact) keep their
   * own J and stress: averaging the volume of such a dilated, stress-free
   * point with its dense neighbours' swelled them, and the forces
   * V_p sigma_p grad phi_i with them (a dilatant column collapse ran away
   * at its base twice as early as without a remedy).
   *
   * The average is over the points of one material in one cell, weighted
   * by their initial volumes, so that the cell's volume of each material is
   * kept: Jbar = sum_p V_p^0 J_p / sum_p V_p^0 (the constant dilatation of
   * the Q1/P0 element; Coombs et al. 2018 for MPM), and a stiff body does
   * not take the volume change of the soil beside it. The points of a cell
   * are on the rank that owns it: no communication. Families whose
   * gradients are constant on each cell (linear functions on
   * triangles/tetrahedra) are refused: every point of a cell has the same
   * J already. (A lumped projection of J onto the shape functions,
   * Zhao, Jiang & Choo 2023, was tried for them and removed: it is soft,
   * G3's load 67 % below Prandtl's on crossed triangles and 6 % below on
   * quadrilaterals; manual, "Volumetric locking".)
   */
  template <int dim>
  class Material;

  template <int dim>
  class FBar : public VolumetricLockingRemedy<dim>
  {
  public:
    /**
     * F-bar has no entries of its own.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    void
    initialize(const ShapeFunctions<dim>  &shape_functions,
               const NodalSystem<dim>     &system,
               const MaterialLibrary<dim> &materials) override;

    std::string
    description() const override;

    void
    correct(MaterialPoints<dim>          &material_points,
            const ParticleShapeData<dim> &shape_data,
            const double                  dt,
            std::vector<Tensor<2, dim>>  &velocity_gradients) override;

    /**
     * Replace the mean stresses of the points of each group of correct()
     * by their weighted linear least-squares fit.
     */
    void
    after_stress_update(MaterialPoints<dim> &material_points) override;

  private:
    /**
     * What correct() needs of a material: the model, where its internal
     * variables are, and whether its points can lose contact.
     */
    struct Model
    {
      const Material<dim> *material;
      unsigned int         first_variable;
      unsigned int         n_variables;
      bool                 may_lose_contact;
    };

    /// The materials of the run, by number.
    std::vector<Model> models;

    /**
     * Set the average Jacobians of the points [first, end) (of one cell):
     * the mean of each material's points among them.
     */
    void
    average_group(const unsigned int first, const unsigned int end);

    /// The groups of correct(): first and one past the last point of the
    /// points of one material in one cell.
    std::vector<std::pair<unsigned int, unsigned int>> groups;

    /// Per point, in the order of the particle handler: the trial Jacobian
    /// J_p, its average Jbar_p, the weight V_p^0 and the material
    /// (numbers::invalid_unsigned_int for a point that has lost contact,
    /// Material::is_disconnected(), which is left alone).
    std::vector<double>       trial_jacobian;
    std::vector<double>       average_jacobian;
    std::vector<double>       weight;
    std::vector<unsigned int> material;
    /// The position of each point at the start of the step.
    std::vector<Point<dim>> positions;
    /// The property arrays of the points, taken in correct() for
    /// after_stress_update() (the particle handler is not walked again).
    std::vector<double *> stress_views;
    /// The mean stress of each point after the stress update.
    std::vector<double> pressure;
  };
} // namespace MpmOtm

#endif
