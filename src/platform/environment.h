// Setting and removing this process's environment variables (setenv has no Windows
// counterpart of that name).
#pragma once

#include <string>

namespace robottestingframework {
namespace platform {

// NAME=VALUE in this process's environment, replacing any value it had.
void setEnvironment(const std::string& name, const std::string& value);
// NAME no longer in this process's environment.
void unsetEnvironment(const std::string& name);

}  // namespace platform
}  // namespace robottestingframework
