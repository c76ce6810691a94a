#ifndef mpm_otm_base_read_point_h
#define mpm_otm_base_read_point_h

#include <deal.II/base/point.h>

#include <string>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * Read a point from @p text, a comma-separated list of dim numbers, the
   * value of the parameter @p entry (its path, for the message). Stops
   * naming the entry and what is allowed if @p text is not such a list.
   */
  template <int dim>
  Point<dim>
  read_point(const std::string &text, const std::string &entry);
} // namespace MpmOtm

#endif
