// Windows: the C run-time's copy (what getenv reads) and the process's own (what
// CreateProcess hands on and what GetEnvironmentVariable reads) are kept alike.
#include "platform/environment.h"

#include <stdlib.h>
#include <windows.h>

namespace robottestingframework {
namespace platform {

void setEnvironment(const std::string& name, const std::string& value) {
    ::_putenv_s(name.c_str(), value.c_str());
    ::SetEnvironmentVariableA(name.c_str(), value.c_str());
}

void unsetEnvironment(const std::string& name) {
    ::_putenv_s(name.c_str(), "");  // an empty value removes it
    ::SetEnvironmentVariableA(name.c_str(), nullptr);
}

}  // namespace platform
}  // namespace robottestingframework
