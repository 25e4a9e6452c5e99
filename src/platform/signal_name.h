// Names for signals and process endings, as the reports show them.
#pragma once

#include <string>

namespace robottestingframework {
namespace platform {

// "SIGSEGV", "SIGABRT", ... ; "SIGRTMIN+3"; "signal 99" for unknown numbers.
std::string signalName(int signal);
// The number of a signal named as signalName() names it ("SIGTERM"); 0 when none is.
int signalNumber(const std::string& name);
// The platform's description: "Segmentation fault".
std::string signalDescription(int signal);

}  // namespace platform
}  // namespace robottestingframework
