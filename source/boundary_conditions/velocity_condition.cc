#include <deal.II/base/partitioner.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/boundary_conditions/velocity_condition.h>
#include <mpm_otm/shape_functions/shape_functions.h>

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
                      "Type = velocity: dim expressions (m/s), separated "
                      "by ';', in t, and on Boundary ids also in the "
                      "coordinates x, y, z of each node at the start.");
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
    const std::string text = prm.get("Velocity");
    velocity               = std::make_unique<ParsedExpression<dim>>(text,
                                                       dim,
                                                       true,
                                                       path + "Velocity");
    depends_on_position    = velocity->uses_coordinates();
    AssertThrow(!(depends_on_position && this->where.on_box),
                ExcMessage(path + "Velocity: <" + text +
                           "> depends on the coordinates, but the condition "
                           "acts on the nodes in a box, which move as one "
                           "with the box: give a function of t only, or "
                           "Boundary ids for a velocity that varies along "
                           "the sides."));
    velocity->vector_value(Point<dim>(), 0.);
  }



  template <int dim>
  void
  VelocityCondition<dim>::initialize(const ShapeFunctions<dim> &shape_functions)
  {
    communicator =
      shape_functions.dof_handler().get_triangulation().get_communicator();
    if (!depends_on_position)
      return;
    const Utilities::MPI::Partitioner partitioner(
      shape_functions.locally_owned_functions(),
      shape_functions.locally_relevant_functions(),
      communicator);
    std::vector<Point<dim>> points;
    const bool found = shape_functions.function_points(partitioner, points);
    AssertThrow(Utilities::MPI::min(found ? 1 : 0, communicator) == 1,
                ExcMessage(this->where.path() +
                           "Velocity depends on the coordinates, but these "
                           "shape functions do not belong to points at "
                           "which to evaluate it (Powell-Sabin splines "
                           "combine three functions per vertex). Give a "
                           "function of t only, or use Shape functions = "
                           "linear, B-spline or max-ent."));
    node_positions.clear();
    Tensor<1, dim> sum;
    for (const unsigned int i : this->where.functions)
      {
        node_positions.push_back(points[i]);
        sum += points[i];
      }
    const double n_nodes =
      Utilities::MPI::sum(static_cast<double>(node_positions.size()),
                          communicator);
    sum = Utilities::MPI::sum(sum, communicator);
    if (n_nodes > 0.)
      centroid = Point<dim>(sum / n_nodes);
  }



  template <int dim>
  Tensor<1, dim>
  VelocityCondition<dim>::prescribed(const Point<dim> &position,
                                     const double      time) const
  {
    Tensor<1, dim>       result;
    const Tensor<1, dim> value = velocity->vector_value(position, time);
    for (unsigned int d = 0; d < dim; ++d)
      if (components[d])
        result[d] = value[d];
    return result;
  }



  template <int dim>
  void
  VelocityCondition<dim>::check_run(const double end_time) const
  {
    const ConditionNodes<dim> &where = this->where;
    if (where.on_box || !where.fixed_grid || where.normal.norm() == 0.)
      return;
    // The displacement of the prescribed components against the outward
    // normal, by the trapezoidal rule, and its largest value in the run, at
    // each node (a Velocity of time only: at any one).
    const std::vector<Point<dim>> positions =
      depends_on_position ? node_positions :
                            std::vector<Point<dim>>(1, Point<dim>());
    const unsigned int n_intervals = 10000;
    const double       dt          = end_time / n_intervals;
    double             largest     = 0.;
    for (const Point<dim> &position : positions)
      {
        const auto inward_velocity = [&](const double t) {
          return -prescribed(position, t) * where.normal;
        };
        double previous = inward_velocity(0.), travel = 0.;
        for (unsigned int i = 1; i <= n_intervals; ++i)
          {
            const double current = inward_velocity(i * dt);
            travel += 0.5 * dt * (previous + current);
            largest  = std::max(largest, travel);
            previous = current;
          }
      }
    if (depends_on_position)
      largest = Utilities::MPI::max(largest, communicator);
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
  void
  VelocityCondition<dim>::target_velocities(
    const double                 time,
    std::vector<Tensor<1, dim>> &targets) const
  {
    if (depends_on_position)
      for (unsigned int k = 0; k < targets.size(); ++k)
        targets[k] = prescribed(node_positions[k], time);
    else
      std::fill(targets.begin(), targets.end(), prescribed(Point<dim>(), time));
  }



  template <int dim>
  bool
  VelocityCondition<dim>::moves() const
  {
    return true;
  }



  template <int dim>
  double
  VelocityCondition<dim>::advance(
    const std::vector<Tensor<1, dim>> &node_reactions,
    const double                       time,
    const double                       dt)
  {
    double     work        = 0.;
    const auto add_work_of = [&](const Tensor<1, dim> &reaction,
                                 const Tensor<1, dim> &velocity) {
      for (unsigned int d = 0; d < dim; ++d)
        work += dt * reaction[d] * velocity[d];
    };
    if (depends_on_position)
      for (unsigned int k = 0; k < node_reactions.size(); ++k)
        add_work_of(node_reactions[k],
                    prescribed(node_positions[k], time + dt));
    else
      {
        Tensor<1, dim> reaction;
        for (const Tensor<1, dim> &node_reaction : node_reactions)
          reaction += node_reaction;
        add_work_of(reaction, prescribed(Point<dim>(), time + dt));
      }
    this->where.displacement +=
      dt * prescribed(depends_on_position ? centroid : Point<dim>(), time + dt);
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
