#ifndef mpm_otm_base_parsed_expression_h
#define mpm_otm_base_parsed_expression_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * A list of muparser expressions from one parameter entry, separated by
   * ';', in the coordinates (x, y, z: the first dim of them; unless asked
   * not to) and, if asked for, the time t, with the constant pi. Parse errors
   * and values that are not finite stop the run with a message that names the
   * entry and the variables allowed, instead of muparser's own.
   */
  template <int dim>
  class ParsedExpression
  {
  public:
    /**
     * Parse @p text, which must hold @p n_components expressions; @p entry
     * names the parameter (e.g. "Body beam/Initial velocity") in messages.
     * Without @p space_dependent the expressions may use t only (and a
     * coordinate in them is a parse error).
     */
    ParsedExpression(const std::string &text,
                     const unsigned int n_components,
                     const bool         time_dependent,
                     const std::string &entry,
                     const bool         space_dependent = true);

    ~ParsedExpression();

    /**
     * Number of expressions.
     */
    unsigned int
    n_components() const;

    /**
     * Expression @p component at @p point and @p time; stops if the value is
     * not finite.
     */
    double
    value(const Point<dim>  &point,
          const double       time      = 0.,
          const unsigned int component = 0) const;

    /**
     * The dim expressions as a vector (n_components() must be dim).
     */
    Tensor<1, dim>
    vector_value(const Point<dim> &point, const double time = 0.) const;

    /**
     * Whether every expression is the literal 0 (so that the caller may skip
     * evaluating it).
     */
    bool
    is_zero() const;

    /**
     * Whether some expression names a coordinate (x, y or z).
     */
    bool
    uses_coordinates() const;

    /**
     * The variables the expressions may use, e.g. "x, y, t".
     */
    std::string
    variables() const;

  private:
    std::string                          entry;
    bool                                 time_dependent;
    bool                                 space_dependent;
    bool                                 zero        = false;
    bool                                 coordinates = false;
    std::unique_ptr<FunctionParser<dim>> function;
  };
} // namespace MpmOtm

#endif
