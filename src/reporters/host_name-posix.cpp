#include "reporters/host_name.h"

#include <unistd.h>

namespace robottestingframework {
namespace reporters {

std::string hostName() {
    char buffer[256] = {};
    if (gethostname(buffer, sizeof(buffer) - 1) != 0) {
        return "localhost";
    }
    return buffer;
}

}  // namespace reporters
}  // namespace robottestingframework
