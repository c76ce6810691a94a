#include <mpm_otm/base/plugins.h>
#include <mpm_otm/boundary_conditions/velocity_condition.h>

#include <algorithm>
#include <sstream>

namespace MpmOtm
{
  template <int dim>
  void
  VelocityCondition<dim>::declare_parameters(ParameterHandler &prm)
  {
    const std::string zeros = (dim == 1 ? "0" : dim == 2 ? "0; 0" : "0; 0; 0");
    prm.declare_entry("Velocity",
                      zeros,
                      Patterns::Anything(),
                      "Type = velocity: dim expressions in t (m/s), "
                      "separated by ';'.");
    prm.declare_entry("Velocity components",
                      std::string("xyz").substr(0, 1) + (dim > 1 ? ", y" : "") +
                        (dim > 2 ? ", z" : ""),
                      Patterns::List(Patterns::Selection("x|y|z")),
                      "Type = velocity: the components prescribed; the "
                      "others are free.");
  }



  template <int dim>
  void
  VelocityCondition<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string path = this->where.path();
    components.fill(false);
    for (const auto &component :
         Utilities::split_string_list(prm.get("Velocity components")))
      {
        const unsigned int c = component[0] - 'x';
        AssertThrow(c < dim,
                    ExcMessage(path + "Velocity components: <" + component +
                               "> is not a direction in " +
                               std::to_string(dim) + "D."));
        components[c] = true;
      }
    // The velocity is a function of time only (the condition's nodes move
    // as one).
    velocity = std::make_unique<ParsedExpression<dim>>(prm.get("Velocity"),
                                                       dim,
                                                       true,
                                                       path + "Velocity",
                                                       false);
    velocity->vector_value(Point<dim>(), 0.);
  }



  template <int dim>
  void
  VelocityCondition<dim>::check_run(const double end_time) const
  {
    const ConditionNodes<dim> &where = this->where;
    if (where.on_box || !where.fixed_grid || where.normal.norm() == 0.)
      return;
    // The displacement of the prescribed components against the outward
    // normal, by the trapezoidal rule, and its largest value in the run.
    const auto inward_velocity = [&](const double t) {
      const Tensor<1, dim> value  = velocity->vector_value(Point<dim>(), t);
      double               inward = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        if (components[d])
          inward -= value[d] * where.normal[d];
      return inward;
    };
    const unsigned int n_intervals = 10000;
    const double       dt          = end_time / n_intervals;
    double previous = inward_velocity(0.), travel = 0., largest = 0.;
    for (unsigned int i = 1; i <= n_intervals; ++i)
      {
        const double current = inward_velocity(i * dt);
        travel += 0.5 * dt * (previous + current);
        largest  = std::max(largest, travel);
        previous = current;
      }
    std::ostringstream message;
    message << "Boundary " << where.name
            << "/Velocity moves the grid side of its Boundary ids " << largest
            << " m into the grid before the End time, more than half the "
               "depth of the cells along that side ("
            << 0.5 * where.cell_depth
            << " m). MPM's grid stays where it is: once the material "
               "has moved that far from the side, the side's nodes hold "
               "less and less of it, and the condition's reaction stops "
               "being the load on it (a platen loses its specimen). Give "
               "the condition Box lower corner and Box upper corner "
               "instead of Boundary ids (the box follows the "
               "displacement: manual, 'Boundary conditions'), or a "
               "shorter Time/End time.";
    AssertThrow(!(largest > 0.5 * where.cell_depth), ExcMessage(message.str()));
  }



  template <int dim>
  std::array<bool, dim>
  VelocityCondition<dim>::constrained_components() const
  {
    return components;
  }



  template <int dim>
  Tensor<1, dim>
  VelocityCondition<dim>::target_velocity(const double time) const
  {
    Tensor<1, dim>       result;
    const Tensor<1, dim> prescribed =
      velocity->vector_value(Point<dim>(), time);
    for (unsigned int d = 0; d < dim; ++d)
      if (components[d])
        result[d] = prescribed[d];
    return result;
  }



  template <int dim>
  bool
  VelocityCondition<dim>::moves() const
  {
    return true;
  }



  template <int dim>
  double
  VelocityCondition<dim>::advance(const Tensor<1, dim> &reaction,
                                  const double          time,
                                  const double          dt)
  {
    const Tensor<1, dim> prescribed =
      velocity->vector_value(Point<dim>(), time + dt);
    double work = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      if (components[d])
        {
          this->where.displacement[d] += dt * prescribed[d];
          work += dt * reaction[d] * prescribed[d];
        }
    return std::max(work, 0.);
  }



  template class VelocityCondition<1>;
  template class VelocityCondition<2>;
  template class VelocityCondition<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<1>,
  MpmOtm::VelocityCondition<1>,
  "velocity",
  "the components 'Velocity components' prescribed to 'Velocity', the "
  "others free")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<2>,
  MpmOtm::VelocityCondition<2>,
  "velocity",
  "the components 'Velocity components' prescribed to 'Velocity', the "
  "others free")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<3>,
  MpmOtm::VelocityCondition<3>,
  "velocity",
  "the components 'Velocity components' prescribed to 'Velocity', the "
  "others free")
