#include <deal.II/base/utilities.h>

#include <mpm_otm/base/parsed_expression.h>

#include <algorithm>
#include <cmath>
#include <regex>

namespace MpmOtm
{
  namespace
  {
    // FunctionParser<dim> always takes dim coordinates: an expression in
    // time only gets them under names no one writes.
    std::string
    variable_list(const unsigned int dim,
                  const bool         time_dependent,
                  const bool         space_dependent)
    {
      std::string result;
      for (unsigned int d = 0; d < dim; ++d)
        result += (d > 0 ? "," : "") +
                  std::string(space_dependent ? "" : "unused_coordinate_") +
                  std::string(1, "xyz"[d]);
      return time_dependent ? result + ",t" : result;
    }
  } // namespace



  template <int dim>
  ParsedExpression<dim>::ParsedExpression(const std::string &text,
                                          const unsigned int n_components,
                                          const bool         time_dependent,
                                          const std::string &entry,
                                          const bool         space_dependent)
    : entry(entry)
    , time_dependent(time_dependent)
    , space_dependent(space_dependent)
  {
    Assert(space_dependent || time_dependent, ExcInternalError());
    const auto parts = Utilities::split_string_list(text, ';');
    AssertThrow(parts.size() == n_components,
                ExcMessage(entry + ": <" + text + "> must be " +
                           std::to_string(n_components) +
                           " expression(s) separated by ';', in " +
                           variables() + "."));
    zero = std::all_of(parts.begin(), parts.end(), [](const std::string &part) {
      return part == "0";
    });
    // A coordinate is a name of its own: an identifier that is x, y or z.
    const std::regex identifier("[A-Za-z_][A-Za-z0-9_]*");
    for (auto name = std::sregex_iterator(text.begin(), text.end(), identifier);
         name != std::sregex_iterator();
         ++name)
      coordinates = coordinates || name->str() == "x" || name->str() == "y" ||
                    name->str() == "z";
    function = std::make_unique<FunctionParser<dim>>(n_components);
    try
      {
        function->initialize(variable_list(dim,
                                           time_dependent,
                                           space_dependent),
                             parts,
                             {{"pi", numbers::PI}},
                             time_dependent);
        // deal.II parses the expressions at their first evaluation: do it
        // now, so that a parse error is reported as one (the value itself
        // may be anything here).
        for (unsigned int c = 0; c < n_components; ++c)
          function->value(Point<dim>(), c);
      }
    catch (const std::exception &)
      {
        AssertThrow(false,
                    ExcMessage(entry + ": <" + text +
                               "> is not a list of expressions in " +
                               variables() +
                               " that muparser can read (check the variable "
                               "names, brackets and operators)."));
      }
  }



  template <int dim>
  ParsedExpression<dim>::~ParsedExpression() = default;



  template <int dim>
  unsigned int
  ParsedExpression<dim>::n_components() const
  {
    return function->n_components;
  }



  template <int dim>
  bool
  ParsedExpression<dim>::is_zero() const
  {
    return zero;
  }



  template <int dim>
  bool
  ParsedExpression<dim>::uses_coordinates() const
  {
    return coordinates;
  }



  template <int dim>
  std::string
  ParsedExpression<dim>::variables() const
  {
    if (!space_dependent)
      return "t";
    std::string result;
    for (unsigned int d = 0; d < dim; ++d)
      result += (d > 0 ? ", " : "") + std::string(1, "xyz"[d]);
    return time_dependent ? result + " and t" : result;
  }



  template <int dim>
  double
  ParsedExpression<dim>::value(const Point<dim>  &point,
                               const double       time,
                               const unsigned int component) const
  {
    double result = 0;
    try
      {
        // FunctionParser keeps the time as its state.
        function->set_time(time);
        result = function->value(point, component);
      }
    catch (const std::exception &)
      {
        result = std::numeric_limits<double>::quiet_NaN();
      }
    if (!std::isfinite(result))
      {
        std::string where;
        if (space_dependent)
          {
            where = " at (" + Utilities::to_string(point[0]);
            for (unsigned int d = 1; d < dim; ++d)
              where += ", " + Utilities::to_string(point[d]);
            where += ")";
          }
        if (time_dependent)
          where += (space_dependent ? ", t = " : " at t = ") +
                   Utilities::to_string(time);
        AssertThrow(false,
                    ExcMessage(
                      entry + ": expression " + std::to_string(component + 1) +
                      " does not evaluate to a finite number" + where + "."));
      }
    return result;
  }



  template <int dim>
  Tensor<1, dim>
  ParsedExpression<dim>::vector_value(const Point<dim> &point,
                                      const double      time) const
  {
    Assert(n_components() == dim, ExcInternalError());
    Tensor<1, dim> result;
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = value(point, time, d);
    return result;
  }



  template class ParsedExpression<1>;
  template class ParsedExpression<2>;
  template class ParsedExpression<3>;
} // namespace MpmOtm
