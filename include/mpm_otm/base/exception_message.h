#ifndef mpm_otm_base_exception_message_h
#define mpm_otm_base_exception_message_h

#include <exception>
#include <string>

namespace MpmOtm
{
  /**
   * The text of an exception for a message of the program's own: for a
   * deal.II exception its "additional information" without the banner, the
   * stack trace and the surrounding blank space; for any other its what().
   */
  std::string
  message_of(const std::exception &error);
} // namespace MpmOtm

#endif
