#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/read_point.h>

#include <vector>

namespace MpmOtm
{
  template <int dim>
  Point<dim>
  read_point(const std::string &text, const std::string &entry)
  {
    std::vector<double> values;
    try
      {
        values =
          Utilities::string_to_double(Utilities::split_string_list(text));
      }
    catch (const std::exception &)
      {
        values.clear();
      }
    AssertThrow(values.size() == dim,
                ExcMessage(entry + ": <" + text + "> must be " +
                           std::to_string(dim) + " numbers separated by ','."));
    Point<dim> point;
    for (unsigned int d = 0; d < dim; ++d)
      point[d] = values[d];
    return point;
  }



  template Point<1>
  read_point<1>(const std::string &, const std::string &);
  template Point<2>
  read_point<2>(const std::string &, const std::string &);
  template Point<3>
  read_point<3>(const std::string &, const std::string &);
} // namespace MpmOtm
