#include <mpm_otm/base/plugins.h>
#include <mpm_otm/problems/custom_problem.h>

namespace MpmOtm
{
  namespace
  {
    const std::string variables[3] = {"x,t", "x,y,t", "x,y,z,t"};

    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    make_function(const std::string &expressions, const std::string &entry)
    {
      auto function = std::make_unique<FunctionParser<dim>>(dim);
      try
        {
          function->initialize(variables[dim - 1],
                               expressions,
                               {{"pi", numbers::PI}},
                               true);
        }
      catch (const std::exception &error)
        {
          AssertThrow(false,
                      ExcMessage("Custom problem/" + entry + ": <" +
                                 expressions + "> is not a list of " +
                                 std::to_string(dim) + " expressions in " +
                                 variables[dim - 1] +
                                 " separated by ';': " + error.what()));
        }
      return function;
    }

    template <int dim>
    Tensor<1, dim>
    evaluate(const FunctionParser<dim> &function,
             const Point<dim>          &point,
             const double               time)
    {
      // FunctionParser keeps its time as state; it is set on a copy-free
      // path because evaluation is const in the problem interface.
      const_cast<FunctionParser<dim> &>(function).set_time(time);
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        result[d] = function.value(point, d);
      return result;
    }
  } // namespace



  template <int dim>
  void
  CustomProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    const std::string zeros = (dim == 1 ? "0" : dim == 2 ? "0; 0" : "0; 0; 0");
    prm.enter_subsection("Custom problem");
    prm.declare_entry("Initial velocity",
                      zeros,
                      Patterns::Anything(),
                      "dim expressions in the initial position (x, y, z), "
                      "separated by ';'.");
    prm.declare_entry("Body force",
                      zeros,
                      Patterns::Anything(),
                      "Body force per unit mass: dim expressions in the "
                      "initial position (x, y, z) and time t, separated by "
                      "';'.");
    prm.declare_entry("Material lower corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, dim),
                      "Lower corner of the box filled with material at t = 0 "
                      "(empty: the whole grid). Blocks whose centre lies in "
                      "the box are filled.");
    prm.declare_entry("Material upper corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, dim),
                      "Upper corner of the box filled with material at t = 0 "
                      "(empty: the whole grid).");
    prm.declare_entry("Fixed components",
                      "",
                      Patterns::Anything(),
                      "Velocity components fixed to zero per boundary id, "
                      "e.g. '0: x, y; 2: y' (ids: 0 x_min, 1 x_max, 2 y_min, "
                      "3 y_max, 4 z_min, 5 z_max).");
    prm.declare_entry("Traction boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 5)),
                      "Boundary ids whose outermost material points carry "
                      "the traction below.");
    prm.declare_entry("Traction",
                      zeros,
                      Patterns::Anything(),
                      "Traction (force per unit boundary measure): dim "
                      "expressions in t, separated by ';'.");
    prm.declare_entry("Exact displacement",
                      "",
                      Patterns::Anything(),
                      "Optional exact displacement: dim expressions in "
                      "(x, y, z, t); when given, errors are reported.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  CustomProblem<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Custom problem");
    velocity =
      make_function<dim>(prm.get("Initial velocity"), "Initial velocity");
    force = make_function<dim>(prm.get("Body force"), "Body force");
    fixed = this->parse_fixed_components(prm.get("Fixed components"),
                                         "Custom problem/Fixed components");
    for (const int id : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Traction boundary ids"))))
      {
        AssertThrow(id < static_cast<int>(2 * dim),
                    ExcMessage("Custom problem/Traction boundary ids: id " +
                               std::to_string(id) + " must be below " +
                               std::to_string(2 * dim) + "."));
        traction_ids.push_back(id);
      }
    traction_function = make_function<dim>(prm.get("Traction"), "Traction");
    region_lower      = prm.get("Material lower corner");
    region_upper      = prm.get("Material upper corner");
    if (!prm.get("Exact displacement").empty())
      displacement =
        make_function<dim>(prm.get("Exact displacement"), "Exact displacement");
    prm.leave_subsection();
  }



  template <int dim>
  void
  CustomProblem<dim>::initialize(const Material<dim>    &material,
                                 const BoundingBox<dim> &box)
  {
    Problem<dim>::initialize(material, box);
  }



  template <int dim>
  BoundingBox<dim>
  CustomProblem<dim>::material_region() const
  {
    if (region_lower.empty() && region_upper.empty())
      return this->grid_box;
    const auto lower =
      Utilities::string_to_double(Utilities::split_string_list(region_lower));
    const auto upper =
      Utilities::string_to_double(Utilities::split_string_list(region_upper));
    AssertThrow(lower.size() == dim && upper.size() == dim,
                ExcMessage("Custom problem/Material lower corner and "
                           "Material upper corner need " +
                           std::to_string(dim) + " values each."));
    Point<dim> p1, p2;
    for (unsigned int d = 0; d < dim; ++d)
      {
        p1[d] = lower[d];
        p2[d] = upper[d];
        AssertThrow(p2[d] > p1[d],
                    ExcMessage("Custom problem/Material upper corner must be "
                               "above Material lower corner."));
      }
    return BoundingBox<dim>(std::make_pair(p1, p2));
  }



  template <int dim>
  Tensor<1, dim>
  CustomProblem<dim>::initial_velocity(const Point<dim> &X) const
  {
    return evaluate(*velocity, X, 0.);
  }



  template <int dim>
  bool
  CustomProblem<dim>::has_body_force() const
  {
    return true;
  }



  template <int dim>
  Tensor<1, dim>
  CustomProblem<dim>::body_force(const Point<dim> &X, const double time) const
  {
    return evaluate(*force, X, time);
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  CustomProblem<dim>::fixed_components() const
  {
    return fixed;
  }



  template <int dim>
  std::vector<types::boundary_id>
  CustomProblem<dim>::traction_boundaries() const
  {
    return traction_ids;
  }



  template <int dim>
  Tensor<1, dim>
  CustomProblem<dim>::traction(const types::boundary_id,
                               const double time) const
  {
    return evaluate(*traction_function, Point<dim>(), time);
  }



  template <int dim>
  bool
  CustomProblem<dim>::has_exact_solution() const
  {
    return displacement != nullptr;
  }



  template <int dim>
  bool
  CustomProblem<dim>::has_exact_stress() const
  {
    return false;
  }



  template <int dim>
  Tensor<1, dim>
  CustomProblem<dim>::exact_displacement(const Point<dim> &X,
                                         const double      time) const
  {
    return evaluate(*displacement, X, time);
  }



  template class CustomProblem<1>;
  template class CustomProblem<2>;
  template class CustomProblem<3>;
} // namespace MpmOtm

#define MPM_OTM_CUSTOM_DESCRIPTION \
  "conditions given as expressions in subsection 'Custom problem'"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<1>,
                        MpmOtm::CustomProblem<1>,
                        "custom",
                        MPM_OTM_CUSTOM_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<2>,
                        MpmOtm::CustomProblem<2>,
                        "custom",
                        MPM_OTM_CUSTOM_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<3>,
                        MpmOtm::CustomProblem<3>,
                        "custom",
                        MPM_OTM_CUSTOM_DESCRIPTION)
