#include "reporters/host_name.h"

#include <windows.h>

namespace robottestingframework {
namespace reporters {

// The DNS host name, as gethostname gives it on POSIX (and without Winsock's start-up).
std::string hostName() {
    char buffer[256] = {};
    DWORD size = sizeof(buffer) - 1;
    if (GetComputerNameExA(ComputerNameDnsHostname, buffer, &size) == 0 || size == 0) {
        return "localhost";
    }
    return std::string(buffer, size);
}

}  // namespace reporters
}  // namespace robottestingframework
