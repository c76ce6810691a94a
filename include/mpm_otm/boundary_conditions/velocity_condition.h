#ifndef mpm_otm_boundary_conditions_velocity_condition_h
#define mpm_otm_boundary_conditions_velocity_condition_h

#include <mpm_otm/base/parsed_expression.h>
#include <mpm_otm/boundary_conditions/condition.h>

#include <memory>

namespace MpmOtm
{
  /**
   * Type = velocity: the components 'Velocity components' prescribed to
   * 'Velocity', the others free. A box of prescribed velocity moves as one
   * with the displacement it prescribes (a settling footing, a moving
   * platen), so its Velocity is a function of time: every step it acts on
   * the nodes inside the moved box. On grid sides the Velocity may also
   * depend on the position each node has at the start (a wave front that
   * sweeps along the side, a side that rotates); its displacement in the
   * statistics is then that of the centroid of the side's nodes. The work
   * it does is counted in the energy balance.
   */
  template <int dim>
  class VelocityCondition : public Condition<dim>
  {
  public:
    /**
     * Declare "Velocity" and "Velocity components".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    /**
     * For a Velocity that depends on position: the position of each node,
     * from the family's function_points() (refused for a family whose
     * functions do not belong to points), and their centroid. Collective.
     */
    void
    initialize(const ShapeFunctions<dim> &shape_functions) override;

    /**
     * Refuse a condition on grid sides whose prescribed motion takes it
     * more than half a cell into the grid before @p end_time: MPM's grid
     * stays where it is, so the material leaves the side's nodes, which then
     * hold less and less of it, and the condition's reaction stops being the
     * load on the material (a platen on the grid's top side lost the
     * specimen of the biaxial test after 0.04 m of travel on 0.05 m cells).
     * A condition on a box follows its displacement; on a moving grid the
     * side moves with its nodes.
     */
    void
    check_run(const double end_time) const override;

    std::array<bool, dim>
    constrained_components() const override;

    void
    target_velocities(const double                 time,
                      std::vector<Tensor<1, dim>> &targets) const override;

    bool
    moves() const override;

    /**
     * Move the nodes by the prescribed velocity at the end of the step and
     * return the positive part of the work the reaction did.
     */
    double
    advance(const std::vector<Tensor<1, dim>> &node_reactions,
            const double                       time,
            const double                       dt) override;

  private:
    /**
     * The prescribed components of the Velocity at @p position and
     * @p time, the others zero.
     */
    Tensor<1, dim>
    prescribed(const Point<dim> &position, const double time) const;

    std::array<bool, dim>                  components{};
    std::unique_ptr<ParsedExpression<dim>> velocity;
    /// Whether the Velocity uses the coordinates.
    bool depends_on_position = false;
    /// The position at the start of each node where.functions[k] (only for
    /// a Velocity that depends on position).
    std::vector<Point<dim>> node_positions;
    /// The centroid of all ranks' nodes, where the displacement is taken.
    Point<dim> centroid;
    MPI_Comm   communicator = MPI_COMM_WORLD;
  };
} // namespace MpmOtm

#endif
