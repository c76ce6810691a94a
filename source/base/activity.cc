#include <mpm_otm/base/activity.h>

namespace MpmOtm
{
  namespace Activity
  {
    namespace
    {
      const char *activity = "starting";
    }



    void
    set(const char *what)
    {
      activity = what;
    }



    const char *
    current()
    {
      return activity;
    }



    std::string
    out_of_memory()
    {
      return std::string("mpm-otm ran out of memory (std::bad_alloc) while ") +
             activity +
             ": the run needs more memory than this process may have (the "
             "node's, the job's control group's, or the address-space limit "
             "ulimit -v). Use fewer cells or points (Mesh/Subdivisions, "
             "Particles/Particles per cell), more nodes, or a larger memory "
             "limit.";
    }
  } // namespace Activity
} // namespace MpmOtm
