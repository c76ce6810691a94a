#include <mpm_otm/base/plugins.h>
#include <mpm_otm/boundary_conditions/traction_condition.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/shape_functions/shape_functions.h>

namespace MpmOtm
{
  template <int dim>
  void
  TractionCondition<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Traction",
                      (dim == 1 ? "0" :
                       dim == 2 ? "0; 0" :
                                  "0; 0; 0"),
                      Patterns::Anything(),
                      "Type = traction: dim expressions in t (Pa: force per "
                      "current area of the side), separated by ';'.");
  }



  template <int dim>
  void
  TractionCondition<dim>::parse_parameters(ParameterHandler &prm)
  {
    AssertThrow(!this->where.on_box,
                ExcMessage(this->where.path() +
                           "Box lower corner, Box upper corner: Type = "
                           "traction acts on a side of the grid; give "
                           "Boundary ids."));
    // Uniform over the side: a function of time only.
    traction =
      std::make_unique<ParsedExpression<dim>>(prm.get("Traction"),
                                              dim,
                                              true,
                                              this->where.path() + "Traction",
                                              false);
    traction->vector_value(Point<dim>(), 0.);
  }



  template <int dim>
  bool
  TractionCondition<dim>::holds_nodes() const
  {
    return false;
  }



  template <int dim>
  void
  TractionCondition<dim>::initialize(const ShapeFunctions<dim> &shape_functions)
  {
    functions = &shape_functions;
    shares.reinit(
      shape_functions.locally_owned_functions(),
      shape_functions.locally_relevant_functions(),
      shape_functions.dof_handler().get_triangulation().get_communicator());
    find_shares();
  }



  template <int dim>
  void
  TractionCondition<dim>::find_shares()
  {
    shares = 0.;
    for (const auto id : this->where.boundary_ids)
      AssertThrow(functions->boundary_integrals(id, shares),
                  ExcMessage(this->where.path() +
                             "Type = traction needs the integrals of the "
                             "shape functions over the side, which this "
                             "family does not provide; use Shape functions "
                             "= linear, B-spline or max-ent."));
  }



  template <int dim>
  Tensor<1, dim>
  TractionCondition<dim>::add_loads(NodalSystem<dim> &system,
                                    const double      time,
                                    const double)
  {
    // The faces of a moving grid change in every step (collective on
    // every rank alike).
    if (!this->where.fixed_grid)
      find_shares();
    const Tensor<1, dim> value = traction->vector_value(Point<dim>(), time);
    Tensor<1, dim>       load;
    double               power = 0.;
    for (const unsigned int i : this->where.functions)
      {
        if (!(system.lumped_mass.local_element(i) > 0.))
          continue;
        const Tensor<1, dim> force = shares.local_element(i) * value;
        for (unsigned int c = 0; c < dim; ++c)
          {
            system.force[c].local_element(i) += force[c];
            power += force[c] * system.velocity[c].local_element(i);
          }
        load += force;
      }
    system.add_external_power(power);
    return load;
  }



  template class TractionCondition<1>;
  template class TractionCondition<2>;
  template class TractionCondition<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<1>,
  MpmOtm::TractionCondition<1>,
  "traction",
  "the Cauchy traction 'Traction' (functions of time) on the side")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<2>,
  MpmOtm::TractionCondition<2>,
  "traction",
  "the Cauchy traction 'Traction' (functions of time) on the side")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<3>,
  MpmOtm::TractionCondition<3>,
  "traction",
  "the Cauchy traction 'Traction' (functions of time) on the side")
