#ifndef mpm_otm_base_activity_h
#define mpm_otm_base_activity_h

#include <string>

namespace MpmOtm
{
  /**
   * What the program is doing now, in words, for the message that reports
   * memory running out (std::bad_alloc can happen anywhere, and carries no
   * word about what was being allocated). The simulator names each stage of
   * its set-up and the time loop.
   */
  namespace Activity
  {
    /**
     * Record @p what ("seeding the material points"); a string literal,
     * which must outlive the program.
     */
    void
    set(const char *what);

    /**
     * The last activity recorded ("starting" before any).
     */
    const char *
    current();

    /**
     * The message for memory running out now: what the program was doing
     * and what helps.
     */
    std::string
    out_of_memory();
  } // namespace Activity
} // namespace MpmOtm

#endif
