// Windows: the system's words for a Win32 or Winsock error code (FormatMessage), without the
// line break and full stop Windows ends them with; "error N" when it has none. Defined in
// system_error-windows.cpp only: POSIX code words errno with strerror.
#pragma once

#include <string>

namespace robottestingframework {
namespace platform {

std::string systemErrorText(unsigned long code);

}  // namespace platform
}  // namespace robottestingframework
