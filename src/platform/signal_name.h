// Names for signals and process endings, as the reports show them.
#pragma once

#include <string>

namespace robottestingframework {
namespace platform {

// "SIGSEGV", "SIGABRT", ... ; "SIGRTMIN+3"; "signal 99" for unknown numbers.
std::string signalName(int signal);
// The platform's description: "Segmentation fault".
std::string signalDescription(int signal);

}  // namespace platform
}  // namespace robottestingframework
