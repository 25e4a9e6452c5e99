#include "platform/signal_name.h"

// What every platform shares; the names and descriptions are in signal_name-<platform>.cpp.
namespace robottestingframework {
namespace platform {

std::string crashName(int signal) {
    return signalName(signal) + " (" + signalDescription(signal) + ")";
}

}  // namespace platform
}  // namespace robottestingframework
