#include <deal.II/base/exceptions.h>

#include <mpm_otm/base/activity.h>
#include <mpm_otm/base/exception_message.h>

#include <new>
#include <sstream>

namespace MpmOtm
{
  std::string
  message_of(const std::exception &error)
  {
    if (dynamic_cast<const std::bad_alloc *>(&error) != nullptr)
      return Activity::out_of_memory();
    const auto *exception = dynamic_cast<const dealii::ExceptionBase *>(&error);
    if (exception == nullptr)
      return error.what();
    // print_info() indents the text and ends it with a new line.
    std::ostringstream text;
    exception->print_info(text);
    const std::string info  = text.str();
    const auto        begin = info.find_first_not_of(" \n");
    const auto        end   = info.find_last_not_of(" \n");
    return (begin == std::string::npos) ? std::string() :
                                          info.substr(begin, end - begin + 1);
  }
} // namespace MpmOtm
