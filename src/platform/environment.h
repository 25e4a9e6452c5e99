// Setting and removing this process's environment variables (setenv has no Windows
// counterpart of that name).
#pragma once

#include <string>

namespace robottestingframework {
namespace platform {

// What separates the folders of a list such as PATH or RTF_PLUGIN_PATH (a drive letter's colon
// is part of a Windows path).
#ifdef _WIN32
constexpr char pathListSeparator = ';';
#else
constexpr char pathListSeparator = ':';
#endif

// NAME=VALUE in this process's environment, replacing any value it had.
void setEnvironment(const std::string& name, const std::string& value);
// NAME no longer in this process's environment.
void unsetEnvironment(const std::string& name);

}  // namespace platform
}  // namespace robottestingframework
